// SPDX-License-Identifier: GPL-3.0-or-later
// The fleet view and the projector view read from the back of a classroom
// on a 1280×720 projector: no text under 14 px, the battery never cut off a
// tile's mode line, the lesson's progress bar readable at 0 %.
#include "fleet_tile.h"
#include "fleet_view.h"
#include "lesson_panel.h"
#include "lesson_step_view.h"
#include "main_window.h"
#include "projector_view.h"
#include "robot_diagram.h"
#include "sensor_plots.h"

#include <QAbstractButton>
#include <QDir>
#include <QFontInfo>
#include <QLabel>
#include <QProgressBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

namespace {

constexpr int kLeast = 14;

int pixels(const QWidget *w) { return QFontInfo(w->font()).pixelSize(); }

// Every label and button of `root` that shows text, smaller than kLeast.
QStringList tooSmall(const QWidget *root)
{
    QStringList found;
    for (const QLabel *label : root->findChildren<QLabel *>())
        if (label->isVisibleTo(root) && !label->text().isEmpty() && pixels(label) < kLeast)
            found << QStringLiteral("%1 \"%2\": %3 px").arg(label->objectName(), label->text()).arg(pixels(label));
    for (const QAbstractButton *button : root->findChildren<QAbstractButton *>())
        if (!qobject_cast<const FleetTile *>(button) // paints its own type (below)
            && button->isVisibleTo(root) && !button->text().isEmpty() && pixels(button) < kLeast)
            found << QStringLiteral("%1 \"%2\": %3 px").arg(button->objectName(), button->text()).arg(pixels(button));
    return found;
}

// Relative luminance contrast (WCAG): 1 (none) to 21.
double contrast(const QColor &a, const QColor &b)
{
    const auto lum = [](const QColor &c) {
        const auto channel = [](double v) { return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
        return 0.2126 * channel(c.redF()) + 0.7152 * channel(c.greenF()) + 0.0722 * channel(c.blueF());
    };
    const double x = lum(a), y = lum(b);
    return (std::max(x, y) + 0.05) / (std::min(x, y) + 0.05);
}

} // namespace

class TestReadableText : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void fleetViewAt720p()
    {
        FleetView view;
        view.setBrokerText(QStringLiteral("mqtt://127.0.0.1:1883 · robots: 12 · speaking as teacher"), true);
        QList<FleetTileValues> tiles;
        for (int i = 1; i <= 12; ++i) {
            FleetTileValues v;
            v.name = QStringLiteral("robot-%1").arg(i);
            v.online = true;
            v.mode = QStringLiteral("Passive");
            v.modeReason = QStringLiteral("cliff (front left) and wheel drop (right)");
            v.batteryPercent = 100 - i;
            v.link = QStringLiteral("streaming");
            tiles << v;
        }
        view.setTiles(tiles);
        view.resize(1280, 720);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QTRY_VERIFY(view.columns() >= 3);
        const QStringList small = tooSmall(&view);
        QVERIFY2(small.isEmpty(), qPrintable(small.join("; ")));
        QVERIFY2(pixels(view.brokerLabel()) >= kLeast, qPrintable(QString::number(pixels(view.brokerLabel()))));
        for (const FleetTile *t : view.tiles())
            QVERIFY2(t->smallestTextPixels() >= kLeast, qPrintable(QString::number(t->smallestTextPixels())));

        // The battery whole on every tile, at 720p and at 1080p: the mode's
        // reason gives way to it.
        for (const QSize size : {QSize(1280, 720), QSize(1920, 1080)}) {
            view.resize(size);
            QTRY_COMPARE(view.size(), size);
            QCoreApplication::processEvents(); // the tiles laid out at that size
            for (const FleetTile *t : view.tiles())
                QVERIFY2(t->shownModeLine().endsWith(QStringLiteral("battery %1 %").arg(*t->values().batteryPercent)),
                         qPrintable(QStringLiteral("%1 at %2×%3: \"%4\"")
                                        .arg(t->values().name)
                                        .arg(size.width())
                                        .arg(size.height())
                                        .arg(t->shownModeLine())));
        }
    }

    void projectorViewAt720p()
    {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        window.start();
        QVERIFY(window.dock<LessonPanel>()->openLesson(":/lessons/cliff_sensors.json"));
        window.setProjectorView(true);
        ProjectorView *view = window.projectorView();
        // The offscreen screen is smaller: the view as a 1280×720 projector shows it.
        QTRY_VERIFY(view->isVisible());
        QCoreApplication::processEvents();
        view->setGeometry(0, 0, 1280, 720);
        QCoreApplication::processEvents();
        QCOMPARE(view->size(), QSize(1280, 720));
        LessonStepView *step = view->stepView();
        auto *progress = step->findChild<QProgressBar *>("lessonProgress");
        QVERIFY(progress && progress->isVisibleTo(view));

        const QStringList small = tooSmall(view);
        QVERIFY2(small.isEmpty(), qPrintable(small.join("; ")));
        // The sensor boxes' titles ("IR omni"), drawn in the diagram.
        QVERIFY2(step->diagram()->captionPixels() >= kLeast, qPrintable(QString::number(step->diagram()->captionPixels())));
        // The plots' axes are 0.9 times the plots' type.
        QVERIFY2(QFontInfo(step->plots()->font()).pixelSize() * 0.9 >= kLeast,
                 qPrintable(QString::number(QFontInfo(step->plots()->font()).pixelSize())));
        QVERIFY2(pixels(progress) >= kLeast, qPrintable(QString::number(pixels(progress))));
        // At 0 % the bar is its groove and its figure: both seen on black.
        const QPalette &p = progress->palette();
        QVERIFY2(contrast(p.color(QPalette::Text), p.color(QPalette::Base)) >= 7,
                 qPrintable(QString::number(contrast(p.color(QPalette::Text), p.color(QPalette::Base)))));
        QVERIFY2(contrast(p.color(QPalette::Base), Qt::black) >= 1.5,
                 qPrintable(QString::number(contrast(p.color(QPalette::Base), Qt::black))));
        if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS"))
            QVERIFY(view->grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("projector_lesson_1280x720.png")));
        window.setProjectorView(false);
        window.close();
    }
};

QTEST_MAIN(TestReadableText)
#include "tst_readable_text.moc"
