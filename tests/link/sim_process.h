// SPDX-License-Identifier: GPL-3.0-or-later
// The roomba-sim executable as a child process of a test. ROOMBA_SIM_PATH
// must name it.
#pragma once

#include <QDeadlineTimer>
#include <QProcess>
#include <QString>
#include <QStringList>

#include <csignal>
#include <sys/prctl.h>
#include <sys/types.h>

// One roomba-sim process; the first line it prints says where it is.
class SimProcess {
public:
    static constexpr int kTimeoutMs = 10000;

    SimProcess() = default;
    SimProcess(const SimProcess &) = delete;
    SimProcess &operator=(const SimProcess &) = delete;
    ~SimProcess() { stop(); }

    bool start(const QStringList &args)
    {
        m_process.setProgram(QStringLiteral(ROOMBA_SIM_PATH));
        m_process.setArguments(args);
        m_process.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        // Should the test die, the robot goes with it.
        m_process.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGTERM); });
        m_process.start();
        if (!m_process.waitForStarted(kTimeoutMs))
            return false;
        const QDeadlineTimer deadline(kTimeoutMs);
        while (!m_process.canReadLine() && !deadline.hasExpired()
               && m_process.state() == QProcess::Running)
            m_process.waitForReadyRead(100);
        m_where = QString::fromUtf8(m_process.readLine()).trimmed();
        return !m_where.isEmpty();
    }
    QString where() const { return m_where; }
    quint16 tcpPort() const { return static_cast<quint16>(m_where.section(QLatin1Char(':'), -1).toUInt()); }
    bool isRunning() const { return m_process.state() == QProcess::Running; }
    void signal(int number) { ::kill(static_cast<pid_t>(m_process.processId()), number); }
    void kill()
    {
        m_process.kill();
        m_process.waitForFinished(kTimeoutMs);
    }
    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        signal(SIGCONT);
        m_process.terminate();
        if (!m_process.waitForFinished(kTimeoutMs))
            kill();
    }

private:
    QProcess m_process;
    QString m_where;
};
