// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_snapshot.h"

#include <QDateTime>
#include <QMetaType>
#include <QString>

#include <cstdint>

namespace oilink {

enum class LinkState : std::uint8_t {
    Closed,       // not asked to connect, or closed
    Connecting,   // opening the port, probing the robot, or waiting for the first frame
    Streaming,    // frames are arriving
    Stale,        // the port is open but no good frame came for 100 ms
    Lost,         // the port went away; reconnecting follows at once
    Reconnecting, // trying the same port again, with backoff
};

QString linkStateName(LinkState state); // "streaming", for logs and JSON

// How the line is doing. Totals run from open() to close(), across reconnects.
struct LinkStats {
    double framesPerSecond = 0;      // over the last second or so
    quint64 frames = 0;              // good stream frames
    quint64 replies = 0;             // good replies to sensor queries
    quint64 checksumFailures = 0;
    quint64 resyncs = 0;             // frames refused for a length mismatch
    quint64 bytesDiscarded = 0;      // bytes that belonged to no good frame, reply or line of text
    quint64 textLines = 0;           // lines of text the robot printed between frames (RobotLink::robotText)
    quint64 bytesReceived = 0;
    quint64 bytesSent = 0;
    quint32 reconnects = 0;          // times the port came back after it was lost
    int bunchedEveryMs = 0;          // frames come on time but in bunches this far apart (FrameArrivals); 0: one by one
    bool switchedOff = false;        // silent since its power button was held: Wake (RobotLink::wake) switches it on
    QDateTime lastFrameTime;         // invalid until the first good frame

    friend bool operator==(const LinkStats &, const LinkStats &) = default;
};

// "bunched link (frames every 0.3 s)" for a link whose frames come in
// bunches (LinkStats::bunchedEveryMs), else empty.
QString bunchedLinkText(const LinkStats &stats);

// A recording of the link's bytes (RobotLink::startRecording).
struct RecordingStatus {
    bool active = false;
    QString path;
    qint64 bytesWritten = 0;
    QString error; // why it stopped, when it stopped on its own
    double startedSeconds = 0; // when it began, on the clock snapshots are read on

    friend bool operator==(const RecordingStatus &, const RecordingStatus &) = default;
};

// Registers every value type that crosses the link's thread boundary:
// SensorSnapshot, ProfileId, LinkState, LinkStats, LinkSettings, and the
// recording and replay types. Safe to
// call often.
void registerLinkMetaTypes();

} // namespace oilink

Q_DECLARE_METATYPE(oi::SensorSnapshot)
Q_DECLARE_METATYPE(oi::ProfileId)
Q_DECLARE_METATYPE(oilink::LinkState)
Q_DECLARE_METATYPE(oilink::LinkStats)
Q_DECLARE_METATYPE(oilink::RecordingStatus)
