// SPDX-License-Identifier: GPL-3.0-or-later
// Files that are no regular files, as someone might send them in place of
// one: a named pipe (opening it waits for a writer for good) and a link to
// /dev/zero (it says it is empty and never ends).
#pragma once

#include <QDir>
#include <QFile>
#include <QString>

#include <sys/stat.h>

struct NotRegularFiles {
    QString pipe;   // DIR/pipe.SUFFIX
    QString device; // DIR/zero.SUFFIX, linked to /dev/zero
};

// Makes both in `dir`; empty paths if they cannot be made.
inline NotRegularFiles makeNotRegularFiles(const QString &dir, const QString &suffix)
{
    NotRegularFiles files{QDir(dir).filePath("pipe." + suffix), QDir(dir).filePath("zero." + suffix)};
    if (::mkfifo(QFile::encodeName(files.pipe).constData(), 0600) != 0 || !QFile::link("/dev/zero", files.device))
        return {};
    return files;
}
