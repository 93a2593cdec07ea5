// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QPointer>

class LessonRunner;
class ProjectorView;
class QAction;
class QWidget;

// The window in and out of the projector view with one key (F11): the view
// covers the window, which goes full screen, and comes back as it was. The
// window's own keys keep working under it: Space and Esc stop the robot.
class ProjectorMode : public QObject {
    Q_OBJECT
public:
    ProjectorMode(QWidget *window, const LessonRunner *lesson);

    QAction *action() const { return m_action; }
    ProjectorView *view() const { return m_view; }
    bool isOn() const;
    void setOn(bool on);
    void retranslate();

private:
    QWidget *m_window;
    ProjectorView *m_view;
    QAction *m_action;
    Qt::WindowStates m_stateBefore;
    QPointer<QWidget> m_focusBefore;
};
