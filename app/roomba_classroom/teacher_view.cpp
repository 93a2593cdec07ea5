// SPDX-License-Identifier: GPL-3.0-or-later
#include "teacher_view.h"

#include "classroom_dir.h"
#include "hub_log.h"
#include "run_table.h"
#include "sign_in_limits.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

namespace classroom {

namespace {

// The teacher's password as init wrote it: "teacher  NAME  PASSWORD".
QByteArray teacherPassword(const ClassroomDir &c)
{
    QFile f(QDir(c.path()).filePath(QStringLiteral("accounts.txt")));
    if (c.teacher().isEmpty() || !f.open(QIODevice::ReadOnly))
        return {};
    for (const QByteArray &line : f.readAll().split('\n')) {
        const QList<QByteArray> words = line.simplified().split(' ');
        if (words.size() == 3 && words[0] == "teacher" && words[1] == c.teacher().toUtf8())
            return words[2];
    }
    return {};
}

// Compares every byte whatever the first difference, so that the time
// taken tells a guesser nothing.
bool sameSecret(const QByteArray &a, const QByteArray &b)
{
    if (a.size() != b.size())
        return false;
    unsigned char differ = 0;
    for (qsizetype i = 0; i < a.size(); ++i)
        differ |= static_cast<unsigned char>(a[i] ^ b[i]);
    return differ == 0;
}

} // namespace

bool TeacherView::isTeacher(const QByteArray &authorization) const
{
    const QByteArray credentials = QByteArray::fromBase64(authorization.mid(6));
    const qsizetype colon = credentials.indexOf(':');
    const QByteArray password = teacherPassword(m_classroom);
    return !password.isEmpty() && colon > 0 && credentials.left(colon) == m_classroom.teacher().toUtf8()
           && sameSecret(credentials.mid(colon + 1), password);
}

PageFolder::Reply TeacherView::answer(Form form, const QByteArray &authorization, const QString &peer) const
{
    const QByteArray challenge = "WWW-Authenticate: Basic realm=\"the teacher of this classroom\", charset=\"UTF-8\"\r\n";
    if (!authorization.startsWith("Basic "))
        return PageFolder::Reply::plain(401, QStringLiteral("The teacher's account (%1) and its password from accounts.txt.").arg(m_classroom.teacher()),
                     challenge);
    if (const int wait = m_failed.secondsToWait(peer); wait > 0)
        return PageFolder::Reply::plain(429, QStringLiteral("Too many tries: try again in %1 s.").arg(wait),
                     "Retry-After: " + QByteArray::number(wait) + "\r\n");
    if (!isTeacher(authorization)) {
        m_failed.failed(peer);
        hubLog(QStringLiteral("the teacher's view refused %1: not the teacher's account and password").arg(peer));
        return PageFolder::Reply::plain(401, QStringLiteral("Not the teacher's account and password."), challenge);
    }
    if (form == Form::Json)
        return {200, QByteArrayLiteral("application/json"),
                QJsonDocument(QJsonObject{{QStringLiteral("runs"), m_runs.toJson()}}).toJson(QJsonDocument::Compact), {}};
    return {200, QByteArrayLiteral("text/html; charset=utf-8"), html(), {}};
}

QByteArray TeacherView::html() const
{
    QString rows;
    for (const RunTable::Run &r : m_runs.runs())
        rows += QStringLiteral("<tr><td>%1<td>%2<td>%3<td><pre>%4</pre>\n")
                    .arg(r.user.toHtmlEscaped(), r.robot.toHtmlEscaped(),
                         r.since.toLocalTime().toString(QStringLiteral("HH:mm:ss")), r.firstLines.toHtmlEscaped());
    const QString table = rows.isEmpty() ? QStringLiteral("<p>Nobody runs a program.</p>")
                                         : QStringLiteral("<table><tr><th>Student<th>Robot<th>Since<th>Program\n%1</table>")
                                               .arg(rows);
    return QStringLiteral("<!doctype html><meta charset=utf-8><meta http-equiv=refresh content=%1>"
                          "<title>Who runs what</title>\n"
                          "<style>body{font-family:sans-serif}td,th{text-align:left;padding:.2em 1em;vertical-align:top}"
                          "pre{margin:0}</style>\n<h1>Who runs what</h1>\n%2\n")
        .arg(kRefreshSeconds)
        .arg(table)
        .toUtf8();
}

} // namespace classroom
