// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_status.h"

#include <QObject>
#include <QString>

class QLabel;
class QStatusBar;
class QWidget;
class RobotSession;

// The status bar's view of the selected robot: which robot it is, the link,
// profile, firmware, frame rate, line errors, recording, and a hard-to-miss
// flag when no live data arrives.
class RobotStatusBar : public QObject {
    Q_OBJECT
public:
    explicit RobotStatusBar(QStatusBar *bar);

    // Reads everything from `robot` now; later changes come through the show* calls.
    void showRobot(const RobotSession &robot, bool nameIt);
    void showState(oilink::LinkState state);
    void showStatistics(const oilink::LinkStats &stats);
    void showFirmware(const QString &release);
    // The robot's profile, or that it is not yet identified.
    void showProfile(const RobotSession &robot);
    void showRecording(const oilink::RecordingStatus &status);
    // No live data: "NO LIVE DATA", or for a replay "REPLAY, NOT LIVE" and
    // at its end "REPLAY FINISHED".
    void showLive(bool live, bool replay, bool replayEnded = false);
    // Why the robot is in its mode, and the step that fixes it (RobotMode's
    // reason() and nextStep()); empty hides it.
    void showModeReason(const QString &reason);
    void retranslate();
    // Every label shown, joined: for tests and screen readers.
    QString text() const;
    // "streaming", "lost", ...
    static QString linkStateText(oilink::LinkState state);
    // What a robot's card says of its link: its state, or where its replay
    // is (a replay that pauses or ends is not a stale robot).
    static QString linkText(const RobotSession &robot);
    // "Create 2", or "Roomba 500 or Create 2? (not yet identified)".
    static QString profileText(const RobotSession &robot);

private:
    void showRate();
    // One message at a time: while a temporary message (showMessage()) is
    // up, the labels it would be painted over are hidden, and come back after.
    void showLeftLabels();

    // Beside a message: QStatusBar's margins and gaps, and a space before
    // the right-hand labels.
    static constexpr int kMessageRoom = 40;

    QStatusBar *m_bar;
    QWidget *m_linkLabels = nullptr; // the labels from linkState on, at the right
    QLabel *m_robot = nullptr;
    QLabel *m_stale = nullptr;
    QLabel *m_modeReason = nullptr;
    QLabel *m_state = nullptr;
    QLabel *m_profile = nullptr;
    QLabel *m_firmware = nullptr;
    QLabel *m_rate = nullptr;
    QLabel *m_errors = nullptr;
    QLabel *m_recording = nullptr;
    oilink::LinkState m_shownState = oilink::LinkState::Closed;
    oilink::LinkStats m_shownStats;
    oilink::RecordingStatus m_shownRecording;
    QString m_firmwareRelease;
    // A robot beside a bridge: its rate is the bridge's messages, not frames.
    bool m_overNetwork = false;
    bool m_live = false;
    bool m_replay = false;
    bool m_replayEnded = false;
    bool m_nameRobot = false; // the left labels as they show without a message
    bool m_showStale = false;
};
