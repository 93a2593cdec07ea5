// SPDX-License-Identifier: GPL-3.0-or-later
#include "page_folder.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>

namespace classroom {

namespace {

PageFolder::Reply plain(int status, const QString &text)
{
    return {status, QByteArrayLiteral("text/plain; charset=utf-8"), (text + QLatin1Char('\n')).toUtf8()};
}

} // namespace

PageFolder::PageFolder(QString folder) : m_folder(QDir(folder).absolutePath()) {}

QString PageFolder::defaultFolder()
{
    // Run from the build tree, the page the build put there.
    const QString build = QDir(QStringLiteral(ROOMBA_BUILD_DIR)).canonicalPath();
    if (!build.isEmpty() && QDir(QCoreApplication::applicationDirPath()).canonicalPath().startsWith(build + QLatin1Char('/')))
        return QStringLiteral(ROOMBA_BUILD_DIR "/web/blocks");
    return QStringLiteral(ROOMBA_BLOCKS_PAGE_INSTALLED);
}

bool PageFolder::isInstalled() const
{
    return QFileInfo(QDir(m_folder).filePath(QStringLiteral("index.html"))).isFile();
}

QByteArray PageFolder::contentType(const QString &fileName)
{
    static const QHash<QString, QByteArray> types{
        {QStringLiteral("html"), "text/html; charset=utf-8"},
        {QStringLiteral("js"), "text/javascript; charset=utf-8"},
        {QStringLiteral("mjs"), "text/javascript; charset=utf-8"},
        {QStringLiteral("css"), "text/css; charset=utf-8"},
        {QStringLiteral("json"), "application/json"},
        {QStringLiteral("map"), "application/json"},
        {QStringLiteral("txt"), "text/plain; charset=utf-8"},
        {QStringLiteral("svg"), "image/svg+xml"},
        {QStringLiteral("png"), "image/png"},
        {QStringLiteral("jpg"), "image/jpeg"},
        {QStringLiteral("jpeg"), "image/jpeg"},
        {QStringLiteral("gif"), "image/gif"},
        {QStringLiteral("ico"), "image/x-icon"},
        {QStringLiteral("cur"), "image/x-icon"},
        {QStringLiteral("woff2"), "font/woff2"},
        {QStringLiteral("woff"), "font/woff"},
        {QStringLiteral("wasm"), "application/wasm"},
        {QStringLiteral("mp3"), "audio/mpeg"},
        {QStringLiteral("wav"), "audio/wav"},
        {QStringLiteral("ogg"), "audio/ogg"},
    };
    return types.value(QFileInfo(fileName).suffix().toLower(), QByteArrayLiteral("application/octet-stream"));
}

PageFolder::Reply PageFolder::get(const QByteArray &target) const
{
    if (!isInstalled())
        return {503, QByteArrayLiteral("text/html; charset=utf-8"),
                QStringLiteral("<!doctype html><meta charset=utf-8><title>Blocks page not installed</title>\n"
                               "<h1>The blocks page is not installed</h1>\n"
                               "<p>roomba-classroom serve looks for it in %1, which has no index.html. "
                               "Install the page (or build it), or name its folder with serve --page DIR.</p>\n")
                    .arg(m_folder.toHtmlEscaped())
                    .toUtf8()};
    QByteArray path = target;
    if (const qsizetype end = path.indexOf('?'); end >= 0)
        path.truncate(end);
    if (!path.startsWith('/'))
        return plain(400, QStringLiteral("a path starts with /"));
    // An encoded slash, backslash or NUL could walk where a plain one may not.
    const QByteArray lower = path.toLower();
    for (const char *encoded : {"%2f", "%5c", "%00"})
        if (lower.contains(encoded))
            return plain(400, QStringLiteral("no encoded slashes, backslashes or NULs in a path"));
    const QString decoded = QString::fromUtf8(QByteArray::fromPercentEncoding(path));
    if (decoded.contains(QLatin1Char('\\')) || decoded.contains(QChar(0)))
        return plain(400, QStringLiteral("no backslashes in a path"));
    QStringList parts = decoded.split(QLatin1Char('/'), Qt::SkipEmptyParts);
    for (const QString &part : parts)
        if (part.startsWith(QLatin1Char('.')))
            return plain(part == QLatin1String("..") ? 400 : 404,
                         part == QLatin1String("..") ? QStringLiteral("no .. in a path") : QStringLiteral("not found"));
    const QString root = QDir(m_folder).canonicalPath();
    QFileInfo file(QDir(root).filePath(parts.join(QLatin1Char('/'))));
    if (file.isDir())
        file.setFile(QDir(file.filePath()).filePath(QStringLiteral("index.html")));
    // Whatever the name, the file itself must lie inside: a symbolic link out is not served.
    const QString real = file.canonicalFilePath();
    if (real.isEmpty() || !file.isFile())
        return plain(404, QStringLiteral("not found"));
    if (!real.startsWith(root + QLatin1Char('/')))
        return plain(403, QStringLiteral("not served: it lies outside the page's folder"));
    if (file.size() > kMaxFileBytes)
        return plain(500, QStringLiteral("too large to serve"));
    QFile f(real);
    if (!f.open(QIODevice::ReadOnly))
        return plain(403, QStringLiteral("cannot be read"));
    return {200, contentType(real), f.readAll()};
}

} // namespace classroom
