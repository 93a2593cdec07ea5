// SPDX-License-Identifier: GPL-3.0-or-later
#include "frame_arrivals.h"

#include <algorithm>

namespace oilink {

void FrameArrivals::frameAt(qint64 ms)
{
    ++m_frames;
    if (m_lastFrameMs < 0 || ms - m_lastFrameMs > kSameArrivalMs) {
        if (m_lastFrameMs >= 0)
            arrivalEnded();
        m_previousStartMs = m_arrivalStartMs;
        m_arrivalStartMs = ms;
        m_arrivalFrames = 0;
    }
    ++m_arrivalFrames;
    m_lastFrameMs = ms;
}

// An arrival is a bunch when the gap before it was long and it carried at
// least half the frames due in that gap: they were sent on time and held.
void FrameArrivals::arrivalEnded()
{
    if (m_previousStartMs < 0)
        return; // the stream's first arrival: nothing to measure it by
    const int gapMs = int(std::min<qint64>(m_arrivalStartMs - m_previousStartMs, 60'000));
    if (gapMs < kBunchGapMs) {
        m_bunchedInARow = 0;
        if (++m_plainInARow >= kPlainToForget)
            m_bunchedEveryMs = 0;
        return;
    }
    m_plainInARow = 0;
    if (m_arrivalFrames * kFramePeriodMs * 2 < gapMs) {
        m_bunchedInARow = 0; // a stall: the robot was silent, not held
        return;
    }
    std::rotate(m_recentGapsMs.rbegin(), m_recentGapsMs.rbegin() + 1, m_recentGapsMs.rend());
    m_recentGapsMs.front() = gapMs;
    if (++m_bunchedInARow >= kBunchesToLearn)
        m_bunchedEveryMs = *std::max_element(m_recentGapsMs.begin(), m_recentGapsMs.end());
}

} // namespace oilink
