// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl: the Open Interface core, and robots through the link, from the
// command line. Each command is in a file of its own (*_command.cpp).

#include "ctl_command_line.h"

#include <iostream>
#include <string>
#include <vector>

namespace {

constexpr const char *kUsage = R"(Usage: roomba-ctl COMMAND [OPTIONS] ...

Commands:
  encode [--profile P] [--hex] NAME ARGS...
      Print the bytes of one Open Interface command, e.g.
        roomba-ctl encode drive -200 500          -> 137 255 56 1 244
        roomba-ctl encode song 0 C4:32 D4:32 rest:16
        roomba-ctl encode digit-leds-ascii ABCD
        roomba-ctl encode schedule "wed 15:00, fri 10:36"
        roomba-ctl encode --profile create1 script "drive 300 straight; wait-distance 400; drive 0 0"
      Options go before NAME, so negative numbers reach the command.
  decode [--profile P] [--reply IDS] [--numbers] [--legacy-checksum]
      Read bytes from standard input and print one JSON object per stream
      frame or sensor reply, then a line of parser counters.
        --reply IDS        read unframed replies to Sensors / Query List for
                           these comma-separated packet or group ids
        --numbers          input is text: decimal or 0x hex byte values
        --legacy-checksum  leave the header out of the checksum (not what
                           robots do; for the documents' old examples)
  disassemble [--profile P] BYTE...
      Turn a Create script body (the bytes after 152 LENGTH) into text.
  commands [--profile P]
      List every command the profile has, with its opcode and arguments.
  packets [--profile P]
      Print the profile's packet table and groups.
  sensors ROBOT [--profile P] [--baud B] [--brc-line L] [--count N]
      Connect, start the sensor stream that fits the baud, print N stream
      frames (default 10) as JSON lines like decode, then one line of link
      statistics. Closing leaves the robot stopped and in Passive mode.
  send ROBOT [--profile P] [--baud B] [--brc-line L] [--no-mode-change] NAME ARGS...
      Send one command (as encode makes it) so that the robot carries it
      out: the robot is asked for its mode first; Start goes out only if it
      is silent (Off mode), and a command that works only in Safe or Full
      mode (drive, motors, LEDs, play, play-script...) enters Safe from
      Passive. Baud is refused over raw TCP, where the bridge's rate cannot
      follow (use --rfc2217, or change ser2net's config). A
      warning says when the robot will ignore the command as things are
      (a wheel dropped, on the dock, a song playing). The answers to
      sensors and query-list are printed as JSON lines like decode.
        --no-mode-change   never send Start or Safe; refuse a command the
                           robot's mode would ignore
        roomba-ctl send --port /dev/ttyUSB0 safe
        roomba-ctl send --port /dev/ttyUSB0 drive 200 straight
        roomba-ctl send --sim sensors 7
  doctor ROBOT [--profile P] [--baud B] [--brc-line L]
      Find out why a robot gives no valid data, and print what was tried:
      each baud with and without Start, a BRC pulse to wake it (given up to
      2 s, as slow robots need; then on the other line), the three pulses
      for 19200 baud, then which robot answers. Exit status 0 when
      the robot answers as it is (woken by a pulse included; a Roomba 500
      or Create 2 found without --profile is named on standard error with
      the flag to give), 1 with what to change on the last line.
        roomba-ctl doctor --port /dev/ttyUSB0
  wake ROBOT [--profile P] [--brc-line L]
      Pulse the robot's BRC pin: wakes a Roomba 500 or Create 2 that sleeps,
      and switches on one switched off at its power button (the link never
      does that by itself). Then sends Start (Passive mode) and asks its
      mode; exit status 0 when it answers.
        roomba-ctl wake --port /dev/ttyUSB0
  calibrate ROBOT [--profile P] [--baud B] (--straight MM | --turns N)
      Drive one calibration run by the wheel encoders, counted with the
      documented 72 mm wheels and 235 mm wheel base, in Safe mode, slowly
      (100 mm/s), then stop: --straight MM ahead, or --turns N whole turns
      on the spot (counter-clockwise). A bump, cliff or wheel drop stops the
      run (exit status 1); so does Ctrl+C. Prints one JSON line: the counts
      and the robot's own distance and angle packets. Measure what the robot
      really did (a tape from start to end; a mark on the floor for turns)
      and give it to calibrate --compute.
        roomba-ctl calibrate --port /dev/ttyUSB0 --straight 1000
  calibrate --compute [--straight MM --measured MM] [--turns N --measured-angle DEG]
      Work out the wheels from runs driven as above: the wheel diameters
      (left, right), their scale against the documented 72 mm, the wheel base,
      and the error of a 1 m square before and after, as one JSON line.
        roomba-ctl calibrate --compute --straight 1000 --measured 1040 --turns 2 --measured-angle 700
  battery [ROBOT] [--watch] [--text] [--seconds N]
      The health of each robot's pack, as the dashboard measured and kept
      it per robot: good, worn or replace, with the measured capacity
      against what the robot claims, the internal resistance, how much of
      a cycle was seen and the trend, as one JSON line per robot (--text:
      a line of words). With ROBOT, measures that robot from its stream for
      N seconds (default 10) and prints it; --watch prints it every N
      seconds (default 5) until Ctrl+C. Measuring needs the robot to drive
      (resistance) and part of a discharge or charge (capacity).
        roomba-ctl battery --text
        roomba-ctl battery --port /dev/ttyUSB0 --watch
  csv RECORDING
      Print a recording (.oirec, from the dashboard or its --record) as CSV:
      time_s, then one column per packet (key[unit]), one row per stream frame. A damaged
      recording prints up to the damage and says where it is on stderr.
  mcap RECORDING -o OUT.mcap [--compression zstd|lz4|none]
      Export a recording as MCAP for Foxglove, Lichtblick or PlotJuggler:
      telemetry as JSON with a JSON Schema, the odometry pose, the bytes both
      ways, events and mode changes as log messages (docs/mcap.md). zstd is
      the default. A damaged recording is exported up to the damage, which
      is named on stderr (exit status 1); OUT.mcap is never left half-written.
  serve RECORDING --foxglove [ADDRESS:]PORT
      Serve a recording live over the Foxglove WebSocket protocol, as the
      dashboard serves its robots (docs/foxglove.md), with its time range:
      Foxglove's timeline plays, pauses, seeks and sets the speed of the
      replay. 127.0.0.1 (this computer only) unless ADDRESS is given.
      Ctrl+C ends.
        roomba-ctl serve run.oirec --foxglove 8765
  --help, --version

ROBOT is one of:
  --port PATH        a serial port, USB adapter or pseudo-terminal
  --tcp HOST:PORT    a serial-over-TCP bridge (ser2net raw mode); add
                     --rfc2217 for a bridge in telnet mode with RFC 2217,
                     through which the robot's BRC pin can be pulsed
  --sim              the built-in virtual robot, playing --profile
  --brc-line LINE    the wake line: the adapter's line wired to the robot's
                     BRC pin, pulsed to wake it and keep it awake: rts
                     (default), dtr, both, or none (the cable has no BRC
                     wire: no pulse is tried). The doctor tries the other
                     line when the robot does not wake, and names it.
Without --profile, sensors and send find the robot's profile (and on a
serial port, its baud among 115200, 57600 and 19200) by asking it. A Roomba
500 and a Create 2 answer alike but read their wheel encoders (43, 44) the
other way round: found without --profile, they are taken for a create2 and
say so on standard error; sensors leaves 43 and 44 out, and send refuses to
ask for them (or for groups 100 and 101). Name the robot with --profile.

Profiles: roomba500, create2 (also roomba600), create1 (also create),
roomba400 (also sci, discovery, dirtdog: the 2005 SCI, polled).
The default profile is create2 (encode, decode, --sim).
)";

} // namespace

int main(int argc, char **argv)
{
    const ctl::Arguments args(argv + 1, argv + argc);
    if (args.empty())
        return ctl::fail(std::string("no command given\n") + kUsage);
    const std::string &command = args[0];
    if (command == "--help" || command == "-h" || command == "help") {
        std::cout << kUsage;
        return 0;
    }
    if (command == "--version") {
        std::cout << "roomba-ctl " << ROOMBA_VERSION << "\n";
        return 0;
    }
    if (command == "encode")
        return ctl::encode(args);
    if (command == "decode")
        return ctl::decode(args);
    if (command == "disassemble")
        return ctl::disassemble(args);
    if (command == "commands")
        return ctl::listCommands(args);
    if (command == "packets")
        return ctl::listPackets(args);
    if (command == "sensors")
        return ctl::streamSensors(argc, argv, args);
    if (command == "send")
        return ctl::sendToRobot(argc, argv, args);
    if (command == "doctor")
        return ctl::runDoctor(argc, argv, args);
    if (command == "wake")
        return ctl::wakeRobot(argc, argv, args);
    if (command == "calibrate")
        return ctl::calibrate(argc, argv, args);
    if (command == "battery")
        return ctl::batteryHealth(argc, argv, args);
    if (command == "csv")
        return ctl::recordingCsv(args);
    if (command == "mcap")
        return ctl::recordingMcap(args);
    if (command == "serve")
        return ctl::serveRecording(argc, argv, args);
    return ctl::fail("unknown command '" + command + "'; try --help");
}
