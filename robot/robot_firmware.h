// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "link_settings.h"

#include <QByteArray>
#include <QObject>
#include <QString>
#include "link_clock.h"

#include <memory>

#include <optional>

// What one robot's firmware is, and so what it reports wrongly (ERRATA 16):
// learned from the banner the robot prints after Reset (7), and remembered
// per robot between runs (QSettings, under robotIdentity()), so reconnecting
// to the same robot keeps its corrections and connecting to another forgets
// them. Owned by the robot's session, which shows it the bytes each way.
class RobotFirmware : public QObject {
    Q_OBJECT
public:
    // A robot reboots before it prints its banner.
    static constexpr int kBannerTimeoutMs = 10'000;

    explicit RobotFirmware(QObject *parent = nullptr);

    // "release-3.4.0", or empty while unknown.
    QString release() const;
    std::optional<oi::FirmwareVersion> version() const;
    // None while the firmware is unknown.
    const oi::FirmwareCorrections &corrections() const;
    // The banner's line that names the version, printable text only; empty
    // when the firmware came from the settings.
    QString banner() const { return m_banner; }
    // What the corrections mean, in a sentence or two for the user.
    QString correctionsText() const;
    // The robot reports its mode (packet 35) one too high, as some Wi-Fi
    // Roomba 600s do: found by its link (RobotLink::modeReportedOneHigh),
    // whatever the firmware version, and remembered per robot like the
    // version, so its link corrects the mode from the first frame.
    bool modeReportedOneHigh() const { return m_modeOneHigh; }
    void noteModeReportedOneHigh();

    // A connection to `link` begins: another robot's firmware is forgotten
    // and what was learned of this one before comes back.
    void connectingTo(const oilink::LinkSettings &link);

    // A Reset was asked for: the banner that follows is read.
    void listenForBanner();
    // Bytes the link received, where a banner may be.
    void watchReceived(const QByteArray &bytes);

    // A Reset is about to go out on purpose: read() or readFailed() follows,
    // the latter after timeoutMs without a banner.
    void expectBanner(int timeoutMs = kBannerTimeoutMs);
    bool isReading() const { return m_deadline->isActive(); }
    // The clock the deadline runs on (the session's, which tests advance).
    void setClock(oilink::Clock &clock);

signals:
    // The release changed: learned, restored for this robot, or forgotten.
    void changed(const QString &release);
    // A banner was read (after any Reset), whether or not the release is new.
    void read(const QString &release);
    void readFailed(const QString &message);

private:
    void setFirmware(const std::optional<oi::FirmwareInfo> &info);
    QString settingsKey() const;
    QString modeSettingsKey() const;

    QString m_robot; // robotIdentity() of the robot connected
    std::optional<oi::FirmwareInfo> m_info;
    bool m_modeOneHigh = false;
    bool m_listening = false;
    QByteArray m_received; // since the Reset, bounded
    QString m_banner;
    std::unique_ptr<oilink::ClockTimer> m_deadline;
};
