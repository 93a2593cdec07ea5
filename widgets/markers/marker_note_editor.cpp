// SPDX-License-Identifier: GPL-3.0-or-later
#include "marker_note_editor.h"

#include "recording_markers.h"

#include <QApplication>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>

MarkerNoteEditor::MarkerNoteEditor(QWidget *parent) : QWidget(parent)
{
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(4, 0, 4, 0);
    m_label = new QLabel(this);
    m_label->setObjectName("markerNoteLabel");
    m_label->setTextFormat(Qt::PlainText); // a note from a recording, as written
    m_field = new QLineEdit(this);
    m_field->setObjectName("markerNoteField");
    m_field->setMaxLength(oilink::kMaxMarkerNoteLength);
    m_field->setMinimumWidth(220);
    m_field->setClearButtonEnabled(true);
    m_label->setBuddy(m_field);
    row->addWidget(m_label);
    row->addWidget(m_field, 1);
    connect(m_field, &QLineEdit::returnPressed, this, &MarkerNoteEditor::finish);
    m_field->installEventFilter(this);
    retranslateUi();
}

void MarkerNoteEditor::edit(int id, const QString &what)
{
    if (m_id)
        finish(); // the previous marker keeps what was typed for it
    m_id = id;
    m_label->setText(what);
    m_field->clear();
    QWidget *focus = QApplication::focusWidget();
    m_focusBefore = focus && focus != m_field ? focus : nullptr;
    emit visibilityWanted(true);
    m_field->setFocus(Qt::OtherFocusReason);
}

void MarkerNoteEditor::finish()
{
    const int id = m_id;
    if (!id)
        return;
    m_id = 0;
    const QString note = m_field->text().simplified();
    QPointer<QWidget> back = m_focusBefore;
    m_focusBefore = nullptr;
    emit visibilityWanted(false);
    if (back)
        back->setFocus(Qt::OtherFocusReason);
    if (!note.isEmpty())
        emit noteEntered(id, note);
}

bool MarkerNoteEditor::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_field && event->type() == QEvent::FocusOut)
        finish();
    return QWidget::eventFilter(watched, event);
}

void MarkerNoteEditor::retranslateUi()
{
    m_field->setPlaceholderText(tr("a short note, then Enter"));
    m_field->setToolTip(tr("The marker is already set; a note is optional"));
}

void MarkerNoteEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

#include "moc_marker_note_editor.cpp"
