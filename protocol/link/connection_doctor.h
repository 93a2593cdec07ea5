// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "connection_report.h"
#include "exchange.h"
#include "link_clock.h"
#include "link_settings.h"
#include "link_status.h" // the metatype of oi::ProfileId

#include "robot_profile.h"
#include "stream_parser.h"
#include "typed_commands.h"

#include <QByteArray>
#include <QList>
#include <QObject>
#include <QString>

#include <functional>
#include <optional>

namespace oilink {

class BrcPulser;
class Transport;

// Why a link gets no valid data, found by trying, one step at a time, on an
// open transport the doctor has to itself:
//  1. at each baud (the one asked for first; a transport without a baud of
//     its own has one pass), Sensors 0 without Start, then after
//     Start: an answer names the baud; bytes that make no sense mean a
//     wrong baud;
//  2. silent everywhere: a BRC pulse on the wake line (a sleeping robot
//     wakes), each baud again once it has had time to wake and again once
//     even a slow robot has (2 s); still silent, the same on the other line
//     (RTS for DTR and the other way round); then, 2 s after it woke (the
//     documents), the three pulses for 19200 baud on the wake line;
//  3. once it answers, Sensors 35 tells the Open Interface from the
//     Roomba 400's SCI (no packet 35), and Sensors 101 a Create from a
//     Roomba 500 / Create 2, which answer alike: which of those two only
//     the user knows.
// Lines of text among the answers are a docked Roomba's charging status:
// readable, they prove the baud and the cable, and a robot on its dock,
// whether or not it answers (then the doctor changes no baud).
class ConnectionDoctor : public QObject {
    Q_OBJECT
public:
    using Finding = ConnectionReport::Finding;
    using Report = ConnectionReport;

    // `profile` and `baud` as the link was set up (nullopt / 0 = Auto).
    ConnectionDoctor(Transport &transport, std::optional<oi::ProfileId> profile, int baud,
                     Clock &clock = Clock::steady(), QObject *parent = nullptr);
    ~ConnectionDoctor() override;

    static QList<int> candidateBauds(int asked);
    // The transport must be open.
    void start();
    // Everything the transport receives while the doctor runs.
    void feed(const QByteArray &bytes);

signals:
    void stepDone(const QString &step);
    void sent(const QByteArray &bytes, const std::vector<oi::OiCommand> &commands); // written to the robot
    void startSent(); // among those bytes, Start (128): the robot goes to Passive
    void finished(const oilink::ConnectionDoctor::Report &report);

private:
    using Answer = std::function<void(const QByteArray &)>;
    bool write(const std::vector<oi::OiCommand> &commands);
    void ask(const oi::OiCommand &question, qsizetype expected, Answer then);
    // A pause between steps, in which nothing is asked and nothing heard.
    void after(int ms, std::function<void()> then);
    void tryBaud(qsizetype index);
    void askMode(bool withStart, std::function<void(bool answered)> then);
    void afterSilence();
    void afterWakePulse(qsizetype index);
    bool wakeOnOtherLine();
    void pulseForBaud19200();
    void answered(int baud, Finding cause);
    void identified(int baud, Finding cause, oi::ProfileId found);
    void conclude(Finding finding, const QString &summary);
    void concludeSilent();
    void concludeGarbled();
    // Concludes TextOnDock if the robot printed text; false if it did not.
    bool concludeFromText();
    // The transport now talks at `baud` (0: it has no baud of its own).
    void listenAt(int baud);
    void step(const QString &text);
    QString baudName(int baud) const;

    Transport &m_transport;
    std::optional<oi::ProfileId> m_askedProfile;
    int m_askedBaud;
    bool m_hasBaud = true;
    QList<int> m_bauds;
    QList<int> m_garbledAt;
    BrcPulser *m_pulser;
    Clock &m_clock;
    Exchange m_exchange; // each question and the wait for its answer
    ClockTimer m_timer;  // the pauses between steps
    qint64 m_wokeMs = 0;  // when the first woken robot listened
    qint64 m_awakeMs = 0; // when the robot woken on this line listened
    bool m_roundAfterWakeTime = false; // every baud asked after even a slow robot listens
    BrcLine m_wakeLine = BrcLine::Rts; // as the link was set up
    bool m_onOtherLine = false;
    oi::StreamParser m_textReader; // the robot's text among what is heard
    int m_listeningBaud = 0;
    std::optional<int> m_textBaud; // where the robot printed text
    QString m_textLine;            // the last line it printed
    bool m_foundSci = false;       // it answered as a Roomba 400 (SCI)
    qsizetype m_heard = 0; // bytes heard at the baud being tried
    std::function<void()> m_onTimer;
    Report m_report;
    bool m_running = false;
};

} // namespace oilink
