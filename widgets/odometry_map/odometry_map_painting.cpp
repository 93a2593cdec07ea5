// SPDX-License-Identifier: GPL-3.0-or-later
// How the odometry map paints: the grid, the room, the trails, the robots,
// the legend, the scale bar and the editing banner.
#include "odometry_map.h"
#include "odometry_map_measures.h"

#include "display_palette.h"
#include "display_tick.h"
#include "room_edit_tool.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

void OdometryMap::paintEvent(QPaintEvent *)
{
    if (!DisplayTick::instance().isListening(this))
        followDisplay(); // on screen again, by whatever way
    QPainter painter(this);
    const QRect area = mapRect();
    painter.fillRect(area, palette().base());
    painter.setClipRect(area);
    painter.setRenderHint(QPainter::Antialiasing);

    paintGrid(painter, area);
    if (m_world)
        paintWorld(painter);
    m_editTool->paintSelection(painter, *this);

    const bool identified = !m_odometry || m_odometry->isIdentified();
    const QList<QPointF> trail = this->trail();
    if (identified && trail.size() > 1) {
        painter.setPen(QPen(odometryColour(), 2));
        painter.drawPolyline(widgetPolygon(trail));
    }
    if (m_comparisonPath.size() > 1) {
        painter.setPen(comparisonPen());
        painter.drawPolyline(widgetPolygon(m_comparisonPath));
    }
    paintTruePoses(painter);
    if (identified)
        paintRobot(painter, pose(), odometryColour(), false);
    paintScaleBar(painter, area);

    painter.setClipping(false);
    paintLegend(painter);
    if (m_editTool->isEditing())
        paintEditBanner(painter, area);
}

void OdometryMap::setComparisonPath(const QVector<QPointF> &pointsMm, const QString &label)
{
    m_comparisonPath = pointsMm;
    m_comparisonLabel = pointsMm.isEmpty() ? QString() : label;
    update();
}

QPen OdometryMap::comparisonPen() const
{
    // Neither a robot's colour nor a solid or dashed line: another run.
    QColor colour = palette().color(QPalette::Text);
    colour.setAlpha(170);
    QPen pen(colour, 2.5, Qt::DashDotLine);
    pen.setCapStyle(Qt::FlatCap);
    return pen;
}

QList<OdometryMap::LegendEntry> OdometryMap::legend() const
{
    // Everything the map draws, drawn as the map draws it.
    QList<LegendEntry> entries;
    entries << LegendEntry{tr("odometry"), QPen(odometryColour(), 2)};
    if (!m_truePoses.isEmpty()) {
        // The selected robot's, or the first robot's: in the dashboard the
        // odometry's own colour, dashed.
        qsizetype index = 0;
        for (qsizetype i = 0; i < m_truePoses.size(); ++i)
            if (m_truePoses[i].robot == m_selected)
                index = i;
        entries << LegendEntry{tr("true pose"), QPen(truePoseColour(index), 2, Qt::DashLine)};
    }
    if (m_comparisonPath.size() > 1)
        entries << LegendEntry{m_comparisonLabel.isEmpty() ? tr("comparison run") : m_comparisonLabel,
                               comparisonPen()};
    if (m_world) {
        if (!m_world->walls.empty())
            entries << LegendEntry{tr("wall"), wallPen()};
        if (!m_world->dropOffs.empty()) {
            const QColor drop = display::stateColor(display::State::Alert, palette());
            entries << LegendEntry{tr("stage edge"), QPen(drop, 2), QBrush(drop, Qt::BDiagPattern)};
        }
        if (m_world->virtualWall)
            entries << LegendEntry{tr("virtual wall"), virtualWallPen()};
        if (m_world->dock) {
            const QColor dock = display::stateColor(display::State::Warning, palette());
            entries << LegendEntry{tr("dock"), QPen(dock.darker(130), 1.5), QBrush(dock)};
        }
    }
    return entries;
}

QPen OdometryMap::wallPen() const
{
    return QPen(palette().color(QPalette::Text), 4, Qt::SolidLine, Qt::SquareCap);
}

QPen OdometryMap::virtualWallPen() const
{
    return QPen(display::stateColor(display::State::Stale, palette()), 3, Qt::DashLine);
}

QStringList OdometryMap::legendLabels() const
{
    QStringList labels;
    for (const LegendEntry &entry : legend())
        labels << entry.text;
    return labels;
}

QList<QRect> OdometryMap::robotRects() const
{
    const double radius = std::max(8.0, map_measures::kRobotDiameterMm / 2 * m_scale) + 3; // its pen, and a heading line
    const auto around = [&](const oi::Pose &p) {
        const QPointF c = widgetPointFor({p.xMm, p.yMm});
        return QRectF(c.x() - radius, c.y() - radius, 2 * radius, 2 * radius).toAlignedRect();
    };
    QList<QRect> rects;
    if (!m_odometry || m_odometry->isIdentified())
        rects << around(pose());
    for (const TruePose &t : m_truePoses)
        rects << around(t.pose);
    return rects;
}

QRect OdometryMap::legendRect() const
{
    const QList<LegendEntry> entries = legend();
    const QFontMetrics fm(font());
    // Sizes follow the font, so the legend grows with it.
    const int gap = fm.averageCharWidth();
    const int swatch = fm.ascent() * 3 / 2;
    int textWidth = 0;
    for (const LegendEntry &entry : entries)
        textWidth = std::max(textWidth, fm.horizontalAdvance(entry.text));
    const QSize size(3 * gap + swatch + textWidth, int(entries.size()) * (fm.height() + 4) + 4);
    const QRect area = mapRect();
    // Clear of the grid's labels along the top and the pose and scale bar along the bottom.
    const QRect room = area.adjusted(gap, 2 * fm.height(), -gap, -3 * fm.height());
    const QList<QRect> robots = robotRects();
    const QList<QRect> corners = {QRect(QPoint(room.right() - size.width(), room.top()), size),
                                  QRect(room.topLeft() + QPoint(3 * fm.height(), 0), size),
                                  QRect(QPoint(room.right() - size.width(), room.bottom() - size.height()), size),
                                  QRect(QPoint(room.left() + 3 * fm.height(), room.bottom() - size.height()), size)};
    for (const QRect &corner : corners)
        if (std::none_of(robots.begin(), robots.end(), [&](const QRect &r) { return r.intersects(corner); }))
            return corner;
    return corners.first(); // a robot in every corner: a small map, and they move
}

void OdometryMap::paintLegend(QPainter &painter) const
{
    const QList<LegendEntry> entries = legend();
    const QFontMetrics fm(font());
    const int gap = fm.averageCharWidth();
    const int swatch = fm.ascent() * 3 / 2;
    const QRect box = legendRect();
    QColor back = palette().color(QPalette::Base);
    back.setAlpha(220);
    painter.fillRect(box, back);
    int y = box.top() + 2;
    for (const LegendEntry &entry : entries) {
        const QRect sample(box.left() + gap, y + 2, swatch, fm.height() - 4);
        const QRect text(sample.right() + gap, y, box.right() - sample.right() - gap, fm.height());
        if (entry.fill.style() != Qt::NoBrush) {
            painter.setPen(entry.pen);
            painter.setBrush(entry.fill);
            painter.drawRect(sample);
            painter.setBrush(Qt::NoBrush);
        } else {
            painter.setPen(entry.pen);
            painter.drawLine(QPointF(sample.left(), sample.center().y() + 0.5),
                             QPointF(sample.right(), sample.center().y() + 0.5));
        }
        painter.setPen(palette().color(QPalette::Text));
        painter.drawText(text, Qt::AlignLeft | Qt::AlignVCenter, entry.text);
        y += fm.height() + 4;
    }
}

void OdometryMap::paintGrid(QPainter &painter, const QRect &area) const
{
    const double spacing = gridSpacingMm();
    const QPointF c = QRectF(area).center();
    const double xMin = m_centreMm.x() - (c.x() - area.left()) / m_scale;
    const double xMax = m_centreMm.x() + (area.right() - c.x()) / m_scale;
    const double yMin = m_centreMm.y() - (area.bottom() - c.y()) / m_scale;
    const double yMax = m_centreMm.y() + (c.y() - area.top()) / m_scale;

    QColor minor = palette().color(QPalette::Text);
    minor.setAlpha(35);
    QColor axis = palette().color(QPalette::Text);
    axis.setAlpha(110);
    const QFontMetrics fm(font());
    for (double x = std::ceil(xMin / spacing) * spacing; x <= xMax; x += spacing) {
        const double px = widgetPointFor({x, 0}).x();
        painter.setPen(QPen(std::abs(x) < spacing / 2 ? axis : minor, 1));
        painter.drawLine(QPointF(px, area.top()), QPointF(px, area.bottom()));
        painter.setPen(axis);
        // Along the top: the pose text and the scale bar sit at the bottom.
        painter.drawText(QPointF(px + 3, area.top() + fm.ascent() + 2), QString::number(x, 'f', 0));
    }
    for (double y = std::ceil(yMin / spacing) * spacing; y <= yMax; y += spacing) {
        const double py = widgetPointFor({0, y}).y();
        painter.setPen(QPen(std::abs(y) < spacing / 2 ? axis : minor, 1));
        painter.drawLine(QPointF(area.left(), py), QPointF(area.right(), py));
        painter.setPen(axis);
        painter.drawText(QPointF(area.left() + 3, py - 3), QString::number(y, 'f', 0));
    }
}

void OdometryMap::paintWorld(QPainter &painter) const
{
    const sim::World &world = *m_world;
    const QColor drop = display::stateColor(display::State::Alert, palette());
    QColor dropFill = drop;
    dropFill.setAlpha(70);
    for (const sim::Area &a : world.dropOffs) {
        const QRectF r = QRectF(widgetPointFor({a.xMin, a.yMax}), widgetPointFor({a.xMax, a.yMin})).normalized();
        painter.fillRect(r, QBrush(dropFill));
        painter.fillRect(r, QBrush(drop, Qt::BDiagPattern));
        painter.setPen(QPen(drop, 2));
        painter.drawRect(r);
    }
    painter.setPen(wallPen());
    for (const sim::Segment &s : world.walls)
        painter.drawLine(widgetPointFor({s.x1, s.y1}), widgetPointFor({s.x2, s.y2}));
    if (m_editTool->isEditing()) {
        // Every wall's ends can be taken: show where.
        painter.setPen(Qt::NoPen);
        painter.setBrush(palette().color(QPalette::Text));
        for (const sim::Segment &s : world.walls)
            for (const QPointF end : {QPointF(s.x1, s.y1), QPointF(s.x2, s.y2)})
                painter.drawEllipse(widgetPointFor(end), 5, 5);
        painter.setBrush(Qt::NoBrush);
    }

    if (world.virtualWall) {
        const auto &v = *world.virtualWall;
        const QPointF from = widgetPointFor({v.x, v.y});
        const QPointF to = widgetPointFor({v.x + v.rangeMm * std::cos(v.headingRad),
                                           v.y + v.rangeMm * std::sin(v.headingRad)});
        painter.setPen(virtualWallPen());
        painter.drawLine(from, to);
        painter.setBrush(virtualWallPen().color());
        painter.setPen(Qt::NoPen);
        painter.drawEllipse(from, 6, 6);
        painter.setBrush(Qt::NoBrush);
    }
    if (world.dock) {
        const auto &d = *world.dock;
        const QColor dock = display::stateColor(display::State::Warning, palette());
        // A base 300 mm wide behind the contacts, facing out along its heading.
        const double half = 150, depth = 120;
        const double c = std::cos(d.headingRad), s = std::sin(d.headingRad);
        const auto at = [&](double back, double side) {
            return widgetPointFor({d.x - back * c - side * s, d.y - back * s + side * c});
        };
        QPolygonF base{at(0, -half), at(0, half), at(depth, half), at(depth, -half)};
        painter.setPen(QPen(dock.darker(130), 1.5));
        painter.setBrush(dock);
        painter.drawPolygon(base);
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(dock, 2));
        painter.drawLine(at(0, 0), at(-200, 0));
        painter.setPen(palette().color(QPalette::Text));
        painter.drawText(at(depth, half) + QPointF(4, 0), tr("dock"));
    }
}

void OdometryMap::paintTruePoses(QPainter &painter) const
{
    const QFontMetrics fm(font());
    for (qsizetype i = 0; i < m_truePoses.size(); ++i) {
        const TruePose &t = m_truePoses[i];
        const QColor colour = truePoseColour(i);
        const QPointF centre = widgetPointFor({t.pose.xMm, t.pose.yMm});
        const double radius = std::max(8.0, map_measures::kRobotDiameterMm / 2 * m_scale);
        if (t.lifted) {
            // Held up: its shadow on the floor below and to the right.
            QColor shadow = palette().color(QPalette::Text);
            shadow.setAlpha(60);
            painter.setPen(Qt::NoPen);
            painter.setBrush(shadow);
            painter.drawEllipse(centre + QPointF(radius / 4, radius / 4), radius, radius);
            painter.setBrush(Qt::NoBrush);
        }
        const bool selected = m_selected == t.robot;
        if (selected) {
            painter.setPen(QPen(colour, 1, Qt::DashLine));
            painter.drawLine(centre, widgetPointFor({pose().xMm, pose().yMm}));
            // A halo marks the robot this map's odometry belongs to.
            QColor halo = colour;
            halo.setAlpha(90);
            painter.setPen(QPen(halo, 6));
            painter.drawEllipse(centre, radius + 4, radius + 4);
        }
        paintRobot(painter, t.pose, colour, true);
        if (m_truePoses.size() > 1) {
            const QString number = QString::number(t.robot);
            painter.setPen(palette().color(QPalette::Text));
            painter.drawText(centre + QPointF(radius + 4, -radius), number);
        }
    }
}

void OdometryMap::paintRobot(QPainter &painter, const oi::Pose &pose, const QColor &colour, bool outline) const
{
    const QPointF centre = widgetPointFor({pose.xMm, pose.yMm});
    const double radius = std::max(8.0, map_measures::kRobotDiameterMm / 2 * m_scale);
    QColor fill = colour;
    fill.setAlpha(outline ? 0 : 70);
    painter.setBrush(fill);
    painter.setPen(QPen(colour, 2, outline ? Qt::DashLine : Qt::SolidLine));
    painter.drawEllipse(centre, radius, radius);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(colour, 2.5));
    painter.drawLine(centre, centre + QPointF(radius * std::cos(pose.thetaRad), -radius * std::sin(pose.thetaRad)));
}

void OdometryMap::paintScaleBar(QPainter &painter, const QRect &area) const
{
    const double spacing = gridSpacingMm();
    const double px = spacing * m_scale;
    const QPointF right(area.right() - 12, area.bottom() - 12);
    const QPointF left = right - QPointF(px, 0);
    painter.setPen(QPen(palette().color(QPalette::Text), 2));
    painter.drawLine(left, right);
    painter.drawLine(left, left - QPointF(0, 5));
    painter.drawLine(right, right - QPointF(0, 5));
    const QString text = spacing >= 1000 ? tr("%1 m").arg(spacing / 1000) : tr("%1 mm").arg(spacing);
    // Centred over the bar, one line high above its ticks.
    const QFontMetricsF fm(font());
    const double w = std::max(px, fm.horizontalAdvance(text));
    painter.drawText(QRectF(right.x() - w, left.y() - 6 - fm.height(), w, fm.height()), Qt::AlignCenter, text);
}

void OdometryMap::paintEditBanner(QPainter &painter, const QRect &area) const
{
    // A frame round the map says the floor is open to the hand, from the back of the room.
    const QColor frame = palette().color(QPalette::Highlight);
    painter.setPen(QPen(frame, 4));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(QRectF(area).adjusted(2, 2, -2, -2));
    const QString text = m_editTool->bannerText();
    const QFont bold = display::valueFont(font(), 1.15);
    const QFontMetrics fm(bold);
    const int pad = fm.averageCharWidth();
    // At the foot of the map, between the pose and the scale bar, clear of
    // the room's far corners where walls are often taken.
    const int w = fm.horizontalAdvance(text) + 2 * pad, h = fm.height() + pad;
    const int left = std::max(m_poseLabel->geometry().right() + 8, area.center().x() - w / 2);
    const QRect box(std::min(left, std::max(8, area.right() - 8 - w)), area.bottom() - 8 - h, w, h);
    painter.setPen(Qt::NoPen);
    painter.setBrush(frame);
    painter.drawRoundedRect(box, 4, 4);
    painter.setBrush(Qt::NoBrush);
    painter.setFont(bold);
    painter.setPen(palette().color(QPalette::HighlightedText));
    painter.drawText(box, Qt::AlignCenter, text);
    painter.setFont(font());
}
