// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"
#include "sensor_snapshot.h"

#include <QByteArray>
#include <QHash>
#include <QWidget>

#include <functional>
#include <optional>

class QComboBox;
class QLabel;
class QPushButton;

// The OI mode and cleaning commands. Buttons encode their command for the
// current profile and emit the bytes; buttons for commands the profile lacks
// are disabled with a tooltip saying why. The current mode (packet 35) is
// highlighted, Full asks first, and a drop from Safe to Passive that nobody
// asked for is explained.
class ModePanel : public QWidget {
    Q_OBJECT
public:
    explicit ModePanel(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    void setSnapshot(const oi::SensorSnapshot &snapshot);
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
    // Sends a mode or cleaning command as its button would (Full asks first);
    // for other inputs such as a gamepad's mode buttons.
    void request(oi::Command command);
    QString safetyMessage() const;

signals:
    void sendRequested(const QByteArray &bytes);

protected:
    void changeEvent(QEvent *e) override;

private:
    void retranslateUi();
    QString safetyText(const oi::SensorSnapshot &snapshot) const;
    QPushButton *addButton(const QString &name, oi::Command command);
    void refreshButtons();
    void showMode(std::optional<oi::OiMode> mode);

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    QHash<QString, QPushButton *> m_buttons;
    QHash<QPushButton *, oi::Command> m_commands;
    QComboBox *m_demo = nullptr;
    QLabel *m_modeLabel = nullptr;
    QLabel *m_firmwareLabel = nullptr;
    QLabel *m_safetyLabel = nullptr;
    std::optional<oi::OiMode> m_mode;
    bool m_passiveRequested = false;
    QString m_firmware;
    QString m_unavailable;
    std::optional<oi::SensorSnapshot> m_safetyDropFrame; // the frame that explains the drop shown
    std::function<bool(QWidget *)> m_confirmFull;
};
