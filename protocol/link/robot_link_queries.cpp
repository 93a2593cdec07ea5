// SPDX-License-Identifier: GPL-3.0-or-later
// RobotLink: the sensor queries, Show Script and the connection check, one
// at a time, each with the line to itself.
#include "robot_link.h"
#include "robot_link_shared.h"

#include "connection_doctor.h"
#include "brc_pulser.h"
#include "profile_probe.h"
#include "queued_call.h"
#include "transport.h"

#include <algorithm>

namespace oilink {

namespace {
// A paused stream has drained once nothing came for this long (frames come
// every 15 ms).
constexpr int kQueryQuietMs = 50;
constexpr int kQueryTimeoutMs = 500;

std::vector<oi::OiCommand> streamState(bool running)
{
    return {oi::OiCommand{oi::Command::PauseResumeStream, {running ? 1 : 0}, {}}};
}
} // namespace

using robot_link::fromStd;

// --- The queries ---

void RobotLink::querySensors(const QList<int> &packetIds, bool internal)
{
    if (!m_profile || !m_transport || !portOpen() || (m_probe && m_probe->isRunning())) {
        reportError(tr("not connected: the sensor query was not sent"), false);
        return;
    }
    std::vector<std::uint8_t> ids;
    for (int id : packetIds) {
        if (!m_profile->isValidSensorId(id)) {
            reportError(tr("sensor query: %1 is not a packet or group of the %2")
                            .arg(id)
                            .arg(fromStd(m_profile->name)),
                        false);
            return;
        }
        ids.push_back(static_cast<std::uint8_t>(id));
    }
    if (ids.empty() || ids.size() > 255) {
        reportError(tr("sensor query: ask for 1 to 255 packets"), false);
        return;
    }
    if (ids.size() > 1 && !m_profile->has(oi::Command::QueryList)) {
        reportError(tr("sensor query: the %1 has no Query List; ask for one group at a time (0 is every packet)")
                        .arg(fromStd(m_profile->name)),
                    false);
        return;
    }
    enqueue(Request{Request::Kind::Sensors, std::move(ids), internal});
}

void RobotLink::showScript()
{
    if (!m_profile || !m_transport || !portOpen() || (m_probe && m_probe->isRunning())) {
        emit scriptFailed(tr("not connected: Show Script was not sent"));
        return;
    }
    if (!m_profile->has(oi::Command::ShowScript)) {
        emit scriptFailed(tr("the %1 has no scripts").arg(fromStd(m_profile->name)));
        return;
    }
    enqueue(Request{Request::Kind::Script, {}});
}

void RobotLink::enqueue(Request request)
{
    m_queries.push_back(std::move(request));
    if (m_queryPhase == QueryPhase::None)
        startNextQuery();
}

// A reply carries no framing (ERRATA 3): it must not meet stream bytes, so
// the stream is paused, allowed to drain, and resumed after the answer.
void RobotLink::startNextQuery()
{
    if (m_queries.empty() || m_queryPhase != QueryPhase::None || !m_transport || !portOpen())
        return;
    if (m_queries.front().kind == Request::Kind::Doctor) {
        startDoctor();
        return;
    }
    const auto drained = [this](Exchange::Outcome outcome, const QByteArray &) {
        if (outcome == Exchange::Outcome::Answered)
            sendQuery();
        else
            onQueryTimeout();
    };
    if (polling()) {
        // The polls stop; the last one's answer drains before the question.
        m_queryPhase = QueryPhase::Pausing;
        m_watchdog.stop();
        m_exchange.ask({}, Exchange::Expect::silence(kQueryQuietMs), kQueryTimeoutMs, drained);
        return;
    }
    // Without streaming, a stream an earlier client left running is paused too.
    if ((streamRequested() || !m_settings.streaming) && writingProfile().has(oi::Command::PauseResumeStream)) {
        m_queryPhase = QueryPhase::Pausing;
        m_watchdog.stop();
        m_exchange.ask(streamState(false), Exchange::Expect::silence(kQueryQuietMs), kQueryTimeoutMs, drained);
    } else {
        sendQuery();
    }
}

void RobotLink::sendQuery()
{
    if (m_queries.empty() || !m_transport)
        return;
    dropPartialInput();
    m_pollAsked = false; // an answer still to come is dropped with the rest
    const Request &request = m_queries.front();
    const bool script = request.kind == Request::Kind::Script;
    const oi::OiCommand command = script ? oi::OiCommand{oi::Command::ShowScript, {}, {}}
                                  : request.packetIds.size() == 1
                                      ? oi::OiCommand{oi::Command::Sensors, {request.packetIds.front()}, {}}
                                      : oi::OiCommand{oi::Command::QueryList, {}, request.packetIds};
    // Show Script's reply is a length byte and that many bytes, read here;
    // a sensor reply, the parser reads (onReply).
    const auto wholeScript = [](const QByteArray &r) { return !r.isEmpty() && r.size() >= 1 + quint8(r.front()); };
    if (!script)
        m_parser.expectReply(request.packetIds);
    m_queryPhase = QueryPhase::Waiting;
    m_exchange.ask({command}, script ? Exchange::Expect::pattern(wholeScript) : Exchange::Expect::reader(),
                   kQueryTimeoutMs, [this](Exchange::Outcome outcome, const QByteArray &received) {
                       if (outcome == Exchange::Outcome::Answered)
                           onQueryAnswered(received);
                       else
                           onQueryTimeout();
                   });
}

void RobotLink::onReply(const oi::SensorSnapshot &reply)
{
    if (m_queryPhase != QueryPhase::Waiting || !m_transport)
        return;
    emit sensorReply(reply);
    m_exchange.answered();
}

// True when the bytes were taken: the answer to Show Script, which the parser does not know.
bool RobotLink::takeScriptReply(const QByteArray &bytes)
{
    if (m_queryPhase != QueryPhase::Waiting || m_queries.empty() || m_queries.front().kind != Request::Kind::Script)
        return false;
    m_exchange.feed(bytes);
    return true;
}

void RobotLink::onQueryAnswered(const QByteArray &received)
{
    if (!m_queries.empty() && m_queries.front().kind == Request::Kind::Script)
        emit scriptReply(received.mid(1, static_cast<std::uint8_t>(received.front())));
    finishQuery(); // a sensor reply went out as the parser read it
}

void RobotLink::onQueryTimeout()
{
    const bool internal = !m_queries.empty() && m_queries.front().internal;
    if (m_queryPhase == QueryPhase::Pausing) {
        const QString message = tr("%1: the stream did not pause; the sensor query was not sent").arg(m_settings.describe());
        if (!internal)
            reportError(message, false);
        if (!m_queries.empty() && m_queries.front().kind == Request::Kind::Sensors)
            emit sensorQueryFailed(message);
    } else if (!m_queries.empty() && m_queries.front().kind == Request::Kind::Script) {
        emit scriptFailed(tr("%1: no reply to Show Script").arg(m_settings.describe()));
    } else {
        m_parser.cancelReplies();
        dropPartialInput();
        const QString message = tr("%1: no reply to the sensor query").arg(m_settings.describe());
        if (!internal)
            reportError(message, false);
        emit sensorQueryFailed(message);
    }
    finishQuery();
}

void RobotLink::finishQuery()
{
    if (!m_queries.empty())
        m_queries.pop_front();
    m_queryPhase = QueryPhase::None;
    m_exchange.cancel();
    if (streamRequested()) {
        if (!polling()) // polls go on at the next tick
            writeCommands(streamState(true));
        m_watchdog.start();
    }
    // Not at once: this may run inside the parser, which the next query resets.
    if (!m_queries.empty())
        threads::queueCall(this, [this] { startNextQuery(); });
}

// --- The connection doctor ---

void RobotLink::checkConnection()
{
    // One check at a time; its finding answers every request for it.
    if (m_doctor || std::any_of(m_queries.begin(), m_queries.end(),
                                [](const Request &r) { return r.kind == Request::Kind::Doctor; }))
        return;
    if (!m_transport || !portOpen()) {
        ConnectionDoctor::Report report; // nothing comes back
        report.summary = m_state == LinkState::Closed ? tr("not connected: there is nothing to check")
                         : !m_lastTransportError.isEmpty()
                             ? m_lastTransportError
                             : tr("%1: the port is not open yet").arg(m_settings.describe());
        emit connectionChecked(report);
        return;
    }
    enqueue(Request{Request::Kind::Doctor, {}});
}

// The doctor has the port to itself: motion stops, and the stream, the
// probe and the keep-awake pulses give way until it is done.
void RobotLink::startDoctor()
{
    m_queryPhase = QueryPhase::Checking;
    if (streamRequested())
        writeCommands(oi::stopMotionCommands(*m_profile));
    m_phase = Phase::Checking;
    m_parser.setTextHandler([this](std::string_view line) {
        emit robotText(QString::fromLatin1(line.data(), qsizetype(line.size())));
    });
    for (ClockTimer *t : {&m_watchdog, &m_noData, &m_probeRetry})
        t->stop();
    if (m_probe) {
        m_probe->cancel();
        m_probe->deleteLater();
        m_probe = nullptr;
    }
    m_brc->setTransport(nullptr);
    dropPartialInput();
    setState(LinkState::Connecting);
    m_doctor = new ConnectionDoctor(*m_transport, m_settings.profile, m_settings.baud, m_clock, this);
    connect(m_doctor, &ConnectionDoctor::sent, this, &RobotLink::noteSent);
    connect(m_doctor, &ConnectionDoctor::startSent, this, &RobotLink::noteStartSent);
    connect(m_doctor, &ConnectionDoctor::stepDone, this, &RobotLink::connectionCheckStep);
    connect(m_doctor, &ConnectionDoctor::finished, this, &RobotLink::onDoctorFinished);
    m_doctor->start();
}

// Greets the robot again with what the doctor found: the baud it answered
// at, and for another robot than the one named, the probe's answer.
void RobotLink::onDoctorFinished(const ConnectionDoctor::Report &report)
{
    disconnect(m_doctor, nullptr, this, nullptr);
    m_doctor->deleteLater(); // inside its own signal
    m_doctor = nullptr;
    if (!m_queries.empty())
        m_queries.pop_front();
    m_queryPhase = QueryPhase::None;
    if (report.baud > 0)
        m_baud = report.baud;
    if (report.finding == ConnectionDoctor::Finding::OtherProfile) {
        m_profile = nullptr;
        m_profileAssumed = false;
    }
    m_rearmMs = kNoDataAfterMs;
    m_brc->setTransport(m_transport);
    m_phase = Phase::Greeting; // again, with what the doctor found
    emit connectionChecked(report);
    greetRobot();
    if (!m_queries.empty())
        threads::queueCall(this, [this] { startNextQuery(); });
}

// The port went away or the link closed while the doctor ran.
void RobotLink::endDoctor(const QString &why)
{
    if (!m_doctor)
        return;
    disconnect(m_doctor, nullptr, this, nullptr);
    m_doctor->deleteLater();
    m_doctor = nullptr;
    ConnectionDoctor::Report report; // nothing comes back
    report.summary = why;
    emit connectionChecked(report);
}

} // namespace oilink
