// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl mcap RECORDING -o OUT.mcap [--compression zstd|lz4|none].
#include "ctl_command_line.h"
#include "recording_file.h"
#include "recording_mcap.h"

#include <QFileInfo>

#include <iostream>

namespace ctl {

int recordingMcap(const Arguments &args)
{
    QCommandLineParser parser;
    parser.addOptions({{{QStringLiteral("o"), QStringLiteral("output")}, QString(), QStringLiteral("OUT.mcap")},
                       {QStringLiteral("compression"), QString(), QStringLiteral("NAME")}});
    if (!parseCommandLine(parser, args, true, "mcap: "))
        return 2;
    oilink::McapExportOptions options;
    if (parser.isSet(QStringLiteral("compression"))) {
        const QString name = parser.value(QStringLiteral("compression"));
        if (name.isEmpty() || !mcap::compressionFromName(name, &options.compression))
            return fail("mcap: unknown compression '" + toStd(name) + "'; use zstd, lz4 or none");
    }
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1)
        return fail("mcap takes one recording file; '" + toStd(files[1]) + "' is a second");
    const std::string in = files.isEmpty() ? std::string() : toStd(files.first());
    const std::string out = toStd(parser.value(QStringLiteral("output")));
    if (in.empty() || out.empty())
        return fail("mcap needs a recording file and -o OUT.mcap");
    QString error;
    const std::optional<oilink::Recording> recording = oilink::Recording::load(QString::fromStdString(in), &error);
    if (recording)
        error = oilink::exportRecordingMcap(*recording, QString::fromStdString(out), options);
    if (!error.isEmpty())
        return fail(error.toStdString() + "; nothing was written");
    sayMarkersLeftOut(in, recording->markersLeftOut());
    if (const std::optional<oilink::RecordingDamage> &damage = recording->damage()) {
        std::cerr << "roomba-ctl: " << in << ": damaged: " << damage->describe().toStdString()
                  << "; exported up to there\n";
        return 1;
    }
    std::cerr << "roomba-ctl: wrote " << out << " (" << QFileInfo(QString::fromStdString(out)).size() << " bytes)\n";
    return 0;
}

} // namespace ctl
