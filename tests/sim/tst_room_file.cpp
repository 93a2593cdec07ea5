// SPDX-License-Identifier: GPL-3.0-or-later
// Rooms as files: the shipped rooms, saving and loading, and bad files
// refused with a message that names what is wrong.
#include "body.h"
#include "room.h"
#include "room_file.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "not_regular_files.h" // tests/common

namespace {
const QString kRooms = QStringLiteral(ROOMBA_ROOMS_DIR);
}

class TestRoomFile : public QObject {
    Q_OBJECT
private slots:
    void shippedRoomsLoad_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("name");
        QTest::newRow("empty floor") << "empty_floor.json" << "Empty floor";
        QTest::newRow("table top") << "table_top.json" << "Table top";
        QTest::newRow("corridor") << "corridor.json" << "Corridor";
        QTest::newRow("dock corner") << "dock_corner.json" << "Dock corner";
        QTest::newRow("classroom") << "classroom.json" << "Classroom";
    }
    void shippedRoomsLoad()
    {
        QFETCH(QString, file);
        QFETCH(QString, name);
        QString error;
        const std::optional<sim::World> world = sim::loadRoomFile(QDir(kRooms).filePath(file), &error);
        QVERIFY2(world, qPrintable(error));
        QCOMPARE(QString::fromStdString(world->name), name);
        // Two robots fit, the first at the start.
        sim::Room room(*world);
        const sim::RobotId first = room.placeNewRobot(), second = room.placeNewRobot();
        QCOMPARE(room.robot(first)->pose.xMm, world->startX);
        QCOMPARE(room.robot(first)->pose.yMm, world->startY);
        const oi::Pose a = room.robot(first)->pose, b = room.robot(second)->pose;
        QVERIFY(std::hypot(a.xMm - b.xMm, a.yMm - b.yMm) > 2 * sim::kBodyRadiusMm);
    }

    void theTableHasEdgesAllRound()
    {
        const std::optional<sim::World> table = sim::loadRoomFile(QDir(kRooms).filePath("table_top.json"));
        QVERIFY(table);
        // Straight out from the start in every direction, the floor ends.
        for (int deg = 0; deg < 360; deg += 15) {
            const double rad = deg * 3.14159265358979323846 / 180;
            bool edge = false;
            for (double r = 0; r < 3000 && !edge; r += 10)
                edge = std::any_of(table->dropOffs.begin(), table->dropOffs.end(), [&](const sim::Area &a) {
                    return sim::isInside(a, {r * std::cos(rad), r * std::sin(rad)});
                });
            QVERIFY2(edge, qPrintable(QString("no edge at %1°").arg(deg)));
        }
    }

    // The dock corner has a dark rug: the cliff sensors read a cliff on it.
    void theDockCornerHasADarkRug()
    {
        const std::optional<sim::World> room = sim::loadRoomFile(QDir(kRooms).filePath("dock_corner.json"));
        QVERIFY(room);
        QCOMPARE(room->rugs.size(), std::size_t(1));
        const sim::Area &a = room->rugs[0].area;
        const sim::FloorContact f =
            sim::senseFloor(*room, oi::Pose{(a.xMin + a.xMax) / 2, (a.yMin + a.yMax) / 2, 0, 0});
        QVERIFY(f.cliff[1] && f.cliff[2]);
        QVERIFY(!f.wheelDropLeft && !f.wheelDropRight);
    }

    void theClassroomFileIsTheBuiltInRoom()
    {
        QCOMPARE(*sim::loadRoomFile(QDir(kRooms).filePath("classroom.json")), sim::World::classroom());
    }

    void savesAndLoadsBack()
    {
        sim::World w = sim::World::classroom();
        w.name = "Küche \"B\"";
        w.startX = 12.5;
        w.startHeadingRad = 0.75;
        w.virtualWall->rangeMm = 987.25;
        w.rugs = {{{400, 400, 1200, 1200.5}, 0.85}};
        QTemporaryDir dir;
        const QString path = dir.filePath("room.json");
        QString error;
        QVERIFY2(sim::saveRoomFile(path, w, &error), qPrintable(error));
        const std::optional<sim::World> back = sim::loadRoomFile(path, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->name, w.name);
        QCOMPARE(back->walls, w.walls);
        QCOMPARE(back->dropOffs, w.dropOffs);
        QCOMPARE(back->rugs, w.rugs);
        QCOMPARE(back->dock, w.dock);
        QCOMPARE(back->startX, w.startX);
        QCOMPARE(back->startHeadingRad, w.startHeadingRad);
        QCOMPARE(back->virtualWall->rangeMm, w.virtualWall->rangeMm);
        QVERIFY(std::abs(back->virtualWall->headingRad - w.virtualWall->headingRad) < 1e-12);
        // One wall to a line, for people to read and edit.
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readAll().contains("    [-1000, -1500, 3000, -1500],\n"));
    }

    void aFailedSaveKeepsTheOldFile()
    {
        QString error;
        QVERIFY(!sim::saveRoomFile("/nonexistent-dir/room.json", sim::World::classroom(), &error));
        QVERIFY2(error.startsWith("/nonexistent-dir/room.json: cannot write"), qPrintable(error));
    }

    void refusesBadFiles_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        const QByteArray head = R"("format": "roomba-room", "version": 1)";
        const auto with = [&head](const char *rest) { return "{" + head + ", " + rest + "}"; };
        QTest::newRow("not json") << QByteArray("{\n  \"format\": \"roomba-room\",\n  oops\n}")
                                  << "not JSON at line 3, column ";
        QTest::newRow("not an object") << QByteArray("[1, 2]") << "a room file holds one JSON object";
        QTest::newRow("another format") << QByteArray(R"({"format": "song", "version": 1})")
                                        << "\"format\" must be \"roomba-room\"";
        QTest::newRow("newer version") << QByteArray(R"({"format": "roomba-room", "version": 2})")
                                       << "\"version\" 2 is not one this program reads (it reads 1)";
        QTest::newRow("misspelt key") << with(R"("dropoffs": [])") << "unknown key \"dropoffs\"";
        QTest::newRow("walls not a list") << with(R"("walls": 4)") << "\"walls\" must be a list";
        QTest::newRow("wall of three") << with(R"("walls": [[0, 0, 1, 1], [0, 0, 1]])")
                                       << "walls[1] must be a list of 4 numbers";
        QTest::newRow("wall of text") << with(R"("walls": [[0, 0, "1", 1]])") << "walls[0][2] must be a number";
        QTest::newRow("wall of no length") << with(R"("walls": [[5, 5, 5, 5]])")
                                           << "walls[0]: a wall must have some length";
        QTest::newRow("drop-off inside out") << with(R"("drop_offs": [[10, 0, 0, 10]])")
                                             << "drop_offs[0]: x_min must be below x_max and y_min below y_max";
        QTest::newRow("dock without y") << with(R"("dock": {"x_mm": 0, "heading_deg": 0})")
                                        << "dock: \"y_mm\" is missing";
        QTest::newRow("dock with extra") << with(R"("dock": {"x_mm": 0, "y_mm": 0, "heading_deg": 0, "z": 1})")
                                         << "dock: unknown key \"z\"";
        QTest::newRow("start not an object") << with(R"("start": [0, 0])")
                                             << "\"start\" must be an object with x_mm, y_mm and heading_deg";
        QTest::newRow("beam of no length")
            << with(R"("virtual_wall": {"x_mm": 0, "y_mm": 0, "heading_deg": 0, "range_mm": 0})")
            << "virtual_wall: \"range_mm\" must be above 0, not 0";
        QTest::newRow("rug too dark") << with(R"("rugs": [[0, 0, 10, 10, 1.5]])")
                                      << "rugs[0]: the shade (the fifth number) must be from 0 (the floor as it is) "
                                         "to 1 (black), not 1.5";
        QTest::newRow("rug lighter than the floor") << with(R"("rugs": [[0, 0, 10, 10, -0.2]])")
                                                    << "rugs[0]: the shade (the fifth number) must be from 0";
        QTest::newRow("rug without a shade") << with(R"("rugs": [[0, 0, 10, 10]])")
                                             << "rugs[0] must be a list of 5 numbers";
        QTest::newRow("rug shade as text") << with(R"("rugs": [[0, 0, 10, 10, "dark"]])")
                                           << "rugs[0][4] must be a number";
        QTest::newRow("rug inside out") << with(R"("rugs": [[10, 0, 0, 10, 0.9]])")
                                        << "rugs[0]: x_min must be below x_max";
        // Each robot checks every wall at each step: 200,000 took a core.
        QByteArray walls = "[0, 0, 1, 1]";
        for (std::size_t i = 1; i <= sim::World::kMaxShapes; ++i)
            walls += ", [0, 0, 1, 1]";
        QTest::newRow("too many walls") << with("\"walls\": [" + walls + "]")
                                        << "\"walls\" has 1001 entries; a room holds at most 1000";
    }
    void refusesBadFiles()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        QString why;
        QVERIFY(!sim::roomFromJson(json, &why));
        QVERIFY2(why.startsWith(error), qPrintable(why));

        // From a file, the message starts with the file's name.
        QTemporaryDir dir;
        const QString path = dir.filePath("bad.json");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(json);
        file.close();
        QVERIFY(!sim::loadRoomFile(path, &why));
        QCOMPARE(why.left(why.indexOf(error)), QStringLiteral("bad.json: "));
    }

    // A room is read only from a regular file of at most 1 MB: /dev/zero was
    // read until memory ran out, a named pipe blocked for good.
    void aFileThatIsNoRoomIsRefusedUnread()
    {
        QTemporaryDir dir;
        const QString big = dir.filePath("big.json");
        QFile file(big);
        QVERIFY(file.open(QIODevice::WriteOnly));
        const QByteArray room = R"({"format": "roomba-room", "version": 1})";
        QVERIFY(file.write(room + QByteArray((1 << 20) + 1 - room.size(), ' ')) == (1 << 20) + 1);
        file.close();
        const NotRegularFiles no = makeNotRegularFiles(dir.path(), "json");
        QVERIFY(!no.pipe.isEmpty());
        QString why;
        QVERIFY(!sim::loadRoomFile(big, &why));
        QCOMPARE(why, big + ": cannot read: 1048577 bytes, larger than the 1 MB this program reads of such a file");
        QVERIFY(!sim::loadRoomFile(no.device, &why));
        QCOMPARE(why, no.device + ": cannot read: not a regular file but a device");
        QVERIFY(!sim::loadRoomFile(no.pipe, &why));
        QCOMPARE(why, no.pipe + ": cannot read: not a regular file but a named pipe");
    }

    void aMissingFileIsSaidSo()
    {
        QString why;
        QVERIFY(!sim::loadRoomFile("/nonexistent/room.json", &why));
        QVERIFY2(why.startsWith("/nonexistent/room.json: cannot read"), qPrintable(why));
    }
};

QTEST_GUILESS_MAIN(TestRoomFile)
#include "tst_room_file.moc"
