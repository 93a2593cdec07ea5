// SPDX-License-Identifier: GPL-3.0-or-later
// Telemetry bytes per second per robot, as a bridge publishes them: a
// virtual Create 2 streaming group 100, driven round its default room for
// ten simulated minutes (forward until it bumps, back, turn; Safe again
// after a cliff), its frames
// told as docs/mqtt.md says, with each message's MQTT header and topic
// counted. Offline and deterministic: the robot's own clock is advanced.
#include "command_encoder.h"
#include "snapshot_json.h"
#include "stream_parser.h"
#include "telemetry_changes.h"
#include "virtual_robot.h"

#include <QJsonDocument>

#include <cstdio>

namespace {

constexpr int kMinutes = 10;
// PUBLISH fixed header (2), topic length (2), "roomba/r1/telemetry".
constexpr double kMqttBytesPerMessage = 2 + 2 + 19;

void send(sim::VirtualRobot &robot, const oi::EncodeResult &bytes)
{
    robot.receive(bytes.value());
}

} // namespace

int main()
{
    const oi::RobotProfile &profile = oi::profile(oi::ProfileId::Create2);
    const oi::CommandEncoder encode(profile);
    sim::VirtualRobot robot(profile);
    send(robot, encode.start());
    send(robot, encode.safe());
    const int group[] = {100};
    send(robot, encode.stream(group));

    oi::StreamParser parser(profile);
    oilink::TelemetryChanges changes;
    double fullBytes = 0, changedBytes = 0, frames = 0, messages = 0, keyFrames = 0;
    qint64 nowMs = 0;
    enum class Drive { Forward, Back, Turn } drive = Drive::Forward;
    qint64 phaseEndsMs = 0;
    parser.setSnapshotHandler([&](const oi::SensorSnapshot &frame, oi::FrameKind kind) {
        if (kind != oi::FrameKind::Stream)
            return;
        const double stamp = 1795000000.0 + double(nowMs) / 1000.0;
        QJsonObject whole = oilink::snapshotToJson(frame);
        whole.insert(QLatin1String("key_frame"), true);
        whole.insert(QLatin1String("timestamp"), stamp);
        fullBytes += double(QJsonDocument(whole).toJson(QJsonDocument::Compact).size()) + kMqttBytesPerMessage;

        ++frames;
        const auto told = changes.next(frame, nowMs);
        if (told.send) {
            QJsonObject o = oilink::snapshotToJson(told.packets);
            if (told.keyFrame)
                o.insert(QLatin1String("key_frame"), true);
            o.insert(QLatin1String("timestamp"), stamp);
            changedBytes += double(QJsonDocument(o).toJson(QJsonDocument::Compact).size()) + kMqttBytesPerMessage;
            ++messages;
            keyFrames += told.keyFrame;
        }

        // A cliff drops it to Passive: back into Safe, as a driver would.
        if (frame.raw(35) != int(oi::OiMode::Safe))
            send(robot, encode.safe());
        // Forward until a bump, back for 0.5 s, turn for 0.7 s.
        const bool bumped = (frame.raw(7) & 0x03) != 0 || frame.raw(45) != 0;
        if (drive == Drive::Forward && bumped) {
            drive = Drive::Back;
            phaseEndsMs = nowMs + 500;
            send(robot, encode.driveDirect(-200, -200));
        } else if (drive == Drive::Back && nowMs >= phaseEndsMs) {
            drive = Drive::Turn;
            phaseEndsMs = nowMs + 700;
            send(robot, encode.driveDirect(-150, 150));
        } else if (drive == Drive::Turn && nowMs >= phaseEndsMs) {
            drive = Drive::Forward;
            send(robot, encode.driveDirect(300, 300));
        }
    });
    send(robot, encode.driveDirect(300, 300));
    while (nowMs < kMinutes * 60'000) {
        robot.advance(std::chrono::milliseconds(1));
        nowMs = std::chrono::duration_cast<std::chrono::milliseconds>(robot.now()).count();
        const oi::Bytes out = robot.takeOutput();
        parser.feed(out);
    }

    std::printf("parser: %llu good, %llu checksum failures, %llu discarded\n", (unsigned long long)parser.counters().framesGood, (unsigned long long)parser.counters().checksumFailures, (unsigned long long)parser.counters().bytesDiscarded);
    const double seconds = kMinutes * 60.0;
    std::printf("telemetry of a driven virtual Create 2, %d simulated minutes, %.0f frames (%.1f per second)\n",
                kMinutes, frames, frames / seconds);
    std::printf("  every packet in every message (--full-telemetry): %8.0f bytes/s, a message a frame\n", fullBytes / seconds);
    std::printf("  what changed, key frame each second (default):    %8.0f bytes/s, %.1f messages a second (%.0f key frames)\n",
                changedBytes / seconds, messages / seconds, keyFrames);
    return 0;
}
