// SPDX-License-Identifier: GPL-3.0-or-later
#include "typed_time_edit.h"

#include <QKeyEvent>
#include <QRegularExpression>

TypedTimeEdit::TypedTimeEdit(QWidget *parent) : QTimeEdit(parent) {}

std::optional<QTime> TypedTimeEdit::parseTyped(const QString &typed)
{
    static const QRegularExpression time(
        QStringLiteral("^\\s*(\\d{1,2})(?:\\s*[:.h]\\s*(\\d{0,2})|(\\d{2}))?\\s*(a|am|a\\.m\\.|p|pm|p\\.m\\.)?\\s*$"),
        QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch m = time.match(typed);
    if (!m.hasMatch())
        return std::nullopt;
    int hour = m.captured(1).toInt();
    const QString minutes = m.captured(2).isEmpty() ? m.captured(3) : m.captured(2);
    const int minute = minutes.toInt();
    const QString half = m.captured(4).toLower();
    if (!half.isEmpty()) {
        if (hour < 1 || hour > 12)
            return std::nullopt;
        hour = hour % 12 + (half.startsWith('p') ? 12 : 0);
    }
    if (hour > 23 || minute > 59)
        return std::nullopt;
    return QTime(hour, minute);
}

void TypedTimeEdit::keyPressEvent(QKeyEvent *event)
{
    const QString text = event->text();
    const bool typing = !text.isEmpty() && !(event->modifiers() & (Qt::ControlModifier | Qt::AltModifier))
                        && (text.at(0).isDigit() || text.at(0).isLetter() || text == ":" || text == "."
                            || (text == " " && !m_typed.isEmpty()));
    if (typing) {
        // A prefix of a time is kept while typing goes on: "1", "15", "15:",
        // "15:3"; a key that cannot go on from there starts a new time.
        static const QRegularExpression prefix(QStringLiteral("^\\d{1,2}(\\s*[:.h]?\\s*\\d{0,2})?\\s*[apm.]*$"),
                                               QRegularExpression::CaseInsensitiveOption);
        const QString next = prefix.match(m_typed + text).hasMatch() ? m_typed + text : text;
        event->accept();
        if (!prefix.match(next).hasMatch())
            return; // not a time: the box keeps what it shows
        m_typed = next;
        if (const std::optional<QTime> t = parseTyped(m_typed))
            setTime(*t);
        return;
    }
    if (event->key() == Qt::Key_Backspace && !m_typed.isEmpty()) {
        m_typed.chop(1);
        if (const std::optional<QTime> t = parseTyped(m_typed))
            setTime(*t);
        event->accept();
        return;
    }
    // Anything else (arrows, Tab, Enter) ends the typed time.
    m_typed.clear();
    QTimeEdit::keyPressEvent(event);
}

void TypedTimeEdit::focusInEvent(QFocusEvent *event)
{
    m_typed.clear();
    QTimeEdit::focusInEvent(event);
}

void TypedTimeEdit::focusOutEvent(QFocusEvent *event)
{
    m_typed.clear();
    QTimeEdit::focusOutEvent(event);
}

#include "moc_typed_time_edit.cpp"
