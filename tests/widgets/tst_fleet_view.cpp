// SPDX-License-Identifier: GPL-3.0-or-later
// The fleet view: a tile per robot with its few values, as many columns as
// fit, a click that asks for the robot, repaints only for a changed tile,
// and every text translated.

#include "fleet_view.h"
#include "pseudo_translation.h"

#include <QComboBox>
#include <QDir>
#include <QSignalSpy>
#include <QPushButton>
#include <QTest>

namespace {

FleetTileValues robot(int n)
{
    FleetTileValues v;
    v.name = QStringLiteral("robot-%1").arg(n);
    v.online = true;
    v.mode = QStringLiteral("Safe");
    v.batteryPercent = 90 - n;
    v.link = QStringLiteral("streaming");
    v.linkHealthy = true;
    v.framesPerSecond = 66;
    return v;
}

} // namespace

class TestFleetView : public QObject {
    Q_OBJECT

private slots:
    void tilesShowTheirValues()
    {
        FleetView view;
        FleetTileValues bumped = robot(1);
        bumped.bumpLeft = true;
        bumped.controller = QStringLiteral("alice");
        FleetTileValues cliff = robot(2);
        cliff.cliffs = 2;
        cliff.wheelDrop = true;
        cliff.mode = QStringLiteral("Passive");
        cliff.modeReason = QStringLiteral("cliff (front left)");
        FleetTileValues offline = robot(3);
        offline.online = false;
        offline.link = QStringLiteral("lost");
        offline.linkHealthy = false;
        offline.framesPerSecond.reset();
        view.setTiles({bumped, cliff, offline});
        QCOMPARE(view.tiles().size(), 3);

        const FleetTile *t1 = view.tile("robot-1");
        QCOMPARE(t1->statusText(), QStringLiteral("ONLINE"));
        QCOMPARE(t1->modeText(), QStringLiteral("Safe · battery 89 %"));
        QCOMPARE(t1->hazardText(), QStringLiteral("BUMP left"));
        QCOMPARE(t1->linkText(), QStringLiteral("link streaming · 66/s"));
        QCOMPARE(t1->controlText(), QStringLiteral("driven by alice"));
        // A student's program through the Python library says its name.
        bumped.program = QStringLiteral("square.py");
        view.setTiles({bumped, cliff, offline});
        QCOMPARE(t1->controlText(), QStringLiteral("alice's program square.py"));
        bumped.program.clear();
        view.setTiles({bumped, cliff, offline});
        QCOMPARE(view.tile("robot-2")->hazardText(), QStringLiteral("CLIFF ×2 · WHEEL DROP"));
        // Why it is in Passive travels with its own tile.
        QCOMPARE(view.tile("robot-2")->modeText(), QStringLiteral("Passive: cliff (front left) · battery 88 %"));
        QCOMPARE(view.tile("robot-3")->statusText(), QStringLiteral("OFFLINE"));
        // Its bridge is what is gone (its last will), not the robot's link.
        QCOMPARE(view.tile("robot-3")->linkText(), QStringLiteral("bridge offline"));
        QCOMPARE(view.tile("robot-3")->controlText(), QStringLiteral("nobody in control"));
        QVERIFY(t1->accessibleDescription().contains("BUMP left"));

        // A robot that comes later gets a tile after the others; values update in place.
        bumped.bumpLeft = false;
        view.setTiles({bumped, cliff, offline, robot(4)});
        QCOMPARE(view.tiles().size(), 4);
        QCOMPARE(view.tiles().last()->values().name, QStringLiteral("robot-4"));
        QCOMPARE(view.tile("robot-1")->hazardText(), QStringLiteral("no bump, no cliff"));
    }

    void clickAsksForTheRobot()
    {
        FleetView view;
        view.resize(1200, 700);
        view.setTiles({robot(1), robot(2)});
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QSignalSpy clicked(&view, &FleetView::robotClicked);
        QTest::mouseClick(view.tile("robot-2"), Qt::LeftButton);
        QCOMPARE(clicked.count(), 1);
        QCOMPARE(clicked[0][0].toString(), QStringLiteral("robot-2"));
        view.setSelected("robot-2");
        QVERIFY(view.tile("robot-2")->isChecked());
        QVERIFY(!view.tile("robot-1")->isChecked());
    }

    // Tiles go in the order of their robots' names, numbers as numbers,
    // whichever robot came online first.
    void tilesAreInNameOrder()
    {
        FleetView view;
        view.setTiles({robot(10), robot(2)});
        view.setTiles({robot(1)});
        QStringList names;
        for (const FleetTile *t : view.tiles())
            names << t->values().name;
        QCOMPARE(names, (QStringList{"robot-1", "robot-2", "robot-10"}));

        FleetView other;
        QList<FleetTileValues> tiles;
        for (const char *name : {"b", "A10", "a9", "a09x"}) {
            FleetTileValues v = robot(1);
            v.name = QString::fromLatin1(name);
            tiles << v;
        }
        other.setTiles(tiles);
        names.clear();
        for (const FleetTile *t : other.tiles())
            names << t->values().name;
        QCOMPARE(names, (QStringList{"a9", "a09x", "A10", "b"}));
    }

    // By pack health: the pack to replace first, the least capacity first
    // among equals, the unmeasured last; the tile says it.
    void tilesSortByPackHealth()
    {
        FleetView view;
        QList<FleetTileValues> tiles{robot(1), robot(2), robot(3), robot(4)};
        tiles[0].packCondition = BatteryCondition::Good;
        tiles[0].packCapacityMah = 2950;
        tiles[1].packCondition = BatteryCondition::Replace;
        tiles[1].packCapacityMah = 1350;
        tiles[2].packCondition = BatteryCondition::Worn;
        tiles[2].packCapacityMah = 2400;
        view.setTiles(tiles);
        const auto names = [&] {
            QStringList n;
            for (const FleetTile *t : view.tiles())
                n << t->values().name;
            return n;
        };
        QCOMPARE(names(), (QStringList{"robot-1", "robot-2", "robot-3", "robot-4"}));
        view.setOrder(FleetView::Order::PackHealth);
        QCOMPARE(names(), (QStringList{"robot-2", "robot-3", "robot-1", "robot-4"}));
        QVERIFY2(view.tile("robot-2")->modeText().endsWith("pack replace, 1350 mAh"), qPrintable(view.tile("robot-2")->modeText()));
        // A pack measured worse moves up.
        tiles[0].packCondition = BatteryCondition::Replace;
        tiles[0].packCapacityMah = 1200;
        view.setTiles(tiles);
        QCOMPARE(names(), (QStringList{"robot-1", "robot-2", "robot-3", "robot-4"}));
        view.orderBox()->setCurrentIndex(0);
        emit view.orderBox()->activated(0);
        QCOMPARE(view.order(), FleetView::Order::Name);
    }

    void asManyColumnsAsFit()
    {
        FleetView view;
        QList<FleetTileValues> tiles;
        for (int i = 1; i <= 30; ++i)
            tiles << robot(i);
        view.setTiles(tiles);
        view.resize(1600, 1000);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const int wide = view.columns();
        const int tileWidth = view.tiles().first()->width();
        QVERIFY2(wide >= 3 && wide * tileWidth <= 1600, qPrintable(QString::number(wide)));
        view.resize(700, 1000);
        QTRY_VERIFY(view.columns() < wide);
        QVERIFY(view.columns() >= 1);
    }

    // Maximized on a 1080p screen the tiles and their type grow until the
    // robots fill the screen, all in view, from 3 robots to 30; on a 720p
    // one a robot alone as large as tiles get. Screenshots into ROOMBA_SCREENSHOTS when set.
    void tilesFillTheScreen_data()
    {
        QTest::addColumn<int>("robots");
        QTest::addColumn<QSize>("screen");
        QTest::addRow("3 at 1920x1080") << 3 << QSize(1920, 1080);
        QTest::addRow("30 at 1920x1080") << 30 << QSize(1920, 1080);
        QTest::addRow("1 at 1280x720") << 1 << QSize(1280, 720);
    }
    // The header's button says what it does now: connect, or change broker.
    void theConnectButtonSaysWhatItDoes()
    {
        FleetView view;
        auto *button = view.findChild<QPushButton *>("fleetConnect");
        QVERIFY(button);
        QCOMPARE(button->text(), QStringLiteral("Connect to broker…"));
        view.setBrokerText(QStringLiteral("mqtt://pi:1883"), true);
        QCOMPARE(button->text(), QStringLiteral("Another broker…"));
        view.setBrokerText(QStringLiteral("No MQTT broker answers at pi:1883. Still trying."), false);
        QCOMPARE(button->text(), QStringLiteral("Connect to broker…"));
    }

    void tilesFillTheScreen()
    {
        QFETCH(int, robots);
        QFETCH(QSize, screen);
        FleetView view;
        view.setBrokerText(QStringLiteral("broker.local:1883"), true);
        QList<FleetTileValues> tiles;
        for (int i = 1; i <= robots; ++i)
            tiles << robot(i);
        view.setTiles(tiles);
        view.resize(screen);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QCoreApplication::processEvents();
        QRect covered;
        for (const FleetTile *t : view.tiles()) {
            const QRect at(t->mapTo(&view, QPoint(0, 0)), t->size());
            QVERIFY2(view.rect().contains(at), qPrintable(t->values().name + " is out of view"));
            QVERIFY(t->width() >= t->sizeHint().width() && t->height() >= t->sizeHint().height());
            covered |= at;
        }
        // The tiles reach across the screen one way or the other (one robot
        // alone as large as tiles get).
        QVERIFY2(covered.width() >= screen.width() * 0.85 || covered.height() >= screen.height() * 0.8
                     || view.tileScale() >= 2.9,
                 qPrintable(QStringLiteral("%1x%2").arg(covered.width()).arg(covered.height())));
        if (robots <= 3)
            QVERIFY2(view.tileScale() >= 2, qPrintable(QString::number(view.tileScale())));
        const QString dir = qEnvironmentVariable("ROOMBA_SCREENSHOTS");
        if (!dir.isEmpty()) {
            QDir().mkpath(dir);
            QVERIFY(view.grab().save(
                QDir(dir).filePath(QStringLiteral("fleet_%1x%2_%3robots.png").arg(screen.width()).arg(screen.height()).arg(robots))));
        }
    }

    // Only the tile whose values changed repaints: robot-2 changes, and by
    // the time it has repainted, robot-1 (given the same values) has not.
    void onlyAChangedTileRepaints()
    {
        FleetView view;
        view.resize(1200, 700);
        view.setTiles({robot(1), robot(2)});
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        FleetTile *same = view.tile("robot-1");
        FleetTile *changed = view.tile("robot-2");
        QTRY_VERIFY(same->paintCount() > 0 && changed->paintCount() > 0);
        const int samePaints = same->paintCount(), changedPaints = changed->paintCount();
        FleetTileValues bumped = robot(2);
        bumped.bumpRight = true;
        view.setTiles({robot(1), bumped});
        QTRY_VERIFY(changed->paintCount() > changedPaints);
        QCOMPARE(same->paintCount(), samePaints);
    }

    // A tile whose bridge went while its robot drove says so in words that
    // fit whole, at 720p and 1080p; and a mode is never squeezed out by the
    // pack's health (the battery is said shorter).
    void aLostBridgeIsSaidWhole_data()
    {
        QTest::addColumn<QSize>("screen");
        QTest::newRow("1280x720") << QSize(1280, 720);
        QTest::newRow("1920x1080") << QSize(1920, 1080);
    }

    void aLostBridgeIsSaidWhole()
    {
        QFETCH(QSize, screen);
        FleetTileValues moving = robot(1);
        moving.online = false;
        moving.bridgeLostAt = QTime(21, 58);
        moving.cutOffController = QStringLiteral("alice-290251");
        moving.cutOffProgram = QStringLiteral("square.py");
        moving.mayBeMoving = true;
        FleetTileValues standing = robot(2);
        standing.online = false;
        standing.bridgeLostAt = QTime(21, 59);
        standing.packCondition = BatteryCondition::Good;
        FleetTileValues healthy = robot(3);
        healthy.mode = QStringLiteral("Passive");
        healthy.packCondition = BatteryCondition::Replace;
        healthy.packCapacityMah = 1350;
        FleetView view;
        view.setBrokerText(QStringLiteral("mqtt://127.0.0.1:1883 · robots: 3 · speaking as teacher"), true);
        view.setTiles({moving, standing, healthy, robot(4)});
        view.resize(screen);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QCoreApplication::processEvents();

        const QStringList lost = view.tile("robot-1")->shownLines();
        QCOMPARE(lost.at(0), QStringLiteral("MAY STILL BE MOVING"));
        QCOMPARE(lost.at(1), QStringLiteral("pick it up, switch it off"));
        QCOMPARE(lost.at(2), QStringLiteral("bridge offline since 21:58"));
        // The long name leaves no room for "'s program": the driver is named all the same.
        QVERIFY2(lost.at(3) == QStringLiteral("alice-290251's program cut off")
                     || lost.at(3) == QStringLiteral("alice-290251 cut off"),
                 qPrintable(lost.at(3)));
        const QString advice = FleetTile::bridgeLostText(moving);
        QVERIFY2(advice.contains(QStringLiteral("cutting off alice-290251's program square.py. A real robot keeps its "
                                                "last drive when its bridge dies")),
                 qPrintable(advice));
        QVERIFY(view.tile("robot-1")->toolTip().contains(advice));
        QCOMPARE(view.tile("robot-2")->shownLines().at(2), QStringLiteral("bridge offline since 21:59"));
        // The bridge runs, its robot is silent: the robot is named.
        FleetTileValues silent = robot(4);
        silent.link = QStringLiteral("stale");
        silent.linkHealthy = false;
        view.setTiles({silent});
        QCOMPARE(view.tile("robot-4")->shownLines().at(2), QStringLiteral("robot silent (link stale)"));
        silent.link = QStringLiteral("lost");
        silent.framesPerSecond.reset();
        view.setTiles({silent});
        QCOMPARE(view.tile("robot-4")->shownLines().at(2), QStringLiteral("robot not answering"));
        QCOMPARE(view.tile("robot-2")->shownLines().at(3), QStringLiteral("nobody in control"));
        QVERIFY(FleetTile::bridgeLostText(standing).contains(QStringLiteral("(the broker is fine)")));
        QVERIFY(FleetTile::bridgeLostText(healthy).isEmpty());
        // The mode whole, the pack's health beside the charge, said shorter.
        QCOMPARE(view.tile("robot-3")->shownModeLine(), QStringLiteral("Passive 87 % · pack replace"));
        for (const FleetTile *t : view.tiles())
            for (const QString &line : t->shownLines())
                QVERIFY2(!line.contains(QChar(0x2026)), qPrintable(t->values().name + ": " + line));
        const QString dir = qEnvironmentVariable("ROOMBA_SCREENSHOTS");
        if (!dir.isEmpty()) {
            QDir().mkpath(dir);
            QVERIFY(view.grab().save(
                QDir(dir).filePath(QStringLiteral("fleet_bridge_lost_%1x%2.png").arg(screen.width()).arg(screen.height()))));
        }
    }

    void everyTextTranslated()
    {
        FleetView empty;
        FleetView view;
        FleetTileValues v = robot(1);
        v.bumpLeft = v.bumpRight = true;
        v.controller = QStringLiteral("alice");
        view.setTiles({v});
        view.setBrokerText(QStringLiteral("mqtt://pi:1883"), true);
        ScopedPseudoTranslation pseudo;
        QCoreApplication::processEvents();
        const QStringList allowed{QStringLiteral("robot-1"), QStringLiteral("mqtt://pi:1883")};
        QStringList untranslated = untranslatedTexts(&view, allowed) + untranslatedTexts(&empty, allowed);
        QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
        const FleetTile *t = view.tile("robot-1");
        for (const QString &s : {t->statusText(), t->hazardText(), t->linkText(), t->controlText()})
            QVERIFY2(s.contains(kPseudoOpen), qPrintable(s));
        // And what a tile says of a bridge that went while its robot drove.
        v.online = false;
        v.bridgeLostAt = QTime(21, 58);
        v.cutOffController = QStringLiteral("alice");
        v.mayBeMoving = true;
        view.setTiles({v});
        for (const QString &s : {t->modeOnlyText(), t->hazardText(), t->linkText(), t->controlText(),
                                 FleetTile::bridgeLostText(v)})
            QVERIFY2(s.contains(kPseudoOpen), qPrintable(s));
    }
};

QTEST_MAIN(TestFleetView)
#include "tst_fleet_view.moc"
