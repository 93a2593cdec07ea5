// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"

#include <QList>
#include <QString>
#include <QPushButton>

#include <vector>

class QAction;
class QMenu;

// A button whose menu lists every sensor packet of the profile, grouped by
// what it tells (bumps and cliffs, battery, motion, ...), one sub-menu per
// group with a checkable entry per packet. Several channels can be checked;
// the menu stays open while the user ticks them.
class ChannelChooser : public QPushButton {
    Q_OBJECT
public:
    struct ChannelGroup {
        QString title;
        std::vector<int> ids; // packet ids, ascending
    };
    // The groups, in menu order, covering every single packet of `profile`
    // exactly once. Groups the profile has no packet for are left out.
    static std::vector<ChannelGroup> groups(const oi::RobotProfile &profile);
    // "Voltage [mV]", or the bare name where the packet has no unit.
    static QString channelLabel(const oi::PacketInfo &info);

    explicit ChannelChooser(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    // Ticks exactly these channels; ids the profile lacks are ignored.
    void setChannels(const std::vector<int> &ids);
    std::vector<int> channels() const { return m_channels; }
    // At most this many can be ticked; the other entries are disabled then.
    void setMaximumChannels(int count);

    // The checkable entry for a packet, or nullptr (for tests).
    QAction *actionFor(int packetId) const;

signals:
    // The user ticked (on) or unticked (off) a channel.
    void channelToggled(int packetId, bool on);

protected:
    void changeEvent(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void rebuildMenu();
    void updateChecks();

    const oi::RobotProfile *m_profile;
    QMenu *m_menu;
    QList<QMenu *> m_subMenus;
    QList<QAction *> m_actions; // indexed by packet id, nullptr where none
    std::vector<int> m_channels;
    int m_maximum = 8;
};
