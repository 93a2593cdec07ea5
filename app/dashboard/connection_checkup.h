// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "connection_doctor.h"
#include "link_settings.h"

#include <QObject>

#include <functional>
#include <optional>

class DoctorDetails;
class QWidget;
class RobotSession;

// When a session's link gets no valid data, finds out why: asks the link to
// run the connection doctor on its port (RobotSession::checkConnection()),
// shows the steps and the finding (DoctorDetails), and where the finding
// changes the settings (another baud, another robot), connects again with
// what works. Otherwise the link resumes by itself.
//
// A robot that may be a Roomba 500 or a Create 2 (the link's probe, or the
// doctor, cannot tell them apart) is asked about once per port or bridge:
// the answer is kept in the settings, the session reads the robot with it
// (and a saved robot keeps it as its profile), and Create 2 is never picked
// for it silently. A profile named in the connection bar is kept for the
// port too, which is how an answer is changed later.
class ConnectionCheckup : public QObject {
    Q_OBJECT
public:
    // Asks the user which of the two robots it is; nullopt if they do not
    // say. `robot` names it and its port ("Robot 1 on /dev/ttyUSB0").
    using AskWhich = std::function<std::optional<oi::ProfileId>(const QString &robot)>;

    // Asks with a message box over `parent`.
    static AskWhich askWithDialog(QWidget *parent);

    ConnectionCheckup(RobotSession &session, DoctorDetails &details, AskWhich askWhich,
                      QObject *parent = nullptr);
    ~ConnectionCheckup() override;

    bool isRunning() const { return m_running; }
    // The profile remembered for this robot (its port or bridge), if the user named one.
    static std::optional<oi::ProfileId> rememberedProfile(const oilink::LinkSettings &robot);
    static void rememberProfile(const oilink::LinkSettings &robot, oi::ProfileId profile);
    // Runs the check now (also what happens on "no data").
    void run();

signals:
    void finished(const oilink::ConnectionDoctor::Report &report);

private:
    void onLinkError();
    void onFinished(const oilink::ConnectionDoctor::Report &report);
    void identify();
    // The remembered answer for the session's port, or the user's (then kept).
    std::optional<oi::ProfileId> whichRobot(const oilink::LinkSettings &settings);

    RobotSession &m_session;
    DoctorDetails &m_details;
    AskWhich m_askWhich;
    oilink::LinkSettings m_settings;
    bool m_running = false;
    bool m_checkedThisConnection = false;
    bool m_asking = false;
};
