// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QTimeEdit>

#include <optional>

// A time box that takes a time typed whole ("15:30", "1530", "3:30 pm"),
// wherever its cursor is and whatever the locale's display (12 or 24
// hours): QTimeEdit alone types into the section under the cursor, so
// "15:30" typed in the minutes gives 00:30, and a 12-hour display takes no
// hour above 12. Arrows and the mouse wheel step sections as before.
class TypedTimeEdit : public QTimeEdit {
    Q_OBJECT
public:
    explicit TypedTimeEdit(QWidget *parent = nullptr);

    // The time `typed` means, if any: hours and minutes with or without a
    // separator, then "am"/"pm" (or a letter of it) for a 12-hour time.
    static std::optional<QTime> parseTyped(const QString &typed);

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void focusInEvent(QFocusEvent *event) override;
    void focusOutEvent(QFocusEvent *event) override;

private:
    QString m_typed; // what was typed since the box took focus or its last arrow step
};
