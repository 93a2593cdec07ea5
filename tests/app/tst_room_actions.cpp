// SPDX-License-Identifier: GPL-3.0-or-later
// The room as a document: open and save round-trip, a bad file leaves the
// room as it was, the shipped rooms, the last room at the next start, and
// edits from the map with Undo. The window's robots in the room, and the
// robots the window starts with, each without a window.
#include "room_actions.h"

#include "fleet_directory.h"
#include "restored_robots.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "room_robots.h"

#include "room_file.h"

#include <QAction>
#include <QFile>
#include <QMenu>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QWidget>

class TestRoomActions : public QObject {
    Q_OBJECT

    QWidget m_window;
    QTemporaryDir m_dir;

private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void saveAndOpenRoundTrip()
    {
        auto room = std::make_shared<sim::Room>(sim::World::classroom());
        RoomActions actions(room, &m_window);
        sim::World edited = room->world();
        edited.walls.push_back({100, 200, 300, 400});
        edited.dock.reset();
        room->setWorld(edited);
        const QString path = m_dir.filePath("edited.json");
        QString error;
        QVERIFY2(actions.saveRoom(path, &error), qPrintable(error));

        auto other = std::make_shared<sim::Room>(sim::World{});
        RoomActions reopen(other, &m_window);
        QVERIFY2(reopen.openRoom(path, &error), qPrintable(error));
        QCOMPARE(other->world(), edited);
        QCOMPARE(QSettings().value("room/file").toString(), path);
    }

    void aBadFileLeavesTheRoomAsItWas()
    {
        auto room = std::make_shared<sim::Room>(sim::World::classroom());
        RoomActions actions(room, &m_window);
        const std::uint64_t version = room->worldVersion();
        const QString path = m_dir.filePath("bad.json");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "roomba-room", "version": 1, "walls": [[0, 0, 0, 0]]})");
        file.close();
        QString error;
        QVERIFY(!actions.openRoom(path, &error));
        QVERIFY2(error.contains("walls[0]"), qPrintable(error));
        QCOMPARE(room->world(), sim::World::classroom());
        QCOMPARE(room->worldVersion(), version);
        QVERIFY(!QSettings().contains("room/file"));
        // Saving where it cannot write says why and keeps nothing half-written.
        QVERIFY(!actions.saveRoom(m_dir.filePath("no/such/folder/room.json"), &error));
        QVERIFY(!error.isEmpty());
    }

    void theShippedRoomsOpenFromTheMenu()
    {
        auto room = std::make_shared<sim::Room>(sim::World::classroom());
        RoomActions actions(room, &m_window);
        actions.retranslate();
        const QList<QAction *> rooms = actions.shippedMenu()->actions();
        QCOMPARE(rooms.size(), 5);
        for (QAction *a : rooms)
            QVERIFY(!a->text().isEmpty());
        QSignalSpy messages(&actions, &RoomActions::message);
        QAction *corridor = nullptr;
        for (QAction *a : rooms)
            if (a->objectName() == "room_corridor")
                corridor = a;
        QVERIFY(corridor);
        const sim::RobotId robot = room->addRobotAt({0, 0, 0, 0});
        corridor->trigger();
        QCOMPARE(QString::fromStdString(room->world().name), QStringLiteral("Corridor"));
        // The robot is put down at the room's start.
        QCOMPARE(room->robot(robot)->pose.xMm, room->world().startX);
        QCOMPARE(room->robot(robot)->pose.yMm, room->world().startY);
        QCOMPARE(messages.size(), 1);
    }

    void theLastRoomOpensAtTheNextStart()
    {
        {
            auto room = std::make_shared<sim::Room>(sim::World::classroom());
            RoomActions actions(room, &m_window);
            QVERIFY(actions.openRoom(":/rooms/table_top.json"));
        }
        auto room = std::make_shared<sim::Room>(sim::World::classroom());
        RoomActions actions(room, &m_window);
        actions.restoreLastRoom();
        QCOMPARE(QString::fromStdString(room->world().name), QStringLiteral("Table top"));

        // Gone since: said once, forgotten, and the room stays.
        QSettings().setValue("room/file", m_dir.filePath("gone.json"));
        auto fresh = std::make_shared<sim::Room>(sim::World::classroom());
        RoomActions again(fresh, &m_window);
        QSignalSpy messages(&again, &RoomActions::message);
        again.restoreLastRoom();
        QCOMPARE(messages.size(), 1);
        QCOMPARE(fresh->world(), sim::World::classroom());
        QVERIFY(!QSettings().contains("room/file"));
    }

    // A room that cannot be read at the start (here /dev/zero, read until the
    // memory ran out and the dashboard aborted at every start) is said once
    // and forgotten: the next start does not try it again.
    void aRoomThatCannotBeReadAtTheStartIsSaidAndForgotten()
    {
        const QString zero = m_dir.filePath("zero.json");
        QVERIFY(QFile::link("/dev/zero", zero));
        QSettings().setValue("room/file", zero);
        auto room = std::make_shared<sim::Room>(sim::World::classroom());
        RoomActions actions(room, &m_window);
        QSignalSpy messages(&actions, &RoomActions::message);
        actions.restoreLastRoom();
        QCOMPARE(messages.size(), 1);
        QCOMPARE(messages[0][0].toString(), "The room of last time could not be opened: " + zero +
                                                ": cannot read: not a regular file but a device");
        QCOMPARE(room->world(), sim::World::classroom());
        QVERIFY(!QSettings().contains("room/file"));
    }

    void editsReachTheRoomAndUndoAsOneDrag()
    {
        auto room = std::make_shared<sim::Room>(sim::World::classroom());
        RoomActions actions(room, &m_window);
        const sim::World start = room->world();
        // Three steps of one drag of the first wall's end, then a delete.
        for (double x : {3100.0, 3200.0, 3300.0}) {
            sim::WorldEdit e = sim::WorldEdit::put({sim::WorldPart::Wall, 0}, start);
            e.wall.x2 = x;
            e.gesture = 7;
            actions.edit(e);
        }
        QCOMPARE(room->world().walls[0].x2, 3300.0);
        sim::WorldEdit remove = sim::WorldEdit::remove({sim::WorldPart::Dock, 0});
        remove.gesture = 8;
        actions.edit(remove);
        QVERIFY(!room->world().dock);
        QCOMPARE(actions.undoStack()->count(), 2);
        // An edit that does not apply (the dock is gone) is no step.
        actions.edit(remove);
        QCOMPARE(actions.undoStack()->count(), 2);

        actions.undoAction()->trigger();
        QVERIFY(room->world().dock);
        QCOMPARE(room->world().walls[0].x2, 3300.0);
        actions.undoAction()->trigger();
        QCOMPARE(room->world(), start);
        actions.redoAction()->trigger();
        QCOMPARE(room->world().walls[0].x2, 3300.0);
        // Opening a room starts afresh.
        QVERIFY(actions.openRoom(":/rooms/empty_floor.json"));
        QCOMPARE(actions.undoStack()->count(), 0);
    }

    // A virtual robot is put down in the room and its odometry starts where
    // it stands; connected elsewhere, it gives its spot back; removed, too.
    void virtualRobotsTakeAPlaceInTheRoom()
    {
        auto room = std::make_shared<sim::Room>(sim::World::classroom());
        RobotFleet fleet;
        FleetDirectory directory;
        RoomRobots robots(room, fleet, directory);
        RobotSession *first = fleet.addRobot(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, {}), {}, false);
        RobotSession *second = fleet.addRobot(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, {}), {}, false);
        QVERIFY(robots.placeOf(first) >= 0);
        QVERIFY(robots.placeOf(second) >= 0);
        QVERIFY(robots.placeOf(first) != robots.placeOf(second));
        QCOMPARE(room->robots().size(), std::size_t(2));
        const std::optional<oi::Pose> where = robots.truePose(second);
        QVERIFY(where);
        QCOMPARE(second->odometry().start().xMm, where->xMm);
        QCOMPARE(second->odometry().start().yMm, where->yMm);

        robots.place(second, oilink::LinkSettings::serial("/dev/ttyUSB0"));
        QCOMPARE(robots.placeOf(second), -1);
        QVERIFY(!robots.truePose(second));
        QCOMPARE(room->robots().size(), std::size_t(1));

        QVERIFY(fleet.removeRobot(first));
        QCOMPARE(robots.placeOf(first), -1);
        QVERIFY(room->robots().empty());
    }

    // First start: the virtual robot. A settings file from the single-robot
    // versions: that robot. Recordings and broker robots are not kept.
    void theRobotsTheWindowStartsWith()
    {
        QSettings settings;
        QList<SavedRobot> first = robotsToRestore(settings);
        QCOMPARE(first.size(), 1);
        QCOMPARE(first[0].link.transport, oilink::TransportKind::Virtual);

        settings.setValue("connection/transport", 2); // TCP, as those versions numbered it
        settings.setValue("connection/host", "raspberrypi");
        settings.setValue("connection/tcpPort", 3333);
        settings.setValue("connection/profile", int(oi::ProfileId::Roomba500));
        const QList<SavedRobot> single = robotsToRestore(settings);
        QCOMPARE(single.size(), 1);
        QCOMPARE(single[0].link.transport, oilink::TransportKind::Tcp);
        QCOMPARE(single[0].link.host, QString("raspberrypi"));
        QCOMPARE(single[0].link.tcpPort, quint16(3333));
        QCOMPARE(single[0].link.profile, std::optional(oi::ProfileId::Roomba500));

        QList<SavedRobot> all = single;
        all << SavedRobot{"replay", {}, oilink::LinkSettings::replayOf("run.oirec", oi::ProfileId::Create2, 115200, {}), false}
            << SavedRobot{"r1", {}, oilink::LinkSettings::networkRobotOf("r1", oi::ProfileId::Create2), false};
        const QList<SavedRobot> kept = robotsToKeep(all);
        QCOMPARE(kept.size(), 1);
        QCOMPARE(kept[0].link.host, QString("raspberrypi"));
    }
};

QTEST_MAIN(TestRoomActions)
#include "tst_room_actions.moc"
