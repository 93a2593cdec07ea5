// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_firmware.h"

#include "robot_identity.h"

#include <QSettings>
#include <QUrl>

namespace {
constexpr qsizetype kMaxBannerBytes = 8192;

// A stored release, read as the banner line it came from.
std::optional<oi::FirmwareInfo> firmwareOfRelease(const QString &release)
{
    if (release.isEmpty())
        return std::nullopt;
    return oi::parseFirmwareBanner((release + QLatin1Char('\n')).toStdString());
}

// A line of the banner for people: printable ASCII only.
QString printable(const QByteArray &line)
{
    QString text;
    for (const char c : line)
        if (c >= ' ' && c <= '~')
            text += QLatin1Char(c);
    return text.trimmed();
}
} // namespace

RobotFirmware::RobotFirmware(QObject *parent) : QObject(parent) { setClock(oilink::Clock::steady()); }

void RobotFirmware::setClock(oilink::Clock &clock)
{
    m_deadline = std::make_unique<oilink::ClockTimer>(clock, this);
    m_deadline->setSingleShot(true);
    connect(m_deadline.get(), &oilink::ClockTimer::timeout, this, [this] {
        m_listening = false;
        emit readFailed(tr("The robot printed no firmware version within %1 s of Reset. Check that it is "
                           "switched on and connected, and try again once it streams.")
                            .arg(m_deadline->interval() / 1000.0));
    });
}

QString RobotFirmware::release() const
{
    return m_info ? QString::fromStdString(m_info->release) : QString();
}

std::optional<oi::FirmwareVersion> RobotFirmware::version() const
{
    return m_info ? std::optional(m_info->version) : std::nullopt;
}

const oi::FirmwareCorrections &RobotFirmware::corrections() const
{
    static const oi::FirmwareCorrections none;
    return m_info ? m_info->corrections : none;
}

QString RobotFirmware::correctionsText() const
{
    const QString mode = m_modeOneHigh ? tr("This robot reports its mode (packet 35) one too high (Passive as 2, Safe "
                                            "as 3, Full as 4): the true mode is shown and used everywhere.")
                                       : QString();
    const auto withMode = [&mode](const QString &text) { return mode.isEmpty() ? text : text + QLatin1Char(' ') + mode; };
    if (!m_info)
        return withMode(tr("The firmware version is not known: values are shown as the robot reports them."));
    const oi::FirmwareCorrections &c = m_info->corrections;
    if (!c.any())
        return withMode(tr("This firmware reports distance, angle and radius correctly: nothing needs correcting."));
    QStringList text;
    if (c.angleDivisor)
        text << tr("It reports the angle (packet 20) multiplied by %1: the angle is divided by %1 wherever it "
                   "is shown, plotted, exported or used for the map.")
                    .arg(*c.angleDivisor);
    if (c.distanceUnreliable || c.radiusUnreliable)
        text << tr("It reports the distance (packet 19) and the requested radius (packet 40) wrongly: they are "
                   "greyed, and the map uses the wheel encoders.");
    return withMode(text.join(QLatin1Char(' ')));
}

QString RobotFirmware::settingsKey() const
{
    return QStringLiteral("firmware/") + QString::fromLatin1(QUrl::toPercentEncoding(m_robot));
}

QString RobotFirmware::modeSettingsKey() const
{
    return QStringLiteral("modeReportedOneHigh/") + QString::fromLatin1(QUrl::toPercentEncoding(m_robot));
}

void RobotFirmware::noteModeReportedOneHigh()
{
    if (m_modeOneHigh)
        return;
    m_modeOneHigh = true;
    QSettings().setValue(modeSettingsKey(), true);
}

void RobotFirmware::connectingTo(const oilink::LinkSettings &link)
{
    const QString robot = robotIdentity(link);
    if (robot == m_robot)
        return;
    m_robot = robot;
    m_listening = false;
    m_deadline->stop();
    m_banner.clear();
    m_modeOneHigh = QSettings().value(modeSettingsKey()).toBool();
    setFirmware(firmwareOfRelease(QSettings().value(settingsKey()).toString()));
}

void RobotFirmware::expectBanner(int timeoutMs)
{
    listenForBanner();
    m_deadline->start(timeoutMs);
}

void RobotFirmware::listenForBanner()
{
    m_listening = true;
    m_received.clear();
}

void RobotFirmware::watchReceived(const QByteArray &bytes)
{
    if (!m_listening)
        return;
    m_received += bytes;
    if (m_received.size() > kMaxBannerBytes)
        m_received = m_received.right(kMaxBannerBytes);
    const auto info = oi::parseFirmwareBanner(std::string_view(m_received.constData(), std::size_t(m_received.size())));
    if (!info)
        return;
    m_listening = false;
    m_deadline->stop();
    // The line that names the version; the lines before it may hold the end
    // of a stream frame.
    const qsizetype versionAt = m_received.indexOf(QByteArray::fromStdString(info->release));
    const qsizetype lineStart = m_received.lastIndexOf('\n', versionAt) + 1;
    const qsizetype lineEnd = m_received.indexOf('\n', versionAt);
    m_banner = printable(m_received.mid(lineStart, lineEnd < 0 ? -1 : lineEnd - lineStart));
    QSettings().setValue(settingsKey(), QString::fromStdString(info->release));
    setFirmware(info);
    emit read(release());
}

void RobotFirmware::setFirmware(const std::optional<oi::FirmwareInfo> &info)
{
    const QString before = release();
    m_info = info;
    if (release() != before)
        emit changed(release());
}

#include "moc_robot_firmware.cpp"
