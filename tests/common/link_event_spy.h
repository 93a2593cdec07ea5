// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_port.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QList>
#include <QObject>
#include <QVariant>

// Every event of one kind a robot port hands out, kept as QSignalSpy
// keeps a signal's arguments (the event's fields, in order), so that a test
// reads them as it would a spy's.
template <typename Kind>
class LinkEventSpy : public QList<QVariantList> {
public:
    explicit LinkEventSpy(const oilink::RobotPort &link)
    {
        oilink::connectEvent<Kind>(&link, &m_context,
                                   [this](const Kind &k) {
                                       append(std::apply(
                                           [](const auto &...f) { return QVariantList{QVariant::fromValue(f)...}; },
                                           oilink::fields(k)));
                                   });
    }
    // Like QSignalSpy::wait: true once another event of this kind came.
    bool wait(int timeoutMs = 5000)
    {
        const qsizetype before = size();
        const QDeadlineTimer deadline(timeoutMs);
        while (size() == before && !deadline.hasExpired())
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 10);
        return size() > before;
    }

private:
    QObject m_context; // the connection ends with the spy
};
