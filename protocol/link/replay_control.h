// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What a replay is asked and what it reports: the values the link's signals
// and slots carry, apart from the replay itself (replay_transport.h).

#include "recording_markers.h"

#include <QList>
#include <QMetaType>
#include <QString>

namespace oilink {

// What the user asks of a replay. Speed is 0.25 to 10.
struct ReplayCommand {
    enum class Kind : quint8 { Play, Pause, SetSpeed, Seek, Step };
    Kind kind = Kind::Play;
    double speed = 1.0; // SetSpeed
    qint64 timeUs = 0;  // Seek
    int frames = 1;     // Step: +1 next frame, -1 previous
    // Seek: to the first frame at or after timeUs rather than the state at
    // it (the last frame at or before), for a viewer whose timeline asks
    // for the next message from a time.
    bool atOrAfter = false;

    static ReplayCommand play() { return {Kind::Play}; }
    static ReplayCommand pause() { return {Kind::Pause}; }
    static ReplayCommand setSpeed(double speed) { return {Kind::SetSpeed, speed}; }
    static ReplayCommand seek(qint64 timeUs) { return {Kind::Seek, 1.0, timeUs}; }
    static ReplayCommand step(int frames) { return {Kind::Step, 1.0, 0, frames}; }
    static ReplayCommand seekAtOrAfter(qint64 timeUs) { return {Kind::Seek, 1.0, timeUs, 1, true}; }
};

// Where a replay is. Sent on every command and a few times a second while it
// plays, always before the bytes of the frames it counts.
struct ReplayStatus {
    QString path;
    qint64 positionUs = 0;
    qint64 durationUs = 0;
    int frame = -1; // the last frame delivered, -1 before the first
    int frameCount = 0;
    bool playing = false;
    bool finished = false; // played to the end (or to the damage)
    double speed = 1.0;
    QString damage; // empty for an intact recording
    QList<RecordingMarker> markers; // as the file held them when the replay opened it
    int markersLeftOut = 0;         // added in the file beyond kMaxMarkers, not read

    friend bool operator==(const ReplayStatus &, const ReplayStatus &) = default;
};

inline constexpr double kMinReplaySpeed = 0.25;
inline constexpr double kMaxReplaySpeed = 10.0;

} // namespace oilink

Q_DECLARE_METATYPE(oilink::ReplayCommand)
Q_DECLARE_METATYPE(oilink::ReplayStatus)
