// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A real mosquitto for a test: started on a free loopback port with a config
// the test may extend (password file, ACL), stopped with the test.

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>

class MosquittoBroker {
public:
    static QString program() { return QStringLiteral("/usr/sbin/mosquitto"); }

    // `extraConfig` is appended to the listener line: for example
    // "allow_anonymous false\npassword_file %DIR%/passwords\n", where %DIR%
    // is the broker's own folder (see writeFile, addUser). Without it,
    // anonymous clients may do anything.
    explicit MosquittoBroker(QString extraConfig = QStringLiteral("allow_anonymous true\n"))
        : m_extraConfig(std::move(extraConfig))
    {
        // Run as root, mosquitto drops to the "mosquitto" user, which must
        // still read its config, passwords and ACL.
        QFile::setPermissions(m_dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner
                                                | QFile::ReadGroup | QFile::ExeGroup | QFile::ReadOther
                                                | QFile::ExeOther);
        QTcpServer probe;
        probe.listen(QHostAddress::LocalHost, 0);
        m_port = probe.serverPort();
    }
    ~MosquittoBroker() { stop(); }

    int port() const { return m_port; }
    QString url() const { return QStringLiteral("mqtt://127.0.0.1:%1").arg(m_port); }
    QString dir() const { return m_dir.path(); }
    QString error() const { return m_error; }

    // Writes a file into the broker's folder (passwords, ACL) and returns its path.
    QString writeFile(const QString &name, const QByteArray &contents)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        if (f.open(QIODevice::WriteOnly | QIODevice::Truncate))
            f.write(contents);
        f.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup | QFile::ReadOther);
        return path;
    }

    // A mosquitto password file entry, hashed by mosquitto_passwd.
    bool addUser(const QString &user, const QString &password)
    {
        const QString file = m_dir.filePath(QStringLiteral("passwords"));
        if (!QFile::exists(file))
            writeFile(QStringLiteral("passwords"), {});
        const int rc = QProcess::execute(QStringLiteral("/usr/bin/mosquitto_passwd"),
                                         {QStringLiteral("-b"), file, user, password});
        QFile::setPermissions(file, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup | QFile::ReadOther);
        return rc == 0;
    }

    // Starts it and waits until it accepts connections (at most 10 s).
    bool start()
    {
        return startWith(writeFile(QStringLiteral("mosquitto.conf"),
                                   QStringLiteral("listener %1 127.0.0.1\npersistence false\nset_tcp_nodelay true\n%2")
                                       .arg(m_port)
                                       .arg(QString(m_extraConfig).replace(QStringLiteral("%DIR%"), dir()))
                                       .toUtf8()));
    }
    // The same with a config of the test's own, which listens on port().
    bool startWith(const QString &config)
    {
        m_process.setProcessChannelMode(QProcess::MergedChannels);
        m_process.start(program(), {QStringLiteral("-c"), config});
        if (!m_process.waitForStarted(5000)) {
            m_error = QStringLiteral("%1 did not start: %2").arg(program(), m_process.errorString());
            return false;
        }
        // mosquitto says "running" once its listeners are open.
        const QDeadlineTimer deadline(10000);
        QByteArray said;
        while (!said.contains(" running") && m_process.waitForReadyRead(int(deadline.remainingTime())))
            said += m_process.readAll();
        if (said.contains(" running")) {
            QTcpSocket s;
            s.connectToHost(QHostAddress::LocalHost, quint16(m_port));
            if (s.waitForConnected(int(deadline.remainingTime())))
                return true;
        }
        said += m_process.readAll();
        m_error = QStringLiteral("mosquitto did not listen on port %1: %2")
                      .arg(m_port)
                      .arg(QString::fromLocal8Bit(said));
        stop();
        return false;
    }

    // Kills it as a crash would (SIGKILL): clients see the connection drop.
    void kill()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.kill();
        m_process.waitForFinished(5000);
    }

    // What the broker logged since the last call (its connections and
    // disconnections among it), once start() has returned.
    QByteArray readOutput() { return m_process.readAll(); }

    // The broker's process, for a test that freezes it (SIGSTOP).
    qint64 processId() const { return m_process.processId(); }

    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(5000))
            kill();
    }

private:
    QString m_extraConfig;
    QTemporaryDir m_dir;
    QProcess m_process;
    int m_port = 0;
    QString m_error;
};
