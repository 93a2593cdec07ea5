// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"
#include "robot_mode.h"
#include "typed_commands.h"

#include <QByteArray>
#include <QColor>
#include <QTimer>
#include <QWidget>

#include <array>
#include <optional>
#include <vector>

class QCheckBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSlider;
class SevenSegmentDisplay;

// Edits what the robot shows: the 7-segment digits (163 raw segments or 164
// ASCII), the LEDs and power LED (139) and the scheduling LEDs (162). Only
// the commands changed since the last send go out, each as one
// sendRequested, either on apply() or, in live mode, at most every 100 ms
// with the latest state. The preview shows exactly those bytes.
class LedEditor : public QWidget {
    Q_OBJECT
public:
    static constexpr int kLiveIntervalMs = 100;

    explicit LedEditor(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &robotProfile() const { return *m_profile; }

    bool liveMode() const;
    // Milliseconds until live mode sends what is pending; -1 when nothing is due.
    int msUntilLiveSend() const { return m_liveTimer.isActive() ? m_liveTimer.remainingTime() : -1; }
    void setLiveMode(bool live);
    // The selected robot's mode: in Passive the robot ignores the LED
    // commands, so nothing is sent (Apply disabled, the reason as its
    // tooltip) and the changes wait; live mode sends them once it can.
    void setMode(const RobotMode &mode);

    // The commands apply() would send now, one per entry, in sending order.
    std::vector<oi::Bytes> pendingCommands() const;
    // Those bytes in decimal, one command a line ("139 4 0 128"), or a
    // sentence saying nothing changed.
    QString bytePreview() const;
    // The last refusal or warning shown to the user, or empty.
    QString message() const;

    // The power LED as the robot lights it: green (0) to red (255), dimmed by
    // intensity (0..255).
    static QColor powerLedColor(int colour, int intensity);

protected:
    void changeEvent(QEvent *event) override;

public slots:
    // Sends every pending command, then clears them; in Passive sends
    // nothing and says why.
    void apply();

signals:
    void sendRequested(const std::vector<oi::OiCommand> &commands);

private:
    enum class DigitSource { Raw, Ascii };

    QWidget *buildDigits();
    QWidget *buildLeds();
    QWidget *buildSchedulingLeds();
    QCheckBox *addCheck(const QString &name, QWidget *parent);
    void retranslateUi();
    void changed();
    void asciiEdited();
    QString asciiProblem(const QString &text, bool *refused) const;
    void refresh();
    int ledBits() const;
    int weekdayBits() const;
    int schedulingBits() const;
    oi::OiCommand digitsCommand() const;
    std::vector<oi::OiCommand> pendingTyped() const;

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    bool m_ledsPending = false;
    bool m_schedulingPending = false;
    std::optional<DigitSource> m_digitsPending;
    std::array<std::uint8_t, 4> m_asciiCodes{32, 32, 32, 32};
    QTimer m_liveTimer;
    QString m_blocked; // why the robot ignores LED commands now, or empty

    QGroupBox *m_digitsGroup = nullptr;
    QWidget *m_digitsContent = nullptr;
    QLabel *m_digitsReason = nullptr;
    SevenSegmentDisplay *m_segments = nullptr;
    QLabel *m_rawWarning = nullptr;
    QLineEdit *m_asciiText = nullptr;
    SevenSegmentDisplay *m_asciiPreview = nullptr;
    QLabel *m_asciiMessage = nullptr;
    QPushButton *m_clear = nullptr;
    QLabel *m_rawTitle = nullptr;
    QLabel *m_asciiTitle = nullptr;
    QLabel *m_asciiCaption = nullptr;

    QGroupBox *m_ledsGroup = nullptr;
    QLabel *m_colourLabel = nullptr;
    QLabel *m_greenLabel = nullptr;
    QLabel *m_redLabel = nullptr;
    QLabel *m_intensityLabel = nullptr;
    QLabel *m_offLabel = nullptr;
    QLabel *m_fullLabel = nullptr;

    QCheckBox *m_debris = nullptr;
    QCheckBox *m_spot = nullptr;
    QCheckBox *m_dock = nullptr;
    QCheckBox *m_checkRobot = nullptr;
    QCheckBox *m_play = nullptr;
    QCheckBox *m_advance = nullptr;
    QSlider *m_colour = nullptr;
    QSlider *m_intensity = nullptr;
    QLabel *m_colourValue = nullptr;
    QLabel *m_intensityValue = nullptr;
    QLabel *m_swatch = nullptr;

    QGroupBox *m_schedulingGroup = nullptr;
    QWidget *m_schedulingContent = nullptr;
    QLabel *m_schedulingReason = nullptr;
    std::array<QCheckBox *, 7> m_weekdays{};
    QCheckBox *m_schedule = nullptr;
    QCheckBox *m_clock = nullptr;
    QCheckBox *m_am = nullptr;
    QCheckBox *m_pm = nullptr;
    QCheckBox *m_colon = nullptr;

    QCheckBox *m_live = nullptr;
    QPushButton *m_apply = nullptr;
    QLabel *m_willSend = nullptr;
    QLabel *m_preview = nullptr;
    QLabel *m_message = nullptr;
};
