// SPDX-License-Identifier: GPL-3.0-or-later
#include "display_palette.h"
#include "pseudo_translation.h"
#include "oi_text.h"
#include "robot_diagram.h"
#include "sensor_scenes.h"

#include <QImage>
#include <QTest>

using namespace oi;
using namespace sensor_scenes;
using display::State;

namespace {

constexpr CliffSensor kCliffs[] = {CliffSensor::Left, CliffSensor::FrontLeft,
                                   CliffSensor::FrontRight, CliffSensor::Right};
constexpr LightBumper kLightBumpers[] = {LightBumper::Left,        LightBumper::FrontLeft,
                                         LightBumper::CenterLeft,  LightBumper::CenterRight,
                                         LightBumper::FrontRight, LightBumper::Right};

QColor colourAt(const QImage &image, QPointF at) { return image.pixelColor(at.toPoint()); }

QColor stateColour(const RobotDiagram &w, State state)
{
    return display::stateColor(state, w.palette());
}

} // namespace

class TestRobotDiagram : public QObject {
    Q_OBJECT
private:
    void addProfileRows()
    {
        QTest::addColumn<ProfileId>("id");
        QTest::newRow("roomba500") << ProfileId::Roomba500;
        QTest::newRow("create2") << ProfileId::Create2;
        QTest::newRow("create1") << ProfileId::Create1;
    }

    // A diagram of `id` at `size` showing `values`.
    static void show(RobotDiagram &w, ProfileId id, const std::map<int, int> &values,
                     QSize size = {480, 480})
    {
        w.setPalette(lightPalette());
        w.resize(size);
        w.setProfile(profile(id));
        w.setSnapshot(decoded(profile(id), values));
    }

private slots:
    // The dock's beams in a few letters where a box is small; the spoken
    // and tooltip texts keep the whole name.
    void dockBeamsHaveAShortName()
    {
        oi::IrCharacter ir = oi::decodeIrCharacter(profile(ProfileId::Create2), 172);
        QCOMPARE(oitext::infraredName(ir), QString("Red Buoy and Green Buoy"));
        QCOMPARE(oitext::infraredShortName(ir), QString("Red + Green"));
        ir = oi::decodeIrCharacter(profile(ProfileId::Create2), 173);
        QCOMPARE(oitext::infraredShortName(ir), QString("Red + Green + Field"));
        ir = oi::decodeIrCharacter(profile(ProfileId::Create2), 129);
        QCOMPARE(oitext::infraredShortName(ir), oitext::infraredName(ir)); // a remote's key as it is
    }

    void sizeHintsAreLargeEnoughToRead()
    {
        RobotDiagram w;
        // Small enough for the middle of a 1280×720 window, large enough to read.
        QVERIFY(w.minimumSizeHint().width() >= 240);
        QVERIFY(w.minimumSizeHint().height() >= 240);
        QVERIFY(w.sizeHint().width() >= w.minimumSizeHint().width());
        QVERIFY(w.sizeHint().height() >= w.minimumSizeHint().height());
    }

    void shortChipsPutTheirCaptionsBesideTheirValues()
    {
        RobotDiagram w;
        // The diagram's dock in a 1280×720 window: the chips' rows are too
        // short for a caption above its value without clipping the value's
        // descenders ("Red Buoy", "not moving").
        w.resize(470, 260);
        QVERIFY(w.chipCaptionsBesideValues());
        // In a 1920×1080 window there is room for both lines.
        w.resize(600, 430);
        QVERIFY(!w.chipCaptionsBesideValues());
    }

    void drawingKeepsItsAspectAndScales()
    {
        RobotDiagram w;
        w.resize(400, 400);
        const QRectF small = w.robotRect();
        w.resize(800, 600);
        const QRectF wide = w.robotRect();
        QCOMPARE(qRound(wide.width()), qRound(wide.height()));
        QCOMPARE(qRound(small.width()), qRound(small.height()));
        QVERIFY(wide.width() > small.width() * 1.4);
        QVERIFY(QRectF(w.rect()).contains(wide));
        QCOMPARE(qRound(wide.center().x()), 400);
    }

    void rightBumperIsOnTheRight()
    {
        // Seen from above with the front up, the robot's right is the widget's right.
        RobotDiagram w;
        w.resize(480, 480);
        const qreal middle = w.robotRect().center().x();
        QVERIFY(w.bumperCentre(false).x() > middle);
        QVERIFY(w.bumperCentre(true).x() < middle);
        QVERIFY(w.bumperRect(false).center().x() > middle);
        QVERIFY(w.bumperRect(true).center().x() < middle);
        QVERIFY(w.bumperRect(true).contains(w.bumperCentre(true)));
        QVERIFY(w.cliffSensorCentre(CliffSensor::Right).x() > w.cliffSensorCentre(CliffSensor::FrontRight).x());
        QVERIFY(w.cliffSensorCentre(CliffSensor::FrontRight).x() > middle);
        QVERIFY(w.cliffSensorCentre(CliffSensor::FrontLeft).x() < middle);
        QVERIFY(w.cliffSensorCentre(CliffSensor::Left).x() < w.cliffSensorCentre(CliffSensor::FrontLeft).x());
        QVERIFY(w.cliffSensorCentre(CliffSensor::FrontLeft).y() < w.cliffSensorCentre(CliffSensor::Left).y());
        QVERIFY(w.wheelCentre(false).x() > middle);
        QVERIFY(w.wallCentre().x() > w.robotRect().right());
        for (int i = 1; i < 6; ++i)
            QVERIFY(w.lightBumperCentre(kLightBumpers[i]).x() > w.lightBumperCentre(kLightBumpers[i - 1]).x());
    }

    void bumpLightsOnlyThatHalf_data() { addProfileRows(); }
    void bumpLightsOnlyThatHalf()
    {
        QFETCH(ProfileId, id);
        RobotDiagram w;
        std::map<int, int> values = quietValues(profile(id));

        values[7] = bit::BumpLeft;
        show(w, id, values);
        QImage image = w.grab().toImage();
        QCOMPARE(colourAt(image, w.bumperCentre(true)), stateColour(w, State::Alert));
        QCOMPARE(colourAt(image, w.bumperCentre(false)), stateColour(w, State::Idle));

        values[7] = bit::BumpRight; // bit 0 is the right bumper
        show(w, id, values);
        image = w.grab().toImage();
        QCOMPARE(colourAt(image, w.bumperCentre(false)), stateColour(w, State::Alert));
        QCOMPARE(colourAt(image, w.bumperCentre(true)), stateColour(w, State::Idle));

        values[7] = 0;
        show(w, id, values);
        image = w.grab().toImage();
        QCOMPARE(colourAt(image, w.bumperCentre(false)), stateColour(w, State::Idle));
        QCOMPARE(colourAt(image, w.bumperCentre(true)), stateColour(w, State::Idle));
    }

    void cliffLightsOnlyThatSensor_data()
    {
        QTest::addColumn<ProfileId>("id");
        QTest::addColumn<CliffSensor>("sensor");
        const std::pair<const char *, ProfileId> profiles[] = {
            {"roomba500", ProfileId::Roomba500}, {"create2", ProfileId::Create2},
            {"create1", ProfileId::Create1}};
        const char *names[] = {"left", "front left", "front right", "right"};
        for (const auto &[key, id] : profiles)
            for (int i = 0; i < 4; ++i)
                QTest::addRow("%s %s", key, names[i]) << id << kCliffs[i];
    }
    void cliffLightsOnlyThatSensor()
    {
        QFETCH(ProfileId, id);
        QFETCH(CliffSensor, sensor);
        RobotDiagram w;
        std::map<int, int> values = quietValues(profile(id));
        values[9 + static_cast<int>(sensor)] = 1;
        show(w, id, values);
        const QImage image = w.grab().toImage();
        for (CliffSensor other : kCliffs) {
            const State expected = other == sensor ? State::Alert : State::Idle;
            QCOMPARE(colourAt(image, w.cliffSensorCentre(other)), stateColour(w, expected));
        }
        QCOMPARE(colourAt(image, w.bumperCentre(true)), stateColour(w, State::Idle));
    }

    void cliffSignalRectsDoNotOverlap()
    {
        RobotDiagram w;
        w.resize(360, 360);
        for (CliffSensor a : kCliffs) {
            QVERIFY(w.robotRect().contains(w.cliffSignalRect(a)));
            QVERIFY(!w.cliffSignalRect(a).contains(w.cliffSensorCentre(a)));
            for (CliffSensor b : kCliffs)
                if (a != b)
                    QVERIFY(!w.cliffSignalRect(a).intersects(w.cliffSignalRect(b)));
        }
    }

    void lightBumpersOnRoombas_data()
    {
        QTest::addColumn<ProfileId>("id");
        QTest::newRow("roomba500") << ProfileId::Roomba500;
        QTest::newRow("create2") << ProfileId::Create2;
    }
    void lightBumpersOnRoombas()
    {
        QFETCH(ProfileId, id);
        RobotDiagram w;
        std::map<int, int> values = quietValues(profile(id));
        values[45] = bit::LightBumperCenterLeft;
        values[46 + static_cast<int>(LightBumper::CenterLeft)] = 3000;
        values[46 + static_cast<int>(LightBumper::Right)] = 2048;
        show(w, id, values);
        const QImage image = w.grab().toImage();
        for (LightBumper b : kLightBumpers) {
            const State expected = b == LightBumper::CenterLeft ? State::Warning : State::Idle;
            QCOMPARE(colourAt(image, w.lightBumperCentre(b)), stateColour(w, expected));
        }
        // The bar reaches as far out as the signal is strong.
        const QColor track = colourAt(image, w.lightBumpSignalPoint(LightBumper::Left, 0.5));
        QCOMPARE(colourAt(image, w.lightBumpSignalPoint(LightBumper::CenterLeft, 0.6)),
                 stateColour(w, State::Warning));
        QCOMPARE(colourAt(image, w.lightBumpSignalPoint(LightBumper::CenterLeft, 0.85)), track);
        const QColor rightNear = colourAt(image, w.lightBumpSignalPoint(LightBumper::Right, 0.4));
        QVERIFY(rightNear != track);
        QVERIFY(rightNear != stateColour(w, State::Warning));
        QCOMPARE(colourAt(image, w.lightBumpSignalPoint(LightBumper::Right, 0.6)), track);
    }

    void noLightBumpersOnCreate1()
    {
        // Even a snapshot that carries light-bumper packets draws none on a Create 1.
        RobotDiagram w;
        show(w, ProfileId::Create1, quietValues(profile(ProfileId::Create1)));
        SensorSnapshot s = decoded(profile(ProfileId::Create1), quietValues(profile(ProfileId::Create1)));
        s.set(45, 0x3F);
        for (int id = 46; id <= 51; ++id)
            s.set(id, 4095);
        w.setSnapshot(s);
        const QImage image = w.grab().toImage();
        const QColor background = w.palette().color(QPalette::Window);
        for (LightBumper b : kLightBumpers) {
            QCOMPARE(colourAt(image, w.lightBumperCentre(b)), stateColour(w, State::Idle));
            const QPoint bar = w.lightBumpSignalPoint(b, 0.1).toPoint();
            if (image.rect().contains(bar))
                QCOMPARE(image.pixelColor(bar), background);
        }
    }

    void wheelDropsAndCaster_data() { addProfileRows(); }
    void wheelDropsAndCaster()
    {
        QFETCH(ProfileId, id);
        RobotDiagram w;
        std::map<int, int> values = quietValues(profile(id));
        values[7] = bit::WheelDropLeft | bit::WheelDropCaster;
        show(w, id, values);
        const QImage image = w.grab().toImage();
        QCOMPARE(colourAt(image, w.wheelCentre(true)), stateColour(w, State::Alert));
        QVERIFY(colourAt(image, w.wheelCentre(false)) != stateColour(w, State::Alert));
        const bool create1 = id == ProfileId::Create1;
        // Bit 4 is the caster only on the Create 1; the Roombas draw no caster.
        QCOMPARE(colourAt(image, w.casterCentre()) == stateColour(w, State::Alert), create1);
    }

    // A lesson points at parts with a ring in the highlight colour.
    void highlightRingsTheParts()
    {
        RobotDiagram w;
        show(w, ProfileId::Create2, quietValues(profile(ProfileId::Create2)));
        const qreal scale = w.robotRect().width() / 500; // the body is 500 scene units across
        const QColor ring = w.palette().color(QPalette::Highlight);
        for (const QString part : {"cliff_front_left", "bump_right", "wall", "ir_receiver", "light_bump_right"}) {
            const qreal radius = part.startsWith("cliff") ? 36 : 46;
            const QPointF onRing = *w.partCentre(part) + QPointF(radius * scale, 0);
            w.setHighlightedParts({});
            QVERIFY2(colourAt(w.grab().toImage(), onRing) != ring, qPrintable(part));
            w.setHighlightedParts({part});
            QVERIFY2(colourAt(w.grab().toImage(), onRing) == ring, qPrintable(part));
        }
        QVERIFY(!w.partCentre("nose"));
        w.setProfile(profile(ProfileId::Create1));
        QVERIFY(!w.partCentre("light_bump_right")); // the Create has none
    }

    void wallSensor()
    {
        RobotDiagram w;
        std::map<int, int> values = quietValues(profile(ProfileId::Create2));
        show(w, ProfileId::Create2, values);
        QCOMPARE(colourAt(w.grab().toImage(), w.wallCentre()), stateColour(w, State::Idle));
        values[8] = 1;
        show(w, ProfileId::Create2, values);
        QCOMPARE(colourAt(w.grab().toImage(), w.wallCentre()), stateColour(w, State::Warning));
    }

    void staleGreysEverything()
    {
        RobotDiagram w;
        std::map<int, int> values = quietValues(profile(ProfileId::Create2));
        values[7] = bit::BumpLeft;
        values[11] = 1;
        values[45] = bit::LightBumperLeft;
        show(w, ProfileId::Create2, values);
        QImage image = w.grab().toImage();
        QCOMPARE(colourAt(image, w.bumperCentre(true)), stateColour(w, State::Alert));

        w.setStale(true);
        QVERIFY(w.isStale());
        image = w.grab().toImage();
        const QPointF points[] = {w.bumperCentre(true), w.bumperCentre(false),
                                  w.cliffSensorCentre(CliffSensor::FrontRight),
                                  w.lightBumperCentre(LightBumper::Left)};
        for (QPointF at : points) {
            QVERIFY2(isGrey(colourAt(image, at)), qPrintable(colourAt(image, at).name()));
            QVERIFY(colourAt(image, at) != stateColour(w, State::Alert));
        }
        // Still readable: what was lit stays apart from what was not.
        QVERIFY(colourAt(image, w.bumperCentre(true)) != colourAt(image, w.bumperCentre(false)));
        // The STALE banner sits in the middle of the robot.
        const QRectF robot = w.robotRect();
        const QPointF bannerEdge(robot.center().x() - robot.width() * 0.35,
                                 robot.center().y() + robot.height() * 0.27);
        QCOMPARE(colourAt(image, bannerEdge), stateColour(w, State::Stale));

        w.setStale(false);
        image = w.grab().toImage();
        QCOMPARE(colourAt(image, w.bumperCentre(true)), stateColour(w, State::Alert));
    }

    void darkPaletteUsesItsColours()
    {
        RobotDiagram w;
        std::map<int, int> values = quietValues(profile(ProfileId::Create2));
        values[7] = bit::BumpRight;
        show(w, ProfileId::Create2, values);
        w.setPalette(darkPalette());
        const QImage image = w.grab().toImage();
        QCOMPARE(colourAt(image, w.bumperCentre(false)), display::stateColor(State::Alert, darkPalette()));
        QCOMPARE(colourAt(image, QPointF(2, 2)), darkPalette().color(QPalette::Window));
    }

    void statusNamesComeFromTheProfile()
    {
        RobotDiagram w;
        show(w, ProfileId::Create2, busyValues(profile(ProfileId::Create2)));
        QCOMPARE(w.statusTexts(),
                 QStringList({"IR omni: Red Buoy and Force Field", "IR left: Forward", "IR right: Green Buoy",
                              "Buttons: Clean + Dock", "Stasis: DIRTY WHEEL", "Virtual wall: seen",
                              "Overcurrent: Left Wheel"}));

        show(w, ProfileId::Create1, busyValues(profile(ProfileId::Create1)));
        QCOMPARE(w.statusTexts(),
                 QStringList({"IR: Red Buoy and Force Field", "Virtual wall: seen", "Buttons: Play",
                              "Overcurrent: Left Wheel"}));

        std::map<int, int> values = quietValues(profile(ProfileId::Create1));
        values[14] = bit::OcLowSideDriver0 | bit::OcLowSideDriver2;
        values[18] = bit::ButtonAdvance;
        show(w, ProfileId::Create1, values);
        QCOMPARE(w.statusTexts(),
                 QStringList({"IR: None", "Virtual wall: none", "Buttons: Advance",
                              "Overcurrent: Low Side Driver 0, Low Side Driver 2"}));
    }

    void stasisIsNotOnlyOneOrZero_data()
    {
        QTest::addColumn<int>("value");
        QTest::addColumn<QString>("text");
        QTest::newRow("not moving") << 0 << "Stasis: not moving";
        QTest::newRow("moving") << 1 << "Stasis: moving";
        QTest::newRow("dirty wheel") << 2 << "Stasis: DIRTY WHEEL";
        QTest::newRow("reserved") << 3 << "Stasis: reserved (3)";
    }
    void stasisIsNotOnlyOneOrZero()
    {
        QFETCH(int, value);
        QFETCH(QString, text);
        RobotDiagram w;
        std::map<int, int> values = quietValues(profile(ProfileId::Create2));
        values[58] = value;
        show(w, ProfileId::Create2, values);
        QVERIFY2(w.statusTexts().contains(text), qPrintable(w.statusTexts().join(" | ")));
    }

    void missingPacketsShowADash()
    {
        RobotDiagram w;
        w.setProfile(profile(ProfileId::Create2));
        SensorSnapshot s(profile(ProfileId::Create2));
        s.set(7, bit::BumpLeft);
        w.setSnapshot(s);
        for (const QString &text : w.statusTexts())
            QVERIFY2(text.endsWith(QStringLiteral("\u2014")), qPrintable(text));
    }

    void translatesOnTheSpot()
    {
        RobotDiagram w;
        show(w, ProfileId::Create2, busyValues(profile(ProfileId::Create2)));
        w.show();
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList left = untranslatedTexts(&w);
            QVERIFY2(left.isEmpty(), qPrintable(left.join('\n')));
            // Painted chips and the spoken summary follow the language too.
            for (const QString &text : w.statusTexts())
                QVERIFY2(!looksUntranslated(text), qPrintable(text));
            QVERIFY2(!looksUntranslated(w.accessibleDescription()), qPrintable(w.accessibleDescription()));
            QVERIFY2(w.statusTexts().first().contains(QString(kPseudoOpen) + "Red Buoy" + kPseudoClose),
                     qPrintable(w.statusTexts().first()));
        }
        QCoreApplication::processEvents();
        QCOMPARE(w.statusTexts().first(), QString("IR omni: Red Buoy and Force Field"));
        QCOMPARE(w.accessibleName(), QString("Robot sensor diagram"));
    }

    void accessibleDescriptionFollowsTheData()
    {
        RobotDiagram w;
        QVERIFY(!w.accessibleName().isEmpty());
        QCOMPARE(w.accessibleDescription(), QString("No sensor data"));
        show(w, ProfileId::Create1, quietValues(profile(ProfileId::Create1)));
        QCOMPARE(w.accessibleDescription(), QString("Nothing detected"));
        std::map<int, int> values = quietValues(profile(ProfileId::Create2));
        show(w, ProfileId::Create2, values);
        QCOMPARE(w.accessibleDescription(), QString("Stasis: moving"));
        values[7] = bit::BumpLeft;
        values[11] = 1; // cliff front right
        show(w, ProfileId::Create2, values);
        QCOMPARE(w.accessibleDescription(), QString("Bump left; Cliff front right; Stasis: moving"));
        w.setStale(true);
        QVERIFY(w.accessibleDescription().startsWith("Data is stale; Bump left"));
    }

    void screenshots()
    {
        const QSize sizes[] = {{480, 480}, {800, 600}, {360, 360}, {400, 760}, {1200, 420}};
        for (ProfileId id : allProfiles()) {
            for (QSize size : sizes) {
                for (bool dark : {false, true}) {
                    RobotDiagram w;
                    show(w, id, busyValues(profile(id)), size);
                    w.setPalette(dark ? darkPalette() : lightPalette());
                    const QString name = sceneName("diagram", profile(id), size, dark);
                    saveScreenshot(w, name);
                    w.setStale(true);
                    saveScreenshot(w, name + "_stale");
                }
            }
        }
        // Longer texts, as translations are, still fit their boxes.
        RobotDiagram w;
        show(w, ProfileId::Create1, busyValues(profile(ProfileId::Create1)), {360, 360});
        w.setStale(true);
        ScopedPseudoTranslation pseudo;
        QCoreApplication::processEvents();
        saveScreenshot(w, "diagram_create1_360x360_pseudo");
    }
};

QTEST_MAIN(TestRobotDiagram)
#include "tst_robot_diagram.moc"
