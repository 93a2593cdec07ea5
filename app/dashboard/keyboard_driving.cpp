// SPDX-License-Identifier: GPL-3.0-or-later
#include "keyboard_driving.h"

#include "teleop_controller.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>

namespace {

// Widgets where letters, arrows and Space are typing, not driving.
bool isTextInput(const QWidget *w)
{
    return qobject_cast<const QLineEdit *>(w) || qobject_cast<const QAbstractSpinBox *>(w)
        || qobject_cast<const QTextEdit *>(w) || qobject_cast<const QPlainTextEdit *>(w);
}

// W A S D fold onto the arrows; 0 for any other key.
int driveKey(int key)
{
    switch (key) {
    case Qt::Key_Up: case Qt::Key_W: return Qt::Key_Up;
    case Qt::Key_Down: case Qt::Key_S: return Qt::Key_Down;
    case Qt::Key_Left: case Qt::Key_A: return Qt::Key_Left;
    case Qt::Key_Right: case Qt::Key_D: return Qt::Key_Right;
    default: return 0;
    }
}

} // namespace

KeyboardDriving::KeyboardDriving(QWidget *window, QWidget *quietZone, QObject *parent)
    : QObject(parent), m_window(window), m_quietZone(quietZone)
{
    qApp->installEventFilter(this);
}

KeyboardDriving::~KeyboardDriving()
{
    qApp->removeEventFilter(this);
}

void KeyboardDriving::setTarget(std::function<TeleopController *()> teleop, std::function<int()> speedLimit)
{
    m_teleop = std::move(teleop);
    m_speedLimit = std::move(speedLimit);
}

bool KeyboardDriving::eventFilter(QObject *watched, QEvent *event)
{
    const QEvent::Type type = event->type();
    if ((type != QEvent::KeyPress && type != QEvent::KeyRelease) || !watched->isWidgetType()
        || static_cast<QWidget *>(watched)->window() != m_window || !m_teleop)
        return false;
    auto *key = static_cast<QKeyEvent *>(event);
    TeleopController *teleop = m_teleop();
    // Shift+Esc stops every robot in the window, whatever is selected.
    if (key->key() == Qt::Key_Escape && key->modifiers() == Qt::ShiftModifier) {
        if (type == QEvent::KeyPress && !key->isAutoRepeat()) {
            m_held.clear();
            emit stopAllRequested();
        }
        return true;
    }
    // Esc always stops the selected robot. Space does too, except where it
    // already means something: inside the plots it pauses them, and in a
    // text field it types a space.
    const QWidget *focus = QApplication::focusWidget();
    const bool stopKey = key->key() == Qt::Key_Escape
        || (key->key() == Qt::Key_Space && !isTextInput(focus)
            && !(focus && m_quietZone && (focus == m_quietZone || m_quietZone->isAncestorOf(focus))));
    if (stopKey && key->modifiers() == Qt::NoModifier) {
        if (type == QEvent::KeyPress && !key->isAutoRepeat()) {
            m_held.clear();
            if (teleop)
                teleop->stopAll();
            if (key->key() == Qt::Key_Escape)
                emit escapePressed();
        }
        return true;
    }
    return handleDriveKey(key);
}

bool KeyboardDriving::handleDriveKey(QKeyEvent *event)
{
    const int key = driveKey(event->key());
    TeleopController *teleop = m_teleop();
    if (!key || !teleop)
        return false;
    if (event->type() == QEvent::KeyRelease) {
        // A held key is always let go, wherever the focus went meanwhile.
        if (!m_held.contains(key))
            return false;
        if (event->isAutoRepeat())
            return true;
        m_held.remove(key);
        const MotionCommand motion = command();
        if (motion.isStop())
            teleop->deadManReleased();
        else
            teleop->requestMotion(motion);
        return true;
    }
    if (event->isAutoRepeat())
        return m_held.contains(key);
    if ((event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        || isTextInput(QApplication::focusWidget()))
        return false;
    m_held.insert(key);
    teleop->requestMotion(command());
    return true;
}

MotionCommand KeyboardDriving::command() const
{
    const int speed = m_speedLimit ? m_speedLimit() : 0;
    const int ahead = int(m_held.contains(Qt::Key_Up)) - int(m_held.contains(Qt::Key_Down));
    const int left = int(m_held.contains(Qt::Key_Left)) - int(m_held.contains(Qt::Key_Right));
    MotionCommand motion;
    if (ahead != 0) {
        motion.velocity = ahead * speed;
        if (left != 0)
            motion.radius = left * kArcRadius; // positive radius turns left
    } else if (left != 0) {
        motion.velocity = speed;
        motion.radius = left > 0 ? oi::kRadiusTurnInPlaceCounterClockwise : oi::kRadiusTurnInPlaceClockwise;
    }
    return motion;
}
