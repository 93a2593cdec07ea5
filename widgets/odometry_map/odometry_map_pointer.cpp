// SPDX-License-Identifier: GPL-3.0-or-later
// The odometry map under the hand: the wheel zooms, a drag carries or turns
// a robot, a double click lifts it, and the keys and context menu edit the room.
#include "odometry_map.h"
#include "odometry_map_measures.h"

#include "room_edit_tool.h"

#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

void OdometryMap::wheelEvent(QWheelEvent *event)
{
    const int steps = event->angleDelta().y();
    if (steps == 0)
        return;
    zoomBy(std::pow(map_measures::kZoomStep, steps / 120.0), event->position());
    event->accept();
}

QPointF OdometryMap::floorPointFor(QPointF widgetPoint) const
{
    const QPointF c = QRectF(mapRect()).center();
    return QPointF(m_centreMm.x() + (widgetPoint.x() - c.x()) / m_scale,
                   m_centreMm.y() - (widgetPoint.y() - c.y()) / m_scale);
}

const OdometryMap::TruePose *OdometryMap::truePoseAt(QPointF widgetPoint) const
{
    const double radius = std::max(8.0, map_measures::kRobotDiameterMm / 2 * m_scale);
    // The last drawn is on top.
    for (qsizetype i = m_truePoses.size() - 1; i >= 0; --i) {
        const QPointF d = widgetPointFor({m_truePoses[i].pose.xMm, m_truePoses[i].pose.yMm}) - widgetPoint;
        if (std::hypot(d.x(), d.y()) <= radius)
            return &m_truePoses[i];
    }
    return nullptr;
}

void OdometryMap::mousePressEvent(QMouseEvent *event)
{
    if (!mapRect().contains(event->position().toPoint()))
        return;
    if (event->button() == Qt::LeftButton
        && m_editTool->press(floorPointFor(event->position()), gripToleranceMm(),
                             (event->modifiers() & Qt::ShiftModifier) != 0, truePoseAt(event->position()))) {
        setCursor(m_editTool->hoverCursor(floorPointFor(event->position()), gripToleranceMm()));
        return;
    }
    const bool turn = event->button() == Qt::RightButton
                      || (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
    if (event->button() == Qt::LeftButton || turn) {
        if (const TruePose *t = truePoseAt(event->position())) {
            m_hold = Hold{t->robot, t->pose, floorPointFor(event->position()) - QPointF(t->pose.xMm, t->pose.yMm), turn};
            setCursor(turn ? Qt::SizeAllCursor : Qt::ClosedHandCursor);
            return;
        }
    }
    if (event->button() == Qt::LeftButton) {
        m_dragFrom = event->position();
        setCursor(Qt::ClosedHandCursor);
    }
}

void OdometryMap::mouseMoveEvent(QMouseEvent *event)
{
    if (m_editTool->drag(floorPointFor(event->position())))
        return;
    if (m_editTool->isEditing() && !m_hold && !m_dragFrom) {
        const Qt::CursorShape shape = m_editTool->hoverCursor(floorPointFor(event->position()), gripToleranceMm());
        if (shape == Qt::ArrowCursor)
            unsetCursor();
        else
            setCursor(shape);
        return;
    }
    if (m_hold) {
        const QPointF at = floorPointFor(event->position());
        if (m_hold->turning) {
            // It faces the pointer.
            m_hold->pose.thetaRad = std::atan2(at.y() - m_hold->pose.yMm, at.x() - m_hold->pose.xMm);
        } else {
            m_hold->pose.xMm = at.x() - m_hold->grabOffsetMm.x();
            m_hold->pose.yMm = at.y() - m_hold->grabOffsetMm.y();
        }
        emit robotMoveRequested(m_hold->robot, m_hold->pose);
        return;
    }
    if (!m_dragFrom)
        return;
    const QPointF delta = event->position() - *m_dragFrom;
    m_dragFrom = event->position();
    setViewCentreMm(m_centreMm + QPointF(-delta.x() / m_scale, delta.y() / m_scale));
}

void OdometryMap::mouseReleaseEvent(QMouseEvent *)
{
    m_dragFrom.reset();
    m_hold.reset();
    m_editTool->release();
    unsetCursor();
}

void OdometryMap::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return;
    if (const TruePose *t = truePoseAt(event->position()))
        emit robotLiftRequested(t->robot, !t->lifted);
}

void OdometryMap::keyPressEvent(QKeyEvent *event)
{
    if (!m_editTool->keyPressed(event->key()))
        QWidget::keyPressEvent(event);
}

QMenu *OdometryMap::contextMenuAt(QPoint at)
{
    if (!m_world)
        return nullptr;
    auto *menu = new QMenu(this);
    m_editTool->fillMenu(menu, floorPointFor(at), gripToleranceMm());
    // Whatever the owner of the room added (Undo, Redo).
    if (m_editTool->isEditing() && !actions().isEmpty()) {
        menu->addSeparator();
        menu->addActions(actions());
    }
    return menu;
}

void OdometryMap::contextMenuEvent(QContextMenuEvent *event)
{
    // The right button turning a robot is not a call for the menu.
    if (m_hold || truePoseAt(event->pos()))
        return;
    if (QMenu *menu = contextMenuAt(event->pos())) {
        menu->exec(event->globalPos());
        delete menu;
    }
}
