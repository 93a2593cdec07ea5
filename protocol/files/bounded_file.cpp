// SPDX-License-Identifier: GPL-3.0-or-later
#include "bounded_file.h"

#include <QCoreApplication>
#include <QSettings>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace files {

namespace {

// The messages' context for translators.
struct BoundedFile {
    Q_DECLARE_TR_FUNCTIONS(BoundedFile)
};

void setError(QString *error, const QString &message)
{
    if (error)
        *error = message;
}

QString kindOf(mode_t mode)
{
    if (S_ISFIFO(mode))
        return BoundedFile::tr("not a regular file but a named pipe");
    if (S_ISDIR(mode))
        return BoundedFile::tr("not a regular file but a folder");
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return BoundedFile::tr("not a regular file but a device");
    return BoundedFile::tr("not a regular file");
}

} // namespace

bool openBounded(QFile &file, const QString &path, qint64 maxBytes, QString *error, QIODevice::OpenMode mode)
{
    // A resource (":/lessons/…") is the program's own, built into it.
    if (path.startsWith(QLatin1Char(':'))) {
        file.setFileName(path);
        if (file.open(mode))
            return true;
        setError(error, file.errorString());
        return false;
    }
    // Without blocking, so that a named pipe with no writer is refused, not
    // waited on; the check is made on what was opened, so nothing can be
    // put in the file's place between the check and the reading.
    const int access = mode & QIODevice::WriteOnly ? O_RDWR : O_RDONLY;
    const int fd = ::open(QFile::encodeName(path).constData(), access | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        setError(error, QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    struct stat st {};
    QString why;
    if (::fstat(fd, &st) != 0)
        why = QString::fromLocal8Bit(std::strerror(errno));
    else if (!S_ISREG(st.st_mode))
        why = kindOf(st.st_mode);
    else if (st.st_size > maxBytes)
        // In bytes where the rounded sizes would read the same.
        why = BoundedFile::tr("%1, larger than the %2 this program reads of such a file")
                  .arg(sizeText(st.st_size) != sizeText(maxBytes) ? sizeText(st.st_size)
                                                                  : BoundedFile::tr("%1 bytes").arg(st.st_size),
                       sizeText(maxBytes));
    else if (::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK) != 0
             || !file.open(fd, mode, QFileDevice::AutoCloseHandle))
        why = file.errorString();
    else
        return true;
    ::close(fd);
    setError(error, why);
    return false;
}

std::optional<QByteArray> readBounded(const QString &path, qint64 maxBytes, QString *error)
{
    QFile file;
    if (!openBounded(file, path, maxBytes, error))
        return std::nullopt;
    // One byte more than the limit tells a file that grew after the check.
    QByteArray bytes = file.read(maxBytes + 1);
    if (bytes.size() > maxBytes) {
        setError(error, BoundedFile::tr("larger than the %1 this program reads of such a file").arg(sizeText(maxBytes)));
        return std::nullopt;
    }
    if (file.error() != QFileDevice::NoError) {
        setError(error, file.errorString());
        return std::nullopt;
    }
    return bytes;
}

int beginReadBoundedArray(QSettings &settings, const QString &prefix, int max)
{
    const int size = settings.beginReadArray(prefix);
    if (size <= max)
        return size;
    qWarning("%s: %s/size is %d; the first %d are read", qPrintable(settings.fileName()), qPrintable(prefix), size, max);
    return max;
}

QString sizeText(qint64 bytes)
{
    const auto scaled = [&](double unit, const char *name) {
        QString number = QString::number(double(bytes) / unit, 'f', 1);
        if (number.endsWith(QLatin1String(".0")))
            number.chop(2);
        return QStringLiteral("%1 %2").arg(number, QLatin1String(name));
    };
    if (bytes >= qint64(1) << 30)
        return scaled(double(qint64(1) << 30), "GB");
    if (bytes >= 1 << 20)
        return scaled(1 << 20, "MB");
    if (bytes >= 1 << 10)
        return scaled(1 << 10, "KB");
    return BoundedFile::tr("%1 bytes").arg(bytes);
}

} // namespace files
