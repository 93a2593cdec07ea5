// SPDX-License-Identifier: GPL-3.0-or-later
// A program run to its end as a script runs it: its exit status, standard
// output and standard error.
#pragma once

#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

struct ProcessRun {
    int exitCode = -1; // -1: it did not start, did not finish in time, or crashed
    QByteArray out, err;
};

// Runs `program` with `input` on its standard input, which is then closed.
inline ProcessRun runProcess(const QString &program, const QStringList &arguments, const QString &workingDirectory = {},
                             int timeoutMs = 60000, const QByteArray &input = {},
                             const QProcessEnvironment &environment = QProcessEnvironment::systemEnvironment())
{
    QProcess p;
    if (!workingDirectory.isEmpty())
        p.setWorkingDirectory(workingDirectory);
    p.setProcessEnvironment(environment);
    p.start(program, arguments);
    if (!p.waitForStarted())
        return {};
    p.write(input);
    p.closeWriteChannel();
    if (!p.waitForFinished(timeoutMs))
        p.kill();
    p.waitForFinished();
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
            p.readAllStandardError()};
}

// A line a program printed as a JSON object; an empty object when it is not one.
inline QJsonObject jsonObjectOf(const QString &line)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(line.toUtf8(), &error);
    return error.error == QJsonParseError::NoError ? doc.object() : QJsonObject();
}
