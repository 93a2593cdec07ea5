// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "motion_command.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QSet>

#include <functional>

class QKeyEvent;
class QWidget;
class TeleopController;

// The keyboard as a drive input for one window: arrows or W A S D held drive
// the selected robot; Space and Esc stop it; Shift+Esc stops every robot,
// from any window of the program. Auto-repeat is ignored. While a text field
// has focus (a line edit, an editable combo box, a spin box, a text editor)
// the letters, arrows and Space are typing, never driving; Esc there stops
// the robot and gives the keys back to driving.
class KeyboardDriving : public QObject {
    Q_OBJECT
public:
    // The turn radius for an arc from two keys held together.
    static constexpr int kArcRadius = 500;

    // `window`: only key events of its widgets drive. `quietZone`: a widget
    // where Space means something else (the plots pause with it).
    KeyboardDriving(QWidget *window, QWidget *quietZone, QObject *parent = nullptr);
    ~KeyboardDriving() override;

    // Where motion goes (the selected robot's teleop), and its speed limit.
    void setTarget(std::function<TeleopController *()> teleop, std::function<int()> speedLimit);
    // Where the keys go when Esc leaves a text field (the robot diagram).
    void setHome(QWidget *home) { m_home = home; }
    // Another window (the fleet view) where Space and Esc stop the selected
    // robot; it does not drive.
    void addStopWindow(QWidget *window) { m_stopWindows << window; }
    // Forget the held keys: the window lost focus, or a stop came from elsewhere.
    void releaseAll() { m_held.clear(); }
    // Letters, arrows and Space type into this widget instead of driving.
    static bool isTextInput(const QWidget *w);

signals:
    void stopAllRequested();
    // Esc stopped the selected robot; a full-screen view also leaves on it.
    void escapePressed();
    // A driving key was typed into `field`, once each time a field gets the
    // focus: the window says where the key went and how to drive.
    void typedIntoField(QWidget *field);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    bool handleDriveKey(QKeyEvent *event);
    void noticeTyping(QKeyEvent *event, QWidget *focus);
    MotionCommand command() const;

    QWidget *m_window;
    QWidget *m_quietZone;
    QPointer<QWidget> m_home;
    QList<QPointer<QWidget>> m_stopWindows;
    QPointer<QWidget> m_told; // the field whose typing was last pointed out
    std::function<TeleopController *()> m_teleop;
    std::function<int()> m_speedLimit;
    QSet<int> m_held; // as Qt::Key values folded to arrows
};
