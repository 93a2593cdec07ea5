// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_mailbox.h"

#include <QObject>

#include <type_traits>
#include <variant>

namespace oilink {

// A robot model's one way to its robot, whatever is behind it (a link on a
// worker thread: LocalRobotPort): requests in, as one value each (typed
// commands, sensor queries, open and close...), and what the robot says
// out, in order, as one value each (frames with their read time, replies,
// state, statistics, errors...).
class RobotPort : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    // To the robot, in the order posted. Without a robot, a request that
    // wants an answer is answered with why none comes.
    virtual void post(const oilink::LinkRequest &request) = 0;
    // Leaves the robot stopped, waits until it is, and hands out what it
    // said last.
    virtual void closeAndWait() = 0;
    virtual bool isRunning() const = 0;

signals:
    // Everything the robot said, in order (see LinkEvent).
    void event(const oilink::LinkEvent &event);
};

// Calls `handler` on `context`'s thread with each event of kind `Kind`
// (see handEvent: the event, or its leading fields).
template <typename Kind, typename Handler>
QMetaObject::Connection connectEvent(const RobotPort *port, const QObject *context, Handler handler)
{
    return QObject::connect(port, &RobotPort::event, context, [handler = std::move(handler)](const LinkEvent &e) mutable {
        if (const Kind *k = std::get_if<Kind>(&e))
            handEvent(handler, *k);
    });
}

} // namespace oilink
