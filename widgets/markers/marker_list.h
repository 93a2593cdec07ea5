// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "recording_markers.h"

#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

// A run's markers, one row each: the time in the recording and the note.
// The note is edited in place (a rename); Delete removes the selected
// marker; Jump, Enter or a double click on the time goes there in a replay.
class MarkerList : public QWidget {
    Q_OBJECT
public:
    explicit MarkerList(QWidget *parent = nullptr);

    void setMarkers(const QList<oilink::RecordingMarker> &markers);
    const QList<oilink::RecordingMarker> &markers() const { return m_markers; }
    // Whether markers can change now (a recording runs, or a replay is open);
    // `why` says what to do when they cannot.
    void setEditable(bool editable, const QString &why = {});
    // Whether a marker can be jumped to (a replay).
    void setJumpable(bool jumpable);
    // Selects the row of marker `id`.
    void select(int id);
    int selectedId() const; // 0 for none

    QTableWidget *table() const { return m_table; }
    QPushButton *jumpButton() const { return m_jump; }
    QPushButton *deleteButton() const { return m_delete; }

signals:
    void renameRequested(int id, const QString &note);
    void deleteRequested(int id);
    void jumpRequested(int id);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void showButtons();

    QList<oilink::RecordingMarker> m_markers;
    QTableWidget *m_table = nullptr;
    QPushButton *m_jump = nullptr;
    QPushButton *m_delete = nullptr;
    QLabel *m_hint = nullptr;
    bool m_editable = false;
    bool m_jumpable = false;
    bool m_filling = false;
};
