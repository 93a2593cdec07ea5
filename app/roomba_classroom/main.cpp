// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-classroom: a classroom's broker in one command (init), and the
// blocks page with its hub (serve). docs/classroom.md, docs/blocks.md.

#include "classroom_commands.h"

#include <QCoreApplication>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    if (QCoreApplication::arguments().value(1) == QLatin1String("serve"))
        return classroom::serveCommand();
    return classroom::initCommand(); // init, --help, --version and mistakes
}
