// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What every roomba-ctl command shares: its arguments read with
// QCommandLineParser, one-line errors, the JSON lines it prints, and the
// options that say where the robot is.

#include "link_settings.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"
#include "stream_parser.h"

#include <QCommandLineParser>
#include <QString>

#include <string>
#include <vector>

namespace oilink {
class LocalRobotPort;
}
class QTimer;

namespace ctl {

// The command's words, its name first ("encode", "--hex", "drive", ...).
using Arguments = std::vector<std::string>;

// Prints "roomba-ctl: MESSAGE" on standard error; returns 2, the status of
// a usage error.
int fail(const std::string &message);
std::string toStd(const QString &text);
// Says on standard error, when a recording at `path` held markers beyond the
// limit, how many were left out of what is written.
void sayMarkersLeftOut(const std::string &path, int leftOut);

// Reads the command's words with `parser`. Options go before the first
// other argument, so negative numbers reach the command, unless
// `optionsAnywhere` (a command that takes no numbers). False after printing
// what is wrong, which starts with `prefix` ("mcap: ").
bool parseCommandLine(QCommandLineParser &parser, const Arguments &args, bool optionsAnywhere = false,
                      const std::string &prefix = {});

// For the commands that work without a robot: adds --profile P to the
// command's other options, reads its words, and returns the profile
// (create2 when left out); nullptr after printing what is wrong.
const oi::RobotProfile *parseWithProfile(QCommandLineParser &parser, const Arguments &args);

// One JSON line for a decoded frame or reply, {"kind": ..., "packets": {...}}
// with the packets as snapshotToJson writes them: what decode, sensors and
// send print.
std::string snapshotJson(const oi::SensorSnapshot &s, oi::FrameKind kind);

// Where the robot is and how to reach it (ROBOT in the usage).
struct LinkOptions {
    oilink::LinkSettings settings;
    std::optional<oi::ProfileId> profile; // as given: nullopt to find it
    int baud = 0;
};
// --port, --tcp, --rfc2217, --sim, --profile, --baud, --brc-line.
void addLinkOptions(QCommandLineParser &parser);
// False after printing the error; `command` names the command in it.
bool readLinkOptions(const QCommandLineParser &parser, const std::string &command, LinkOptions &o);

constexpr int kFirstFrameTimeoutMs = 20000; // covers probing three bauds, twice

// How a command that runs the event loop ends: once, with its status and any
// message on standard error ("roomba-ctl: MESSAGE").
struct LoopEnd {
    int status = 0;
    bool finished = false;
    void operator()(int code, const std::string &message);
};
// Opens the link and runs the event loop until `finish`; `silence` (a
// single shot each frame restarts) ends it when no data comes. The link is
// stopped, the robot in Passive; returns the status. When `linkSaid` holds
// the link's own last words (already printed), they are the reason given.
int runStreaming(oilink::LocalRobotPort &link, const oilink::LinkSettings &settings, QTimer &silence, LoopEnd &finish,
                 const QString *linkSaid = nullptr);

// The commands, each in a file of its own.
int encode(const Arguments &args);
int decode(const Arguments &args);
int disassemble(const Arguments &args);
int listCommands(const Arguments &args);
int listPackets(const Arguments &args);
int streamSensors(int argc, char **argv, const Arguments &args);
int sendToRobot(int argc, char **argv, const Arguments &args);
int runDoctor(int argc, char **argv, const Arguments &args);
int wakeRobot(int argc, char **argv, const Arguments &args);
int calibrate(int argc, char **argv, const Arguments &args);
int batteryHealth(int argc, char **argv, const Arguments &args);
int recordingCsv(const Arguments &args);
int recordingMcap(const Arguments &args);
int serveRecording(int argc, char **argv, const Arguments &args);

} // namespace ctl
