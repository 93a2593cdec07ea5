// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

// The lessons that come with the program (resources/lessons/, embedded as
// :/lessons/), and the translation of lesson texts.
namespace lesson {

// The embedded lesson files, in teaching order.
QStringList shippedLessonPaths();
// Every text of the shipped lessons, as lupdate finds them (lesson_texts.cpp).
QStringList shippedTexts();
// A lesson text in the user's language: the shipped lessons' texts are
// translated in the "Lesson" context; a teacher's own text shows as written.
QString translated(const QString &text);

} // namespace lesson
