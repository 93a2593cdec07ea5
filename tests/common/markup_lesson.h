// SPDX-License-Identifier: GPL-3.0-or-later
// A lesson file whose texts are markup, as someone might send one: each
// holds a tag and a picture 400 px high. Shown as rich text, a label would
// open the picture and be that tall; shown as written, it is a line or two.
#pragma once

#include <QDir>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QString>
#include <QStringList>
#include <QWidget>

inline constexpr int kMarkupPicturePixels = 400;

// Writes the picture and the lesson into `dir`; the lesson's path, or empty.
inline QString writeMarkupLesson(const QString &dir)
{
    QImage picture(kMarkupPicturePixels, kMarkupPicturePixels, QImage::Format_RGB32);
    picture.fill(Qt::red);
    const QString png = QDir(dir).filePath("picture.png");
    if (!picture.save(png))
        return {};
    const QString markup = QStringLiteral(R"(<b>x</b> <img src=\"%1\">)").arg(png);
    const QString json = QStringLiteral(R"({"format":"roomba-lesson","version":1,"title":"%1","summary":"%1",)"
                                        R"("steps":[{"text":"%1","goal":{"drive_mm":500},)"
                                        R"("virtual_robot":{"label":"%1","forward_mm":10}}]})")
                             .arg(markup);
    const QString path = QDir(dir).filePath("markup.json");
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(json.toUtf8()) != json.toUtf8().size())
        return {};
    return path;
}

// The labels under `root` that show some of the lesson's markup, by name in
// alphabetical order, and, for
// each one drawn as rich text or as tall as the picture, what is wrong.
inline QStringList labelsShowingMarkup(QWidget *root, QStringList *wrong)
{
    QStringList shown;
    for (const QLabel *label : root->findChildren<QLabel *>()) {
        if (!label->isVisibleTo(root) || !label->text().contains(QLatin1String("<img")))
            continue;
        shown << label->objectName();
        if (label->textFormat() != Qt::PlainText)
            *wrong << label->objectName() + ": not shown as written";
        if (label->sizeHint().height() >= kMarkupPicturePixels)
            *wrong << label->objectName() + ": as tall as the picture";
    }
    shown.sort();
    return shown;
}
