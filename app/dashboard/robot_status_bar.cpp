// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_status_bar.h"

#include "display_palette.h"
#include "live_label.h"
#include "oi_text.h"
#include "robot_session.h"

#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QStatusBar>

RobotStatusBar::RobotStatusBar(QStatusBar *bar) : QObject(bar), m_bar(bar)
{
    // The right-hand labels in one widget, which a long message can hide.
    m_linkLabels = new QWidget(m_bar);
    m_linkLabels->setObjectName("linkLabels");
    auto *row = new QHBoxLayout(m_linkLabels);
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(12);
    m_bar->addPermanentWidget(m_linkLabels);
    auto label = [this, row](const char *name) {
        auto *l = new QLabel(m_linkLabels);
        l->setObjectName(name);
        l->setTextFormat(Qt::PlainText); // names of files and robots, as written
        row->addWidget(l);
        return l;
    };
    m_robot = new QLabel(m_bar);
    m_robot->setObjectName("selectedRobot");
    m_robot->setTextFormat(Qt::PlainText);
    m_bar->addWidget(m_robot);
    m_stale = new QLabel(m_bar);
    m_stale->setObjectName("staleIndicator");
    m_stale->setFont(display::valueFont(m_bar->font(), 1.2));
    const display::State alert = display::State::Alert;
    m_stale->setStyleSheet(QString("QLabel { background: %1; color: %2; padding: 2px 8px; }")
                               .arg(display::stateColor(alert, m_bar->palette()).name(),
                                    display::textOn(alert, m_bar->palette()).name()));
    m_bar->addWidget(m_stale);
    m_modeReason = new QLabel(m_bar);
    m_modeReason->setObjectName("modeReason");
    m_modeReason->setVisible(false);
    m_bar->addWidget(m_modeReason);
    m_state = label("linkState");
    m_profile = label("profile");
    m_firmware = label("firmware");
    m_rate = label("frameRate");
    m_errors = label("lineErrors");
    m_recording = label("recording");
    m_recording->setVisible(false);
    m_recording->setStyleSheet(QString("QLabel { color: %1; font-weight: bold; }")
                                   .arg(display::stateColor(alert, m_bar->palette()).name()));
    connect(m_bar, &QStatusBar::messageChanged, this, &RobotStatusBar::showLeftLabels);
}

void RobotStatusBar::showLeftLabels()
{
    const QString text = m_bar->currentMessage();
    const bool message = !text.isEmpty();
    m_robot->setVisible(m_nameRobot && !message);
    m_stale->setVisible(m_showStale && !message);
    m_modeReason->setVisible(!m_modeReason->text().isEmpty() && !message);
    // QStatusBar cuts a message off where the right-hand labels begin, mid
    // word and against their text: one too long for that space has the
    // whole bar while it is up.
    const int beside = m_bar->width() - m_linkLabels->sizeHint().width() - kMessageRoom;
    m_linkLabels->setVisible(!message || m_bar->fontMetrics().horizontalAdvance(text) <= beside);
}

void RobotStatusBar::showRobot(const RobotSession &robot, bool nameIt)
{
    m_nameRobot = nameIt;
    showLeftLabels();
    m_robot->setText(robot.name());
    m_robot->setStyleSheet(QString("QLabel { border-left: 8px solid %1; padding-left: 4px; font-weight: bold; }")
                               .arg(robot.colour().name()));
    m_firmwareRelease = robot.firmwareRelease();
    m_overNetwork = robot.settings().transport == oilink::TransportKind::Network;
    showProfile(robot);
    showState(robot.state());
    showStatistics(robot.statistics());
    showRecording(robot.recording());
    showFirmware(robot.firmwareRelease());
}

QString RobotStatusBar::linkStateText(oilink::LinkState state)
{
    using S = oilink::LinkState;
    switch (state) {
    case S::Closed: return tr("closed");
    case S::Connecting: return tr("connecting");
    case S::Streaming: return tr("streaming");
    case S::Stale: return tr("stale");
    case S::Lost: return tr("lost");
    case S::Reconnecting: return tr("reconnecting");
    }
    return QString();
}

QString RobotStatusBar::linkText(const RobotSession &robot)
{
    if (!robot.isConnected())
        return tr("not connected");
    if (robot.isReplay())
        return robot.replay().finished  ? tr("replay finished")
               : robot.replay().playing ? tr("replaying")
                                        : tr("replay paused");
    return linkStateText(robot.state());
}

void RobotStatusBar::showState(oilink::LinkState state)
{
    m_shownState = state;
    m_state->setText(m_replayEnded ? tr("Link: replay finished")
                     : m_replay    ? tr("Link: replaying a recording")
                                   : tr("Link: %1").arg(linkStateText(state)));
    showRate();
}

void RobotStatusBar::showStatistics(const oilink::LinkStats &stats)
{
    m_shownStats = stats;
    setLiveText(m_errors, tr("checksum failures %1, resyncs %2").arg(stats.checksumFailures).arg(stats.resyncs));
    // Said once there is something to say, so that a small screen keeps room
    // for the rest. A bridge tells only what changed, in fewer messages than
    // the robot's frames, and checks the robot's bytes itself.
    m_errors->setVisible(!m_overNetwork && (stats.checksumFailures > 0 || stats.resyncs > 0));
    showRate();
}

// A rate only while frames can come: a closed or lost link has none.
void RobotStatusBar::showRate()
{
    const oilink::LinkStats &stats = m_shownStats;
    m_rate->setVisible(m_shownState == oilink::LinkState::Streaming || m_shownState == oilink::LinkState::Stale);
    QString rate = m_overNetwork ? tr("%1 messages/s from the bridge").arg(stats.framesPerSecond, 0, 'f', 1)
                                 : tr("%1 frames/s").arg(stats.framesPerSecond, 0, 'f', 1);
    // Frames on time but in bunches (a Bluetooth adapter, a Wi-Fi bridge): said, not shown as stale.
    if (const QString bunched = oilink::bunchedLinkText(stats); !bunched.isEmpty())
        rate = tr("%1, %2").arg(rate, bunched);
    setLiveText(m_rate, rate);
    m_rate->setToolTip(m_overNetwork ? tr("Telemetry messages from the robot's bridge, which sends only what changed. "
                                          "The robot's own frame rate is on its tile in the fleet view.")
                                     : QString());
}

void RobotStatusBar::showFirmware(const QString &release)
{
    m_firmwareRelease = release;
    m_firmware->setText(release.isEmpty() ? QString() : tr("Firmware %1").arg(release));
}

QString RobotStatusBar::profileText(const RobotSession &robot)
{
    return robot.isIdentified() ? oitext::fromView(robot.robotProfile().name)
                                : tr("Roomba 500 or Create 2? (not yet identified)");
}

void RobotStatusBar::showProfile(const RobotSession &robot)
{
    m_profile->setText(profileText(robot));
}

void RobotStatusBar::showRecording(const oilink::RecordingStatus &status)
{
    // The same file ended without an error: say where it is.
    if (m_shownRecording.active && !status.active && status.error.isEmpty() && !status.path.isEmpty()
        && status.path == m_shownRecording.path)
        m_bar->showMessage(tr("Recording saved: %1").arg(QDir::toNativeSeparators(status.path)), 10000);
    m_shownRecording = status;
    m_recording->setVisible(status.active);
    m_recording->setText(tr("● REC %1 kB %2").arg(status.bytesWritten / 1024).arg(QFileInfo(status.path).fileName()));
    m_recording->setToolTip(status.path);
}

void RobotStatusBar::showLive(bool live, bool replay, bool replayEnded)
{
    m_live = live;
    m_replay = replay;
    m_replayEnded = replay && replayEnded;
    m_stale->setText(m_replayEnded ? tr("  REPLAY FINISHED  ")
                     : replay      ? tr("  REPLAY, NOT LIVE  ")
                                   : tr("  NO LIVE DATA  "));
    m_showStale = !live || replay;
    showLeftLabels();
    showState(m_shownState);
}

void RobotStatusBar::retranslate()
{
    showState(m_shownState);
    showStatistics(m_shownStats);
    showRecording(m_shownRecording);
    showFirmware(m_firmwareRelease);
    showLive(m_live, m_replay, m_replayEnded);
}

void RobotStatusBar::showModeReason(const QString &reason)
{
    m_modeReason->setText(reason);
    showLeftLabels();
}

QString RobotStatusBar::text() const
{
    QStringList parts;
    // The left labels as they show once any temporary message is gone.
    for (auto [l, shown] : {std::pair{m_robot, m_nameRobot}, std::pair{m_stale, m_showStale},
                            std::pair{m_modeReason, true}})
        if (shown && !l->text().trimmed().isEmpty())
            parts << l->text().trimmed();
    for (QLabel *l : {m_state, m_profile, m_firmware, m_rate, m_errors})
        if (!l->isHidden() && !l->text().isEmpty())
            parts << l->text();
    return parts.join(" | ");
}

#include "moc_robot_status_bar.cpp"
