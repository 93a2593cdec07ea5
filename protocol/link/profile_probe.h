// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "exchange.h"
#include "link_clock.h"
#include "link_status.h" // the metatype of oi::ProfileId, which a signal carries

#include "robot_profile.h"
#include "sensor_snapshot.h"
#include "typed_commands.h"

#include <QByteArray>
#include <QList>
#include <QObject>

#include <cstdint>
#include <vector>

namespace oilink {

class Transport;

// Finds which robot is on an open transport, and at which baud.
//
// At each baud (a serial port tries 115200, 57600 and 19200; TCP and the
// virtual robot have no baud of their own and get one pass):
//  1. Start (128) and Pause Stream (150 0), in case an earlier client left a
//     stream running; after 80 ms of letting it drain, forget what came.
//  2. Sensors 0 (packets 7..26): both protocols answer it, the Open
//     Interface and the Roomba 400's older SCI (2005), with the same 26
//     bytes: a bumps byte with bits 5..7 clear, a charging state of 0..5.
//     Anything else is the wrong baud or no robot; asked twice, so one
//     corrupted answer on a noisy line does not skip the right baud.
//  3. Sensors 35 (OI mode): an Open Interface robot answers one byte of 1..3
//     (Start has just made it Passive). The SCI has no packet 35 and says
//     nothing: asked twice, still silent, it is a Roomba 400.
//  4. Sensors 101 (43..58): the Roomba 500 and Create 2 send its 28 bytes;
//     the Create has no such group and sends nothing, or something that is
//     not 28 bytes. That is the Create.
// No question ends in a byte the SCI reads as a command (128 and above, or
// 7, which it takes as Reset): an older Roomba is asked, never restarted.
// The Roomba 500 and the Create 2 answer every question alike (the same
// commands, packet ids and sizes); they differ only in what packets 43/44
// mean (ERRATA 4) and in the range of 58, which no answer reveals. The probe
// says Create 2, the newer and commoner of the two, and isAmbiguous() of that
// answer is true: it stands for both, and whoever uses it must have the
// profile named (remembered, or asked) before trusting which encoder count
// is which.
class ProfileProbe : public QObject {
    Q_OBJECT
public:
    // `bauds` is tried in order on a transport with a baud of its own.
    ProfileProbe(Transport &transport, QList<int> bauds, Clock &clock = Clock::steady(), QObject *parent = nullptr);

    static QList<int> defaultBauds() { return {115200, 57600, 19200}; }

    // Shared with the connection doctor, which asks the same questions.
    static constexpr int kDrainMs = 80;
    // Generous: a robot answers within a frame time, but a busy machine
    // running the virtual robot in another process may not schedule it at once.
    static constexpr int kReplyTimeoutMs = 400;
    // After the expected bytes, wait this long for more: extra bytes mean
    // the answer was garbage.
    static constexpr int kQuietMs = 30;
    // The handshake's commands encode alike on every profile, so they are
    // written before the profile is known.
    static QByteArray handshakeBytes(const std::vector<oi::OiCommand> &commands);
    // Pause any stream, after Start when asked.
    static std::vector<oi::OiCommand> pauseCommands(bool withStart);
    // Enough Starts to finish the longest command a robot can be left
    // waiting inside (an earlier program that stopped halfway through a
    // Song leaves it taking the next bytes as notes): each one is data for
    // that command or, once it is done, a Start. As data, 128 is no baud
    // code, day or hour, so nothing else changes.
    static std::vector<oi::OiCommand> finishingStarts();
    // Sensors 0 (packets 7..26), which every robot answers alike.
    static oi::OiCommand firstQuestionCommand() { return {oi::Command::Sensors, {0}, {}}; }
    static constexpr qsizetype kFirstAnswerBytes = 26;
    // 26 bytes: a bumps byte with bits 5..7 clear, the one-bit sensors 0 or 1
    // and a charging state of 0..5.
    static bool isFirstAnswer(const QByteArray &answer);
    // Sensors 35 (OI mode): one byte of 1..3 from an Open Interface robot,
    // nothing from the SCI.
    static oi::OiCommand modeQuestionCommand() { return {oi::Command::Sensors, {35}, {}}; }
    static QByteArray modeQuestion() { return handshakeBytes({modeQuestionCommand()}); }
    static bool isModeAnswer(const QByteArray &answer);
    // The unframed answer of `size` bytes among what was received: as it
    // came, or with the lines of text a docked robot prints taken out.
    static QByteArray answerOf(const QByteArray &received, qsizetype size);
    // Whether `detected` stands for any of the profiles that answer alike
    // (the Roomba 500 and the Create 2) rather than a certain answer.
    static bool isAmbiguous(oi::ProfileId detected) { return oi::profile(detected).hasLookalike(); }
    // Whether the answer to a packet or group reads differently on a Roomba
    // 500 and a Create 2: the encoder counts 43 and 44, alone or in a group
    // (100, 101). Such an answer is not given while the profile is assumed.
    static bool dependsOnRoombaOrCreate2(int packetOrGroupId);

    enum class StartPolicy : std::uint8_t {
        Always,   // Start goes out first at every baud, as above (the default)
        IfSilent, // asked first without Start, which would drop Safe or Full
                  // to Passive; Start goes out only when nothing answers
        Never,    // a robot in Off mode is not found
    };
    void setStartPolicy(StartPolicy policy) { m_startPolicy = policy; }
    // The OI mode the robot answered with, once detected.
    oi::OiMode modeFound() const { return m_mode; }

    void start();
    void cancel();
    bool isRunning() const { return m_step != Step::Idle; }
    // Everything the transport receives while the probe runs.
    void feed(const QByteArray &bytes);

signals:
    void sent(const QByteArray &bytes, const std::vector<oi::OiCommand> &commands);
    void startSent(); // among those bytes, Start (128): the robot goes to Passive
    // `baud` is 0 where the transport has no baud of its own.
    void detected(oi::ProfileId profile, int baud);
    void failed();

private:
    enum class Step { Idle, Draining, AskFirst, AskMode, AskRoombaGroup };

    void tryBaud();
    void nextBaud();
    bool send(const std::vector<oi::OiCommand> &commands);
    void ask(const oi::OiCommand &question, qsizetype expected, Step step);
    // What came back to the question of `m_step` (or during the drain).
    void onAnswer(const QByteArray &received);
    void finish(oi::ProfileId profile);

    Transport &m_transport;
    QList<int> m_bauds;
    qsizetype m_baudIndex = 0;
    int m_baud = 0;
    int m_attempts = 0;
    Step m_step = Step::Idle;
    qsizetype m_expected = 0;
    StartPolicy m_startPolicy = StartPolicy::Always;
    bool m_startSent = false;
    oi::OiMode m_mode = oi::OiMode::Off;
    Exchange m_exchange;
};

} // namespace oilink
