// SPDX-License-Identifier: GPL-3.0-or-later
#include "program_command_line.h"

#include <QCoreApplication>

#include <cstdio>

ProgramCommandLine::ProgramCommandLine(QCommandLineParser &parser, const QString &name, const QString &version,
                                       const QString &description)
    : m_parser(parser), m_help(parser.addHelpOption()), m_version(parser.addVersionOption())
{
    QCoreApplication::setApplicationName(name);
    QCoreApplication::setApplicationVersion(version);
    parser.setApplicationDescription(description);
}

std::optional<int> ProgramCommandLine::parse(const QString &hint) const
{
    const QString name = QCoreApplication::applicationName();
    if (!m_parser.parse(QCoreApplication::arguments())) {
        std::fprintf(stderr, "%s: %s\n", qPrintable(name), qPrintable(m_parser.errorText() + hint));
        return kUsageError;
    }
    if (m_parser.isSet(m_help)) {
        std::fputs(qPrintable(m_parser.helpText()), stdout);
        return 0;
    }
    if (m_parser.isSet(m_version)) {
        std::printf("%s %s\n", qPrintable(name), qPrintable(QCoreApplication::applicationVersion()));
        return 0;
    }
    return std::nullopt;
}
