// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_mode.h"

#include <QHash>
#include <QWidget>

#include <functional>
#include <optional>

class QComboBox;
class QLabel;
class QPushButton;

// The OI mode and cleaning commands. Buttons ask for their command
// (modeRequested()); buttons for commands the profile lacks are disabled
// with a tooltip saying why. It shows the selected robot's mode as its
// session sees it (RobotMode): the mode reported is highlighted, and why it
// changed is said, with the step that fixes it. Full asks first.
class ModePanel : public QWidget {
    Q_OBJECT
public:
    explicit ModePanel(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    // What the selected robot's session says of its mode; nothing is kept.
    void setMode(const RobotMode &mode);
    // Shown after Reset: the banner's firmware release, e.g. "release-3.4.1".
    void setFirmware(const QString &release);
    // Why no command can reach a robot now (no link, a replay), or empty when
    // one can: every button is then disabled, with the reason as its tooltip.
    void setUnavailable(const QString &reason);

    // Asked before entering Full mode; returns true to go ahead. Replaceable
    // so tests need not click a dialog.
    void setFullModeConfirmation(std::function<bool(QWidget *)> confirm);

    QPushButton *button(const QString &name) const; // "start", "safe", "full", "demo", ...
    std::optional<oi::OiMode> highlightedMode() const;
    // Asks for a mode or cleaning command as its button would (Full asks
    // first); for other inputs such as a gamepad's mode buttons.
    void request(oi::Command command);
    // Why the mode changed and what to do, as shown; empty when nothing is.
    QString safetyMessage() const;

signals:
    // `demo` is the demo's number, for Demo only.
    void modeRequested(oi::Command command, int demo);

protected:
    void changeEvent(QEvent *e) override;

private:
    void retranslateUi();
    QPushButton *addButton(const QString &name, oi::Command command);
    void refreshButtons();
    void highlight(std::optional<oi::OiMode> mode);

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    QHash<QString, QPushButton *> m_buttons;
    QHash<QPushButton *, oi::Command> m_commands;
    QComboBox *m_demo = nullptr;
    QLabel *m_modeLabel = nullptr;
    QLabel *m_firmwareLabel = nullptr;
    QLabel *m_safetyLabel = nullptr;
    QString m_firmware;
    QString m_unavailable;
    std::function<bool(QWidget *)> m_confirmFull;
};
