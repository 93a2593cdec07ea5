// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot_marker.h"

#include <QList>
#include <QObject>
#include <QPointer>

class LessonRunner;
class MarkerList;
class MarkerNoteEditor;
class QAction;
class QToolBar;
class ReplayBar;
class RobotFleet;
class RobotSession;
class SensorPlots;

// Markers on the selected robot's run: M (and the toolbar's button) drops
// one on the frame on screen, with an optional note typed in the toolbar
// while driving goes on; the markers list renames, deletes and jumps; comma
// and full stop jump to the previous and next marker in a replay. The plots
// draw them as lines, the replay bar as ticks.
class MarkerActions : public QObject {
    Q_OBJECT
public:
    MarkerActions(RobotFleet &fleet, SensorPlots *plots, ReplayBar *replayBar, QToolBar *toolBar,
                  QWidget *parent);

    QAction *dropAction() const { return m_drop; }
    QAction *previousAction() const { return m_previous; }
    QAction *nextAction() const { return m_next; }
    MarkerList *list() const { return m_list; }
    MarkerNoteEditor *noteEditor() const { return m_noteEditor; }

    // Drops a marker on the selected robot now and offers its note; its id,
    // or 0 (and a message saying why).
    int drop();
    // Each step of a lesson done while the selected robot records drops a
    // marker naming the step, so the recording shows where it happened.
    void markStepsOf(const LessonRunner &runner);
    void retranslate();

signals:
    void message(const QString &text);

private:
    void follow(RobotSession *robot);
    void show();
    void jumpTo(int id);
    void jumpBy(int direction);

    RobotFleet &m_fleet;
    SensorPlots *m_plots;
    ReplayBar *m_replayBar;
    QAction *m_drop = nullptr;
    QAction *m_previous = nullptr;
    QAction *m_next = nullptr;
    QAction *m_noteEditorAction = nullptr;
    MarkerList *m_list = nullptr;
    MarkerNoteEditor *m_noteEditor = nullptr;
    QPointer<RobotSession> m_noteRobot; // whose marker the note is for
    QString m_leftOutSaidFor;           // the file whose markers left out were last told
    QList<QMetaObject::Connection> m_followed;
};
