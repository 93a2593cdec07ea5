// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-classroom's commands, one file each: init (init_command.cpp) and
// serve (serve_command.cpp). Each parses the process's arguments itself.
#pragma once

#include "program_command_line.h"

#include <QString>

#include <cstdio>

namespace classroom {

int initCommand();
int serveCommand();

// "roomba-classroom: what" on standard error; returns `status`.
inline int fail(const QString &message, int status = ProgramCommandLine::kUsageError)
{
    std::fprintf(stderr, "roomba-classroom: %s\n", qPrintable(message));
    return status;
}

} // namespace classroom
