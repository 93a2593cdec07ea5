// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl encode [--profile P] [--hex] NAME ARGS...: the bytes of one command.
#include "command_catalog.h"
#include "command_encoder.h"
#include "ctl_command_line.h"

#include <cstdio>
#include <iostream>

namespace ctl {

int encode(const Arguments &args)
{
    QCommandLineParser parser;
    parser.addOption({QStringLiteral("hex"), QString()});
    const oi::RobotProfile *profile = parseWithProfile(parser, args);
    if (!profile)
        return 2;
    const QStringList words = parser.positionalArguments();
    if (words.isEmpty())
        return fail("encode needs a command name; see 'roomba-ctl commands'");
    const oi::CommandEncoder encoder(*profile);
    std::vector<std::string> rest;
    for (qsizetype i = 1; i < words.size(); ++i)
        rest.push_back(toStd(words[i]));
    const oi::EncodeResult bytes = oi::encodeCommand(encoder, toStd(words.first()), rest);
    if (!bytes) {
        std::cerr << "roomba-ctl: " << bytes.error().describe() << "\n";
        return 1;
    }
    if (!bytes.warning.empty())
        std::cerr << "roomba-ctl: warning: " << bytes.warning << "\n";
    const bool hex = parser.isSet(QStringLiteral("hex"));
    std::string line;
    char buf[8];
    for (std::uint8_t b : *bytes) {
        std::snprintf(buf, sizeof buf, hex ? "%02X" : "%u", static_cast<unsigned>(b));
        if (!line.empty())
            line += ' ';
        line += buf;
    }
    std::cout << line << "\n";
    return 0;
}

} // namespace ctl
