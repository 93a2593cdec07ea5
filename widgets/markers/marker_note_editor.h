// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QLabel;
class QLineEdit;

// The note of a marker just dropped, typed where it shows (a toolbar), never
// in a dialog: driving goes on meanwhile. Enter keeps the note; leaving the
// field keeps what was typed; an empty note leaves the marker without one.
class MarkerNoteEditor : public QWidget {
    Q_OBJECT
public:
    explicit MarkerNoteEditor(QWidget *parent = nullptr);

    // Shows the editor for marker `id`, labelled `what` ("Marker #3 at 0:12.5"),
    // with the focus in its field. Where the focus was comes back after.
    void edit(int id, const QString &what);
    int markerId() const { return m_id; } // 0 while hidden
    QLineEdit *field() const { return m_field; }

signals:
    void noteEntered(int id, const QString &note);
    // Shown or hidden: the toolbar that holds it shows or hides its place.
    void visibilityWanted(bool visible);

protected:
    void changeEvent(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void finish();
    void retranslateUi();

    QLabel *m_label = nullptr;
    QLineEdit *m_field = nullptr;
    QWidget *m_focusBefore = nullptr;
    int m_id = 0;
};
