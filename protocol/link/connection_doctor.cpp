// SPDX-License-Identifier: GPL-3.0-or-later
#include "connection_doctor.h"

#include "brc_pulser.h"
#include "profile_probe.h"
#include "transport.h"

#include <algorithm>

namespace oilink {

namespace {
constexpr int kDrainMs = ProfileProbe::kDrainMs;
constexpr int kReplyTimeoutMs = ProfileProbe::kReplyTimeoutMs;
constexpr int kQuietMs = ProfileProbe::kQuietMs;
constexpr int kAfterBaudPulsesMs = 200;
// The documents: the three baud pulses come 2 s after the robot woke, which
// it did as the wake pulse ended, BrcPulser::kWakeMs before awake().
constexpr int kBaudPulsesAfterAwakeMs = oi::RobotProfile::kBaudPulsesAfterWakeMs - BrcPulser::kWakeMs;
constexpr int kRoombaGroup = 101;
// From awake() until even a slow robot listens.
constexpr int kSlowWakeAfterAwakeMs = BrcPulser::kSlowWakeMs - BrcPulser::kWakeMs;

QString lineWords(BrcLine line)
{
    const std::string_view words = oi::brcLineWords(line);
    return QString::fromUtf8(words.data(), qsizetype(words.size()));
}

QString profileName(oi::ProfileId id)
{
    const std::string_view name = oi::profile(id).name;
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}
} // namespace

ConnectionDoctor::ConnectionDoctor(Transport &transport, std::optional<oi::ProfileId> profile, int baud,
                                   Clock &clock, QObject *parent)
    : QObject(parent), m_transport(transport), m_askedProfile(profile), m_askedBaud(baud),
      m_pulser(new BrcPulser(clock, this)), m_clock(clock),
      m_exchange(clock, [this](const std::vector<oi::OiCommand> &commands) { return write(commands); }, this),
      m_timer(clock, this)
{
    qRegisterMetaType<oilink::ConnectionDoctor::Report>();
    connect(m_pulser, &BrcPulser::awake, this, [this] {
        m_awakeMs = m_clock.nowMs();
        if (!m_onOtherLine)
            m_wokeMs = m_awakeMs;
        afterWakePulse(0);
    });
    m_textReader.setTextHandler([this](std::string_view line) {
        m_textLine = QString::fromLatin1(line.data(), qsizetype(line.size())).simplified();
        if (!m_textBaud)
            step(tr("At %1 the robot prints text: \"%2\".").arg(baudName(m_listeningBaud), m_textLine));
        m_textBaud = m_listeningBaud;
    });
    m_timer.setSingleShot(true);
    connect(&m_timer, &ClockTimer::timeout, this, [this] {
        if (auto then = std::exchange(m_onTimer, nullptr))
            then();
    });
}

ConnectionDoctor::~ConnectionDoctor() = default;

QList<int> ConnectionDoctor::candidateBauds(int asked)
{
    QList<int> bauds;
    if (asked > 0)
        bauds.append(asked);
    for (int b : ProfileProbe::defaultBauds())
        if (!bauds.contains(b))
            bauds.append(b);
    return bauds;
}

void ConnectionDoctor::start()
{
    m_running = true;
    m_report = {};
    m_garbledAt.clear();
    m_wakeLine = m_transport.brcLine();
    m_onOtherLine = false;
    m_textBaud.reset();
    m_textLine.clear();
    m_foundSci = false;
    const int asked = m_askedBaud > 0 ? m_askedBaud : m_askedProfile ? oi::profile(*m_askedProfile).defaultBaud : 0;
    m_bauds = candidateBauds(asked);
    m_hasBaud = m_transport.setBaud(m_bauds.front());
    if (!m_hasBaud)
        m_bauds = {0};
    m_pulser->setTransport(&m_transport);
    tryBaud(0);
}

void ConnectionDoctor::listenAt(int baud)
{
    if (baud > 0)
        m_transport.setBaud(baud);
    m_listeningBaud = baud;
    m_textReader.reset();
    m_heard = 0;
}

void ConnectionDoctor::feed(const QByteArray &data)
{
    // Heard only while a question (or the drain before it) waits.
    if (!m_exchange.isWaiting())
        return;
    m_heard += data.size();
    m_textReader.feed({reinterpret_cast<const std::uint8_t *>(data.constData()), std::size_t(data.size())});
    m_exchange.feed(data);
}

void ConnectionDoctor::after(int ms, std::function<void()> then)
{
    m_onTimer = std::move(then);
    m_timer.start(ms);
}

bool ConnectionDoctor::write(const std::vector<oi::OiCommand> &commands)
{
    const QByteArray data = ProfileProbe::handshakeBytes(commands);
    if (!m_transport.write(data))
        return false;
    emit sent(data, commands);
    return true;
}

// Extra bytes in the settle time mean garbage: the answer is judged by all that came.
void ConnectionDoctor::ask(const oi::OiCommand &question, qsizetype expected, Answer then)
{
    m_exchange.ask({question}, Exchange::Expect::bytes(expected, kQuietMs), kReplyTimeoutMs,
                   [then = std::move(then)](Exchange::Outcome, const QByteArray &received) { then(received); });
}

QString ConnectionDoctor::baudName(int baud) const
{
    return baud > 0 ? tr("%1 baud").arg(baud) : m_transport.describe();
}

// Pause any stream, let it drain, and ask for the mode; with Start first
// when asked to.
void ConnectionDoctor::askMode(bool withStart, std::function<void(bool)> then)
{
    const auto drained = [this, then = std::move(then)](Exchange::Outcome, const QByteArray &) {
        constexpr qsizetype kBytes = ProfileProbe::kFirstAnswerBytes;
        ask(ProfileProbe::firstQuestionCommand(), kBytes, [then](const QByteArray &answer) {
            then(ProfileProbe::isFirstAnswer(ProfileProbe::answerOf(answer, kBytes)));
        });
    };
    // What comes meanwhile is heard (the robot's text), then let go.
    m_exchange.ask(ProfileProbe::pauseCommands(withStart), Exchange::Expect::nothing(), kDrainMs, drained);
    if (withStart)
        emit startSent();
}

void ConnectionDoctor::tryBaud(qsizetype index)
{
    if (index >= m_bauds.size()) {
        afterSilence();
        return;
    }
    const int baud = m_bauds[index];
    listenAt(baud);
    askMode(false, [this, index, baud](bool answeredPlain) {
        if (answeredPlain) {
            step(tr("At %1 it answers.").arg(baudName(baud)));
            answered(baud, Finding::Healthy);
            return;
        }
        askMode(true, [this, index, baud](bool answeredAfterStart) {
            if (answeredAfterStart) {
                step(tr("At %1 it answers after Start (it was in Off mode).").arg(baudName(baud)));
                answered(baud, Finding::Healthy);
                return;
            }
            // Text is the robot's own words, not bytes that make no sense.
            const qsizetype got = m_heard - qsizetype(m_textReader.counters().textBytes);
            if (m_textBaud == baud && m_textReader.counters().textLines > 0) {
                // Readable text: this is the robot's baud; only a wake is left to try, here.
                step(tr("At %1 it prints text but does not answer.").arg(baudName(baud)));
                m_bauds = {baud};
                afterSilence();
                return;
            }
            if (got > 0) {
                m_garbledAt.append(baud);
                step(tr("At %1: %n byte(s) that make no sense.", nullptr, int(got)).arg(baudName(baud)));
            } else {
                step(tr("At %1: nothing comes back, with or without Start.").arg(baudName(baud)));
            }
            tryBaud(index + 1);
        });
    });
}

void ConnectionDoctor::afterSilence()
{
    if (!m_pulser->wake()) {
        step(m_transport.brcUnavailable() + QLatin1Char('.'));
        if (concludeFromText())
            return;
        if (!m_garbledAt.isEmpty())
            concludeGarbled();
        else
            conclude(Finding::NothingComesBack,
                     tr("Nothing comes back: is the robot on and the cable plugged in? (A sleeping robot "
                        "cannot be woken over this connection.)"));
        return;
    }
    step(tr("Pulsed the BRC pin on the wake line (%1) to wake the robot.").arg(lineWords(m_wakeLine)));
    // afterWakePulse() follows BrcPulser::awake().
}

void ConnectionDoctor::afterWakePulse(qsizetype index)
{
    const qint64 sinceAwake = m_clock.nowMs() - m_awakeMs;
    if (index == 0)
        m_roundAfterWakeTime = sinceAwake >= kSlowWakeAfterAwakeMs;
    if (index < m_bauds.size()) {
        const int baud = m_bauds[index];
        listenAt(baud);
        askMode(true, [this, index, baud](bool ok) {
            if (ok) {
                step(tr("At %1 it answers after the pulse.").arg(baudName(baud)));
                answered(baud, m_onOtherLine ? Finding::WokeOnOtherLine : Finding::WokeAfterPulse);
            } else {
                afterWakePulse(index + 1);
            }
        });
        return;
    }
    if (!m_roundAfterWakeTime) {
        // Some robots listen only up to 2 s after the pulse: each baud once
        // more before anything is concluded or the baud is touched.
        step(tr("Silent so far; a slow robot takes up to 2 s to wake: asking again once it has had that time."));
        after(int(std::max<qint64>(0, kSlowWakeAfterAwakeMs - sinceAwake)), [this] { afterWakePulse(0); });
        return;
    }
    if (wakeOnOtherLine())
        return;
    // The three baud pulses go where the link pulses.
    m_transport.setBrcLine(m_wakeLine, m_transport.brcAssertedIsLow());
    // Readable text proves the baud: no pulses to change it.
    if (!m_hasBaud || m_textBaud) {
        concludeSilent();
        return;
    }
    const qint64 untilBaudPulses = std::max<qint64>(0, kBaudPulsesAfterAwakeMs - (m_clock.nowMs() - m_wokeMs));
    after(int(untilBaudPulses), [this] { pulseForBaud19200(); });
}

// Silent after a pulse on the wake line: many cables carry the BRC pin on
// the other one.
bool ConnectionDoctor::wakeOnOtherLine()
{
    const BrcLine other = m_wakeLine == BrcLine::Rts ? BrcLine::Dtr
                          : m_wakeLine == BrcLine::Dtr ? BrcLine::Rts
                                                       : BrcLine::None;
    if (m_onOtherLine || other == BrcLine::None)
        return false;
    m_onOtherLine = true;
    m_transport.setBrcLine(other, m_transport.brcAssertedIsLow());
    if (!m_pulser->wake())
        return false;
    step(tr("Still silent: pulsed the other line (%1) instead.").arg(lineWords(other)));
    return true; // afterWakePulse() follows BrcPulser::awake()
}

void ConnectionDoctor::pulseForBaud19200()
{
    m_pulser->pulseForBaud19200();
    step(tr("2 s after the wake pulse, pulsed the BRC pin three times for 19200 baud."));
    const int wait = 3 * (BrcPulser::kBaudPulseMs + BrcPulser::kBaudGapMs) + kAfterBaudPulsesMs;
    after(wait, [this] {
        listenAt(19200);
        askMode(true, [this](bool ok) {
            if (ok) {
                step(tr("At 19200 baud it answers after the three pulses."));
                answered(19200, Finding::Baud19200AfterPulses);
                return;
            }
            concludeSilent();
        });
    });
}

bool ConnectionDoctor::concludeFromText()
{
    if (!m_textBaud)
        return false;
    m_report.baud = *m_textBaud;
    conclude(Finding::TextOnDock,
             tr("At %1 the robot prints its charging status (\"%2\"): the baud and the cable are right, and it "
                "is a Roomba on its dock. It does not answer there: asleep on its dock (firmware before "
                "release-3.8.2 / release-stm32-3.7.7 does not wake by BRC there). Press Clean, or lift it off "
                "the dock.")
                 .arg(baudName(*m_textBaud), m_textLine));
    return true;
}

void ConnectionDoctor::concludeGarbled()
{
    if (concludeFromText())
        return;
    if (m_hasBaud)
        conclude(Finding::GarbledAtEveryBaud,
                 tr("Bytes come back, but at no baud do they make sense: a noisy cable, or a device "
                    "that is not an Open Interface robot."));
    else
        conclude(Finding::GarbledAtEveryBaud,
                 tr("Bytes come back, but they make no sense. This connection cannot change the "
                    "bridge's rate: the robot may talk at another baud than the bridge's serial port "
                    "(set the bridge to the robot's rate, or use its RFC 2217 telnet mode so that "
                    "each rate can be tried), or the device is not an Open Interface robot."));
}

void ConnectionDoctor::concludeSilent()
{
    if (concludeFromText())
        return;
    if (!m_garbledAt.isEmpty()) {
        concludeGarbled(); // it was never silent, only not making sense
        return;
    }
    conclude(Finding::AsleepDidNotWake,
             tr("No line wakes it: still silent after BRC pulses on RTS and on DTR. The cable may not carry "
                "the BRC pin (press Clean to wake the robot), or the robot is off or unplugged, or asleep on "
                "its dock with firmware before release-3.8.2 / release-stm32-3.7.7, which does not wake by "
                "BRC there (lift it off the dock, or press Clean)."));
}

// It answers Sensors 0, which the Open Interface and the older SCI share:
// packet 35 tells them apart, then group 101 the Create from the others.
void ConnectionDoctor::answered(int baud, Finding cause)
{
    m_report.baud = baud;
    ask(ProfileProbe::modeQuestionCommand(), 1, [this, baud, cause](const QByteArray &mode) {
        if (!ProfileProbe::isModeAnswer(ProfileProbe::answerOf(mode, 1))) {
            step(tr("It answers Sensors 0 but has no packet 35 (OI mode): a Roomba 400 series, which speaks the "
                    "older SCI (2005)."));
            identified(baud, cause, oi::ProfileId::Roomba400);
            return;
        }
        const oi::PacketGroup *group = oi::profile(oi::ProfileId::Create2).group(kRoombaGroup);
        ask({oi::Command::Sensors, {kRoombaGroup}, {}}, group->bytes, [this, baud, cause, group](const QByteArray &answer) {
            const bool roomba = ProfileProbe::answerOf(answer, group->bytes).size() == group->bytes;
            step(roomba ? tr("It answers Sensors 101: a Roomba 500 or a Create 2 (they answer alike).")
                        : tr("It has no packet group 101: a Create."));
            identified(baud, cause, roomba ? oi::ProfileId::Create2 : oi::ProfileId::Create1);
        });
    });
}

void ConnectionDoctor::identified(int baud, Finding cause, oi::ProfileId found)
{
    m_report.profile = found;
    m_foundSci = oi::profile(found).polled();
    const bool roomba = ProfileProbe::isAmbiguous(found);
    // The Roomba 500 and the Create 2 answer alike: either name fits such an answer.
    const bool asNamed = m_askedProfile && oi::profile(*m_askedProfile).answersAlike(oi::profile(found));
    const int askedBaud = m_askedBaud > 0 ? m_askedBaud : m_askedProfile ? oi::profile(*m_askedProfile).defaultBaud : 0;
    if (cause == Finding::WokeOnOtherLine) {
        const BrcLine line = m_transport.brcLine();
        m_report.wakeLine = line;
        const std::string_view name = oi::brcLineName(line);
        conclude(cause, tr("The wake pulse works on %1, not %2: the cable carries the robot's BRC pin on %1. "
                           "Set the wake line to %1 (--brc-line %3).")
                            .arg(lineWords(line), lineWords(m_wakeLine),
                                 QString::fromUtf8(name.data(), qsizetype(name.size()))));
    } else if (cause == Finding::WokeAfterPulse) {
        conclude(cause, baud > 0 ? tr("The robot was asleep; a BRC pulse woke it, and it talks at %1 baud.").arg(baud)
                                 : tr("The robot was asleep; a BRC pulse woke it."));
    } else if (cause == Finding::Baud19200AfterPulses) {
        conclude(cause, tr("After three BRC pulses the robot now talks at 19200 baud: set the baud to 19200."));
    } else if (m_hasBaud && askedBaud > 0 && baud != askedBaud) {
        conclude(Finding::WrongBaud, tr("Wrong baud: the robot answers at %1 baud, not %2.").arg(baud).arg(askedBaud));
    } else if (m_askedProfile && !asNamed) {
        conclude(Finding::OtherProfile, tr("The robot answers as a %1, not as the %2 the connection names.")
                                            .arg(roomba ? tr("Roomba 500 or Create 2") : profileName(found),
                                                 profileName(*m_askedProfile)));
    } else if (!m_askedProfile && roomba) {
        conclude(Finding::RoombaOrCreate2, tr("The robot answers at %1 as a Roomba 500 or a Create 2. The "
                                              "two answer alike but read their wheel encoders the other way "
                                              "round: name which it is.")
                                               .arg(baudName(baud)));
    } else {
        conclude(Finding::Healthy, tr("The robot answers at %1 as a %2.")
                                       .arg(baudName(baud), profileName(m_askedProfile.value_or(found))));
    }
}

void ConnectionDoctor::conclude(Finding finding, const QString &summary)
{
    m_running = false;
    m_timer.stop();
    m_onTimer = nullptr;
    m_exchange.cancel();
    m_pulser->setTransport(nullptr);
    // The link pulses on from here: on the line found to work, else on its own.
    if (finding != Finding::WokeOnOtherLine)
        m_transport.setBrcLine(m_wakeLine, m_transport.brcAssertedIsLow());
    m_report.finding = finding;
    m_report.summary = summary;
    if (m_textBaud && finding != Finding::TextOnDock && m_foundSci)
        m_report.summary += QLatin1Char(' ')
                            + tr("It printed \"%1\": the text a Roomba 400 prints as it starts up, not a charging "
                                 "status.")
                                  .arg(m_textLine);
    else if (m_textBaud && finding != Finding::TextOnDock)
        m_report.summary += QLatin1Char(' ')
                            + tr("It prints its charging status (\"%1\"): it is on its dock.").arg(m_textLine);
    emit finished(m_report);
}

void ConnectionDoctor::step(const QString &text)
{
    m_report.steps.append(text);
    emit stepDone(text);
}

} // namespace oilink

#include "moc_connection_doctor.cpp"
#include "moc_connection_report.cpp"
