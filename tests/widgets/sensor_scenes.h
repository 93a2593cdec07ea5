// SPDX-License-Identifier: GPL-3.0-or-later
// Snapshots, palettes and screenshots shared by the sensor widget tests.
#pragma once

#include "sensor_snapshot.h"

#include <QColor>
#include <QCoreApplication>
#include <QDir>
#include <QSize>
#include <QTemporaryDir>
#include <QTest>
#include <QImage>
#include <QMetaType>
#include <QPalette>
#include <QString>
#include <QWidget>
#include <QtGlobal>

#include <cstdint>
#include <map>
#include <vector>

// oi::ProfileId is declared with the link's value types, which a test of a
// robot's session sees too.
#include "link_status.h"
Q_DECLARE_METATYPE(oi::CliffSensor)
Q_DECLARE_METATYPE(oi::LightBumper)

namespace sensor_scenes {

// The data bytes a sensor reply to `groupId` carries for these values (high
// byte first, two's complement where the packet is signed); packets not in
// `values` are zero.
inline std::vector<std::uint8_t> groupBytes(const oi::RobotProfile &profile, int groupId,
                                            const std::map<int, int> &values)
{
    std::vector<std::uint8_t> out;
    const oi::PacketGroup *group = profile.group(groupId);
    const int first = group ? group->first : groupId;
    const int last = group ? group->last : groupId;
    for (int id = first; id <= last; ++id) {
        const oi::PacketInfo *info = profile.packet(id);
        const auto it = values.find(id);
        const auto v = static_cast<std::uint16_t>(it == values.end() ? 0 : it->second);
        if (info->bytes == 2)
            out.push_back(static_cast<std::uint8_t>(v >> 8));
        out.push_back(static_cast<std::uint8_t>(v & 0xFF));
    }
    return out;
}

// A snapshot decoded from the profile's largest group, as a stream would
// deliver it.
inline oi::SensorSnapshot decoded(const oi::RobotProfile &profile, const std::map<int, int> &values)
{
    oi::SensorSnapshot s(profile);
    // The profile's largest group: 100, 6 on the Create, 0 on the SCI.
    int group = 0;
    for (const oi::PacketGroup &g : profile.groups())
        if (g.bytes > profile.replySize(group))
            group = g.id;
    const std::vector<std::uint8_t> bytes = groupBytes(profile, group, values);
    s.decode(group, bytes);
    return s;
}

// A quiet robot on the floor: no bumps, no cliffs, a fairly full battery.
inline std::map<int, int> quietValues(const oi::RobotProfile &profile)
{
    std::map<int, int> v = {
        {17, profile.irNone}, {21, 0}, {22, 15120}, {23, -210}, {24, 27}, {25, 2140},
        {26, 2696}, {28, 2610}, {29, 2890}, {30, 2750}, {31, 2480}, {35, 2}, {40, 32767},
    };
    if (profile.id == oi::ProfileId::Create1) {
        v[32] = 0x10; // the baud-rate-change pin idles high
    } else {
        v[52] = profile.irNone;
        v[53] = profile.irNone;
        v[58] = 1;
    }
    return v;
}

// A busy moment with something to show in every part of the widgets.
inline std::map<int, int> busyValues(const oi::RobotProfile &profile)
{
    std::map<int, int> v = quietValues(profile);
    const bool create1 = profile.id == oi::ProfileId::Create1;
    v[7] = oi::bit::BumpLeft | oi::bit::WheelDropRight | (create1 ? oi::bit::WheelDropCaster : 0);
    v[8] = 1;
    v[11] = 1;
    v[13] = 1;
    v[14] = oi::bit::OcLeftWheel;
    v[17] = 250; // red buoy and force field
    v[18] = create1 ? oi::bit::ButtonPlay : oi::bit::ButtonClean | oi::bit::ButtonDock;
    v[21] = 3;
    v[23] = 640;
    v[27] = create1 ? 1870 : 512;
    v[30] = 180;
    v[34] = oi::bit::SourceHomeBase;
    v[39] = 200;
    v[40] = -1;
    if (create1) {
        v[32] = oi::bit::DigitalInput0 | oi::bit::DigitalInput2; // baud pin low: asserted
        v[33] = 712;
    } else {
        v[15] = 42;
        v[45] = oi::bit::LightBumperCenterLeft | oi::bit::LightBumperFrontRight;
        v[46] = 40;
        v[47] = 310;
        v[48] = 3620;
        v[49] = 1210;
        v[50] = 2980;
        v[51] = 95;
        v[52] = 130;
        v[53] = 164; // drive-on charger: green buoy
        v[54] = 212;
        v[55] = 198;
        v[56] = 344;
        v[57] = 61;
        v[58] = profile.id == oi::ProfileId::Create2 ? 2 : 1;
    }
    return v;
}

inline QPalette darkPalette()
{
    QPalette p;
    p.setColor(QPalette::Window, QColor(37, 39, 43));
    p.setColor(QPalette::WindowText, QColor(232, 232, 232));
    p.setColor(QPalette::Base, QColor(24, 25, 28));
    p.setColor(QPalette::AlternateBase, QColor(45, 47, 52));
    p.setColor(QPalette::Text, QColor(232, 232, 232));
    p.setColor(QPalette::Button, QColor(50, 52, 57));
    p.setColor(QPalette::ButtonText, QColor(232, 232, 232));
    p.setColor(QPalette::Mid, QColor(80, 82, 88));
    p.setColor(QPalette::Dark, QColor(20, 20, 22));
    p.setColor(QPalette::Light, QColor(90, 92, 98));
    p.setColor(QPalette::Highlight, QColor(42, 130, 218));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::PlaceholderText, QColor(150, 150, 150));
    return p;
}

inline QPalette lightPalette()
{
    QPalette p;
    p.setColor(QPalette::Window, QColor(239, 239, 239));
    p.setColor(QPalette::WindowText, QColor(20, 20, 20));
    p.setColor(QPalette::Base, Qt::white);
    p.setColor(QPalette::AlternateBase, QColor(247, 247, 247));
    p.setColor(QPalette::Text, QColor(20, 20, 20));
    p.setColor(QPalette::Button, QColor(239, 239, 239));
    p.setColor(QPalette::ButtonText, QColor(20, 20, 20));
    p.setColor(QPalette::Mid, QColor(184, 184, 184));
    p.setColor(QPalette::Dark, QColor(160, 160, 160));
    p.setColor(QPalette::Light, Qt::white);
    p.setColor(QPalette::Highlight, QColor(48, 140, 198));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::PlaceholderText, QColor(120, 120, 120));
    return p;
}

// Saves the widget as NAME.png: into ROOMBA_SCREENSHOTS when set, so a
// person can look at what the tests see, otherwise into a scratch folder, so
// rendering every scene is still checked.
inline void saveScreenshot(QWidget &widget, const QString &name)
{
    static QTemporaryDir scratch;
    QString dir = qEnvironmentVariable("ROOMBA_SCREENSHOTS");
    if (dir.isEmpty())
        dir = scratch.path();
    QDir().mkpath(dir);
    QCoreApplication::processEvents(); // charts lay out their titles lazily
    const QPixmap shot = widget.grab();
    QVERIFY(!shot.isNull());
    QVERIFY(shot.save(QDir(dir).filePath(name + ".png")));
}

// "gauges_create2_480x480_dark": what a scene's screenshot is called.
inline QString sceneName(const QString &widget, const oi::RobotProfile &profile, QSize size, bool dark)
{
    return QStringLiteral("%1_%2_%3x%4_%5")
        .arg(widget, QString::fromUtf8(profile.key.data(), qsizetype(profile.key.size())))
        .arg(size.width())
        .arg(size.height())
        .arg(dark ? "dark" : "light");
}

inline bool isGrey(const QColor &c)
{
    return qAbs(c.red() - c.green()) <= 2 && qAbs(c.green() - c.blue()) <= 2;
}

} // namespace sensor_scenes
