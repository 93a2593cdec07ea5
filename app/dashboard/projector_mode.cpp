// SPDX-License-Identifier: GPL-3.0-or-later
#include "projector_mode.h"

#include "projector_view.h"

#include <QAction>
#include <QApplication>
#include <QWidget>

ProjectorMode::ProjectorMode(QWidget *window, const LessonRunner *lesson,
                             std::function<void(ProjectorView *)> made)
    : QObject(window), m_window(window), m_lesson(lesson), m_made(std::move(made))
{
    m_action = new QAction(this);
    m_action->setObjectName("projectorAction");
    m_action->setCheckable(true);
    m_action->setShortcut(QKeySequence(Qt::Key_F11));
    // On the window itself too, so the key works while the view hides the menus.
    window->addAction(m_action);
    connect(m_action, &QAction::toggled, this, &ProjectorMode::setOn);
    retranslate();
}

ProjectorView *ProjectorMode::view()
{
    if (!m_view) {
        m_view = new ProjectorView(m_window);
        m_view->setLesson(m_lesson);
        m_made(m_view);
    }
    return m_view;
}

bool ProjectorMode::isOn() const { return m_view && m_view->isVisible(); }

void ProjectorMode::setOn(bool on)
{
    m_action->setChecked(on);
    if (on == (m_view && !m_view->isHidden()))
        return;
    if (on) {
        m_stateBefore = m_window->windowState();
        m_focusBefore = QApplication::focusWidget();
        view()->setGeometry(m_window->rect());
        m_view->show();
        m_view->raise();
        // Keys typed now must not land in a text field hidden under the view.
        m_view->setFocus(Qt::OtherFocusReason);
        m_window->setWindowState(m_stateBefore | Qt::WindowFullScreen);
    } else {
        m_view->hide();
        m_window->setWindowState(m_stateBefore & ~Qt::WindowFullScreen);
        if (m_focusBefore)
            m_focusBefore->setFocus(Qt::OtherFocusReason);
    }
}

void ProjectorMode::retranslate()
{
    m_action->setText(tr("&Projector view"));
    m_action->setToolTip(tr("Large type, high contrast, the selected robot or the lesson alone (F11)"));
}

#include "moc_projector_mode.cpp"
