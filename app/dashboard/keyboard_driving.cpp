// SPDX-License-Identifier: GPL-3.0-or-later
#include "keyboard_driving.h"

#include "teleop_controller.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>

#include <algorithm>

namespace {

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

bool withCommandModifier(const QKeyEvent *event)
{
    return event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier);
}

} // namespace

bool KeyboardDriving::isTextInput(const QWidget *w)
{
    if (!w)
        return false;
    // A combo box the user can type into; a plain one picks from its list.
    if (const auto *combo = qobject_cast<const QComboBox *>(w))
        return combo->isEditable();
    // Qt's text fields, read-only ones too (arrows move in them), any other
    // widget that takes typed text, and one that says arrows move in it
    // (the byte log).
    return qobject_cast<const QLineEdit *>(w) || qobject_cast<const QAbstractSpinBox *>(w)
        || qobject_cast<const QTextEdit *>(w) || qobject_cast<const QPlainTextEdit *>(w)
        || w->testAttribute(Qt::WA_InputMethodEnabled) || w->property("readsArrowKeys").toBool();
}

KeyboardDriving::KeyboardDriving(QWidget *window, QWidget *quietZone, QObject *parent)
    : QObject(parent), m_window(window), m_quietZone(quietZone)
{
    qApp->installEventFilter(this);
    // A field that gets the focus again gets the word about typing again.
    connect(qApp, &QApplication::focusChanged, this, [this](QWidget *, QWidget *now) {
        if (now != m_told)
            m_told = nullptr;
    });
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
    if ((type != QEvent::KeyPress && type != QEvent::KeyRelease) || !watched->isWidgetType() || !m_teleop)
        return false;
    auto *key = static_cast<QKeyEvent *>(event);
    const bool press = type == QEvent::KeyPress && !key->isAutoRepeat();
    // Shift+Esc stops every robot from any window of the program (the fleet
    // view on the projector, a dialog), whatever is selected.
    if (key->key() == Qt::Key_Escape && key->modifiers() == Qt::ShiftModifier) {
        if (press) {
            m_held.clear();
            emit stopAllRequested();
        }
        return true;
    }
    QWidget *window = static_cast<QWidget *>(watched)->window();
    const bool driving = window == m_window;
    if (!driving && !std::any_of(m_stopWindows.cbegin(), m_stopWindows.cend(),
                                 [window](const QPointer<QWidget> &w) { return w == window; }))
        return false;
    TeleopController *teleop = m_teleop();
    QWidget *focus = QApplication::focusWidget();
    const bool typing = isTextInput(focus);
    // Esc always stops the selected robot, and takes the keys out of a text
    // field. Space does too, except where it already means something:
    // inside the plots it pauses them, and in a text field it types a space.
    const bool quiet = focus && m_quietZone && (focus == m_quietZone || m_quietZone->isAncestorOf(focus));
    const bool stopKey = key->key() == Qt::Key_Escape || (key->key() == Qt::Key_Space && !typing && !quiet);
    if (stopKey && key->modifiers() == Qt::NoModifier) {
        if (press) {
            m_held.clear();
            if (teleop)
                teleop->stopAll();
            if (driving && key->key() == Qt::Key_Escape) {
                if (typing && m_home)
                    m_home->setFocus(Qt::OtherFocusReason);
                emit escapePressed();
            }
        }
        return true;
    }
    if (!driving)
        return false;
    if (typing && press)
        noticeTyping(key, focus);
    return handleDriveKey(key);
}

void KeyboardDriving::noticeTyping(QKeyEvent *event, QWidget *focus)
{
    if ((driveKey(event->key()) || event->key() == Qt::Key_Space) && !withCommandModifier(event) && focus != m_told) {
        m_told = focus;
        emit typedIntoField(focus);
    }
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
    if (withCommandModifier(event) || isTextInput(QApplication::focusWidget()))
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

#include "moc_keyboard_driving.cpp"
