// SPDX-License-Identifier: GPL-3.0-or-later
// What serve needs of a classroom folder (classroom_files.cpp writes it).
#include "classroom_dir.h"

#include "fleet_topics.h"

#include <QDir>
#include <QFile>

namespace classroom {

namespace {

std::optional<QByteArray> readFile(const QDir &dir, const QString &name, QString *error)
{
    QFile f(dir.filePath(name));
    if (!f.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot read %1 (%2): is %3 a folder that roomba-classroom init wrote, and "
                                "do you run serve as the user who wrote it?")
                     .arg(f.fileName(), f.errorString(), dir.path());
        return std::nullopt;
    }
    return f.readAll();
}

} // namespace

QHash<QString, ClassroomDir::Rights> ClassroomDir::readAcl(const QByteArray &acl)
{
    QHash<QString, Rights> rights;
    Rights *block = nullptr; // lines before any `user` apply to anonymous clients, whom init refuses
    for (const QByteArray &raw : acl.split('\n')) {
        const QList<QByteArray> words = raw.simplified().split(' ');
        if (words.size() == 2 && words[0] == "user") {
            block = &rights[QString::fromUtf8(words[1])];
        } else if (block && words.size() >= 2 && words[0] == "topic") {
            // "topic TOPIC" grants both; "topic read|write|readwrite|deny TOPIC".
            const QByteArray access = words.size() == 2 ? QByteArray("readwrite") : words[1];
            const QString topic = QString::fromUtf8(words.last());
            if (access == "write" || access == "readwrite")
                block->writes << topic;
            if (access == "read" || access == "readwrite")
                block->reads << topic;
        }
    }
    return rights;
}

std::optional<ClassroomDir> ClassroomDir::read(const QString &dirName, QString *error)
{
    const QDir dir(QDir(dirName).absolutePath());
    ClassroomDir c;
    c.m_path = dir.path();
    const std::optional<QByteArray> config = readFile(dir, QStringLiteral("mosquitto.conf"), error);
    if (!config)
        return std::nullopt;
    const std::optional<QByteArray> acl = readFile(dir, QStringLiteral("acl"), error);
    if (!acl)
        return std::nullopt;
    bool listener = false;
    for (const QByteArray &raw : config->split('\n')) {
        const QList<QByteArray> words = raw.simplified().split(' ');
        if (words.value(0) == "listener" && words.size() >= 2) {
            bool ok = false;
            c.m_broker.port = words[1].toInt(&ok);
            listener = ok && c.m_broker.port > 0 && c.m_broker.port < 65536;
            c.m_broker.host = words.size() >= 3 ? QString::fromUtf8(words[2]) : QStringLiteral("127.0.0.1");
        } else if (words.value(0) == "max_packet_size" && words.size() == 2) {
            c.m_maxPacketBytes = words[1].toInt();
        }
    }
    if (!listener) {
        *error = QStringLiteral("%1 has no listener line with a port: is it the one roomba-classroom init wrote?")
                     .arg(dir.filePath(QStringLiteral("mosquitto.conf")));
        return std::nullopt;
    }
    c.m_broker.tls = true;
    c.m_broker.caFile = c.caFile();
    c.m_rights = readAcl(*acl);
    for (auto it = c.m_rights.cbegin(); it != c.m_rights.cend(); ++it)
        if (it->writes.contains(mqtt::topics::stopAll()))
            c.m_teacher = it.key();
    for (const QString &file : {c.caFile(), c.serverCertificateFile(), c.serverKeyFile()})
        if (!readFile(dir, QFileInfo(file).fileName(), error))
            return std::nullopt;
    return c;
}

QString ClassroomDir::caFile() const
{
    return QDir(m_path).filePath(QStringLiteral("ca.crt"));
}

QString ClassroomDir::serverCertificateFile() const
{
    return QDir(m_path).filePath(QStringLiteral("server.crt"));
}

QString ClassroomDir::serverKeyFile() const
{
    return QDir(m_path).filePath(QStringLiteral("server.key"));
}

bool ClassroomDir::isPerson(const QString &account) const
{
    const auto it = m_rights.constFind(account);
    return it != m_rights.cend() && it->reads.contains(QStringLiteral("roomba/#"));
}

QStringList ClassroomDir::robotsFor(const QString &account) const
{
    QStringList robots;
    const auto it = m_rights.constFind(account);
    if (it == m_rights.cend())
        return robots;
    for (const QString &topic : it->writes) {
        const std::optional<mqtt::topics::Topic> t = mqtt::topics::parse(topic);
        if (t && t->kind == mqtt::topics::Kind::Command && t->client == account
            && it->writes.contains(mqtt::topics::control(t->robot, account)) && !robots.contains(t->robot))
            robots << t->robot;
    }
    return robots;
}

} // namespace classroom
