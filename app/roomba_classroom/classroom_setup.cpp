// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-classroom init: checking the request, making the certificates and
// passwords, and writing the classroom's folder for the broker's user.
#include "classroom_setup.h"
#include "classroom_files.h"

#include "fleet_topics.h"

#include <QDir>
#include <QFile>
#include <QHostAddress>
#include <QProcess>
#include <QRandomGenerator>
#include <QSaveFile>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <grp.h>
#include <optional>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace classroom {

namespace {

constexpr QFileDevice::Permissions kOwnerOnly = QFileDevice::ReadOwner | QFileDevice::WriteOwner;
constexpr QFileDevice::Permissions kEveryoneReads = kOwnerOnly | QFileDevice::ReadGroup | QFileDevice::ReadOther;
// Debian's broker user, made by the mosquitto package.
constexpr const char *kBrokerUser = "mosquitto";

// 20 characters from 56 that no one misreads (no 0/O, 1/l/I): about 116 bits.
QString strongPassword()
{
    static const QString alphabet = QStringLiteral("abcdefghijkmnopqrstuvwxyzABCDEFGHJKLMNPQRSTUVWXYZ23456789");
    QString p;
    for (int i = 0; i < 20; ++i)
        p += alphabet.at(int(QRandomGenerator::system()->bounded(quint32(alphabet.size()))));
    return p;
}

bool writeFile(const QString &path, const QByteArray &contents, QFileDevice::Permissions permissions, QString *error)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(contents) != contents.size() || !f.setPermissions(permissions)
        || !f.commit()) {
        *error = QStringLiteral("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

bool run(const QString &program, const QStringList &args, const QString &workDir, QString *error)
{
    QProcess p;
    p.setWorkingDirectory(workDir);
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(program, args);
    if (!p.waitForFinished(60000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
        *error = QStringLiteral("%1 %2 failed: %3").arg(program, args.join(QLatin1Char(' ')),
                                                        QString::fromLocal8Bit(p.readAll()).trimmed()
                                                            + p.errorString());
        return false;
    }
    return true;
}

QString program(const char *name) { return QStandardPaths::findExecutable(QString::fromLatin1(name)); }

bool isHostName(const QString &host)
{
    if (!QHostAddress(host).isNull())
        return true;
    if (host.isEmpty() || host.size() > 253 || host.startsWith(QLatin1Char('-')))
        return false;
    for (QChar c : host)
        if (!(c.isLetterOrNumber() && c.unicode() < 128) && c != QLatin1Char('-') && c != QLatin1Char('.'))
            return false;
    return true;
}

// The CA, and the broker's certificate signed by it for the names the
// clients use to reach it.
bool makeCertificates(const Request &r, const QString &dir, QString *error)
{
    const QString openssl = program("openssl");
    const QStringList ec{QStringLiteral("-newkey"), QStringLiteral("ec"), QStringLiteral("-pkeyopt"),
                         QStringLiteral("ec_paramgen_curve:prime256v1"), QStringLiteral("-nodes")};
    QString names = QStringLiteral("DNS:localhost,IP:127.0.0.1");
    if (r.host != QLatin1String("127.0.0.1") && r.host != QLatin1String("localhost"))
        names += (QHostAddress(r.host).isNull() ? QStringLiteral(",DNS:") : QStringLiteral(",IP:")) + r.host;
    const QString serial = QStringLiteral("0x%1").arg(QRandomGenerator::system()->generate64() >> 1, 0, 16);
    QString ignored;
    const bool ok =
        run(openssl,
            QStringList{QStringLiteral("req"), QStringLiteral("-x509")} + ec
                + QStringList{QStringLiteral("-keyout"), QStringLiteral("ca.key"), QStringLiteral("-out"),
                              QStringLiteral("ca.crt"), QStringLiteral("-days"), QStringLiteral("3650"),
                              QStringLiteral("-subj"), QStringLiteral("/CN=Roomba classroom CA"),
                              QStringLiteral("-addext"), QStringLiteral("basicConstraints=critical,CA:TRUE"),
                              QStringLiteral("-addext"), QStringLiteral("keyUsage=critical,keyCertSign,cRLSign")},
            dir, error)
        && run(openssl,
               QStringList{QStringLiteral("req")} + ec
                   + QStringList{QStringLiteral("-keyout"), QStringLiteral("server.key"), QStringLiteral("-out"),
                                 QStringLiteral("server.csr"), QStringLiteral("-subj"),
                                 QStringLiteral("/CN=%1").arg(r.host)},
               dir, error)
        && writeFile(QDir(dir).filePath(QStringLiteral("server.ext")),
                     QStringLiteral("basicConstraints=CA:FALSE\nkeyUsage=critical,digitalSignature\n"
                                    "extendedKeyUsage=serverAuth\nsubjectAltName=%1\n")
                         .arg(names)
                         .toUtf8(),
                     kOwnerOnly, error)
        && run(openssl,
               {QStringLiteral("x509"), QStringLiteral("-req"), QStringLiteral("-in"), QStringLiteral("server.csr"),
                QStringLiteral("-CA"), QStringLiteral("ca.crt"), QStringLiteral("-CAkey"), QStringLiteral("ca.key"),
                QStringLiteral("-set_serial"), serial, QStringLiteral("-days"), QStringLiteral("3650"),
                QStringLiteral("-extfile"), QStringLiteral("server.ext"), QStringLiteral("-out"),
                QStringLiteral("server.crt")},
               dir, error);
    QFile::remove(QDir(dir).filePath(QStringLiteral("server.csr")));
    QFile::remove(QDir(dir).filePath(QStringLiteral("server.ext")));
    if (!ok)
        return false;
    for (const char *secret : {"ca.key", "server.key"})
        QFile::setPermissions(QDir(dir).filePath(QString::fromLatin1(secret)), kOwnerOnly);
    QFile::setPermissions(QDir(dir).filePath(QStringLiteral("ca.crt")), kEveryoneReads);
    QFile::setPermissions(QDir(dir).filePath(QStringLiteral("server.crt")), kEveryoneReads);
    return true;
}

// Who the broker runs as: started as root, mosquitto becomes the config's
// `user` before it reads the password file, the ACL and the key. Run by a
// user, init names that user, who owns the files. Run as root, it names
// Debian's broker user rather than root (a broker should not run as root),
// and hands it the files it reads.
struct BrokerUser {
    QString name; // empty: no passwd entry for whoever runs init; no `user` line
    uid_t uid = 0;
    gid_t gid = 0;
    bool handOver = false; // init runs as root: chown the broker's files to it
};

std::optional<BrokerUser> brokerUser(QString *error)
{
    if (::geteuid() != 0) {
        const passwd *owner = ::getpwuid(::geteuid());
        return owner ? BrokerUser{QString::fromLocal8Bit(owner->pw_name), owner->pw_uid, owner->pw_gid, false}
                     : BrokerUser{};
    }
    const passwd *mosquitto = ::getpwnam(kBrokerUser);
    if (!mosquitto) {
        *error = QStringLiteral("init runs as root, and the broker should not: it runs as the user %1, which "
                                "this machine does not have. Install the broker (apt-get install mosquitto), "
                                "or run init as the user the broker should run as.")
                     .arg(QString::fromLatin1(kBrokerUser));
        return std::nullopt;
    }
    return BrokerUser{QString::fromLatin1(kBrokerUser), mosquitto->pw_uid, mosquitto->pw_gid, true};
}

// The first folder above `dir` that the broker's user cannot pass through,
// or empty. Once it is that user, the broker could not open its files there.
QString closedFolderAbove(const QString &dir, const BrokerUser &u)
{
    int count = 64;
    std::vector<gid_t> groups(64);
    if (::getgrouplist(u.name.toLocal8Bit().constData(), u.gid, groups.data(), &count) < 0)
        count = 0;
    groups.resize(size_t(std::max(count, 0)));
    groups.push_back(u.gid);
    for (QString path = QFileInfo(dir).absolutePath();; path = QFileInfo(path).absolutePath()) {
        struct stat st {};
        // A folder not there yet is made by init (mkpath), searchable by all.
        if (::stat(QFile::encodeName(path).constData(), &st) == 0) {
            const mode_t search = st.st_uid == u.uid ? S_IXUSR
                                  : std::find(groups.begin(), groups.end(), st.st_gid) != groups.end() ? S_IXGRP
                                                                                                        : S_IXOTH;
            if (!(st.st_mode & search))
                return path;
        }
        if (path == QLatin1String("/") || QFileInfo(path).absolutePath() == path)
            return {};
    }
}

// The broker, once it is its user, reads the password file, the ACL and the
// key: they become its own (as mosquitto asks of them), still unreadable by
// others. The folder lets its group through; the config, the certificates,
// accounts.txt, ca.key and the bridges' configs stay root's, so the broker's
// user can change neither the config root starts it with nor anyone's secret.
bool handOver(const QDir &dir, const BrokerUser &u, QString *error)
{
    const auto chownTo = [error](const QString &path, uid_t uid, gid_t gid) {
        if (::chown(QFile::encodeName(path).constData(), uid, gid) == 0)
            return true;
        *error = QStringLiteral("cannot hand %1 to the broker's user: %2").arg(path, QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    };
    for (const char *file : {"passwords", "acl", "server.key"})
        if (!chownTo(dir.filePath(QString::fromLatin1(file)), u.uid, u.gid))
            return false;
    if (!chownTo(dir.path(), 0, u.gid))
        return false;
    QFile::setPermissions(dir.path(), kOwnerOnly | QFileDevice::ExeOwner | QFileDevice::ReadGroup | QFileDevice::ExeGroup);
    return true;
}

} // namespace

QString bridgeAccount(const QString &robot) { return QStringLiteral("bridge-") + robot; }

QString stopLineAccount(const QString &robot) { return bridgeAccount(robot) + QStringLiteral("-stops"); }

QString brokerUrl(const Request &request)
{
    const bool ipv6 = QHostAddress(request.host).protocol() == QAbstractSocket::IPv6Protocol;
    return QStringLiteral("mqtts://%1:%2").arg(ipv6 ? QStringLiteral("[%1]").arg(request.host) : request.host).arg(request.port);
}

QString check(const Request &r)
{
    static const QString rule = QStringLiteral("1 to 64 letters (a-z, A-Z), digits, '-' or '_'");
    if (r.robots.isEmpty())
        return QStringLiteral("name the robots: --robots r1,r2,r3");
    if (r.students.isEmpty())
        return QStringLiteral("name the students: --students alice,bob");
    QSet<QString> accounts;
    const auto name = [&](const QString &what, const QString &n, const QString &option) -> QString {
        if (!mqtt::topics::isValidName(n))
            return QStringLiteral("%1 '%2' (%3) is not a name: %4. Use such a name instead.")
                .arg(what, n.left(80), option, rule);
        return {};
    };
    const auto account = [&](const QString &n, const QString &option) -> QString {
        if (accounts.contains(n))
            return QStringLiteral("the account '%1' (%2) is named twice: each account needs a name of its own").arg(n, option);
        accounts.insert(n);
        return {};
    };
    QSet<QString> robots;
    for (const QString &robot : r.robots) {
        if (QString e = name(QStringLiteral("robot"), robot, QStringLiteral("--robots")); !e.isEmpty())
            return e;
        if (robot == QLatin1String("fleet"))
            return QStringLiteral("'fleet' (--robots) cannot name a robot: roomba/fleet/ is Stop all's topic");
        if (robots.contains(robot))
            return QStringLiteral("the robot '%1' (--robots) is named twice").arg(robot);
        robots.insert(robot);
        if (stopLineAccount(robot).size() > 64)
            return QStringLiteral("robot '%1' (--robots): its bridge's account %2 is over 64 characters; use a shorter name")
                .arg(robot, stopLineAccount(robot));
        if (QString e = account(bridgeAccount(robot), QStringLiteral("the bridge of robot %1").arg(robot)); !e.isEmpty())
            return e;
        if (QString e = account(stopLineAccount(robot), QStringLiteral("the stop line of robot %1").arg(robot)); !e.isEmpty())
            return e;
    }
    const QList<std::pair<QStringList, QString>> people{{{r.teacher}, QStringLiteral("--teacher")},
                                                        {r.students, QStringLiteral("--students")},
                                                        {r.spectators, QStringLiteral("--spectators")}};
    for (const auto &[names, option] : people)
        for (const QString &n : names) {
            if (QString e = name(QStringLiteral("account"), n, option); !e.isEmpty())
                return e;
            if (QString e = account(n, option); !e.isEmpty())
                return e;
        }
    if (!isHostName(r.host) || QHostAddress(r.host) == QHostAddress::AnyIPv4 || QHostAddress(r.host) == QHostAddress::AnyIPv6)
        return QStringLiteral("'%1' (--host) is not this machine's address: give the address (or name) by which the "
                              "robots and laptops reach it on the classroom network, e.g. --host 192.168.1.10")
            .arg(r.host.left(80));
    if (r.port < 1 || r.port > 65535)
        return QStringLiteral("the port must be from 1 to 65535, not %1").arg(r.port);
    const QDir dir(r.dir);
    if (r.dir.isEmpty())
        return QStringLiteral("say where: roomba-classroom init DIR ...");
    if (dir.exists() && !dir.isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden | QDir::System))
        return QStringLiteral("%1 is not empty: init writes new passwords only into a new or empty folder, so "
                              "it never overwrites a classroom. Choose another folder (or remove this one to "
                              "start over).")
            .arg(QDir::toNativeSeparators(dir.absolutePath()));
    if (QFileInfo(r.dir).exists() && !QFileInfo(r.dir).isDir())
        return QStringLiteral("%1 is a file, not a folder").arg(r.dir);
    return {};
}

QString missingTools()
{
    if (program("openssl").isEmpty())
        return QStringLiteral("openssl makes the broker's certificates and is not installed: apt-get install openssl");
    if (program("mosquitto_passwd").isEmpty())
        return QStringLiteral("mosquitto_passwd makes the password file and is not installed: apt-get install mosquitto");
    return {};
}

std::optional<QList<Account>> init(const Request &r, QString *error)
{
    if (*error = check(r); !error->isEmpty())
        return std::nullopt;
    if (*error = missingTools(); !error->isEmpty())
        return std::nullopt;
    const QString finalDir = QDir(r.dir).absolutePath();
    const std::optional<BrokerUser> broker = brokerUser(error);
    if (!broker)
        return std::nullopt;
    if (broker->handOver)
        if (const QString closed = closedFolderAbove(finalDir, *broker); !closed.isEmpty()) {
            *error = QStringLiteral("the broker runs as the user %1, which cannot open %2: choose a folder it can "
                                    "reach (e.g. /etc/mosquitto/classroom), or open %2 to it")
                         .arg(broker->name, closed);
            return std::nullopt;
        }
    const QFileInfo target(finalDir);
    if (!QDir().mkpath(target.absolutePath())) {
        *error = QStringLiteral("cannot make the folder %1").arg(target.absolutePath());
        return std::nullopt;
    }
    // Made beside the target, moved into place when complete.
    QTemporaryDir work(QDir(target.absolutePath()).filePath(QStringLiteral(".%1-XXXXXX").arg(target.fileName())));
    if (!work.isValid()) {
        *error = QStringLiteral("cannot make a folder in %1: %2").arg(target.absolutePath(), work.errorString());
        return std::nullopt;
    }
    const QDir w(work.path());

    QList<Account> accounts{{QStringLiteral("teacher"), r.teacher, strongPassword()}};
    for (const QString &s : r.students)
        accounts.append({QStringLiteral("student"), s, strongPassword()});
    for (const QString &s : r.spectators)
        accounts.append({QStringLiteral("spectator"), s, strongPassword()});
    for (const QString &robot : r.robots) {
        accounts.append({QStringLiteral("bridge"), bridgeAccount(robot), strongPassword()});
        accounts.append({QStringLiteral("bridge"), stopLineAccount(robot), strongPassword()});
    }
    const auto passwordOf = [&accounts](const QString &name) {
        for (const Account &a : accounts)
            if (a.name == name)
                return a.password;
        return QString();
    };

    // mosquitto_passwd -U hashes a file of user:password lines in place.
    QByteArray plain;
    for (const Account &a : accounts)
        plain += (a.name + QLatin1Char(':') + a.password + QLatin1Char('\n')).toUtf8();
    if (!makeCertificates(r, w.path(), error) || !writeFile(w.filePath(QStringLiteral("passwords")), plain, kOwnerOnly, error)
        || !run(program("mosquitto_passwd"), {QStringLiteral("-U"), QStringLiteral("passwords")}, w.path(), error)
        || !writeFile(w.filePath(QStringLiteral("acl")), files::acl(r), kOwnerOnly, error)
        || !writeFile(w.filePath(QStringLiteral("mosquitto.conf")), files::brokerConfig(r, finalDir, broker->name), kEveryoneReads, error)
        || !writeFile(w.filePath(QStringLiteral("accounts.txt")), files::accountsText(r, accounts), kOwnerOnly, error))
        return std::nullopt;
    if (!w.mkdir(QStringLiteral("bridges"))
        || !QFile::copy(w.filePath(QStringLiteral("ca.crt")), w.filePath(QStringLiteral("bridges/ca.crt")))) {
        *error = QStringLiteral("cannot write %1").arg(w.filePath(QStringLiteral("bridges")));
        return std::nullopt;
    }
    for (const QString &robot : r.robots)
        if (!writeFile(w.filePath(QStringLiteral("bridges/%1.conf").arg(robot)),
                       files::bridgeConfig(r, robot, passwordOf(bridgeAccount(robot)), passwordOf(stopLineAccount(robot))),
                       kOwnerOnly, error))
            return std::nullopt;
    // One file per student, each with a robot of its own in turn (r1, r2, ..., r1 again).
    QFile ca(w.filePath(QStringLiteral("ca.crt")));
    if (!w.mkdir(QStringLiteral("students")) || !ca.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot write %1").arg(w.filePath(QStringLiteral("students")));
        return std::nullopt;
    }
    const QByteArray caPem = ca.readAll();
    for (qsizetype i = 0; i < r.students.size(); ++i)
        if (!writeFile(w.filePath(QStringLiteral("students/%1.json").arg(r.students[i])),
                       files::connectionFile(r, r.students[i], passwordOf(r.students[i]), r.robots[i % r.robots.size()], caPem),
                       kOwnerOnly, error))
            return std::nullopt;
    QFile::setPermissions(work.path(), kOwnerOnly | QFileDevice::ExeOwner);
    if (broker->handOver && !handOver(w, *broker, error))
        return std::nullopt;
    // An empty target gives way to the finished folder; a rename is all or nothing.
    if (QFileInfo::exists(finalDir) && !QDir().rmdir(finalDir)) {
        *error = QStringLiteral("cannot replace the empty folder %1").arg(finalDir);
        return std::nullopt;
    }
    if (!QDir().rename(work.path(), finalDir)) {
        *error = QStringLiteral("cannot move the classroom into %1").arg(finalDir);
        return std::nullopt;
    }
    work.setAutoRemove(false);
    return accounts;
}

} // namespace classroom
