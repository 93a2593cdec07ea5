// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>

#include <optional>

// The command line as roomba-bridge, roomba-classroom and roomba-sim share
// it: the program's name and version, -h/--help and -v/--version ahead of its
// own options, the help on standard output, "NAME VERSION", and a mistake on
// standard error as "NAME: what" with exit status 2.
class ProgramCommandLine
{
public:
    static constexpr int kUsageError = 2;

    // Names the program for QCoreApplication (which must exist) and adds
    // --help and --version to `parser`; the program adds its own options after.
    ProgramCommandLine(QCommandLineParser &parser, const QString &name, const QString &version,
                       const QString &description);

    // Parses the process's arguments. Empty: go on. Otherwise the status to
    // exit with, the help, the version or the mistake (followed by `hint`)
    // having been printed.
    std::optional<int> parse(const QString &hint = {}) const;

private:
    QCommandLineParser &m_parser;
    QCommandLineOption m_help;
    QCommandLineOption m_version;
};
