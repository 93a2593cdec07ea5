// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

class QSocketNotifier;

// SIGTERM (kill), SIGHUP (a closed terminal) and SIGINT (Ctrl+C) end a
// program the way closing its window does: the handler only writes a byte to
// a socket pair, and requested() follows on the event loop, where the robot
// can be stopped and left in Passive before the program exits. One per
// process; SIGPIPE is ignored while it lives, so a vanished peer is an error
// to report rather than the end.
class TerminationSignals : public QObject {
    Q_OBJECT
public:
    explicit TerminationSignals(QObject *parent = nullptr);
    ~TerminationSignals() override;

    // False when the socket pair could not be made (then nothing is caught).
    bool isInstalled() const { return m_notifier != nullptr; }
    // The exit status a shell expects after this signal: 128 + its number.
    static int exitStatusFor(int signalNumber) { return 128 + signalNumber; }

signals:
    void requested(int signalNumber);

private:
    void onReadable();

    QSocketNotifier *m_notifier = nullptr;
};
