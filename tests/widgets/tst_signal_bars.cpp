// SPDX-License-Identifier: GPL-3.0-or-later
#include "pseudo_translation.h"
#include "sensor_scenes.h"
#include "signal_bars.h"

#include <QBarCategoryAxis>
#include <QBarSet>
#include <QLegend>
#include <QLegendMarker>
#include <QChart>
#include <QStackedBarSeries>
#include <QTest>
#include <QValueAxis>

using namespace oi;
using namespace sensor_scenes;

namespace {

const QStringList kCliffCategories = {"Cliff L", "Cliff FL", "Cliff FR", "Cliff R"};
const QStringList kLightBumpCategories = {"Light L",  "Light FL", "Light CL",
                                          "Light CR", "Light FR", "Light R"};

QList<QBarSet *> barSets(const SignalBars &w)
{
    for (QAbstractSeries *series : w.chart()->series())
        if (auto *bars = qobject_cast<QStackedBarSeries *>(series))
            return bars->barSets();
    return {};
}

} // namespace

class TestSignalBars : public QObject {
    Q_OBJECT
private slots:
    void fixedAxis()
    {
        SignalBars w;
        QCOMPARE(w.valueAxis()->min(), 0.0);
        QCOMPARE(w.valueAxis()->max(), 4095.0);
        SensorSnapshot s(profile(ProfileId::Create2));
        s.set(28, 4095);
        w.setSnapshot(s);
        QCOMPARE(w.valueAxis()->max(), 4095.0); // the axis never follows the data
        QVERIFY(w.minimumSizeHint().width() > 0);
    }

    // In a short dock the value labels thin out instead of each reading "…".
    void valueLabelsFitTheHeight()
    {
        SignalBars w;
        w.resize(420, 180);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY(w.valueAxis()->tickInterval() > 1000);
        const qreal squeezed = w.valueAxis()->tickInterval();
        const qreal pitch = QFontMetricsF(w.valueAxis()->labelsFont()).height();
        QVERIFY((4095 / squeezed + 1) * pitch <= w.chart()->plotArea().height());
        w.resize(420, 700);
        QTRY_COMPARE(w.valueAxis()->tickInterval(), 1000.0);
    }

    void categoriesFollowTheProfile()
    {
        SignalBars w;
        w.setProfile(profile(ProfileId::Create2));
        QCOMPARE(w.categories(), kCliffCategories + kLightBumpCategories);
        w.setProfile(profile(ProfileId::Create1));
        QCOMPARE(w.categories(), kCliffCategories);
        QCOMPARE(w.barValues().size(), 4);
        w.setProfile(profile(ProfileId::Roomba500));
        QCOMPARE(w.categories(), kCliffCategories + kLightBumpCategories);
        QCOMPARE(w.barValues().size(), 10);
    }

    void valuesFromTheSnapshot_data()
    {
        QTest::addColumn<ProfileId>("id");
        QTest::newRow("roomba500") << ProfileId::Roomba500;
        QTest::newRow("create2") << ProfileId::Create2;
        QTest::newRow("create1") << ProfileId::Create1;
    }
    void valuesFromTheSnapshot()
    {
        QFETCH(ProfileId, id);
        SignalBars w;
        w.setProfile(profile(id));
        w.setSnapshot(decoded(profile(id), busyValues(profile(id))));
        QList<qreal> expected = {2610, 2890, 180, 2480};
        if (id != ProfileId::Create1)
            expected += QList<qreal>{40, 310, 3620, 1210, 2980, 95};
        QCOMPARE(w.barValues(), expected);
        QCOMPARE(w.barValue("Cliff FR"), 180.0);
        QCOMPARE(w.barValue("Light CL"), id == ProfileId::Create1 ? -1.0 : 3620.0);
        QCOMPARE(w.barValue("nonsense"), -1.0);

        // A newer snapshot replaces every bar; missing packets read as 0.
        SensorSnapshot s(profile(id));
        s.set(31, 4095);
        w.setSnapshot(s);
        QCOMPARE(w.barValue("Cliff R"), 4095.0);
        QCOMPARE(w.barValue("Cliff L"), 0.0);
        if (id != ProfileId::Create1)
            QCOMPARE(w.barValue("Light CL"), 0.0);
    }

    void cliffAndLightBumpBarsDiffer()
    {
        SignalBars w;
        w.setProfile(profile(ProfileId::Create2));
        w.setSnapshot(decoded(profile(ProfileId::Create2), busyValues(profile(ProfileId::Create2))));
        const QList<QBarSet *> sets = barSets(w);
        QCOMPARE(sets.size(), 2);
        QVERIFY(sets[0]->color() != sets[1]->color());
        QCOMPARE(sets[0]->color(), w.cliffColour());
        QCOMPARE(sets[1]->color(), w.lightBumpColour());
        // Each set carries only its own kind, so bars do not pile up.
        for (int i = 0; i < 4; ++i)
            QCOMPARE(sets[1]->at(i), 0.0);
        for (int i = 4; i < 10; ++i)
            QCOMPARE(sets[0]->at(i), 0.0);

        // The bars are drawn in those colours: sample the tallest of each kind.
        w.resize(640, 400);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const QImage image = w.grab().toImage();
        auto barPixel = [&](int category, qreal value) {
            const QPointF at = w.chart()->mapToPosition(QPointF(category, value / 2));
            return image.pixelColor(w.mapFromScene(w.chart()->mapToScene(at)));
        };
        QCOMPARE(barPixel(1, 2890), w.cliffColour());
        QCOMPARE(barPixel(6, 3620), w.lightBumpColour());
    }

    void staleGreysTheBars()
    {
        SignalBars w;
        w.setStale(true);
        QVERIFY(w.isStale());
        QVERIFY(w.chart()->title().startsWith("STALE"));
        const QList<QBarSet *> sets = barSets(w);
        QVERIFY(isGrey(sets[0]->color()));
        QVERIFY(sets[0]->color() != w.cliffColour());
        w.setStale(false);
        QCOMPARE(sets[0]->color(), w.cliffColour());
        QVERIFY(!w.chart()->title().startsWith("STALE"));
    }

    void translatesOnTheSpot()
    {
        SignalBars w;
        w.setProfile(profile(ProfileId::Create2));
        w.setSnapshot(decoded(profile(ProfileId::Create2), busyValues(profile(ProfileId::Create2))));
        w.setStale(true);
        w.show();
        const QList<qreal> values = w.barValues();
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            QStringList left = untranslatedTexts(&w);
            // The chart draws its own texts; check them too.
            QStringList shown = {w.chart()->title(), w.accessibleDescription()};
            shown += w.categories();
            for (QAbstractAxis *axis : w.chart()->axes(Qt::Horizontal))
                shown += qobject_cast<QBarCategoryAxis *>(axis)->categories();
            for (QLegendMarker *marker : w.chart()->legend()->markers())
                shown << marker->label();
            for (const QString &text : shown)
                if (looksUntranslated(text))
                    left << text;
            QVERIFY2(left.isEmpty(), qPrintable(left.join('\n')));
            QCOMPARE(w.barValues(), values); // the bars keep their heights
        }
        QCoreApplication::processEvents();
        QCOMPARE(w.categories(), kCliffCategories + kLightBumpCategories);
        QCOMPARE(w.chart()->title(), QString("STALE \u2014 Cliff and light-bump signals"));
    }

    void accessibleTextFollowsTheSignals()
    {
        SignalBars w;
        w.setProfile(profile(ProfileId::Create1));
        QCOMPARE(w.accessibleName(), QString("Signal bars"));
        SensorSnapshot s(profile(ProfileId::Create1));
        s.set(28, 2610);
        s.set(31, 12);
        w.setSnapshot(s);
        QCOMPARE(w.accessibleDescription(), QString("Cliff L: 2610, Cliff FL: 0, Cliff FR: 0, Cliff R: 12"));
        w.setStale(true);
        QVERIFY(w.accessibleDescription().startsWith("Stale: Cliff L: 2610"));
    }

    void screenshots()
    {
        const QSize sizes[] = {{480, 480}, {800, 600}, {460, 280}};
        for (ProfileId id : allProfiles()) {
            for (QSize size : sizes) {
                for (bool dark : {false, true}) {
                    SignalBars w;
                    w.setPalette(dark ? darkPalette() : lightPalette());
                    w.setProfile(profile(id));
                    w.setSnapshot(decoded(profile(id), busyValues(profile(id))));
                    w.resize(size);
                    w.show();
                    QVERIFY(QTest::qWaitForWindowExposed(&w));
                    const QString name = sceneName("bars", profile(id), size, dark);
                    saveScreenshot(w, name);
                    w.setStale(true);
                    saveScreenshot(w, name + "_stale");
                }
            }
        }
    }
};

QTEST_MAIN(TestSignalBars)
#include "tst_signal_bars.moc"
