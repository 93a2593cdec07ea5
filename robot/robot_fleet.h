// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_clock.h"
#include "link_settings.h"
#include "robot_lesson.h"
#include "saved_robots.h"

#include <QList>
#include <QObject>
#include <QPointer>

#include <memory>
#include <vector>

class RobotSession;

// The robots of one window, each a RobotSession with its own name and
// colour, and which of them is selected. Stop all reaches every robot,
// whatever is selected. There is always at least one robot.
class RobotFleet : public QObject {
    Q_OBJECT
public:
    explicit RobotFleet(QObject *parent = nullptr);
    ~RobotFleet() override;

    // Makes the transports of every robot added from now on (tests).
    void setTransportFactory(oilink::TransportFactory factory);
    bool hasTransportFactory() const { return bool(m_factory); }
    // The clock of every robot's link from now on (see RobotSession::setLinkClock).
    void setLinkClock(oilink::Clock &clock) { m_linkClock = &clock; }

    // A new robot, named and coloured apart from the others; an empty name
    // gets "Robot N". Connects it when `connect` is set. Not selected.
    RobotSession *addRobot(const oilink::LinkSettings &settings, const QString &name = {}, bool connect = true);
    // Stops it, leaves it in Passive and closes it; the last robot stays.
    bool removeRobot(RobotSession *robot);

    const QList<RobotSession *> &robots() const { return m_robots; }
    qsizetype count() const { return m_robots.size(); }
    qsizetype indexOf(const RobotSession *robot) const;
    RobotSession *selected() const { return m_selected; }
    void select(RobotSession *robot);

    // Drive 0,0 and motors off on every connected robot, at once; then
    // stoppedAll(), for the robots the fleet does not hold (a broker's).
    void stopAll();
    // Stop, Passive, close, for every robot: before the program ends.
    void closeAllAndWait();

    // What is kept between runs, and the robots made from it. The selected
    // robot connects at once; the others wait for connectWaiting() (the
    // window calls it once the first live frame is on screen) or for
    // kRestoreOthersMs, so thirty saved robots do not hold up that picture.
    static constexpr int kRestoreOthersMs = 1000;
    QList<SavedRobot> saved() const;
    void restore(const QList<SavedRobot> &robots);
    bool hasRobotsWaiting() const { return !m_waiting.isEmpty(); }
    void connectWaiting();

    QString uniqueName(const QString &wanted) const;

    // The lesson the class follows, checked on the robot the window points
    // it at (the selected one); the lesson panel and the projector show it.
    RobotLesson &lesson() { return m_lesson; }

signals:
    void robotAdded(RobotSession *robot);
    void robotRemoved(RobotSession *robot);
    void selectionChanged(RobotSession *robot, RobotSession *previous);
    void stoppedAll();

private:
    QColor nextColour() const;

    oilink::TransportFactory m_factory;
    oilink::Clock *m_linkClock = nullptr;
    QList<RobotSession *> m_robots;
    RobotSession *m_selected = nullptr;
    QList<QPointer<RobotSession>> m_waiting; // restored, to connect soon
    RobotLesson m_lesson;
};
