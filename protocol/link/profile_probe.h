// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

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
//  2. Query List 35, 7: exactly two bytes must come back, an OI mode of
//     1..3 (Start has just made it Passive) and a bumps byte with bits 5..7
//     clear. Anything else is the wrong baud or no robot; asked twice, so one
//     corrupted answer on a noisy line does not skip the right baud.
//  3. Sensors 101 (43..58): the Roomba 500 and Create 2 send its 28 bytes;
//     the Create has no such group and sends nothing, or something that is
//     not 28 bytes. That is the Create.
// The Roomba 500 and the Create 2 answer every question alike (the same
// commands, packet ids and sizes); they differ only in what packets 43/44
// mean (ERRATA 4) and in the range of 58, which no answer reveals. The probe
// says Create 2, the newer and commoner of the two, and isRoombaOrCreate2()
// of that answer is true: it stands for the family, and whoever uses it
// must have the profile named (remembered, or asked) before trusting which
// encoder count is which.
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
    // Query List 35 (OI mode), 7 (bumps and wheel drops).
    static oi::OiCommand modeQuestionCommand() { return {oi::Command::QueryList, {}, {35, 7}}; }
    static QByteArray modeQuestion() { return handshakeBytes({modeQuestionCommand()}); }
    // Exactly two bytes: a mode of 1..3 and a bumps byte with bits 5..7 clear.
    static bool isModeAnswer(const QByteArray &answer);
    // The unframed answer of `size` bytes among what was received: as it
    // came, or with the lines of text a docked robot prints taken out.
    static QByteArray answerOf(const QByteArray &received, qsizetype size);
    // Whether `detected` means "a Roomba 500 or a Create 2" rather than a
    // certain answer.
    static bool isRoombaOrCreate2(oi::ProfileId detected) { return detected != oi::ProfileId::Create1; }
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
    enum class Step { Idle, Draining, AskMode, AskRoombaGroup };

    void tryBaud();
    void nextBaud();
    void send(const std::vector<oi::OiCommand> &commands);
    void ask(const oi::OiCommand &question, qsizetype expected, Step step);
    void onTimeout();
    void finish(oi::ProfileId profile);

    Transport &m_transport;
    QList<int> m_bauds;
    qsizetype m_baudIndex = 0;
    int m_baud = 0;
    int m_modeAttempts = 0;
    Step m_step = Step::Idle;
    QByteArray m_received;
    qsizetype m_expected = 0;
    bool m_settling = false;
    StartPolicy m_startPolicy = StartPolicy::Always;
    bool m_startSent = false;
    oi::OiMode m_mode = oi::OiMode::Off;
    ClockTimer m_timer;
};

} // namespace oilink
