// SPDX-License-Identifier: GPL-3.0-or-later
#include "profile_probe.h"

#include "transport.h"

#include "command_encoder.h"
#include "stream_parser.h"

namespace oilink {

namespace {
constexpr int kModeAttempts = 2;
constexpr std::uint8_t kModeMax = 3;
constexpr std::uint8_t kBumpBitsUnused = 0xE0;
} // namespace

QByteArray ProfileProbe::handshakeBytes(const std::vector<oi::OiCommand> &commands)
{
    const oi::EncodeResult encoded =
        oi::encodeCommands(oi::CommandEncoder(oi::profile(oi::ProfileId::Create2)), commands);
    Q_ASSERT(encoded.ok());
    return encoded ? QByteArray(reinterpret_cast<const char *>(encoded->data()), qsizetype(encoded->size()))
                   : QByteArray();
}

std::vector<oi::OiCommand> ProfileProbe::pauseCommands(bool withStart)
{
    std::vector<oi::OiCommand> out;
    if (withStart)
        out.push_back({oi::Command::Start, {}, {}});
    out.push_back({oi::Command::PauseResumeStream, {0}, {}});
    return out;
}

bool ProfileProbe::isModeAnswer(const QByteArray &answer)
{
    const auto at = [&](qsizetype i) { return static_cast<std::uint8_t>(answer.at(i)); };
    return answer.size() == 2 && at(0) >= 1 && at(0) <= kModeMax && (at(1) & kBumpBitsUnused) == 0;
}

QByteArray ProfileProbe::answerOf(const QByteArray &received, qsizetype size)
{
    if (received.size() == size)
        return received;
    const std::vector<std::uint8_t> rest = oi::withoutTextLines(
        {reinterpret_cast<const std::uint8_t *>(received.constData()), std::size_t(received.size())});
    return QByteArray(reinterpret_cast<const char *>(rest.data()), qsizetype(rest.size()));
}

bool ProfileProbe::dependsOnRoombaOrCreate2(int id)
{
    constexpr int kRightOrLeftEncoder = 43, kLeftOrRightEncoder = 44; // ERRATA 4
    if (id == kRightOrLeftEncoder || id == kLeftOrRightEncoder)
        return true;
    const oi::PacketGroup *group = oi::profile(oi::ProfileId::Create2).group(id);
    return group && group->first <= kLeftOrRightEncoder && group->last >= kRightOrLeftEncoder;
}

ProfileProbe::ProfileProbe(Transport &transport, QList<int> bauds, Clock &clock, QObject *parent)
    : QObject(parent), m_transport(transport), m_bauds(std::move(bauds)), m_timer(clock, this)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &ClockTimer::timeout, this, &ProfileProbe::onTimeout);
}

void ProfileProbe::start()
{
    m_baudIndex = 0;
    tryBaud();
}

void ProfileProbe::cancel()
{
    m_timer.stop();
    m_step = Step::Idle;
}

void ProfileProbe::tryBaud()
{
    if (m_baudIndex >= m_bauds.size()) {
        m_step = Step::Idle;
        emit failed();
        return;
    }
    m_baud = m_bauds[m_baudIndex];
    if (!m_transport.setBaud(m_baud)) {
        m_baud = 0;
        m_baudIndex = m_bauds.size(); // one pass only: nothing to change
    }
    m_modeAttempts = 0;
    m_received.clear();
    m_step = Step::Draining;
    m_startSent = m_startPolicy == StartPolicy::Always;
    send(pauseCommands(m_startSent));
    if (m_startSent)
        emit startSent();
    m_timer.start(kDrainMs);
}

void ProfileProbe::nextBaud()
{
    ++m_baudIndex;
    tryBaud();
}

void ProfileProbe::send(const std::vector<oi::OiCommand> &commands)
{
    const QByteArray data = handshakeBytes(commands);
    if (m_transport.write(data))
        emit sent(data, commands);
}

void ProfileProbe::ask(const oi::OiCommand &question, qsizetype expected, Step step)
{
    m_received.clear();
    m_expected = expected;
    m_settling = false;
    m_step = step;
    send({question});
    m_timer.start(kReplyTimeoutMs);
}

void ProfileProbe::feed(const QByteArray &data)
{
    if (m_step == Step::Idle)
        return;
    m_received += data;
    if (m_step != Step::Draining && !m_settling && m_received.size() >= m_expected) {
        m_settling = true;
        m_timer.start(kQuietMs);
    }
}

void ProfileProbe::onTimeout()
{
    switch (m_step) {
    case Step::Idle:
        return;
    case Step::Draining:
        ask(modeQuestionCommand(), 2, Step::AskMode);
        return;
    case Step::AskMode: {
        if (const QByteArray answer = answerOf(m_received, 2); isModeAnswer(answer)) {
            m_mode = static_cast<oi::OiMode>(answer.at(0));
            const oi::PacketGroup *group = oi::profile(oi::ProfileId::Create2).group(101);
            ask({oi::Command::Sensors, {101}, {}}, group->bytes, Step::AskRoombaGroup);
        } else if (!m_startSent && m_startPolicy == StartPolicy::IfSilent) {
            // Silent: Off mode, or the wrong baud. Start opens the interface.
            m_startSent = true;
            send({{oi::Command::Start, {}, {}}});
            emit startSent();
            ask(modeQuestionCommand(), 2, Step::AskMode);
        } else if (++m_modeAttempts < kModeAttempts) {
            ask(modeQuestionCommand(), 2, Step::AskMode);
        } else {
            nextBaud();
        }
        return;
    }
    case Step::AskRoombaGroup:
        finish(answerOf(m_received, m_expected).size() == m_expected ? oi::ProfileId::Create2 : oi::ProfileId::Create1);
        return;
    }
}

void ProfileProbe::finish(oi::ProfileId profile)
{
    m_step = Step::Idle;
    m_timer.stop();
    emit detected(profile, m_baud);
}

} // namespace oilink

#include "moc_profile_probe.cpp"
