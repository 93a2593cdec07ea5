// SPDX-License-Identifier: GPL-3.0-or-later
#include "profile_probe.h"

#include "transport.h"

#include "command_encoder.h"
#include "stream_parser.h"

namespace oilink {

namespace {
constexpr int kAttempts = 2;
constexpr std::uint8_t kModeMax = 3;
constexpr std::uint8_t kBumpBitsUnused = 0xE0;
constexpr qsizetype kChargingStateAt = 16; // packet 21 in group 0
constexpr std::uint8_t kChargingStateMax = 5;
} // namespace

QByteArray ProfileProbe::handshakeBytes(const std::vector<oi::OiCommand> &commands)
{
    const oi::EncodeResult encoded =
        oi::encodeCommands(oi::CommandEncoder(oi::profile(oi::ProfileId::Create2)), commands);
    Q_ASSERT(encoded.ok());
    return encoded ? QByteArray(reinterpret_cast<const char *>(encoded->data()), qsizetype(encoded->size()))
                   : QByteArray();
}

std::vector<oi::OiCommand> ProfileProbe::finishingStarts()
{
    // The opcode has come already: at most the rest of the longest command is owed.
    return std::vector<oi::OiCommand>(oi::kLongestCommandBytes - 1, oi::OiCommand{oi::Command::Start, {}, {}});
}

std::vector<oi::OiCommand> ProfileProbe::pauseCommands(bool withStart)
{
    std::vector<oi::OiCommand> out;
    if (withStart)
        out.push_back({oi::Command::Start, {}, {}});
    out.push_back({oi::Command::PauseResumeStream, {0}, {}});
    return out;
}

bool ProfileProbe::isFirstAnswer(const QByteArray &answer)
{
    if (answer.size() != kFirstAnswerBytes)
        return false;
    const auto at = [&](qsizetype i) { return static_cast<std::uint8_t>(answer.at(i)); };
    constexpr qsizetype kWall = 1, kVirtualWall = 6; // packets 8..13: one bit each
    for (qsizetype i = kWall; i <= kVirtualWall; ++i)
        if (at(i) > 1)
            return false;
    return (at(0) & kBumpBitsUnused) == 0 && at(kChargingStateAt) <= kChargingStateMax;
}

bool ProfileProbe::isModeAnswer(const QByteArray &answer)
{
    return answer.size() == 1 && std::uint8_t(answer.at(0)) >= 1 && std::uint8_t(answer.at(0)) <= kModeMax;
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
    : QObject(parent), m_transport(transport), m_bauds(std::move(bauds)),
      m_exchange(clock, [this](const std::vector<oi::OiCommand> &commands) { return send(commands); }, this)
{
}

void ProfileProbe::start()
{
    m_baudIndex = 0;
    tryBaud();
}

void ProfileProbe::cancel()
{
    m_exchange.cancel();
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
    m_attempts = 0;
    m_step = Step::Draining;
    m_startSent = m_startPolicy == StartPolicy::Always;
    // What a stream left running sends meanwhile is let drain, and forgotten.
    m_exchange.ask(pauseCommands(m_startSent), Exchange::Expect::nothing(), kDrainMs,
                   [this](Exchange::Outcome, const QByteArray &received) { onAnswer(received); });
    if (m_startSent)
        emit startSent();
}

void ProfileProbe::nextBaud()
{
    ++m_baudIndex;
    tryBaud();
}

bool ProfileProbe::send(const std::vector<oi::OiCommand> &commands)
{
    const QByteArray data = handshakeBytes(commands);
    if (!m_transport.write(data))
        return false;
    emit sent(data, commands);
    return true;
}

void ProfileProbe::ask(const oi::OiCommand &question, qsizetype expected, Step step)
{
    m_expected = expected;
    m_step = step;
    m_exchange.ask({question}, Exchange::Expect::bytes(expected, kQuietMs), kReplyTimeoutMs,
                   [this](Exchange::Outcome, const QByteArray &received) { onAnswer(received); });
}

void ProfileProbe::feed(const QByteArray &data)
{
    if (m_step != Step::Idle)
        m_exchange.feed(data);
}

// Whatever the outcome: the answer is judged by what came.
void ProfileProbe::onAnswer(const QByteArray &received)
{
    switch (m_step) {
    case Step::Idle:
        return;
    case Step::Draining:
        ask(firstQuestionCommand(), kFirstAnswerBytes, Step::AskFirst);
        return;
    case Step::AskFirst:
        if (isFirstAnswer(answerOf(received, kFirstAnswerBytes))) {
            m_attempts = 0;
            ask(modeQuestionCommand(), 1, Step::AskMode);
        } else if (!m_startSent && m_startPolicy == StartPolicy::IfSilent) {
            // Silent: Off mode, or the wrong baud. Start opens the interface.
            m_startSent = true;
            send({{oi::Command::Start, {}, {}}});
            emit startSent();
            ask(firstQuestionCommand(), kFirstAnswerBytes, Step::AskFirst);
        } else if (++m_attempts < kAttempts) {
            ask(firstQuestionCommand(), kFirstAnswerBytes, Step::AskFirst);
        } else {
            nextBaud();
        }
        return;
    case Step::AskMode: {
        if (const QByteArray answer = answerOf(received, 1); isModeAnswer(answer)) {
            m_mode = static_cast<oi::OiMode>(answer.at(0));
            const oi::PacketGroup *group = oi::profile(oi::ProfileId::Create2).group(101);
            ask({oi::Command::Sensors, {101}, {}}, group->bytes, Step::AskRoombaGroup);
        } else if (++m_attempts < kAttempts) {
            ask(modeQuestionCommand(), 1, Step::AskMode);
        } else {
            // It answers Sensors 0 but knows no packet 35: the 2005 SCI.
            // Its mode is not reported; Start has made it Passive.
            m_mode = m_startSent ? oi::OiMode::Passive : oi::OiMode::Off;
            finish(oi::ProfileId::Roomba400);
        }
        return;
    }
    case Step::AskRoombaGroup:
        finish(answerOf(received, m_expected).size() == m_expected ? oi::ProfileId::Create2 : oi::ProfileId::Create1);
        return;
    }
}

void ProfileProbe::finish(oi::ProfileId profile)
{
    m_step = Step::Idle;
    m_exchange.cancel();
    emit detected(profile, m_baud);
}

} // namespace oilink

#include "moc_profile_probe.cpp"
