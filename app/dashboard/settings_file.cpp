// SPDX-License-Identifier: GPL-3.0-or-later
#include "settings_file.h"

#include <QApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMainWindow>
#include <QSettings>
#include <QStatusBar>
#include <QStringDecoder>
#include <QTimer>

#include <cstdio>

namespace SettingsFile {

namespace {

// QSettings reads almost any bytes as some keys; the files it writes are
// UTF-8 text without control characters other than line ends and tabs.
bool looksLikeText(const QByteArray &bytes)
{
    for (char c : bytes)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\r' && c != '\t')
            return false;
    QStringDecoder utf8(QStringDecoder::Utf8);
    [[maybe_unused]] const QString text = utf8.decode(bytes);
    return !utf8.hasError();
}

// Why the file cannot be used, or empty.
QString problem(QSettings &settings)
{
    QFile file(settings.fileName());
    if (settings.status() == QSettings::FormatError || (file.open(QIODevice::ReadOnly) && !looksLikeText(file.readAll())))
        return QCoreApplication::translate("SettingsFile", "file damaged");
    if (settings.status() == QSettings::AccessError)
        return QCoreApplication::translate("SettingsFile", "file unreadable");
    const QVariant version = settings.value(kVersionKey);
    if (version.isValid() && version.toString() != QString::number(kVersion))
        return QCoreApplication::translate("SettingsFile", "settings version %1, not %2").arg(version.toString()).arg(kVersion);
    return {};
}

} // namespace

Check check()
{
    Check result;
    QString path;
    QString why;
    {
        QSettings settings;
        path = settings.fileName();
        if (!QFile::exists(path))
            return result;
        why = problem(settings);
        if (why.isEmpty()) {
            if (!settings.contains(kVersionKey))
                settings.setValue(kVersionKey, kVersion);
            return result;
        }
    }
    // Renamed, or copied where it cannot be renamed; never left to be overwritten unseen.
    const QString stem = QStringLiteral("%1.bad-%2").arg(path, QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss"));
    QString aside = stem;
    for (int n = 2; QFile::exists(aside); ++n)
        aside = QStringLiteral("%1-%2").arg(stem).arg(n);
    if (!QFile::rename(path, aside) && !(QFile::copy(path, aside) && QFile::remove(path))) {
        result.notice = QCoreApplication::translate("SettingsFile", "Settings not loaded (%1) and not kept aside: %2").arg(why, QDir::toNativeSeparators(path));
        return result;
    }
    result.keptAs = aside;
    // Short enough for the status bar; the full path goes to standard error.
    result.notice = QCoreApplication::translate("SettingsFile", "Settings reset to defaults: %1; kept as %2").arg(why, QFileInfo(aside).fileName());
    QSettings fresh;
    fresh.clear(); // forget what an earlier QSettings read from the old file
    fresh.setValue(kVersionKey, kVersion);
    return result;
}

void checkAtStart()
{
    const Check result = check();
    if (result.notice.isEmpty())
        return;
    std::fprintf(stderr, "roomba-dashboard: %s\n", qPrintable(result.keptAs.isEmpty() ? result.notice
                                                          : result.notice + " (" + QDir::toNativeSeparators(result.keptAs) + ")"));
    QTimer::singleShot(0, qApp, [notice = result.notice] {
        for (QWidget *w : QApplication::topLevelWidgets())
            if (auto *window = qobject_cast<QMainWindow *>(w))
                window->statusBar()->showMessage(notice);
    });
}

} // namespace SettingsFile
