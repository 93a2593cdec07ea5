// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "page_folder.h"

#include <QByteArray>
#include <QString>

namespace classroom {

class ClassroomDir;
class FailedSignIns;
class RunTable;

// GET /teacher (a page that refreshes itself) and /teacher.json: who runs
// what, for the teacher's account alone. HTTP basic authentication with
// the password in DIR/accounts.txt, which serve, run by the teacher who
// made the classroom, reads: no MQTT connection, so the teacher's console
// keeps the account's. Failed tries count with the hub's failed sign-ins.
class TeacherView {
public:
    TeacherView(const ClassroomDir &classroom, const RunTable &runs, FailedSignIns &failedSignIns)
        : m_classroom(classroom), m_runs(runs), m_failed(failedSignIns)
    {
    }

    enum class Form { Html, Json };
    PageFolder::Reply answer(Form form, const QByteArray &authorization, const QString &peer) const;

    static constexpr int kRefreshSeconds = 5;

private:
    bool isTeacher(const QByteArray &authorization) const;
    QByteArray html() const;

    const ClassroomDir &m_classroom;
    const RunTable &m_runs;
    FailedSignIns &m_failed;
};

} // namespace classroom
