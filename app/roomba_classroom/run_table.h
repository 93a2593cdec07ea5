// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDateTime>
#include <QJsonArray>
#include <QList>
#include <QObject>
#include <QString>

namespace classroom {

// The teacher's view of who runs what: a row per program a student's page
// said it runs (`running`) until it says it ended (`ended`), or the page
// goes. Each change is a line on standard output.
class RunTable : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    struct Run {
        QString user, robot;
        QDateTime since;
        QString firstLines; // the program's first lines, bounded
        const void *owner;  // the page that said so
    };

    // A new run replaces the one `user` had on `robot`.
    void running(const void *owner, const QString &user, const QString &robot, const QString &program);
    // False if `user` runs nothing on `robot`.
    bool ended(const QString &user, const QString &robot, const QString &why);
    // Every run `owner` started, as its page went.
    void endAll(const void *owner, const QString &why);

    const QList<Run> &runs() const { return m_runs; }
    // [{"user", "robot", "since" (ISO 8601, UTC), "program"}, ...]
    QJsonArray toJson() const;

    static constexpr int kFirstLines = 3;
    static constexpr int kLineChars = 120;

signals:
    void changed();

private:
    QList<Run> m_runs;
};

} // namespace classroom
