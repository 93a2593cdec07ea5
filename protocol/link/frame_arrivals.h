// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QtGlobal>

#include <array>

namespace oilink {

// How stream frames reach this computer. A Bluetooth serial adapter or a
// Wi-Fi bridge hands them over on time but in bunches 0.25-0.3 s apart:
// each bunch carries the frames of the gap before it. A stall carries none.
// Told apart by what each arrival brings, never by the silence at one
// instant, so a late bunch is not taken for a stopped stream.
class FrameArrivals {
public:
    // Frames come every 15 ms; a gap shorter than this is no bunch (an FTDI
    // adapter's 16 ms latency timer is fine).
    static constexpr int kFramePeriodMs = 15;
    static constexpr int kBunchGapMs = 50;

    // A good stream frame was read at `ms` (the link's clock).
    void frameAt(qint64 ms);
    // The time between bunches, once two in a row came on time; 0 while the
    // frames come one by one (or once twenty arrivals in a row did).
    int bunchedEveryMs() const { return m_bunchedEveryMs; }
    // Frames counted since the stream started (or reset()).
    quint64 frames() const { return m_frames; }
    void reset() { *this = FrameArrivals{}; }

private:
    void arrivalEnded();

    static constexpr int kSameArrivalMs = 5; // frames read this close together came in one bunch
    static constexpr int kBunchesToLearn = 2;
    static constexpr int kPlainToForget = 20;

    quint64 m_frames = 0;
    qint64 m_arrivalStartMs = -1, m_lastFrameMs = -1, m_previousStartMs = -1;
    int m_arrivalFrames = 0;
    int m_bunchedInARow = 0, m_plainInARow = 0;
    std::array<int, 4> m_recentGapsMs{};
    int m_bunchedEveryMs = 0;
};

} // namespace oilink
