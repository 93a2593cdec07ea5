// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A virtual robot on the bench, driven only through bytes: commands from the
// command encoder, what it says read back with the stream parser, its clock
// advanced by hand.
#include "command_encoder.h"
#include "stream_parser.h"
#include "virtual_robot.h"

#include <QTest>

#include <algorithm>
#include <functional>
#include <optional>
#include <vector>

// The bytes of a command that must encode; a refusal fails the test.
inline oi::Bytes must(const oi::EncodeResult &r)
{
    if (!r.ok()) {
        QTest::qFail(("encoder refused: " + r.error().describe()).c_str(), __FILE__, __LINE__);
        return {};
    }
    return r.value();
}

inline oi::Bytes concat(std::initializer_list<oi::Bytes> parts)
{
    oi::Bytes out;
    for (const oi::Bytes &p : parts)
        out.insert(out.end(), p.begin(), p.end());
    return out;
}

// A robot, an encoder for its profile and a parser for what it says.
struct Bench {
    explicit Bench(const oi::RobotProfile &profile, std::uint32_t seed = 1)
        : robot(profile, seed), encoder(profile), parser(profile)
    {
        parser.setSnapshotHandler([this](const oi::SensorSnapshot &s, oi::FrameKind kind) {
            if (kind == oi::FrameKind::Stream) {
                frames.push_back(s);
                if (onFrame)
                    onFrame(s);
            } else {
                replies.push_back(s);
            }
        });
    }

    void send(const oi::Bytes &bytes)
    {
        robot.receive(bytes);
        collect();
    }
    void send(const oi::EncodeResult &r) { send(must(r)); }

    void run(sim::Microseconds dt)
    {
        // In stream-sized steps, so a frame handler sees frames as they come.
        using namespace std::chrono_literals;
        while (dt > 0us) {
            const sim::Microseconds step = std::min<sim::Microseconds>(dt, 15ms);
            robot.advance(step);
            collect();
            dt -= step;
        }
    }

    void collect()
    {
        const oi::Bytes out = robot.takeOutput();
        raw.insert(raw.end(), out.begin(), out.end());
        parser.feed(out);
    }

    // Sends Query List for `ids` and returns the reply, or nothing if the
    // robot said nothing.
    std::optional<oi::SensorSnapshot> tryQuery(std::vector<int> ids)
    {
        std::vector<std::uint8_t> asBytes(ids.begin(), ids.end());
        if (!parser.expectReply(asBytes))
            return std::nullopt;
        const std::size_t before = replies.size();
        send(encoder.queryList(ids));
        if (replies.size() == before) {
            parser.cancelReplies();
            parser.reset();
            return std::nullopt;
        }
        return replies.back();
    }
    // The reply to Query List for `ids`; a robot that says nothing fails the test.
    oi::SensorSnapshot query(std::vector<int> ids)
    {
        if (const auto s = tryQuery(ids))
            return *s;
        QTest::qFail("the robot did not reply", __FILE__, __LINE__);
        return oi::SensorSnapshot(robot.robotProfile());
    }
    int value(int id) { return query({id}).raw(id); }

    void startSafe() { send(concat({must(encoder.start()), must(encoder.safe())})); }
    void startFull() { send(concat({must(encoder.start()), must(encoder.full())})); }

    sim::VirtualRobot robot;
    oi::CommandEncoder encoder;
    oi::StreamParser parser;
    std::vector<oi::SensorSnapshot> frames, replies;
    std::function<void(const oi::SensorSnapshot &)> onFrame;
    oi::Bytes raw;
};

// A Sensors question for a group, and what came back (raw bytes): the SCI's
// replies, which the stream parser does not read.
inline oi::Bytes askSci(Bench &b, int group)
{
    b.raw.clear();
    b.send(oi::Bytes{142, std::uint8_t(group)});
    return b.raw;
}
