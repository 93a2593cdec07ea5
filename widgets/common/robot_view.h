// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QMetaObject>
#include <QObject>

class RobotMode;
class RobotSession;
namespace oi {
class RobotProfile;
class SensorSnapshot;
} // namespace oi

// Whether what a view shows is live: data arriving now, from a replay, a
// replay that has ended.
struct Liveness {
    bool live = false;
    bool replay = false;
    bool replayEnded = false;
    bool operator==(const Liveness &) const = default;
};

// A view of the selected robot. SelectedRobotView hands every registered view
// the robot, then its profile, its mode, its liveness and its frames as they
// change, and the display's tick as often as the view was registered for.
// A view made late (its dock first shown) gets all of them on registering.
class RobotView {
public:
    virtual ~RobotView() { forget(); }

    // `robot` from now on. Null: no robot is selected; the view keeps what it
    // showed and follows no robot.
    void show(RobotSession *robot)
    {
        forget();
        m_robot = robot;
        if (robot)
            showRobot(*robot);
    }
    RobotSession *robot() const { return m_robot; }

    virtual void showProfile(const oi::RobotProfile &) {}
    // The mode as the robot's session sees it; unknown while disconnected.
    virtual void showMode(const RobotMode &) {}
    virtual void showLiveness(const Liveness &) {}
    // A frame unlike the one shown before it.
    virtual void showSnapshot(const oi::SensorSnapshot &) {}
    // The display's tick: `frame` counts the display's frames at its full
    // pace (a quiet tick counts as several).
    virtual void tick(quint64 frame) { (void)frame; }

protected:
    // What the view shows of `robot` when selected; signals it follows go
    // through follow(), which drops them when another robot is shown.
    virtual void showRobot(RobotSession &robot) { (void)robot; }
    void follow(const QMetaObject::Connection &connection) { m_followed << connection; }

private:
    void forget()
    {
        for (const QMetaObject::Connection &c : std::as_const(m_followed))
            QObject::disconnect(c);
        m_followed.clear();
    }
    RobotSession *m_robot = nullptr;
    QList<QMetaObject::Connection> m_followed;
};
