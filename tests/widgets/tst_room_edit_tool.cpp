// SPDX-License-Identifier: GPL-3.0-or-later
// The room-edit tool on its own: floor points in, edits out, no widget.
#include "room_edit_tool.h"

#include <QAction>
#include <QMenu>
#include <QSignalSpy>
#include <QTest>

using sim::WorldEdit;
using sim::WorldItem;
using sim::WorldPart;

namespace {

// A wall along the x axis and a stage edge apart from it.
sim::World testFloor()
{
    sim::World w;
    w.walls = {{0, 0, 1000, 0}};
    w.dropOffs = {{1500, -500, 2000, 0}};
    return w;
}

constexpr double kTolerance = 40; // mm

} // namespace

class TestRoomEditTool : public QObject {
    Q_OBJECT
    sim::World m_floor = testFloor();

    WorldEdit edit(const QSignalSpy &spy, qsizetype i) const { return spy.at(i).at(0).value<WorldEdit>(); }

private slots:
    void initTestCase() { qRegisterMetaType<WorldEdit>(); }

    void editsOnlyWhileOnAndWithAFloor()
    {
        RoomEditTool tool;
        QSignalSpy editing(&tool, &RoomEditTool::editingChanged);
        tool.setEditing(true); // no floor yet
        QVERIFY(!tool.isEditing());
        tool.setWorld(&m_floor);
        QVERIFY(!tool.press({500, 0}, kTolerance, false, false)); // not editing
        tool.setEditing(true);
        QVERIFY(tool.isEditing());
        QVERIFY(tool.press({500, 0}, kTolerance, false, false));
        QCOMPARE(tool.selectedItem(), (WorldItem{WorldPart::Wall, 0}));
        tool.release();
        // The floor taken away ends editing and lets go.
        tool.setWorld(nullptr);
        QVERIFY(!tool.isEditing());
        QVERIFY(!tool.selectedItem());
        QCOMPARE(editing.count(), 2);
    }

    void aDragAsksForEachNewFloorWithOneGesture()
    {
        RoomEditTool tool;
        tool.setWorld(&m_floor);
        tool.setEditing(true);
        QSignalSpy edits(&tool, &RoomEditTool::editRequested);
        QVERIFY(tool.press({500, 3}, kTolerance, false, false));
        QCOMPARE(tool.hoverCursor({0, 0}, kTolerance), Qt::ClosedHandCursor);
        QVERIFY(tool.drag({500, 103}));
        QVERIFY(tool.drag({500, 104})); // snaps to the same floor: not asked again
        QVERIFY(tool.drag({500, 303}));
        tool.release();
        QVERIFY(!tool.drag({500, 503}));
        QCOMPARE(edits.count(), 2);
        QCOMPARE(edit(edits, 0).item, (WorldItem{WorldPart::Wall, 0}));
        QCOMPARE(edit(edits, 0).wall.y1, 100.0);
        QCOMPARE(edit(edits, 1).wall.y1, 300.0);
        QCOMPARE(edit(edits, 0).gesture, edit(edits, 1).gesture);
    }

    void aRobotOrTheBareFloorIsNotTheTools()
    {
        RoomEditTool tool;
        tool.setWorld(&m_floor);
        tool.setEditing(true);
        QVERIFY(!tool.press({500, 0}, kTolerance, false, true)); // a robot stands on the wall
        QVERIFY(tool.press({500, 0}, kTolerance, false, false));
        tool.release();
        QVERIFY(tool.selectedItem());
        QCOMPARE(tool.hoverCursor({1000, 0}, kTolerance), Qt::CrossCursor); // the wall's end
        QCOMPARE(tool.hoverCursor({500, 900}, kTolerance), Qt::ArrowCursor);
        QVERIFY(!tool.press({500, 900}, kTolerance, false, false)); // bare floor: lets go
        QVERIFY(!tool.selectedItem());
    }

    void keysDeleteAndLetGo()
    {
        RoomEditTool tool;
        tool.setWorld(&m_floor);
        tool.setEditing(true);
        QSignalSpy edits(&tool, &RoomEditTool::editRequested);
        QVERIFY(!tool.keyPressed(Qt::Key_Delete)); // nothing selected
        tool.setSelectedItem(WorldItem{WorldPart::DropOff, 0});
        QVERIFY(tool.keyPressed(Qt::Key_Escape));
        QVERIFY(!tool.selectedItem());
        tool.setSelectedItem(WorldItem{WorldPart::DropOff, 0});
        QVERIFY(tool.keyPressed(Qt::Key_Delete));
        QCOMPARE(edits.count(), 1);
        QCOMPARE(edit(edits, 0).action, WorldEdit::Action::Remove);
        QCOMPARE(edit(edits, 0).item, (WorldItem{WorldPart::DropOff, 0}));
        QVERIFY(!tool.selectedItem());
        QVERIFY(!tool.keyPressed(Qt::Key_A));
    }

    void theMenuAddsAndDeletesWhereItOpened()
    {
        RoomEditTool tool;
        tool.setWorld(&m_floor);
        QMenu off;
        tool.fillMenu(&off, {500, 0}, kTolerance);
        QCOMPARE(off.actions().size(), 1); // Edit room alone
        off.actions().first()->toggle();
        QVERIFY(tool.isEditing());

        QSignalSpy edits(&tool, &RoomEditTool::editRequested);
        QMenu on;
        tool.fillMenu(&on, {500, 0}, kTolerance);
        QAction *addWall = on.findChild<QAction *>("addWallAction");
        QAction *remove = on.findChild<QAction *>("deleteItemAction");
        QVERIFY(addWall && remove);
        QCOMPARE(remove->text(), QStringLiteral("Delete the wall"));
        addWall->trigger();
        QCOMPARE(edit(edits, 0).action, WorldEdit::Action::Add);
        // The new wall, last in the list, is selected.
        QCOMPARE(tool.selectedItem(), (WorldItem{WorldPart::Wall, 1}));
        remove->trigger();
        QCOMPARE(edit(edits, 1).action, WorldEdit::Action::Remove);
        QCOMPARE(edit(edits, 1).item, (WorldItem{WorldPart::Wall, 0}));
        QVERIFY(edit(edits, 0).gesture != edit(edits, 1).gesture);
    }
};

QTEST_MAIN(TestRoomEditTool)
#include "tst_room_edit_tool.moc"
