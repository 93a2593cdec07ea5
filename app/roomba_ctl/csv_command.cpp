// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl csv RECORDING: a recording as CSV, one row per stream frame.
#include "ctl_command_line.h"
#include "recording_file.h"

#include <QTextStream>

#include <iostream>

namespace ctl {

int recordingCsv(const Arguments &args)
{
    QCommandLineParser parser;
    if (!parseCommandLine(parser, args))
        return 2;
    if (parser.positionalArguments().size() != 1)
        return fail("csv needs one recording file");
    const std::string path = toStd(parser.positionalArguments().first());
    QString error;
    const std::optional<oilink::Recording> recording =
        oilink::Recording::load(QString::fromStdString(path), &error);
    if (!recording)
        return fail(error.toStdString());
    sayMarkersLeftOut(path, recording->markersLeftOut());
    QTextStream out(stdout);
    recording->writeCsv(out);
    out.flush();
    if (recording->damage()) {
        std::cerr << "roomba-ctl: " << path << ": damaged: " << recording->damage()->describe().toStdString()
                  << "\n";
        return 1;
    }
    return 0;
}

} // namespace ctl
