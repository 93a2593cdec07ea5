// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "world.h"
#include "world_grip.h"

#include <QObject>
#include <QPointF>

#include <cstdint>
#include <optional>

class OdometryMap;
class QMenu;
class QPainter;

// The hand that edits the room on the map: whether editing is on, what is
// selected, what the pointer holds, and the edits it asks of whoever owns
// the room (editRequested). It keeps no floor of its own; it reads the one
// the map shows, and the map hands it the pointer in floor millimetres.
//
// Click a wall, a stage edge (drop-off), the dock or the virtual wall to
// select it; drag it or its handles (Shift turns the dock); Delete removes
// it; Esc or a click on the bare floor lets go; the context menu adds new
// ones. Every step of a drag asks again, with one gesture number.
class RoomEditTool : public QObject {
    Q_OBJECT
public:
    explicit RoomEditTool(QObject *parent = nullptr);

    // The floor shown, owned by the map; nullptr: none, and editing ends.
    void setWorld(const sim::World *world);

    void setEditing(bool editing);
    bool isEditing() const { return m_editing; }
    std::optional<sim::WorldItem> selectedItem() const { return m_selected; }
    void setSelectedItem(std::optional<sim::WorldItem> item);
    bool isHolding() const { return m_hold.has_value(); }

    // A left press at `floorMm`, within `toleranceMm`: takes hold of what
    // is there and returns true, or returns false for the map to handle
    // (a robot standing there, or the bare floor, which lets go).
    bool press(QPointF floorMm, double toleranceMm, bool turn, bool robotThere);
    // The pointer moved while pressed; false when the tool holds nothing.
    bool drag(QPointF floorMm);
    void release() { m_hold.reset(); }
    // The pointer's shape over `floorMm` while nothing is held.
    Qt::CursorShape hoverCursor(QPointF floorMm, double toleranceMm) const;
    // Delete or Backspace removes the selection, Esc lets it go. Returns
    // whether the key was the tool's.
    bool keyPressed(int key);

    // Asks for a new thing of `part` at `floorMm`, selected once it is there.
    void add(sim::WorldPart part, QPointF floorMm);
    void remove(sim::WorldItem item);
    // The context menu's entries at `floorMm`: Edit room, and while editing
    // the things to add and Delete for what is there.
    void fillMenu(QMenu *menu, QPointF floorMm, double toleranceMm);

    // The selection with its handles and size, on `map`.
    void paintSelection(QPainter &painter, const OdometryMap &map) const;
    // What the banner over the map says while editing.
    QString bannerText() const;
    static QString itemName(sim::WorldPart part);

signals:
    void editRequested(const sim::WorldEdit &edit);
    void editingChanged(bool editing);
    // The selection or editing changed: the map draws again.
    void changed();

private:
    void request(sim::WorldEdit edit);
    void paintLengthLabel(QPainter &painter, const OdometryMap &map, QPointF centre, const QString &text) const;

    const sim::World *m_world = nullptr;
    bool m_editing = false;
    std::optional<sim::WorldItem> m_selected;
    // A thing on the floor held by the pointer, and the floor when it was taken.
    struct Hold {
        WorldGrip grip;
        sim::World start;
        QPointF fromMm;
        bool turning = false;
        sim::WorldEdit last;
    };
    std::optional<Hold> m_hold;
    std::uint64_t m_lastGesture = 0;
};
