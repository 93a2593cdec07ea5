// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "motion_command.h"

#include <QObject>
#include <QSet>

#include <functional>

class QKeyEvent;
class QWidget;
class TeleopController;

// The keyboard as a drive input for one window: arrows or W A S D held drive
// the selected robot; Space and Esc stop it; Shift+Esc stops every robot.
// Auto-repeat is ignored, and keys typed into a text field stay typing.
class KeyboardDriving : public QObject {
    Q_OBJECT
public:
    // The turn radius for an arc from two keys held together.
    static constexpr int kArcRadius = 500;

    // `window`: only key events of its widgets are read. `quietZone`: a
    // widget where Space means something else (the plots pause with it).
    KeyboardDriving(QWidget *window, QWidget *quietZone, QObject *parent = nullptr);
    ~KeyboardDriving() override;

    // Where motion goes (the selected robot's teleop), and its speed limit.
    void setTarget(std::function<TeleopController *()> teleop, std::function<int()> speedLimit);
    // Forget the held keys: the window lost focus, or a stop came from elsewhere.
    void releaseAll() { m_held.clear(); }

signals:
    void stopAllRequested();
    // Esc stopped the selected robot; a full-screen view also leaves on it.
    void escapePressed();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    bool handleDriveKey(QKeyEvent *event);
    MotionCommand command() const;

    QWidget *m_window;
    QWidget *m_quietZone;
    std::function<TeleopController *()> m_teleop;
    std::function<int()> m_speedLimit;
    QSet<int> m_held; // as Qt::Key values folded to arrows
};
