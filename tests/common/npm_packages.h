// SPDX-License-Identifier: GPL-3.0-or-later
// Readers and clients we did not write, from npm, for the tests that prove
// an export or a protocol by them: installed once into the build directory.
#pragma once

#include "process_run.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QString>
#include <QStringList>

// What installNpmPackages() found.
struct NpmInstall {
    QString error;       // a failure of the test's own making: empty when installed
    QString unreachable; // why npm could not reach its registry: the test is skipped
};

// Copies `files` from `sourceDir` into `dir` and, unless every package of
// `packages` is there already, runs npm install in it with bounded waits (a
// registry that swallows packets must not hold the test up).
inline NpmInstall installNpmPackages(const QString &dir, const QString &sourceDir, const QStringList &files,
                                     const QStringList &packages)
{
    if (QStandardPaths::findExecutable("node").isEmpty() || QStandardPaths::findExecutable("npm").isEmpty())
        return {QStringLiteral("node and npm are not installed (.ci/install-deps)"), {}};
    if (!QDir().mkpath(dir))
        return {QStringLiteral("cannot make %1").arg(dir), {}};
    for (const QString &name : files) {
        const QString to = QDir(dir).filePath(name);
        QFile::remove(to);
        if (!QFile::copy(QDir(sourceDir).filePath(name), to))
            return {QStringLiteral("cannot copy %1 into %2").arg(name, dir), {}};
    }
    const bool installed = std::all_of(packages.begin(), packages.end(), [&](const QString &package) {
        return QFile::exists(QDir(dir).filePath(QStringLiteral("node_modules/%1/package.json").arg(package)));
    });
    if (installed)
        return {};
    const ProcessRun npm = runProcess(QStringLiteral("npm"),
                                      {"install", "--no-audit", "--no-fund", "--no-save", "--fetch-timeout=30000",
                                       "--fetch-retries=1"},
                                      dir, 180000);
    if (npm.exitCode == -1)
        return {{}, QStringLiteral("no answer within 3 minutes")};
    if (npm.exitCode != 0) {
        // npm's code for a registry it cannot reach.
        for (const char *code : {"ENOTFOUND", "EAI_AGAIN", "ECONNREFUSED", "ETIMEDOUT", "ECONNRESET", "ENETUNREACH",
                                 "EHOSTUNREACH"})
            if ((npm.out + npm.err).contains(code))
                return {{}, QString::fromLatin1(code)};
        return {QString::fromUtf8(npm.err), {}};
    }
    return {};
}
