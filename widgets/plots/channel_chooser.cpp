// SPDX-License-Identifier: GPL-3.0-or-later
#include "channel_chooser.h"

#include "oi_text.h"
#include "value_axes.h"

#include <QAction>
#include <QEvent>
#include <QMenu>
#include <QMouseEvent>

#include <algorithm>

namespace {

enum class Kind { BumpsCliffs, Battery, Motion, LightBumpers, Motors, CargoBay, IrButtonsMode, Unused };

Kind kindOf(const oi::PacketInfo &info)
{
    if (info.key.starts_with("unused"))
        return Kind::Unused;
    if (info.key.starts_with("dirt_detect")) // 15, and the SCI's right detector, 16
        return Kind::Motors;
    switch (info.id) {
    case 7: case 8: case 9: case 10: case 11: case 12: case 13:
    case 27: case 28: case 29: case 30: case 31:
        return Kind::BumpsCliffs;
    case 21: case 22: case 23: case 24: case 25: case 26: case 34:
        return Kind::Battery;
    case 19: case 20: case 39: case 40: case 41: case 42: case 43: case 44: case 58:
        return Kind::Motion;
    case 45: case 46: case 47: case 48: case 49: case 50: case 51:
        return Kind::LightBumpers;
    case 14: case 15: case 54: case 55: case 56: case 57:
        return Kind::Motors;
    case 32: case 33:
        return Kind::CargoBay;
    default:
        return Kind::IrButtonsMode; // 16..18, 35..38, 52, 53
    }
}

// Plain titles; the menu doubles any '&' itself.
QString titleOf(Kind kind)
{
    switch (kind) {
    case Kind::BumpsCliffs: return ChannelChooser::tr("Bumps & cliffs");
    case Kind::Battery: return ChannelChooser::tr("Battery");
    case Kind::Motion: return ChannelChooser::tr("Motion");
    case Kind::LightBumpers: return ChannelChooser::tr("Light bumpers");
    case Kind::Motors: return ChannelChooser::tr("Motors & dirt");
    case Kind::CargoBay: return ChannelChooser::tr("Cargo bay");
    case Kind::IrButtonsMode: return ChannelChooser::tr("IR, buttons & mode");
    case Kind::Unused: return ChannelChooser::tr("Unused");
    }
    return {};
}

} // namespace

std::vector<ChannelChooser::ChannelGroup> ChannelChooser::groups(const oi::RobotProfile &profile)
{
    constexpr Kind order[] = {Kind::BumpsCliffs, Kind::Battery, Kind::Motion, Kind::LightBumpers,
                              Kind::Motors, Kind::CargoBay, Kind::IrButtonsMode, Kind::Unused};
    std::vector<ChannelGroup> out;
    for (Kind kind : order) {
        ChannelGroup g;
        g.title = titleOf(kind);
        for (const oi::PacketInfo &info : profile.packets())
            if (kindOf(info) == kind)
                g.ids.push_back(info.id);
        std::sort(g.ids.begin(), g.ids.end());
        if (!g.ids.empty())
            out.push_back(std::move(g));
    }
    return out;
}

QString ChannelChooser::channelLabel(const oi::PacketInfo &info)
{
    return oitext::packetLabel(info);
}

ChannelChooser::ChannelChooser(QWidget *parent)
    : QPushButton(parent), m_profile(&oi::profile(oi::ProfileId::Create2)), m_menu(new QMenu(this))
{
    setMenu(m_menu);
    rebuildMenu();
}

void ChannelChooser::changeEvent(QEvent *event)
{
    // The menu is built from translated names; build it again in the new language.
    if (event->type() == QEvent::LanguageChange)
        rebuildMenu();
    QPushButton::changeEvent(event);
}

void ChannelChooser::setProfile(const oi::RobotProfile &profile)
{
    if (&profile == m_profile)
        return;
    m_profile = &profile;
    std::erase_if(m_channels, [&](int id) { return !profile.packet(id); });
    rebuildMenu();
}

void ChannelChooser::setChannels(const std::vector<int> &ids)
{
    m_channels.clear();
    for (int id : ids)
        if (m_profile->packet(id) && std::find(m_channels.begin(), m_channels.end(), id) == m_channels.end())
            m_channels.push_back(id);
    updateChecks();
}

void ChannelChooser::setMaximumChannels(int count)
{
    m_maximum = std::max(1, count);
    updateChecks();
}

QAction *ChannelChooser::actionFor(int packetId) const
{
    return packetId >= 0 && packetId < m_actions.size() ? m_actions[packetId] : nullptr;
}

void ChannelChooser::rebuildMenu()
{
    m_menu->clear();
    // The sub-menus own their entries.
    qDeleteAll(m_subMenus);
    m_subMenus.clear();
    m_actions = QList<QAction *>(oi::kMaxPacketId + 1, nullptr);
    for (const ChannelGroup &g : groups(*m_profile)) {
        const QString title = QString(g.title).replace(QLatin1Char('&'), QStringLiteral("&&"));
        QMenu *sub = m_menu->addMenu(title);
        sub->menuAction()->setData(title);
        sub->installEventFilter(this);
        sub->setToolTipsVisible(true); // why an entry is disabled
        m_subMenus << sub;
        for (int id : g.ids) {
            const oi::PacketInfo *info = m_profile->packet(id);
            QAction *a = sub->addAction(channelLabel(*info));
            a->setCheckable(true);
            a->setData(id);
            connect(a, &QAction::triggered, this, [this, id](bool on) { emit channelToggled(id, on); });
            m_actions[id] = a;
        }
    }
    updateChecks();
}

void ChannelChooser::updateChecks()
{
    const bool full = int(m_channels.size()) >= m_maximum;
    // A plot has two value axes, one unit each: a third unit needs a plot of its own.
    const QStringList units = valueaxes::units(*m_profile, m_channels);
    const auto unitName = [](const QString &unit) { return unit.isEmpty() ? tr("plain numbers") : unit; };
    for (QAction *a : std::as_const(m_actions)) {
        if (!a)
            continue;
        const int id = a->data().toInt();
        const bool on = std::find(m_channels.begin(), m_channels.end(), id) != m_channels.end();
        const oi::PacketInfo *info = m_profile->packet(id);
        const bool otherUnit = !on && units.size() >= valueaxes::kMaxUnits && valueaxes::axisOf(*info, units) < 0;
        a->setChecked(on);
        a->setEnabled(on || (!full && !otherUnit));
        a->setToolTip(otherUnit ? tr("This plot's axes show %1 and %2: add a plot for %3")
                                      .arg(unitName(units[0]), unitName(units[1]),
                                           unitName(oitext::fromView(info->unit)))
                                : QString());
    }
    // A group title counts its ticked channels, so they are easy to find again.
    for (QMenu *sub : std::as_const(m_subMenus)) {
        int ticked = 0;
        for (QAction *a : sub->actions())
            ticked += a->isChecked() ? 1 : 0;
        const QString title = sub->menuAction()->data().toString();
        sub->setTitle(ticked ? QStringLiteral("%1 (%2)").arg(title).arg(ticked) : title);
    }
    QStringList names;
    for (int id : m_channels)
        names << channelLabel(*m_profile->packet(id));
    // The plot names its channels beside the button; the button says how many.
    if (names.isEmpty()) {
        setText(tr("Choose channels"));
        setToolTip(tr("Choose the sensor packets this plot shows"));
    } else {
        setText(tr("Channels (%n)", nullptr, int(names.size())));
        setToolTip(names.join(QLatin1Char('\n')));
    }
}

bool ChannelChooser::eventFilter(QObject *watched, QEvent *event)
{
    // Toggle on release without closing the menu, so several channels can be
    // ticked in one visit.
    if (event->type() == QEvent::MouseButtonRelease) {
        auto *menu = qobject_cast<QMenu *>(watched);
        auto *mouse = static_cast<QMouseEvent *>(event);
        if (menu && mouse->button() == Qt::LeftButton) {
            QAction *a = menu->actionAt(mouse->position().toPoint());
            if (a && a->isCheckable() && a->isEnabled()) {
                a->trigger();
                return true;
            }
        }
    }
    return QPushButton::eventFilter(watched, event);
}

#include "moc_channel_chooser.cpp"
