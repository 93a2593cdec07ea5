// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "connection_doctor.h"
#include "link_settings.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>
#include <optional>

class DoctorDetails;
class QWidget;
class RobotSession;

// When a session's link gets no valid data, finds out why: closes the link,
// runs the connection doctor on a transport of its own, shows the finding
// (DoctorDetails), and connects again with what works. A robot that may be
// a Roomba 500 or a Create 2 is asked about, once per port: the answer is
// kept, and Create 2 is never picked for it silently.
class ConnectionCheckup : public QObject {
    Q_OBJECT
public:
    // Asks the user which of the two robots it is; nullopt if they do not say.
    using AskWhich = std::function<std::optional<oi::ProfileId>(const QString &port)>;

    // Asks with a message box over `parent`.
    static AskWhich askWithDialog(QWidget *parent);

    ConnectionCheckup(RobotSession &session, DoctorDetails &details, AskWhich askWhich,
                      QObject *parent = nullptr);
    ~ConnectionCheckup() override;

    bool isRunning() const { return m_doctor != nullptr; }
    // The profile remembered for this port, if the user named one.
    static std::optional<oi::ProfileId> rememberedProfile(const QString &port);
    static void rememberProfile(const QString &port, oi::ProfileId profile);
    // Runs the check now (also what happens on "no data").
    void run();

signals:
    void finished(const oilink::ConnectionDoctor::Report &report);

private:
    void onLinkError();
    void onFinished(const oilink::ConnectionDoctor::Report &report);
    void onProfileFound(oi::ProfileId found);

    RobotSession &m_session;
    DoctorDetails &m_details;
    AskWhich m_askWhich;
    oilink::LinkSettings m_settings;
    std::unique_ptr<oilink::Transport> m_transport;
    std::unique_ptr<oilink::ConnectionDoctor> m_doctor;
    bool m_checkedThisConnection = false;
    bool m_asking = false;
};
