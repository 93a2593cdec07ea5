// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMetaObject>
#include <QObject>

#include <mutex>
#include <utility>

namespace threads {

// One lock for the whole program (an inline function's static is one object).
inline std::mutex &queueingLock()
{
    static std::mutex lock;
    return lock;
}

// Queues `call` to run on the thread that `receiver` lives on. Qt hands it
// over under a lock of its own, which ThreadSanitizer cannot see (Qt is not
// built with it): two threads queueing calls for a third at once then look
// like a race inside Qt's list of waiting events. In a ThreadSanitizer build
// the calls queued here are also made one at a time under a lock it sees.
template <typename Call>
void queueCall(QObject *receiver, Call &&call)
{
#if defined(__SANITIZE_THREAD__)
    const std::lock_guard seen(queueingLock());
#endif
    QMetaObject::invokeMethod(receiver, std::forward<Call>(call), Qt::QueuedConnection);
}

} // namespace threads
