// SPDX-License-Identifier: GPL-3.0-or-later
#include "display_palette.h"
#include "pseudo_translation.h"
#include "sensor_gauges.h"
#include "sensor_scenes.h"
#include "value_gauge.h"

#include <QLabel>
#include <QTest>

using namespace oi;
using namespace sensor_scenes;

namespace {

const QStringList kRoombaOnly = {"left_motor_current", "right_motor_current", "main_brush_current",
                                 "side_brush_current", "dirt_detect"};
const QStringList kCreate1Only = {"cargo_bay_analog", "digital_input_0", "digital_input_1",
                                  "digital_input_2",  "digital_input_3", "baud_rate_change"};

} // namespace

class TestSensorGauges : public QObject {
    Q_OBJECT
private:
    static void show(SensorGauges &w, ProfileId id, const std::map<int, int> &values)
    {
        w.setProfile(profile(id));
        w.setSnapshot(decoded(profile(id), values));
    }

private slots:
    void valueGaugeShowsValueUnitAndFlag()
    {
        ValueGauge g("Voltage");
        QCOMPARE(g.title(), QString("Voltage"));
        QVERIFY(!g.hasBar());
        g.setValue("14.52", "V");
        QCOMPARE(g.text(), QString("14.52 V"));
        QCOMPARE(g.valueText(), QString("14.52"));
        QCOMPARE(g.unitText(), QString("V"));
        g.setValue("straight");
        QCOMPARE(g.text(), QString("straight"));

        g.resize(220, 110);
        const QColor alert = display::stateColor(display::State::Alert, g.palette());
        QVERIFY(g.grab().toImage().pixelColor(g.width() / 2, 1) != alert);
        QVERIFY(g.findChild<QLabel *>("outOfRange")->isHidden());
        g.setOutOfRange(true);
        QVERIFY(g.isOutOfRange());
        QVERIFY(!g.findChild<QLabel *>("outOfRange")->isHidden());
        QCOMPARE(g.findChild<QLabel *>("outOfRange")->text(), QString("OUT OF RANGE"));
        QCOMPARE(g.grab().toImage().pixelColor(g.width() / 2, 1), alert);
        g.setOutOfRange(false);
        QVERIFY(g.findChild<QLabel *>("outOfRange")->isHidden());
    }

    void valueGaugeBar()
    {
        ValueGauge g("Velocity");
        g.setRange(-500, 500);
        QVERIFY(g.hasBar());
        g.setBarValue(250);
        QCOMPARE(g.barFraction(), 0.25); // from zero, not from the left end
        g.setBarValue(-500);
        QCOMPARE(g.barFraction(), 0.5);
        g.setBarValue(900);
        QCOMPARE(g.barFraction(), 0.5); // clamped to the end of the bar
        g.setBarValue(std::nullopt);
        QCOMPARE(g.barFraction(), 0.0);
        g.setRange(0, 100);
        g.setBarValue(79);
        QCOMPARE(g.barFraction(), 0.79);
        g.clearRange();
        QVERIFY(!g.hasBar());
    }

    void batteryAndPowerTexts_data()
    {
        QTest::addColumn<ProfileId>("id");
        QTest::newRow("roomba500") << ProfileId::Roomba500;
        QTest::newRow("create2") << ProfileId::Create2;
        QTest::newRow("create1") << ProfileId::Create1;
    }
    void batteryAndPowerTexts()
    {
        QFETCH(ProfileId, id);
        SensorGauges w;
        show(w, id, busyValues(profile(id)));
        QCOMPARE(w.gaugeText("battery"), QString("79 %")); // 2140 of 2696 mAh
        QCOMPARE(w.gauge("battery")->detailText(), QString("2140 of 2696 mAh"));
        QCOMPARE(w.gauge("battery")->barFraction(), 2140.0 / 2696.0);
        QCOMPARE(w.gaugeText("voltage"), QString("15.12 V"));
        QCOMPARE(w.gaugeText("current"), QString("640 mA"));
        QCOMPARE(w.gauge("current")->detailText(), QString("charging"));
        QCOMPARE(w.gaugeText("temperature"), QString("27 \u00b0C"));
        QCOMPARE(w.gaugeText("charging_state"), QString("Trickle charging"));
        QCOMPARE(w.gaugeText("charging_sources"), QString("Home Base"));
        for (const QString &key : SensorGauges::allGaugeKeys())
            QVERIFY2(!w.isGaugeOutOfRange(key), qPrintable(key));
    }

    void chargingStates_data()
    {
        QTest::addColumn<int>("value");
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("outOfRange");
        QTest::newRow("0") << 0 << "Not charging" << false;
        QTest::newRow("1") << 1 << "Reconditioning" << false;
        QTest::newRow("2") << 2 << "Full charging" << false;
        QTest::newRow("3") << 3 << "Trickle charging" << false;
        QTest::newRow("4") << 4 << "Waiting" << false;
        QTest::newRow("5") << 5 << "Charging fault" << false;
        QTest::newRow("6") << 6 << "Unknown (6)" << true;
    }
    void chargingStates()
    {
        QFETCH(int, value);
        QFETCH(QString, text);
        QFETCH(bool, outOfRange);
        SensorGauges w;
        std::map<int, int> values = quietValues(profile(ProfileId::Create2));
        values[21] = value;
        show(w, ProfileId::Create2, values);
        QCOMPARE(w.gaugeText("charging_state"), text);
        QCOMPARE(w.isGaugeOutOfRange("charging_state"), outOfRange);
    }

    // The pack's health in the Battery section; the charge's caveat after a
    // boot that guessed it; a charging fault's causes and steps.
    void batteryHealthShown()
    {
        SensorGauges w;
        std::map<int, int> values = quietValues(profile(ProfileId::Create2));
        values[21] = 5;
        show(w, ProfileId::Create2, values);
        QVERIFY(w.isGaugeShown("battery_health"));
        QCOMPARE(w.gaugeText("battery_health"), QString("Not measured yet"));
        QVERIFY(w.gauge("charging_state")->toolTip().contains("Clean the contacts, reseat the pack"));

        BatteryHealthReport r;
        r.measurement.capacityMah = 1350;
        r.measurement.claimedCapacityMah = 3000;
        r.measurement.resistanceMohm = 900;
        r.measurement.cycleSeen = 0.4;
        r.condition = BatteryHealth::judge(r.measurement, &r.reason);
        r.estimatedFromVoltage = true;
        w.setBatteryHealth(r);
        QCOMPARE(w.gaugeText("battery_health"), QString("Replace"));
        QCOMPARE(w.gauge("battery_health")->detailText(), QString("1350 of 3000 mAh, 900 mΩ"));
        QVERIFY(w.gauge("battery_health")->toolTip().startsWith("holds 1350 of the 3000 mAh it claims (45 %)"));
        QVERIFY2(w.gauge("battery")->detailText().endsWith("estimated from voltage"),
                 qPrintable(w.gauge("battery")->detailText()));

        values[21] = 3;
        show(w, ProfileId::Create2, values);
        QVERIFY(w.gauge("charging_state")->toolTip().isEmpty());
    }

    void chargingSourcesUseProfileNames()
    {
        SensorGauges w;
        std::map<int, int> values = quietValues(profile(ProfileId::Roomba500));
        values[34] = 0;
        show(w, ProfileId::Roomba500, values);
        QCOMPARE(w.gaugeText("charging_sources"), QString("none"));
        values[34] = bit::SourceInternalCharger | bit::SourceHomeBase;
        show(w, ProfileId::Roomba500, values);
        QCOMPARE(w.gaugeText("charging_sources"), QString("Internal Charger + Home Base"));
    }

    void requestedVelocity_data()
    {
        QTest::addColumn<int>("velocity");
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("outOfRange");
        QTest::newRow("forward") << 200 << "200 mm/s" << false;
        QTest::newRow("full reverse") << -500 << "-500 mm/s" << false;
        QTest::newRow("too fast") << 600 << "600 mm/s" << true;
        QTest::newRow("too fast backwards") << -501 << "-501 mm/s" << true;
    }
    void requestedVelocity()
    {
        QFETCH(int, velocity);
        QFETCH(QString, text);
        QFETCH(bool, outOfRange);
        for (ProfileId id : allProfiles()) {
            SensorGauges w;
            std::map<int, int> values = quietValues(profile(id));
            values[39] = velocity;
            show(w, id, values);
            if (!profile(id).packet(39)) {
                // The SCI has no requested velocity: a dash, never a value.
                QCOMPARE(w.gaugeText("requested_velocity"), QString(QChar(0x2014)));
                continue;
            }
            QCOMPARE(w.gaugeText("requested_velocity"), text);
            QCOMPARE(w.isGaugeOutOfRange("requested_velocity"), outOfRange);
            const bool flagShown = !w.gauge("requested_velocity")->findChild<QLabel *>("outOfRange")->isHidden();
            QCOMPARE(flagShown, outOfRange);
        }
    }

    void requestedRadius_data()
    {
        QTest::addColumn<int>("radius");
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("outOfRange");
        QTest::newRow("32767") << 32767 << "straight" << false;
        QTest::newRow("32768") << 32768 << "straight" << false; // decodes as -32768
        QTest::newRow("-1") << -1 << "turn in place cw" << false;
        QTest::newRow("1") << 1 << "turn in place ccw" << false;
        QTest::newRow("500") << 500 << "500 mm" << false;
        QTest::newRow("-2000") << -2000 << "-2000 mm" << false;
        QTest::newRow("2001") << 2001 << "2001 mm" << true;
    }
    void requestedRadius()
    {
        QFETCH(int, radius);
        QFETCH(QString, text);
        QFETCH(bool, outOfRange);
        SensorGauges w;
        std::map<int, int> values = quietValues(profile(ProfileId::Create2));
        values[40] = radius;
        show(w, ProfileId::Create2, values);
        QCOMPARE(w.gaugeText("requested_radius"), text);
        QCOMPARE(w.isGaugeOutOfRange("requested_radius"), outOfRange);

        SensorSnapshot direct(profile(ProfileId::Create2));
        direct.set(40, radius);
        w.setSnapshot(direct);
        QCOMPARE(w.gaugeText("requested_radius"), text);
    }

    // ERRATA 16: firmware before 3.3.0 reports the requested radius wrongly.
    // The gauge greys and its tooltip says why; newer firmware lifts it.
    void unreliableRadiusIsGreyedWithTheReason()
    {
        SensorGauges w;
        std::map<int, int> values = quietValues(profile(ProfileId::Create2));
        values[40] = 500;
        show(w, ProfileId::Create2, values);
        ValueGauge *radius = w.gauge("requested_radius");
        QVERIFY(!radius->isGreyed());
        QVERIFY(!radius->toolTip().contains("3.3.0"));

        w.setCorrections(correctionsFor({3, 2, 9}));
        QVERIFY(radius->isGreyed());
        QVERIFY2(radius->toolTip().contains("before 3.3.0") && radius->toolTip().contains("requested radius"),
                 qPrintable(radius->toolTip()));
        QVERIFY(radius->accessibleDescription().contains("unreliable"));
        QCOMPARE(w.gaugeText("requested_radius"), QString("500 mm"));
        QVERIFY(!w.gauge("requested_velocity")->isGreyed());
        // Coming back from stale leaves it grey.
        w.setStale(true);
        w.setStale(false);
        QVERIFY(radius->isGreyed());

        w.setCorrections(correctionsFor({3, 3, 0}));
        QVERIFY(!radius->isGreyed());
        QVERIFY(!radius->toolTip().contains("3.3.0"));
    }

    void profileSwitchingHidesAndShowsGauges()
    {
        SensorGauges w;
        w.resize(640, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));

        show(w, ProfileId::Create1, busyValues(profile(ProfileId::Create1)));
        for (const QString &key : kCreate1Only) {
            QVERIFY2(w.isGaugeShown(key), qPrintable(key));
            QVERIFY(w.gauge(key)->isVisible());
        }
        for (const QString &key : kRoombaOnly) {
            QVERIFY2(!w.isGaugeShown(key), qPrintable(key));
            QVERIFY(!w.gauge(key)->isVisible());
        }
        QCOMPARE(w.shownGaugeKeys().size(), 9 + kCreate1Only.size());

        for (ProfileId id : {ProfileId::Roomba500, ProfileId::Create2}) {
            show(w, id, busyValues(profile(id)));
            for (const QString &key : kRoombaOnly)
                QVERIFY2(w.isGaugeShown(key), qPrintable(key));
            for (const QString &key : kCreate1Only)
                QVERIFY2(!w.isGaugeShown(key), qPrintable(key));
            QCOMPARE(w.shownGaugeKeys().size(), 9 + kRoombaOnly.size());
        }
        QCOMPARE(w.gaugeText("cargo_bay_analog"), QString("\u2014"));
    }

    void motorCurrentsAndDirt()
    {
        SensorGauges w;
        show(w, ProfileId::Create2, busyValues(profile(ProfileId::Create2)));
        QCOMPARE(w.gaugeText("left_motor_current"), QString("212 mA"));
        QCOMPARE(w.gaugeText("right_motor_current"), QString("198 mA"));
        QCOMPARE(w.gaugeText("main_brush_current"), QString("344 mA"));
        QCOMPARE(w.gaugeText("side_brush_current"), QString("61 mA"));
        QCOMPARE(w.gaugeText("dirt_detect"), QString("42"));
    }

    void cargoBayOnCreate1()
    {
        SensorGauges w;
        show(w, ProfileId::Create1, busyValues(profile(ProfileId::Create1)));
        QCOMPARE(w.gaugeText("cargo_bay_analog"), QString("712"));
        QCOMPARE(w.gauge("cargo_bay_analog")->detailText(), QString("3.48 V on pin 4"));
        QCOMPARE(w.gaugeText("digital_input_0"), QString("high"));
        QCOMPARE(w.gaugeText("digital_input_1"), QString("low"));
        QCOMPARE(w.gaugeText("digital_input_2"), QString("high"));
        QCOMPARE(w.gaugeText("digital_input_3"), QString("low"));
        // The baud-rate-change pin is active low: bit 4 clear means asserted.
        QCOMPARE(w.gaugeText("baud_rate_change"), QString("asserted (low)"));
        QCOMPARE(w.gauge("baud_rate_change")->title(), QString("Baud Rate Change (active low)"));
        QCOMPARE(w.gauge("digital_input_2")->title(), QString("Digital Input 2"));

        show(w, ProfileId::Create1, quietValues(profile(ProfileId::Create1)));
        QCOMPARE(w.gaugeText("baud_rate_change"), QString("idle (high)"));
        QCOMPARE(w.gaugeText("digital_input_0"), QString("low"));
    }

    void missingPacketsShowADash()
    {
        SensorGauges w;
        w.setProfile(profile(ProfileId::Create2));
        SensorSnapshot s(profile(ProfileId::Create2));
        s.set(22, 14000);
        w.setSnapshot(s);
        QCOMPARE(w.gaugeText("voltage"), QString("14.00 V"));
        QCOMPARE(w.gaugeText("battery"), QString("\u2014 %"));
        QCOMPARE(w.gaugeText("requested_radius"), QString("\u2014 mm"));
        QCOMPARE(w.gaugeText("charging_state"), QString("\u2014"));
        QCOMPARE(w.gaugeText("nonsense"), QString());
    }

    void staleShowsBannerAndGreys()
    {
        SensorGauges w;
        show(w, ProfileId::Create2, busyValues(profile(ProfileId::Create2)));
        auto *banner = w.findChild<QLabel *>("staleBanner");
        QVERIFY(banner);
        QVERIFY(banner->isHidden());
        ValueGauge *battery = w.gauge("battery");
        battery->resize(200, 100);
        const QImage live = battery->grab().toImage();
        const QPoint stripe(4, battery->height() / 2);
        QCOMPARE(live.pixelColor(stripe), display::stateColor(display::State::Active, battery->palette()));
        w.setStale(true);
        QVERIFY(w.isStale());
        QVERIFY(!banner->isHidden());
        QVERIFY(banner->text().startsWith("STALE"));
        const QImage stale = battery->grab().toImage();
        QVERIFY(stale != live);
        // The stripe down the left edge loses its colour.
        QCOMPARE(stale.pixelColor(stripe), display::stateColor(display::State::Idle, battery->palette()));
        QCOMPARE(w.gaugeText("voltage"), QString("15.12 V")); // the last values stay readable
        w.setStale(false);
        QVERIFY(banner->isHidden());
    }

    void columnsFollowTheWidth()
    {
        SensorGauges w;
        w.resize(330, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const int narrow = w.columnCount();
        w.resize(900, 900);
        QTRY_VERIFY(w.columnCount() > narrow);
        QVERIFY(narrow >= 1);
        // Every shown gauge keeps the width it needs to be read.
        for (const QString &key : w.shownGaugeKeys())
            QVERIFY2(w.gauge(key)->width() >= w.gauge(key)->minimumSizeHint().width(), qPrintable(key));
    }

    // The window's gauges dock, about 390 pixels wide, cut captions to
    // "Requested velo…" and details to "2699 of 3000 m…".
    void captionsAreNeverCutOff_data()
    {
        QTest::addColumn<ProfileId>("id");
        QTest::addColumn<int>("width");
        QTest::addColumn<bool>("oneLine");
        for (ProfileId id : allProfiles()) {
            const QString name = QString::fromUtf8(profile(id).key.data(), qsizetype(profile(id).key.size()));
            for (int width : {390, 480, 620, 900})
                QTest::addRow("%s %d", qPrintable(name), width) << id << width << true;
            // Narrower than any column of whole captions: they wrap.
            QTest::addRow("%s 170", qPrintable(name)) << id << 170 << false;
        }
    }
    void captionsAreNeverCutOff()
    {
        QFETCH(ProfileId, id);
        QFETCH(int, width);
        QFETCH(bool, oneLine);
        SensorGauges w;
        std::map<int, int> values = busyValues(profile(id));
        values[25] = 2699;
        values[26] = 3000;
        show(w, id, values);
        w.resize(width, 600);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY(w.gauge("battery")->findChild<QLabel *>("title")->width() > 0);
        for (const QString &key : w.shownGaugeKeys()) {
            for (const char *part : {"title", "detail"}) {
                const auto *label = w.gauge(key)->findChild<QLabel *>(part);
                QVERIFY(label);
                if (label->isHidden() || label->text().isEmpty())
                    continue;
                const QString what = QStringLiteral("%1 %2: \"%3\" in %4 px").arg(key, part, label->text()).arg(label->width());
                // All of it shows: on one line where the dock is wide enough
                // (for captions of up to 24 characters; longer ones, such as
                // "Baud Rate Change (active low)", may wrap), else wrapped onto
                // lines the gauge has room for.
                QTRY_VERIFY2(label->height() >= label->heightForWidth(label->width()), qPrintable(what));
                if (oneLine && label->text().size() <= 24)
                    QVERIFY2(label->fontMetrics().horizontalAdvance(label->text()) <= label->contentsRect().width(),
                             qPrintable(what));
            }
        }
        QCOMPARE(w.gauge("battery")->detailText(), QString("2699 of 3000 mAh"));
        if (width == 390 && id == ProfileId::Create2)
            saveScreenshot(w, "gauges_create2_390x600");
    }

    void translatesOnTheSpot_data()
    {
        QTest::addColumn<ProfileId>("id");
        QTest::newRow("create2") << ProfileId::Create2;
        QTest::newRow("create1") << ProfileId::Create1;
    }
    void translatesOnTheSpot()
    {
        QFETCH(ProfileId, id);
        SensorGauges w;
        std::map<int, int> values = busyValues(profile(id));
        values[39] = 600; // out of range, so the flag shows
        show(w, id, values);
        w.setStale(true);
        w.resize(800, 600);
        w.show();
        const QString englishCharging = w.gaugeText("charging_state");
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList left = untranslatedTexts(&w);
            QVERIFY2(left.isEmpty(), qPrintable(left.join('\n')));
            // Values painted by the gauges follow at once, from the last snapshot.
            QVERIFY2(w.gaugeText("charging_state").contains(kPseudoOpen), qPrintable(w.gaugeText("charging_state")));
            QVERIFY(w.gauge("requested_velocity")->accessibleDescription().contains(kPseudoOpen));
        }
        QCoreApplication::processEvents();
        QCOMPARE(w.findChildren<QLabel *>("heading").first()->text(), QString("Battery"));
        QCOMPARE(w.gaugeText("charging_state"), englishCharging);
        QCOMPARE(w.findChild<QLabel *>("staleBanner")->text(), QString("STALE \u2014 no fresh data from the robot"));
    }

    void gaugesHaveAccessibleText()
    {
        SensorGauges w;
        std::map<int, int> values = busyValues(profile(ProfileId::Create2));
        values[39] = 600;
        show(w, ProfileId::Create2, values);
        for (const QString &key : w.shownGaugeKeys()) {
            QVERIFY2(!w.gauge(key)->accessibleName().isEmpty(), qPrintable(key));
            QVERIFY2(!w.gauge(key)->accessibleDescription().isEmpty(), qPrintable(key));
        }
        QCOMPARE(w.gauge("voltage")->accessibleName(), QString("Voltage"));
        QCOMPARE(w.gauge("voltage")->accessibleDescription(), QString("15.12 V"));
        QVERIFY2(w.gauge("requested_velocity")->accessibleDescription().endsWith(", out of range"),
                 qPrintable(w.gauge("requested_velocity")->accessibleDescription()));
        values[22] = 14000;
        show(w, ProfileId::Create2, values);
        QCOMPARE(w.gauge("voltage")->accessibleDescription(), QString("14.00 V"));
    }

    void screenshots()
    {
        const QSize sizes[] = {{480, 480}, {800, 600}};
        for (ProfileId id : allProfiles()) {
            for (QSize size : sizes) {
                for (bool dark : {false, true}) {
                    SensorGauges w;
                    w.setPalette(dark ? darkPalette() : lightPalette());
                    std::map<int, int> values = busyValues(profile(id));
                    values[39] = 600; // out of range, to see the flag
                    show(w, id, values);
                    w.resize(size);
                    w.show();
                    QVERIFY(QTest::qWaitForWindowExposed(&w));
                    const QString name = sceneName("gauges", profile(id), size, dark);
                    saveScreenshot(w, name);
                    w.setStale(true);
                    saveScreenshot(w, name + "_stale");
                }
            }
        }
    }
};

QTEST_MAIN(TestSensorGauges)
#include "tst_sensor_gauges.moc"
