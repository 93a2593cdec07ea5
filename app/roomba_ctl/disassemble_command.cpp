// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl disassemble [--profile P] BYTE...: a Create script body as text.
#include "command_catalog.h"
#include "ctl_command_line.h"
#include "script_assembler.h"

#include <iostream>

namespace ctl {

int disassemble(const Arguments &args)
{
    QCommandLineParser parser;
    const oi::RobotProfile *profile = parseWithProfile(parser, args);
    if (!profile)
        return 2;
    oi::Bytes body;
    for (const QString &word : parser.positionalArguments()) {
        long long v = 0;
        if (!oi::parseInteger(toStd(word), v) || v < 0 || v > 255)
            return fail("'" + toStd(word) + "' is not a byte value (0..255)");
        body.push_back(static_cast<std::uint8_t>(v));
    }
    const auto text = oi::disassembleScript(*profile, body);
    if (!text) {
        std::cerr << "roomba-ctl: " << text.error().describe() << "\n";
        return 1;
    }
    std::cout << *text << "\n";
    return 0;
}

} // namespace ctl
