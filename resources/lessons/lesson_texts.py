#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes robot/lessons/lesson_texts.cpp: every text of the shipped lessons,
# marked for lupdate in the "Lesson" context. Run it after changing a lesson
# here, then `cmake --build build --target update_translations`.
# tst_lessons fails while a shipped text is missing from that file.
import json
import pathlib

here = pathlib.Path(__file__).resolve().parent
texts = []
for path in sorted(here.glob("*.json")):
    lesson = json.loads(path.read_text(encoding="utf-8"))
    labels = [s["virtual_robot"]["label"] for s in lesson["steps"] if "virtual_robot" in s]
    for text in [lesson["title"], lesson.get("summary")] + [s["text"] for s in lesson["steps"]] + labels:
        if text and text.strip() not in texts:
            texts.append(text.strip())


def literal(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


lines = [
    "// SPDX-License-Identifier: GPL-3.0-or-later",
    "// Written by resources/lessons/lesson_texts.py from the shipped lessons: do not edit.",
    '#include "shipped_lessons.h"',
    "",
    "#include <QtGlobal>",
    "",
    "QStringList lesson::shippedTexts()",
    "{",
    "    static const char *const texts[] = {",
]
lines += ['        QT_TRANSLATE_NOOP("Lesson", %s),' % literal(t) for t in texts]
lines += [
    "    };",
    "    QStringList out;",
    "    for (const char *text : texts)",
    "        out << QString::fromUtf8(text);",
    "    return out;",
    "}",
    "",
]
out = here.parent.parent / "robot" / "lessons" / "lesson_texts.cpp"
out.write_text("\n".join(lines), encoding="utf-8")
