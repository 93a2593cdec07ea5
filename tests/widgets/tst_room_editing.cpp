// SPDX-License-Identifier: GPL-3.0-or-later
// Editing the room on the odometry map with the mouse and keyboard: the map
// asks (worldEditRequested), this test plays the room's owner and gives the
// edited floor back, as the dashboard does.
#include "odometry_map.h"

#include <QAction>
#include <QDir>
#include <QMenu>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <memory>

using sim::WorldEdit;
using sim::WorldItem;
using sim::WorldPart;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A wall along the x axis, a stage edge, the dock and a virtual wall apart.
sim::World testFloor()
{
    sim::World w;
    w.name = "test";
    w.walls = {{0, 0, 1000, 0}};
    w.dropOffs = {{1500, -500, 2000, 0}};
    w.dock = sim::World::Dock{-500, 500, 0};
    w.virtualWall = sim::World::VirtualWallBeacon{500, 800, -kPi / 2, 600};
    return w;
}

} // namespace

class TestRoomEditing : public QObject {
    Q_OBJECT

    std::unique_ptr<OdometryMap> m_map;
    std::unique_ptr<QSignalSpy> m_edits;
    sim::World m_floor; // the room's floor, as its owner holds it

    QPoint at(double xMm, double yMm) const { return m_map->widgetPointFor({xMm, yMm}).toPoint(); }
    WorldEdit lastEdit() const { return m_edits->last().at(0).value<WorldEdit>(); }
    // What the room does with a request: apply it and show the floor again.
    void giveBack(const WorldEdit &edit)
    {
        QVERIFY(sim::applyEdit(m_floor, edit));
        m_map->setWorld(m_floor);
    }
    void click(QPoint p, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QTest::mouseClick(m_map.get(), Qt::LeftButton, modifiers, p);
    }
    void drag(QPoint from, QList<QPoint> through, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QTest::mousePress(m_map.get(), Qt::LeftButton, modifiers, from);
        for (const QPoint &p : through)
            QTest::mouseMove(m_map.get(), p);
        QTest::mouseRelease(m_map.get(), Qt::LeftButton, modifiers, through.last());
    }
    QAction *menuAction(QMenu *menu, const char *name) const
    {
        for (QAction *a : menu->actions())
            if (a->objectName() == QLatin1String(name))
                return a;
        return nullptr;
    }

private slots:
    void init()
    {
        m_map = std::make_unique<OdometryMap>();
        m_map->resize(900, 650);
        m_map->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_map.get()));
        m_map->setScale(0.2);
        m_map->setViewCentreMm({700, 200});
        m_floor = testFloor();
        m_map->setWorld(m_floor);
        m_edits = std::make_unique<QSignalSpy>(m_map.get(), &OdometryMap::worldEditRequested);
    }
    void cleanup()
    {
        m_edits.reset();
        m_map.reset();
    }

    void editModeIsOfferedWithARoom()
    {
        auto *button = m_map->findChild<QPushButton *>("editRoom");
        QVERIFY(button);
        QVERIFY(button->isVisible());
        QSignalSpy changes(m_map.get(), &OdometryMap::editingChanged);
        QTest::mouseClick(button, Qt::LeftButton);
        QVERIFY(m_map->isEditing());
        QCOMPARE(changes.size(), 1);
        QCOMPARE(changes[0][0].toBool(), true);
        // No room (a real robot): no button, and no edit mode.
        m_map->setWorld(std::nullopt);
        QVERIFY(!button->isVisible());
        QVERIFY(!m_map->isEditing());
        m_map->setEditing(true);
        QVERIFY(!m_map->isEditing());
        QCOMPARE(m_map->contextMenuAt(at(0, 0)), nullptr);
    }

    void clickingSelects()
    {
        // Out of edit mode a click on a wall selects nothing.
        click(at(500, 0));
        QCOMPARE(m_map->selectedItem(), std::nullopt);
        m_map->setEditing(true);
        click(at(500, 0) + QPoint(0, 5)); // 5 px off the line still takes it
        QCOMPARE(m_map->selectedItem(), (WorldItem{WorldPart::Wall, 0}));
        click(at(1750, -250));
        QCOMPARE(m_map->selectedItem(), (WorldItem{WorldPart::DropOff, 0}));
        click(at(-550, 500));
        QCOMPARE(m_map->selectedItem(), (WorldItem{WorldPart::Dock, 0}));
        click(at(500, 500)); // along the beam
        QCOMPARE(m_map->selectedItem(), (WorldItem{WorldPart::VirtualWall, 0}));
        // Empty floor lets go; so does Esc.
        click(at(-500, -700));
        QCOMPARE(m_map->selectedItem(), std::nullopt);
        click(at(500, 0));
        QVERIFY(m_map->selectedItem());
        QTest::keyClick(m_map.get(), Qt::Key_Escape);
        QCOMPARE(m_map->selectedItem(), std::nullopt);
        // Selecting asks nothing of the room.
        QCOMPARE(m_edits->size(), 0);
    }

    void theCursorShowsWhatCanBeTaken()
    {
        m_map->setEditing(true);
        QTest::mouseMove(m_map.get(), at(500, 0));
        QCOMPARE(m_map->cursor().shape(), Qt::OpenHandCursor);
        QTest::mouseMove(m_map.get(), at(1000, 0));
        QCOMPARE(m_map->cursor().shape(), Qt::CrossCursor); // an end
        QTest::mouseMove(m_map.get(), at(-500, -700));
        QCOMPARE(m_map->cursor().shape(), Qt::ArrowCursor);
    }

    void draggingAWallsEndAndTheWholeWall()
    {
        m_map->setEditing(true);
        // The end: 40 px right and 20 px up is 200 mm and 100 mm at 0.2 px/mm.
        const QPoint end = at(1000, 0);
        drag(end, {end + QPoint(20, -10), end + QPoint(40, -20)});
        QCOMPARE(m_edits->size(), 2);
        const WorldEdit first = m_edits->at(0).at(0).value<WorldEdit>();
        const WorldEdit moved = lastEdit();
        QCOMPARE(moved.action, WorldEdit::Action::Put);
        QCOMPARE(moved.item, (WorldItem{WorldPart::Wall, 0}));
        QCOMPARE(moved.wall, (sim::Segment{0, 0, 1200, 100}));
        // One drag, one gesture: undone as one.
        QVERIFY(moved.gesture != 0);
        QCOMPARE(first.gesture, moved.gesture);
        QCOMPARE(m_map->selectedItem(), (WorldItem{WorldPart::Wall, 0}));
        giveBack(moved);

        // The whole wall, by its middle: both ends go the same way.
        const QPoint middle = at(600, 50);
        drag(middle, {middle + QPoint(10, 10)});
        QCOMPARE(m_edits->size(), 3);
        QCOMPARE(lastEdit().wall, (sim::Segment{50, -50, 1250, 50}));
        QVERIFY(lastEdit().gesture != moved.gesture);
        giveBack(lastEdit());
        QCOMPARE(m_map->world()->walls.front(), (sim::Segment{50, -50, 1250, 50}));
    }

    void draggingAStageEdgesCornerTheDockAndTheBeam()
    {
        m_map->setEditing(true);
        click(at(1750, -250));
        // The top right corner of the stage edge out to (2200, 200).
        drag(at(2000, 0), {at(2200, 200)});
        QCOMPARE(lastEdit().item, (WorldItem{WorldPart::DropOff, 0}));
        QCOMPARE(lastEdit().dropOff, (sim::Area{1500, -500, 2200, 200}));
        giveBack(lastEdit());
        // Past the opposite corner it turns over rather than vanish.
        drag(at(2200, 200), {at(1300, -700)});
        QCOMPARE(lastEdit().dropOff, (sim::Area{1300, -700, 1500, -500}));

        // The dock, carried 200 mm down, then turned with Shift to face +y.
        drag(at(-550, 500), {at(-550, 300)});
        QCOMPARE(lastEdit().item, (WorldItem{WorldPart::Dock, 0}));
        QCOMPARE(lastEdit().dock, (sim::World::Dock{-500, 300, 0}));
        giveBack(lastEdit());
        drag(at(-550, 300), {at(-500, 900)}, Qt::ShiftModifier);
        QCOMPARE(lastEdit().dock.x, -500.0);
        QVERIFY(std::abs(lastEdit().dock.headingRad - kPi / 2) < 1e-9);

        // The virtual wall's beam end, selected, aims it and sets its reach.
        click(at(500, 800));
        QCOMPARE(m_map->selectedItem(), (WorldItem{WorldPart::VirtualWall, 0}));
        drag(at(500, 200), {at(1300, 800)});
        const auto beam = lastEdit().virtualWall;
        QCOMPARE(beam.x, 500.0);
        QVERIFY(std::abs(beam.headingRad) < 1e-9);
        QCOMPARE(beam.rangeMm, 800.0);
    }

    void deleteRemovesTheSelection()
    {
        // Out of edit mode Delete is not the map's.
        QTest::keyClick(m_map.get(), Qt::Key_Delete);
        QCOMPARE(m_edits->size(), 0);
        m_map->setEditing(true);
        click(at(500, 0));
        QTest::keyClick(m_map.get(), Qt::Key_Delete);
        QCOMPARE(m_edits->size(), 1);
        QCOMPARE(lastEdit().action, WorldEdit::Action::Remove);
        QCOMPARE(lastEdit().item, (WorldItem{WorldPart::Wall, 0}));
        QCOMPARE(m_map->selectedItem(), std::nullopt);
        giveBack(lastEdit());
        QVERIFY(m_map->world()->walls.empty());
        click(at(-550, 500));
        QTest::keyClick(m_map.get(), Qt::Key_Backspace);
        QCOMPARE(lastEdit().action, WorldEdit::Action::Remove);
        QCOMPARE(lastEdit().item, (WorldItem{WorldPart::Dock, 0}));
        giveBack(lastEdit());
        QVERIFY(!m_map->world()->dock);
    }

    void theContextMenuAddsAndDeletes()
    {
        // Out of edit mode the menu offers edit mode.
        std::unique_ptr<QMenu> menu(m_map->contextMenuAt(at(0, -1000)));
        QVERIFY(menu);
        QVERIFY(!menuAction(menu.get(), "addWallAction"));
        menuAction(menu.get(), "editRoomAction")->trigger();
        QVERIFY(m_map->isEditing());

        menu.reset(m_map->contextMenuAt(at(0, -1000)));
        QVERIFY(!menuAction(menu.get(), "deleteItemAction")); // nothing there
        menuAction(menu.get(), "addWallAction")->trigger();
        QCOMPARE(lastEdit().action, WorldEdit::Action::Add);
        QCOMPARE(lastEdit().item.part, WorldPart::Wall);
        QCOMPARE(lastEdit().wall, (sim::Segment{-500, -1000, 500, -1000}));
        giveBack(lastEdit());
        // The new wall comes back selected.
        QCOMPARE(m_map->selectedItem(), (WorldItem{WorldPart::Wall, 1}));

        menu.reset(m_map->contextMenuAt(at(2500, -1000)));
        menuAction(menu.get(), "addDropOffAction")->trigger();
        QCOMPARE(lastEdit().dropOff, (sim::Area{2200, -1300, 2800, -700}));
        giveBack(lastEdit());
        QCOMPARE(m_map->world()->dropOffs.size(), 2u);

        // The dock and the virtual wall move to where the menu was opened.
        menu.reset(m_map->contextMenuAt(at(2000, 1000)));
        menuAction(menu.get(), "putDockAction")->trigger();
        QCOMPARE(lastEdit().dock, (sim::World::Dock{2000, 1000, 0}));
        menuAction(menu.get(), "putVirtualWallAction")->trigger();
        QCOMPARE(lastEdit().virtualWall.x, 2000.0);
        QCOMPARE(lastEdit().virtualWall.rangeMm, 600.0); // kept from the one it replaces

        // Opened on a thing, it deletes that thing.
        menu.reset(m_map->contextMenuAt(at(1750, -250)));
        QAction *remove = menuAction(menu.get(), "deleteItemAction");
        QVERIFY(remove);
        QCOMPARE(m_map->selectedItem(), (WorldItem{WorldPart::DropOff, 0}));
        remove->trigger();
        QCOMPARE(lastEdit().action, WorldEdit::Action::Remove);
        QCOMPARE(lastEdit().item, (WorldItem{WorldPart::DropOff, 0}));
    }

    void theSelectedHandlesComeBeforeARobot()
    {
        m_map->setEditing(true);
        click(at(500, 0));
        // A robot standing on the wall's end: the end's handle is taken...
        m_map->setTruePoses({{3, oi::Pose{1000, 0, 0, 0}, {}, false}});
        QSignalSpy moves(m_map.get(), &OdometryMap::robotMoveRequested);
        drag(at(1000, 0), {at(1000, 300)});
        QCOMPARE(moves.size(), 0);
        QCOMPARE(lastEdit().wall, (sim::Segment{0, 0, 1000, 300}));
        // ... but elsewhere on it the robot is, and the hand carries it.
        const int edits = int(m_edits->size());
        drag(at(1000, 100), {at(1000, -200)});
        QCOMPARE(moves.size(), 1);
        QCOMPARE(m_edits->size(), edits);
    }

    // Edit mode in the classroom with the bookcase selected, for people to
    // look at (into ROOMBA_SCREENSHOTS when set).
    void screenshots()
    {
        m_map->resize(1000, 720);
        m_map->setScale(0.2);
        m_map->setViewCentreMm({1000, 0});
        m_floor = sim::World::classroom();
        m_map->setWorld(m_floor);
        m_map->setTruePoses({{1, oi::Pose{1200, 900, kPi / 4, 0}, {}, false}, {2, oi::Pose{0, 0, 0, 0}, {}, false}});
        m_map->setSelectedRobot(1);
        m_map->setEditing(true);
        click(at(2000, 700));
        QCOMPARE(m_map->selectedItem(), (WorldItem{WorldPart::Wall, 5}));
        const QImage shot = m_map->grab().toImage();
        // The handles are drawn in the highlight colour at the wall's ends.
        QCOMPARE(shot.pixelColor(at(2200, 700) * m_map->devicePixelRatioF()), m_map->palette().color(QPalette::Highlight));
        if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS")) {
            QVERIFY(shot.save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("room_edit_selected_wall.png")));
            click(at(2600, -1100));
            QVERIFY(m_map->grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("room_edit_stage_edge.png")));
            click(at(-770, 0));
            QVERIFY(m_map->grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("room_edit_dock.png")));
            std::unique_ptr<QMenu> menu(m_map->contextMenuAt(at(2000, 1000)));
            menu->popup(m_map->mapToGlobal(at(2000, 1000)));
            QVERIFY(QTest::qWaitForWindowExposed(menu.get()));
            QVERIFY(menu->grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("room_edit_menu.png")));
        }
    }
};

QTEST_MAIN(TestRoomEditing)
#include "tst_room_editing.moc"
