// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QFile>
#include <QString>

#include <optional>

class QSettings;

// A file someone sent is opened only when it is a regular file no larger
// than its reader's limit, both checked before a byte is read: a named pipe
// would block the program for good, a device such as /dev/zero never ends,
// and a huge file fills the memory. A symbolic link is followed to what it
// names, which is checked the same way.
namespace files {

// Opens the file at `path` into `file` with `mode` (ReadOnly or ReadWrite),
// on the very descriptor that was checked (so `file` has no fileName()); a
// resource of the program's own (":/rooms/…") is opened as it is.
// False, with the reason in `error` and `file` left closed: it cannot be
// opened, it is not a regular file, or it is larger than `maxBytes`. The
// reason names the limit, not the file: callers put the file's name first.
bool openBounded(QFile &file, const QString &path, qint64 maxBytes, QString *error,
                 QIODevice::OpenMode mode = QIODevice::ReadOnly);

// The whole file at `path`, read as openBounded() opens it, never more than
// `maxBytes` even if it grows meanwhile; nullopt with the reason in `error`.
std::optional<QByteArray> readBounded(const QString &path, qint64 maxBytes, QString *error);

// A size as people read it: "512 bytes", "64 KB", "1 MB", "2.5 GB".
QString sizeText(qint64 bytes);

// settings.beginReadArray(prefix), and the number of its entries to read:
// its size, but at most `max`, with a warning naming the file when it says
// more. A settings file with brokers/size=100000000 kept the window from
// ever opening.
int beginReadBoundedArray(QSettings &settings, const QString &prefix, int max);

} // namespace files
