// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_sender.h"

#include "command_catalog.h"
#include "command_modes.h"
#include "transport.h"

namespace {

constexpr int kDrainMs = 80;
constexpr int kStateTimeoutMs = 400;
constexpr int kReplyTimeoutMs = 1000;
constexpr int kFlushMs = 500;
// Mode, song playing, bumps and wheel drops, the four cliffs, charging sources.
constexpr std::uint8_t kStateIds[] = {35, 37, 7, 9, 10, 11, 12, 34};

bool isMotion(oi::Command c)
{
    return c == oi::Command::Drive || c == oi::Command::DriveDirect || c == oi::Command::DrivePwm;
}

QString fromStd(const std::string &text) { return QString::fromStdString(text); }

} // namespace

CommandSender::CommandSender(oilink::Transport &transport, Order order, QObject *parent)
    : QObject(parent), m_transport(transport), m_order(std::move(order)), m_timer(this)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &CommandSender::onTimeout);
    connect(&m_transport, &oilink::Transport::opened, this, &CommandSender::onOpened);
    connect(&m_transport, &oilink::Transport::bytesReceived, this, &CommandSender::onBytes);
    connect(&m_transport, &oilink::Transport::errorOccurred, this,
            [this](const QString &message) { finish(1, message); });
    m_parser.setSnapshotHandler([this](const oi::SensorSnapshot &s, oi::FrameKind kind) {
        if (m_phase == Phase::AskingState) {
            // Not from inside the parser: deciding resets it.
            m_timer.stop();
            m_phase = Phase::Idle;
            QMetaObject::invokeMethod(this, [this, s] { decide(s); }, Qt::QueuedConnection);
        } else if (m_phase == Phase::AwaitingReply) {
            emit replied(s, kind);
            finish(0);
        }
    });
}

CommandSender::~CommandSender() = default;

void CommandSender::start()
{
    // From inside the event loop, so that an answer given during open() can end it.
    QTimer::singleShot(0, this, [this] { m_transport.open(); });
}

void CommandSender::onOpened()
{
    if (m_order.profile) {
        useProfile(*m_order.profile);
        return;
    }
    m_phase = Phase::Probing;
    m_probe = std::make_unique<oilink::ProfileProbe>(m_transport, m_order.bauds);
    m_probe->setStartPolicy(m_order.changeMode ? oilink::ProfileProbe::StartPolicy::IfSilent
                                               : oilink::ProfileProbe::StartPolicy::Never);
    connect(m_probe.get(), &oilink::ProfileProbe::detected, this,
            [this](oi::ProfileId id, int) { useProfile(id); });
    connect(m_probe.get(), &oilink::ProfileProbe::failed, this, [this] {
        finish(1, m_order.changeMode
                      ? QStringLiteral("%1: no data: is the robot on, and is the baud right?").arg(m_transport.describe())
                      : QStringLiteral("%1: no answer: is the robot on, and is the baud right? (In Off mode it answers "
                           "only after Start, which --no-mode-change leaves out.)")
                            .arg(m_transport.describe()));
    });
    m_probe->start();
}

void CommandSender::useProfile(oi::ProfileId id)
{
    m_profile = &oi::profile(id);
    const oi::EncodeResult bytes = oi::encodeCommand(oi::CommandEncoder(*m_profile), m_order.name, m_order.args);
    if (!bytes) {
        finish(1, fromStd(bytes.error().describe()));
        return;
    }
    if (!bytes.warning.empty())
        emit warning(fromStd(bytes.warning));
    m_command = *bytes;
    m_parser.setProfile(*m_profile);
    const oi::CommandSpec *spec = oi::commandSpecForOpcode(*m_profile, m_command.front());
    if (spec && oi::availableWhenOff(spec->command))
        sendCommand(); // works in every mode: nothing to ask
    else
        askState();
}

// An earlier client may have left a stream running: pause it and let it
// drain, since a reply carries no framing (ERRATA 3).
void CommandSender::askState()
{
    m_phase = Phase::Draining;
    write({150, 0});
    m_timer.start(kDrainMs);
}

void CommandSender::onTimeout()
{
    switch (m_phase) {
    case Phase::Draining: {
        m_phase = Phase::AskingState;
        m_parser.reset();
        m_parser.expectReply(kStateIds);
        const std::vector<int> ids(std::begin(kStateIds), std::end(kStateIds));
        write(*oi::CommandEncoder(*m_profile).queryList(ids));
        m_timer.start(kStateTimeoutMs);
        return;
    }
    case Phase::AskingState:
        if (!m_startSent && m_order.changeMode) {
            // Silent: Off mode, which only Start leaves.
            m_startSent = true;
            write({128});
            m_phase = Phase::Draining;
            onTimeout();
            return;
        }
        finish(1, m_order.changeMode
                      ? QStringLiteral("%1: no answer: is the robot on, and is the baud right?").arg(m_transport.describe())
                      : QStringLiteral("%1: no answer: the robot may be in Off mode, which only Start leaves "
                           "(leave out --no-mode-change)")
                            .arg(m_transport.describe()));
        return;
    case Phase::AwaitingReply:
        finish(1, QStringLiteral("%1: no reply to %2").arg(m_transport.describe(), fromStd(m_order.name)));
        return;
    default:
        return;
    }
}

void CommandSender::decide(const oi::SensorSnapshot &state)
{
    const oi::CommandSpec *spec = oi::commandSpecForOpcode(*m_profile, m_command.front());
    const oi::Command command = spec ? spec->command : oi::Command::Start;
    const QString name = fromStd(m_order.name);
    oi::OiMode mode = state.oiMode();
    if (oi::needsSafeOrFull(command) && mode == oi::OiMode::Passive) {
        if (!m_order.changeMode) {
            finish(1, QStringLiteral("%1 works only in Safe or Full mode, and the robot is in Passive mode: send safe "
                         "first, or leave out --no-mode-change")
                          .arg(name));
            return;
        }
        write({131});
        mode = oi::OiMode::Safe;
        emit note(QStringLiteral("the robot was in Passive mode: entered Safe mode for %1").arg(name));
    }
    if (isMotion(command) && mode == oi::OiMode::Safe) {
        const bool cliff = state.cliff(oi::CliffSensor::Left) || state.cliff(oi::CliffSensor::FrontLeft)
                           || state.cliff(oi::CliffSensor::FrontRight) || state.cliff(oi::CliffSensor::Right);
        if (state.wheelDropLeft() || state.wheelDropRight() || state.wheelDropCaster())
            emit warning(QStringLiteral("a wheel is dropped: Safe mode ignores %1 and falls back to Passive").arg(name));
        else if (state.chargingSource(oi::ChargingSource::HomeBase))
            emit warning(QStringLiteral("the robot is on its dock: Safe mode ignores %1 and falls back to Passive").arg(name));
        else if (cliff)
            emit warning(QStringLiteral("a cliff sensor sees a drop: Safe mode stops %1 toward it and falls back to Passive")
                             .arg(name));
    }
    if (command == oi::Command::Play && state.songPlaying() && m_profile->id == oi::ProfileId::Create1)
        emit warning(QStringLiteral("a song is playing: the Create ignores Play until it ends"));
    sendCommand();
}

void CommandSender::sendCommand()
{
    const std::uint8_t opcode = m_command.front();
    if (opcode != 142 && opcode != 149) {
        write(m_command);
        m_transport.flush(kFlushMs);
        finish(0);
        return;
    }
    const std::vector<std::uint8_t> ids(m_command.begin() + (opcode == 142 ? 1 : 2), m_command.end());
    m_parser.reset();
    m_parser.expectReply(ids);
    m_phase = Phase::AwaitingReply;
    write(m_command);
    m_timer.start(kReplyTimeoutMs);
}

void CommandSender::onBytes(const QByteArray &bytes)
{
    if (m_probe && m_probe->isRunning()) {
        m_probe->feed(bytes);
        return;
    }
    if (m_phase == Phase::AskingState || m_phase == Phase::AwaitingReply)
        m_parser.feed({reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size())});
}

void CommandSender::write(const oi::Bytes &bytes)
{
    m_transport.write(QByteArray(reinterpret_cast<const char *>(bytes.data()), qsizetype(bytes.size())));
}

void CommandSender::finish(int status, const QString &error)
{
    if (m_phase == Phase::Done)
        return;
    m_phase = Phase::Done;
    m_timer.stop();
    if (m_probe)
        m_probe->cancel();
    emit finished(status, error);
}
