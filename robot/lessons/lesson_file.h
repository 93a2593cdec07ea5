// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lesson.h"

#include <QByteArray>
#include <QString>

#include <optional>

// Lessons as files: the JSON format of lessons.md.
// The lesson in a file, or nullopt with the reason in `error`: the file's
// name, the step and the field at fault.
std::optional<Lesson> loadLessonFile(const QString &path, QString *error = nullptr);
// The same from the file's bytes; `error` names the step and field at fault.
std::optional<Lesson> lessonFromJson(const QByteArray &json, QString *error = nullptr);
