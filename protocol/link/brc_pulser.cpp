// SPDX-License-Identifier: GPL-3.0-or-later
#include "brc_pulser.h"

#include "transport.h"

#include <algorithm>

namespace oilink {

namespace {
// The Create 2 document's example: low for one second, every minute. A
// second is also too long to be read as one of the three baud pulses.
constexpr int kKeepAwakePulseMs = 1000;
} // namespace

BrcPulser::BrcPulser(QObject *parent) : BrcPulser(Clock::steady(), parent) {}

BrcPulser::BrcPulser(Clock &clock, QObject *parent) : QObject(parent), m_step(clock, this), m_keepAwake(clock, this)
{
    m_step.setSingleShot(true);
    connect(&m_step, &ClockTimer::timeout, this, &BrcPulser::runNextStep);
    connect(&m_keepAwake, &ClockTimer::timeout, this, &BrcPulser::keepAwake);
}

void BrcPulser::setTransport(Transport *transport)
{
    if (m_transport && m_step.isActive())
        m_transport->setBrcLow(false); // never leave the pin held low
    m_transport = transport;
    m_steps.clear();
    m_step.stop();
    m_keepAwake.stop();
    m_waking = false;
    m_probed = false;
    m_mode = oi::OiMode::Passive;
}

bool BrcPulser::canPulse() const
{
    return m_transport && (m_probed ? m_canPulse : m_transport->setBrcLow(false));
}

bool BrcPulser::wake()
{
    if (!queuePulses(1, kWakePulseMs, 0, kWakeMs))
        return false;
    m_steps.push_back({Step::Awake, kSlowWakeMs - kWakeMs});
    m_steps.push_back({Step::WakeTimeOver, 0});
    m_waking = true;
    return true;
}

bool BrcPulser::pulseForBaud19200() { return queuePulses(3, kBaudPulseMs, kBaudGapMs); }

void BrcPulser::setKeepAwake(int periodMs)
{
    m_keepAwake.stop();
    if (periodMs > 0)
        m_keepAwake.start(periodMs);
}

void BrcPulser::keepAwake()
{
    if (m_mode == oi::OiMode::Safe || m_mode == oi::OiMode::Full || !m_steps.empty())
        return;
    // Short enough to let go well before the next one, and never as long as
    // a baud pulse (50 to 500 ms).
    const int widthMs = std::min(kKeepAwakePulseMs, m_keepAwake.interval() / 4);
    queuePulses(1, widthMs > 500 ? widthMs : kWakePulseMs, 0);
}

bool BrcPulser::queuePulses(int count, int widthMs, int gapMs, int holdAfterMs)
{
    if (!m_transport)
        return false;
    if (!m_probed) {
        // Letting the pin go is harmless and tells whether it can be reached.
        m_canPulse = m_transport->setBrcLow(false);
        m_probed = true;
    }
    if (!m_canPulse)
        return false;
    for (int i = 0; i < count; ++i) {
        m_steps.push_back({Step::Low, widthMs});
        m_steps.push_back({Step::High, i + 1 < count ? gapMs : holdAfterMs});
    }
    if (!m_step.isActive())
        runNextStep();
    return true;
}

void BrcPulser::runNextStep()
{
    while (!m_steps.empty() && m_transport) {
        const Step step = m_steps.front();
        m_steps.pop_front();
        if (step.kind == Step::Awake) {
            emit awake();
        } else if (step.kind == Step::WakeTimeOver) {
            m_waking = std::any_of(m_steps.begin(), m_steps.end(),
                                   [](const Step &s) { return s.kind == Step::WakeTimeOver; });
            emit wakeTimeOver();
        } else {
            m_transport->setBrcLow(step.kind == Step::Low);
            if (step.kind == Step::High)
                emit pulsed();
        }
        if (step.holdMs > 0) {
            m_step.start(step.holdMs);
            return;
        }
    }
}

} // namespace oilink

#include "moc_brc_pulser.cpp"
