// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "motion_command.h"

#include <QPointer>
#include <QWidget>

class GamepadInput;
class QLabel;
class StickView;

// Shows what a GamepadInput sees: which pad (or that there is none), the left
// stick, the dead-man, the command it would send and the button roles.
class GamepadPanel : public QWidget {
    Q_OBJECT
public:
    explicit GamepadPanel(QWidget *parent = nullptr);

    // Follows `input` until it is destroyed or replaced; nullptr shows no pad.
    void setInput(GamepadInput *input);

    QString statusText() const;
    QString deadManText() const;
    QString commandText() const;
    QString mappingText() const; // with plain spaces

    // "Forward, arcing right: Drive 68 mm/s, radius -250 mm", "Stop: Drive 0 mm/s", ...
    static QString describe(const MotionCommand &command);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void refresh();

    QPointer<GamepadInput> m_input;
    QLabel *m_status = nullptr;
    QWidget *m_details = nullptr;
    StickView *m_stick = nullptr;
    QLabel *m_deadMan = nullptr;
    QLabel *m_commandTitle = nullptr;
    QLabel *m_command = nullptr;
    QLabel *m_shaping = nullptr;
    QLabel *m_mapping = nullptr;
};
