// SPDX-License-Identifier: GPL-3.0-or-later
#include "connection_checkup.h"

#include "connection_next_steps.h"
#include "doctor_details.h"
#include "robot_session.h"
#include "saved_robots.h"

#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTimer>

namespace {
// Per robot, as its firmware corrections are kept (robotIdentity()).
QString settingsKey(const oilink::LinkSettings &robot)
{
    return QStringLiteral("connection/profileOf/") + robotIdentity(robot).replace(QLatin1Char('/'), QLatin1Char('_'));
}
} // namespace

ConnectionCheckup::ConnectionCheckup(RobotSession &session, DoctorDetails &details, AskWhich askWhich,
                                     QObject *parent)
    : QObject(parent), m_session(session), m_details(details), m_askWhich(std::move(askWhich))
{
    connect(&m_session, &RobotSession::errorOccurred, this, &ConnectionCheckup::onLinkError);
    connect(&m_session, &RobotSession::connectionCheckStep, this, [this](const QString &step) {
        if (m_running)
            m_details.addStep(step);
    });
    connect(&m_session, &RobotSession::connectionChecked, this, &ConnectionCheckup::onFinished);
    connect(&m_session, &RobotSession::profileAssumed, this, [this] {
        QTimer::singleShot(0, this, &ConnectionCheckup::identify); // not inside the session's signal
    });
    connect(&m_session, &RobotSession::stateChanged, this, [this](oilink::LinkState state) {
        // Data flows: the finding is old news, and a later silence is checked again.
        if (state == oilink::LinkState::Streaming && !isRunning()) {
            m_details.clear();
            m_checkedThisConnection = false;
        }
        // A profile named for this port is the answer from now on, where
        // the probe alone could not tell it from a lookalike.
        const oilink::LinkSettings &s = m_session.settings();
        if (state == oilink::LinkState::Streaming && s.profile && oi::profile(*s.profile).hasLookalike()
            && (s.transport == oilink::TransportKind::Serial || s.transport == oilink::TransportKind::Tcp))
            rememberProfile(s, *s.profile);
    });
}

ConnectionCheckup::~ConnectionCheckup() = default;

// In Auto the link takes a Roomba-family robot for a Create 2 (they answer
// alike); the remembered answer, or the user, decides instead.
void ConnectionCheckup::identify()
{
    if (m_session.isIdentified() || m_asking)
        return;
    if (const std::optional<oi::ProfileId> which = whichRobot(m_session.settings()))
        m_session.identifyAs(*which);
}

std::optional<oi::ProfileId> ConnectionCheckup::whichRobot(const oilink::LinkSettings &settings)
{
    const QString port = settings.describe();
    std::optional<oi::ProfileId> which = rememberedProfile(settings);
    if (!which && m_askWhich) {
        m_asking = true;
        which = m_askWhich(m_session.name().isEmpty() ? port : tr("%1 on %2").arg(m_session.name(), port));
        m_asking = false;
    }
    if (which)
        rememberProfile(settings, *which);
    return which;
}

std::optional<oi::ProfileId> ConnectionCheckup::rememberedProfile(const oilink::LinkSettings &robot)
{
    const QString key = QSettings().value(settingsKey(robot)).toString();
    if (const oi::RobotProfile *p = oi::profileByKey(key.toStdString()))
        return p->id;
    return std::nullopt;
}

void ConnectionCheckup::rememberProfile(const oilink::LinkSettings &robot, oi::ProfileId profile)
{
    QSettings().setValue(settingsKey(robot), QString::fromUtf8(oi::profile(profile).key.data(),
                                                              qsizetype(oi::profile(profile).key.size())));
}

// "No data" while connecting and no frame yet: check once per connection.
void ConnectionCheckup::onLinkError()
{
    const oilink::LinkSettings &s = m_session.settings();
    if (isRunning() || m_checkedThisConnection || m_session.state() == oilink::LinkState::Streaming
        || m_session.statistics().frames > 0 || s.transport == oilink::TransportKind::Replay
        || s.transport == oilink::TransportKind::Network)
        return;
    m_checkedThisConnection = true;
    // From the event loop: the session is inside a signal.
    QTimer::singleShot(0, this, &ConnectionCheckup::run);
}

void ConnectionCheckup::run()
{
    if (isRunning())
        return;
    m_running = true;
    m_settings = m_session.settings();
    m_details.start();
    m_session.checkConnection(); // the link runs the doctor on its own port
}

void ConnectionCheckup::onFinished(const oilink::ConnectionDoctor::Report &report)
{
    if (!m_running)
        return; // a check someone else asked the link for
    m_running = false;
    using F = oilink::ConnectionDoctor::Finding;
    m_details.finish(report.summary, ConnectionNextSteps::forReport(m_settings, report));
    emit finished(report);

    oilink::LinkSettings next = m_settings;
    if (report.baud > 0 && m_settings.transport == oilink::TransportKind::Serial)
        next.baud = report.baud;
    if (report.wakeLine)
        next.brcLine = *report.wakeLine; // the line the robot woke on
    switch (report.finding) {
    case F::NothingComesBack:
    case F::AsleepDidNotWake:
    case F::GarbledAtEveryBaud:
        return; // nothing to connect with: the line says what to do
    case F::OtherProfile:
        next.profile.reset(); // let the link find it
        break;
    case F::RoombaOrCreate2: {
        const std::optional<oi::ProfileId> which = whichRobot(m_settings);
        if (!which)
            return;
        next.profile = which;
        break;
    }
    default:
        break;
    }
    // The link has resumed with what it found; new settings are kept by connecting with them.
    if (next != m_settings)
        m_session.connectTo(next);
}

ConnectionCheckup::AskWhich ConnectionCheckup::askWithDialog(QWidget *parent)
{
    return [parent](const QString &robot) -> std::optional<oi::ProfileId> {
        QMessageBox box(QMessageBox::Question, tr("Which robot is this?"),
                        tr("%1 is a Roomba 500 or a Create 2, and the two answer every question alike.\n\n"
                           "The Roomba 500 is the cleaning robot of the 500 series. The Create 2 is iRobot's "
                           "educational robot, built on the Roomba 600 (a Roomba 600 counts as a Create 2).\n\n"
                           "The choice decides how the wheel counts are read: the wrong one mirrors every turn "
                           "on the map. Until you choose, the map draws no path for this robot. The answer is "
                           "kept for this robot; the profile in the connection bar changes it later.")
                            .arg(robot),
                        QMessageBox::Cancel, parent);
        // A guess mirrors every turn: no default, so Enter chooses nothing,
        // only a click or Space on a button does (an AcceptRole button would
        // become the default when the box shows).
        QPushButton *roomba = box.addButton(tr("Roomba 500"), QMessageBox::ActionRole);
        QPushButton *create = box.addButton(tr("Create 2 / Roomba 600"), QMessageBox::ActionRole);
        for (QAbstractButton *button : box.buttons())
            if (auto *push = qobject_cast<QPushButton *>(button))
                push->setAutoDefault(false);
        box.exec();
        if (box.clickedButton() == roomba)
            return oi::ProfileId::Roomba500;
        if (box.clickedButton() == create)
            return oi::ProfileId::Create2;
        return std::nullopt;
    };
}

#include "moc_connection_checkup.cpp"
