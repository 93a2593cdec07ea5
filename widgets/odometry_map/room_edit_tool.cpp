// SPDX-License-Identifier: GPL-3.0-or-later
#include "room_edit_tool.h"

#include "display_palette.h"
#include "odometry_map.h"

#include <QAction>
#include <QMenu>
#include <QPainter>

#include <cmath>

namespace {

constexpr double kHandlePx = 15; // a handle's side

} // namespace

RoomEditTool::RoomEditTool(QObject *parent) : QObject(parent) {}

void RoomEditTool::setWorld(const sim::World *world)
{
    m_world = world;
    if (!m_world)
        setEditing(false);
    else if (m_selected && !sim::contains(*m_world, *m_selected))
        m_selected.reset();
}

void RoomEditTool::setEditing(bool editing)
{
    editing = editing && m_world;
    if (m_editing == editing)
        return;
    m_editing = editing;
    m_hold.reset();
    if (!editing)
        m_selected.reset();
    emit editingChanged(editing);
    emit changed();
}

void RoomEditTool::setSelectedItem(std::optional<sim::WorldItem> item)
{
    if (item && !(m_world && sim::contains(*m_world, *item)))
        item.reset();
    m_selected = item;
    emit changed();
}

bool RoomEditTool::press(QPointF floorMm, double toleranceMm, bool turn, bool robotThere)
{
    if (!m_editing || !m_world)
        return false;
    const std::optional<WorldGrip> grip = WorldGrip::at(*m_world, floorMm, toleranceMm, m_selected);
    // The selected thing's handles come before a robot standing on them;
    // anything else comes after the robots.
    const bool onHandle = grip && grip->item == m_selected && grip->handle != WorldGrip::Handle::Body;
    if (!onHandle && robotThere)
        return false;
    if (!grip) {
        setSelectedItem(std::nullopt);
        return false;
    }
    setSelectedItem(grip->item);
    m_hold = Hold{*grip, *m_world, floorMm, turn, sim::WorldEdit::put(grip->item, *m_world)};
    m_hold->last.gesture = ++m_lastGesture;
    return true;
}

bool RoomEditTool::drag(QPointF floorMm)
{
    if (!m_hold)
        return false;
    sim::WorldEdit edit = m_hold->grip.dragged(m_hold->start, m_hold->fromMm, floorMm, m_hold->turning);
    edit.gesture = m_hold->last.gesture;
    // Snapped: most pointer steps ask for the same floor again.
    if (!(edit == m_hold->last)) {
        m_hold->last = edit;
        emit editRequested(edit);
    }
    return true;
}

Qt::CursorShape RoomEditTool::hoverCursor(QPointF floorMm, double toleranceMm) const
{
    if (m_hold) {
        const bool carried = m_hold->grip.handle == WorldGrip::Handle::Body && !m_hold->turning;
        return carried ? Qt::ClosedHandCursor : Qt::CrossCursor;
    }
    const auto grip = m_world ? WorldGrip::at(*m_world, floorMm, toleranceMm, m_selected) : std::nullopt;
    if (!grip)
        return Qt::ArrowCursor;
    return grip->handle == WorldGrip::Handle::Body ? Qt::OpenHandCursor : Qt::CrossCursor;
}

bool RoomEditTool::keyPressed(int key)
{
    if (!m_editing || !m_selected)
        return false;
    if (key == Qt::Key_Delete || key == Qt::Key_Backspace) {
        remove(*m_selected);
        return true;
    }
    if (key == Qt::Key_Escape) {
        setSelectedItem(std::nullopt);
        return true;
    }
    return false;
}

void RoomEditTool::request(sim::WorldEdit edit)
{
    edit.gesture = ++m_lastGesture;
    emit editRequested(edit);
}

void RoomEditTool::add(sim::WorldPart part, QPointF floorMm)
{
    if (!m_world)
        return;
    // The new one will be last in its list: selected once the floor comes back.
    const int index = part == sim::WorldPart::Wall      ? int(m_world->walls.size())
                      : part == sim::WorldPart::DropOff ? int(m_world->dropOffs.size())
                                                        : 0;
    request(addedAt(*m_world, part, floorMm));
    m_selected = sim::WorldItem{part, index};
    emit changed();
}

void RoomEditTool::remove(sim::WorldItem item)
{
    m_selected.reset();
    m_hold.reset();
    request(sim::WorldEdit::remove(item));
    emit changed();
}

void RoomEditTool::fillMenu(QMenu *menu, QPointF floorMm, double toleranceMm)
{
    QAction *edit = menu->addAction(tr("Edit room"));
    edit->setObjectName("editRoomAction");
    edit->setCheckable(true);
    edit->setChecked(m_editing);
    connect(edit, &QAction::toggled, this, &RoomEditTool::setEditing);
    if (!m_editing || !m_world)
        return;
    menu->addSeparator();
    const auto add = [this, menu, floorMm](const char *name, const QString &text, sim::WorldPart part) {
        QAction *a = menu->addAction(text);
        a->setObjectName(name);
        connect(a, &QAction::triggered, this, [this, part, floorMm] { this->add(part, floorMm); });
    };
    add("addWallAction", tr("Add wall here"), sim::WorldPart::Wall);
    add("addDropOffAction", tr("Add stage edge here"), sim::WorldPart::DropOff);
    add("putVirtualWallAction", m_world->virtualWall ? tr("Move the virtual wall here") : tr("Add virtual wall here"),
        sim::WorldPart::VirtualWall);
    add("putDockAction", tr("Put the dock here"), sim::WorldPart::Dock);
    if (const auto grip = WorldGrip::at(*m_world, floorMm, toleranceMm, m_selected)) {
        setSelectedItem(grip->item);
        menu->addSeparator();
        QAction *remove = menu->addAction(tr("Delete %1").arg(itemName(grip->item.part)));
        remove->setObjectName("deleteItemAction");
        remove->setShortcut(QKeySequence::Delete);
        const sim::WorldItem item = grip->item;
        connect(remove, &QAction::triggered, this, [this, item] { this->remove(item); });
    }
}

QString RoomEditTool::bannerText() const
{
    return m_selected ? tr("Editing %1: drag it or its handles · Delete removes it").arg(itemName(m_selected->part))
                      : tr("Editing the room: click a thing to select it · right-click to add");
}

QString RoomEditTool::itemName(sim::WorldPart part)
{
    switch (part) {
    case sim::WorldPart::Wall: return tr("the wall");
    case sim::WorldPart::DropOff: return tr("the stage edge");
    case sim::WorldPart::Dock: return tr("the dock");
    case sim::WorldPart::VirtualWall: return tr("the virtual wall");
    }
    return QString();
}

void RoomEditTool::paintSelection(QPainter &painter, const OdometryMap &map) const
{
    if (!m_editing || !m_world || !m_selected || !sim::contains(*m_world, *m_selected))
        return;
    const sim::World &world = *m_world;
    const sim::WorldItem item = *m_selected;
    const QPalette palette = map.palette();
    QColor halo = palette.color(QPalette::Highlight);
    halo.setAlpha(110);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(halo, 16, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    switch (item.part) {
    case sim::WorldPart::Wall: {
        const sim::Segment &s = world.walls[std::size_t(item.index)];
        painter.drawLine(map.widgetPointFor({s.x1, s.y1}), map.widgetPointFor({s.x2, s.y2}));
        // The wall itself in the highlight colour, so it stands out from its neighbours.
        painter.setPen(QPen(palette.color(QPalette::Highlight), 6, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(map.widgetPointFor({s.x1, s.y1}), map.widgetPointFor({s.x2, s.y2}));
        paintLengthLabel(painter, map, map.widgetPointFor({(s.x1 + s.x2) / 2, (s.y1 + s.y2) / 2}),
                         tr("%1 m").arg(std::hypot(s.x2 - s.x1, s.y2 - s.y1) / 1000, 0, 'f', 2));
        break;
    }
    case sim::WorldPart::DropOff: {
        const sim::Area &a = world.dropOffs[std::size_t(item.index)];
        painter.setPen(QPen(halo, 10, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin));
        const QRectF r = QRectF(map.widgetPointFor({a.xMin, a.yMax}), map.widgetPointFor({a.xMax, a.yMin})).normalized();
        painter.drawRect(r);
        paintLengthLabel(painter, map, r.center(),
                         tr("%1 × %2 m").arg((a.xMax - a.xMin) / 1000, 0, 'f', 2).arg((a.yMax - a.yMin) / 1000, 0, 'f', 2));
        break;
    }
    case sim::WorldPart::Dock: {
        const auto &d = *world.dock;
        const double r = std::max(14.0, 200 * map.scale());
        painter.drawEllipse(map.widgetPointFor({d.x - 60 * std::cos(d.headingRad), d.y - 60 * std::sin(d.headingRad)}), r, r);
        break;
    }
    case sim::WorldPart::VirtualWall: {
        const auto &v = *world.virtualWall;
        painter.drawLine(map.widgetPointFor({v.x, v.y}), map.widgetPointFor({v.x + v.rangeMm * std::cos(v.headingRad),
                                                                      v.y + v.rangeMm * std::sin(v.headingRad)}));
        break;
    }
    }
    // Handles: squares in the highlight colour, ringed so they show on any floor.
    const QList<std::pair<WorldGrip::Handle, QPointF>> handles = WorldGrip::handles(world, item);
    for (const auto &[handle, where] : handles) {
        const QPointF c = map.widgetPointFor(where);
        if (handle == WorldGrip::Handle::Aim) {
            // The heading handle hangs from a thin line so it reads as "turn me".
            const QPointF from = item.part == sim::WorldPart::Dock ? map.widgetPointFor({world.dock->x, world.dock->y})
                                                                   : map.widgetPointFor({world.virtualWall->x, world.virtualWall->y});
            painter.setPen(QPen(palette.color(QPalette::Highlight), 2, Qt::DotLine));
            painter.drawLine(from, c);
        }
        painter.setPen(QPen(palette.color(QPalette::Base), 2));
        painter.setBrush(palette.color(QPalette::Highlight));
        const QRectF square(c - QPointF(kHandlePx / 2, kHandlePx / 2), QSizeF(kHandlePx, kHandlePx));
        if (handle == WorldGrip::Handle::Aim)
            painter.drawEllipse(square);
        else
            painter.drawRect(square);
    }
    painter.setBrush(Qt::NoBrush);
}

void RoomEditTool::paintLengthLabel(QPainter &painter, const OdometryMap &map, QPointF centre, const QString &text) const
{
    const QPalette palette = map.palette();
    // On a plate of the base colour, so it reads over walls and hatching.
    const QFont bold = display::valueFont(map.font(), 1.1);
    const QFontMetricsF fm(bold);
    const QRectF box(centre.x() - fm.horizontalAdvance(text) / 2 - 4, centre.y() + 8, fm.horizontalAdvance(text) + 8,
                     fm.height() + 2);
    painter.setPen(QPen(palette.color(QPalette::Highlight), 1.5));
    painter.setBrush(palette.color(QPalette::Base));
    painter.drawRoundedRect(box, 3, 3);
    painter.setBrush(Qt::NoBrush);
    painter.setFont(bold);
    painter.setPen(palette.color(QPalette::Text));
    painter.drawText(box, Qt::AlignCenter, text);
    painter.setFont(map.font());
}

#include "moc_room_edit_tool.cpp"
