// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

namespace classroom {

// The blocks page's folder, as `serve` hands it out: a GET's target is
// looked up inside it and nowhere else (no `..`, no encoded slash, no
// symbolic link out, no hidden file), with the content type of its suffix.
class PageFolder {
public:
    explicit PageFolder(QString folder);

    // The installed page, or the build tree's when serve runs from there.
    static QString defaultFolder();

    QString path() const { return m_folder; }
    bool isInstalled() const;

    struct Reply {
        int status = 200;
        QByteArray contentType;
        QByteArray body;
    };
    // The answer to GET `target` (as the request line has it, query and all).
    Reply get(const QByteArray &target) const;

    static constexpr qint64 kMaxFileBytes = 32 * 1024 * 1024;
    // By the file's suffix; application/octet-stream when unknown.
    static QByteArray contentType(const QString &fileName);

private:
    QString m_folder;
};

} // namespace classroom
