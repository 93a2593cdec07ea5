// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QPointer>

#include <functional>

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
    // The view is made the first time it is asked for (F11 at the latest):
    // until then the window has none to build and lay out. `made` wires the
    // new view to the window.
    ProjectorMode(QWidget *window, const LessonRunner *lesson, std::function<void(ProjectorView *)> made);

    QAction *action() const { return m_action; }
    ProjectorView *view();
    bool isOn() const;
    void setOn(bool on);
    void retranslate();

private:
    QWidget *m_window;
    const LessonRunner *m_lesson;
    std::function<void(ProjectorView *)> m_made;
    ProjectorView *m_view = nullptr;
    QAction *m_action;
    Qt::WindowStates m_stateBefore;
    QPointer<QWidget> m_focusBefore;
};
