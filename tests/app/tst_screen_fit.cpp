// SPDX-License-Identifier: GPL-3.0-or-later
// The window and a lesson on the screens a classroom
// has, from a 1280×720 projector up, with fresh settings: everything within
// the window, every dock and the status bar in reach, no tab title or label
// cut short. Screenshots into ROOMBA_SCREENSHOTS when set.
#include "lesson_panel.h"
#include "lesson_step_view.h"
#include "main_window.h"
#include "projector_view.h"
#include "value_gauge.h"
#include "plot_stack.h"
#include "sensor_plots.h"
#include "robot_card.h"
#include "robot_list.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QScrollArea>
#include <QSettings>
#include "custom_plot.h"
#include <QStandardPaths>
#include <QStatusBar>
#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>

namespace {

// What a maximized window has of a screen under a window manager: the
// screen less its title bar.
constexpr int kTitleBar = 30;

QString screenshotDir(const QTemporaryDir &scratch)
{
    const QString dir = qEnvironmentVariableIsEmpty("ROOMBA_SCREENSHOTS") ? scratch.path()
                                                                           : qEnvironmentVariable("ROOMBA_SCREENSHOTS");
    QDir().mkpath(dir);
    return dir;
}

// The part of `w` that its parents do not clip (a scroll area's viewport
// among them), in its own coordinates.
QRect shownPart(const QWidget *w)
{
    QRect shown = w->rect();
    for (const QWidget *p = w->parentWidget(); p && !shown.isEmpty(); p = p->parentWidget()) {
        shown &= QRect(w->mapFrom(p, QPoint(0, 0)), p->size());
        if (p->isWindow())
            break;
    }
    return shown;
}

QString describe(const QWidget *w)
{
    QString name = w->objectName().isEmpty() ? QString::fromLatin1(w->metaObject()->className()) : w->objectName();
    for (const QWidget *p = w->parentWidget(); p; p = p->parentWidget())
        if (qobject_cast<const QDockWidget *>(p))
            name = p->objectName() + QLatin1Char('/') + name;
    if (const auto *label = qobject_cast<const QLabel *>(w))
        name += QStringLiteral(" \"%1\"").arg(label->text());
    return name;
}

// What of `root` is cut short where it stands: a tab bar with less room than
// its titles need that elides them rather than scroll, a label of one line narrower than
// its text, a child sticking out of the window.
QStringList cutShort(QWidget *root, const QRect &window)
{
    QStringList found;
    for (QTabBar *bar : root->findChildren<QTabBar *>()) {
        if (!bar->isVisible() || bar->visibleRegion().isEmpty())
            continue;
        // Whole titles that scroll are read; elided ones are not.
        const bool scrollsWhole = bar->elideMode() == Qt::ElideNone && bar->usesScrollButtons();
        if (!scrollsWhole && bar->sizeHint().width() > bar->width()) {
            QStringList titles;
            for (int i = 0; i < bar->count(); ++i)
                titles << bar->tabText(i);
            found << QStringLiteral("tab bar [%1]: %2 px for %3 px of titles")
                         .arg(titles.join(", "))
                         .arg(bar->width())
                         .arg(bar->sizeHint().width());
        }
    }
    for (QLabel *label : root->findChildren<QLabel *>()) {
        if (!label->isVisible() || label->visibleRegion().isEmpty() || label->text().isEmpty() || label->wordWrap())
            continue;
        if (label->width() < label->minimumSizeHint().width())
            found << QStringLiteral("%1: %2 px of %3").arg(describe(label)).arg(label->width())
                         .arg(label->minimumSizeHint().width());
    }
    // A button's or a list's text wider than it, or cut by its pane's edge.
    for (QWidget *w : root->findChildren<QWidget *>()) {
        if (!w->isVisible() || w->visibleRegion().isEmpty())
            continue;
        QString text;
        int frame = 0; // what the style draws beside the text
        if (auto *button = qobject_cast<QAbstractButton *>(w)) {
            text = button->text().remove(QLatin1Char('&'));
            frame = 6;
        } else if (auto *combo = qobject_cast<QComboBox *>(w); combo && !combo->isEditable()) {
            text = combo->currentText();
            frame = 24;
        }
        if (text.isEmpty())
            continue;
        // The style's own size for the text where it knows it better.
        const int needs = std::min(w->fontMetrics().horizontalAdvance(text) + frame, w->sizeHint().width());
        if (shownPart(w).width() < needs)
            found << QStringLiteral("%1 \"%2\": %3 px shown, %4 px needed").arg(describe(w), text)
                         .arg(shownPart(w).width()).arg(needs);
    }
    for (QWidget *w : root->findChildren<QWidget *>()) {
        if (!w->isVisible() || w->isWindow() || w->visibleRegion().isEmpty())
            continue;
        const QRect at(w->mapTo(root->window(), QPoint(0, 0)), w->size());
        // A part scrolled out of view is in reach; its scroll area is checked.
        const QRect shown = w->visibleRegion().boundingRect().translated(at.topLeft());
        if (!window.contains(shown))
            found << QStringLiteral("%1 at %2,%3 %4x%5 outside the window")
                         .arg(describe(w)).arg(shown.x()).arg(shown.y()).arg(shown.width()).arg(shown.height());
    }
    return found;
}

} // namespace

class TestScreenFit : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void windowFitsTheScreen_data()
    {
        QTest::addColumn<QSize>("screen");
        QTest::addColumn<int>("robots");
        QTest::addColumn<QString>("language");
        for (const QSize screen : {QSize(1280, 720), QSize(1366, 768), QSize(1920, 1080)})
            for (int robots : {1, 3})
                QTest::addRow("%dx%d, %d robot(s)", screen.width(), screen.height(), robots)
                    << screen << robots << QString();
        QTest::addRow("1280x720, German") << QSize(1280, 720) << 3 << QStringLiteral("de");
        QTest::addRow("1600x1000") << QSize(1600, 1000) << 1 << QString();
    }

    // Maximized with fresh settings: the window asks no more than the screen
    // has, and every dock (raised in turn), the status bar and the tab bars
    // are whole inside it.
    void windowFitsTheScreen()
    {
        QFETCH(QSize, screen);
        QFETCH(int, robots);
        QFETCH(QString, language);
        const QSize client(screen.width(), screen.height() - kTitleBar);
        MainWindow window;
        if (!language.isEmpty())
            window.setLanguage(language, false);
        QVERIFY2(window.minimumSizeHint().width() <= client.width() &&
                     window.minimumSizeHint().height() <= client.height(),
                 qPrintable(QStringLiteral("the window needs %1x%2")
                                .arg(window.minimumSizeHint().width())
                                .arg(window.minimumSizeHint().height())));
        window.resize(client);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2), robots);
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(window.session().snapshotCount() > 5, 10000);
        // Identified: the panels show the robot's own names, at their own widths.
        for (RobotSession *robot : window.fleet().robots())
            QTRY_VERIFY_WITH_TIMEOUT(robot->isIdentified(), 10000);
        window.refreshDisplay();
        QApplication::processEvents();
        QCOMPARE(window.size(), client);
        const QRect inside = window.rect();

        QStringList found;
        QVERIFY(window.statusBar()->isVisible());
        QVERIFY2(inside.contains(QRect(window.statusBar()->mapTo(&window, QPoint(0, 0)), window.statusBar()->size())),
                 "the status bar is outside the window");
        for (QDockWidget *dock : window.findChildren<QDockWidget *>()) {
            dock->raise();
            QTRY_VERIFY(dock->widget()->isVisible());
            window.refreshDisplay();
            QApplication::processEvents(); // its scroll bars as its content asks
            QVERIFY2(inside.contains(dock->geometry()), qPrintable(dock->objectName() + " is outside the window"));
            // Each pane shows a few lines of itself (a bar its one row); the rest scrolls.
            QVERIFY2(dock->widget()->height() >= std::min(40, dock->widget()->minimumSizeHint().height()),
                     qPrintable(dock->objectName()));
            found += cutShort(dock, inside);
        }
        // Back to the first tabs, as a first start shows them.
        window.resetLayout();
        // The cards with every robot's mode and battery, as wide as they get.
        for (int i = 0; i < robots; ++i)
            QTRY_VERIFY_WITH_TIMEOUT((window.refreshDisplay(), window.robotList()->card(i)->values().batteryPercent),
                                     10000);
        QApplication::processEvents();
        // Every robot's card whole in the strip, the selected one too.
        for (int i = 0; i < robots; ++i) {
            RobotCard *card = window.robotList()->card(i);
            QVERIFY(card);
            if (shownPart(card) != card->rect())
                found << QStringLiteral("robot card %1 cut to %2x%3 of %4x%5")
                             .arg(i)
                             .arg(shownPart(card).width())
                             .arg(shownPart(card).height())
                             .arg(card->width())
                             .arg(card->height());
        }
        found += cutShort(&window, inside);
        found.removeDuplicates();

        QTemporaryDir scratch;
        const QString file = QStringLiteral("window_%1x%2_%3robot%4%5.png")
                                 .arg(screen.width())
                                 .arg(screen.height())
                                 .arg(robots)
                                 .arg(robots > 1 ? "s" : "")
                                 .arg(language.isEmpty() ? QString() : "_" + language);
        QVERIFY(window.grab().save(QDir(screenshotDir(scratch)).filePath(file)));
        if (!language.isEmpty())
            window.setLanguage(QString(), false);
        QVERIFY2(found.isEmpty(), qPrintable(found.join('\n')));
    }

    // Panes that can be read: the plots and the map, each raised in turn,
    // at least 200 px high, on a laptop screen and a desktop one; a run
    // comparison's plots keep that height (their pane scrolls); and Reset
    // layout gives back the layout of the first start.
    void panesCanBeRead_data()
    {
        QTest::addColumn<QSize>("client");
        QTest::addRow("1280x720") << QSize(1280, 720 - kTitleBar);
        QTest::addRow("1600x1000") << QSize(1600, 1000);
    }
    void panesCanBeRead()
    {
        QFETCH(QSize, client);
        MainWindow window;
        window.resize(client);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        QApplication::processEvents();
        const auto docks = window.findChildren<QDockWidget *>();
        const auto layoutNow = [&] {
            QStringList where;
            for (QDockWidget *dock : docks) // a tab not raised has no place of its own
                where << (dock->visibleRegion().isEmpty()
                              ? QStringLiteral("%1 %2 behind a tab").arg(dock->objectName()).arg(int(window.dockWidgetArea(dock)))
                              : QStringLiteral("%1 %2 %3,%4 %5x%6")
                                    .arg(dock->objectName())
                                    .arg(int(window.dockWidgetArea(dock)))
                                    .arg(dock->x())
                                    .arg(dock->y())
                                    .arg(dock->width())
                                    .arg(dock->height()));
            return where;
        };
        const QStringList firstStart = layoutNow();

        auto *plotsDock = window.findChild<QDockWidget *>("plotsDock");
        plotsDock->raise();
        QTRY_VERIFY(plotsDock->widget()->isVisible());
        const auto plots = plotsDock->findChildren<QCustomPlot *>();
        QCOMPARE(plots.size(), 2);
        for (QCustomPlot *plot : plots)
            QVERIFY2(plot->height() >= 200, qPrintable(QString::number(plot->height())));
        // A plot whole in its pane when raised, not scrolled half away.
        QApplication::processEvents();
        const QWidget *viewport = qobject_cast<QScrollArea *>(plotsDock->widget())->viewport();
        QVERIFY(std::any_of(plots.cbegin(), plots.cend(), [viewport](QCustomPlot *plot) {
            return viewport->rect().contains(QRect(plot->mapTo(viewport, QPoint(0, 0)), plot->size()));
        }));
        auto *mapDock = window.findChild<QDockWidget *>("mapDock");
        mapDock->raise();
        QTRY_VERIFY(mapDock->widget()->isVisible());
        QVERIFY2(mapDock->widget()->height() >= 200, qPrintable(QString::number(mapDock->widget()->height())));

        // More plots, as a comparison adds: none under the readable height.
        PlotStack *stack = window.findChild<SensorPlots *>()->stack();
        stack->addPlot({22});
        stack->addPlot({23});
        QApplication::processEvents();
        for (QCustomPlot *plot : plotsDock->findChildren<QCustomPlot *>())
            QVERIFY(plot->height() >= 200);

        // Moved about by hand, then Reset layout: as at the first start.
        window.addDockWidget(Qt::TopDockWidgetArea, mapDock);
        window.findChild<QDockWidget *>("gaugesDock")->hide();
        window.resetLayout();
        QApplication::processEvents();
        QCOMPARE(layoutNow(), firstStart);
    }

    // More robots than the strip holds: the one selected elsewhere (the
    // fleet view, the keyboard) scrolls into view, whole.
    void selectedRobotComesIntoView()
    {
        MainWindow window;
        window.resize(1280, 720 - kTitleBar);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2), 8);
        QTRY_COMPARE_WITH_TIMEOUT(window.robotList()->count(), 8, 10000);
        for (int index : {7, 0, 5}) {
            window.fleet().select(window.fleet().robots()[index]);
            QApplication::processEvents();
            RobotCard *card = window.robotList()->card(index);
            QCOMPARE(shownPart(card), card->rect());
        }
        QVERIFY(shownPart(window.robotList()->card(7)) != window.robotList()->card(7)->rect()); // it did scroll
    }

    // A lesson in its dock on a 1280×720 screen: the step's text, goal and
    // views within the window, nothing cut short.
    void lessonAt720p_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addRow("English") << QString();
        QTest::addRow("German") << QStringLiteral("de");
    }
    void lessonAt720p()
    {
        QFETCH(QString, language);
        MainWindow window;
        if (!language.isEmpty())
            window.setLanguage(language, false);
        window.resize(1280, 720 - kTitleBar);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        auto *lessonDock = window.findChild<QDockWidget *>("lessonDock");
        QApplication::processEvents();
        // Its tab is in view, one click away, not scrolled off the bar's end.
        bool tabInView = false;
        for (QTabBar *bar : window.findChildren<QTabBar *>())
            for (int i = 0; i < bar->count(); ++i)
                if (bar->isVisible() && bar->tabText(i) == lessonDock->windowTitle()) {
                    const int arrows = bar->sizeHint().width() > bar->width() ? 2 * bar->height() : 0;
                    tabInView = bar->tabRect(i).left() >= 0 && bar->tabRect(i).right() <= bar->width() - arrows;
                }
        QVERIFY2(tabInView, qPrintable(lessonDock->windowTitle()));
        // Open behind the plots' tab, its View menu entry (ticked) brings it to the front.
        QVERIFY(lessonDock->visibleRegion().isEmpty());
        QAction *entry = window.findChild<QAction *>("lessonDockViewAction");
        QVERIFY(entry && entry->isChecked());
        bool inMenu = false;
        for (QAction *top : window.menuBar()->actions())
            inMenu = inMenu || (top->menu() && top->menu()->actions().contains(entry));
        QVERIFY(inMenu);
        entry->trigger();
        QTRY_VERIFY(!lessonDock->visibleRegion().isEmpty());
        QVERIFY(entry->isChecked());
        QVERIFY(window.dock<LessonPanel>()->openLesson(":/lessons/cliff_sensors.json"));
        QTRY_VERIFY(window.dock<LessonPanel>()->stepView()->isVisible());
        window.refreshDisplay();
        window.refreshDisplay();
        QApplication::processEvents();
        QStringList found = cutShort(lessonDock, window.rect());
        QTemporaryDir scratch;
        const QString suffix = language.isEmpty() ? QString() : "_" + language;
        QVERIFY(window.grab().save(QDir(screenshotDir(scratch)).filePath("lesson_1280x720" + suffix + ".png")));
        if (!language.isEmpty())
            window.setLanguage(QString(), false);
        found.removeDuplicates();
        QVERIFY2(found.isEmpty(), qPrintable(found.join('\n')));
    }

    // The projector's readouts, however many a step shows, at 1280x720 and
    // 1920x1080 in every shipped language: each value shows whole, and its
    // title neither runs into it nor is cut off.
    void projectorReadoutsFit_data()
    {
        QTest::addColumn<QSize>("screen");
        QTest::addColumn<QString>("language");
        for (const QSize screen : {QSize(1280, 720), QSize(1920, 1080)})
            for (const char *language : {"en", "de", "es"})
                QTest::addRow("%dx%d %s", screen.width(), screen.height(), language) << screen << QString(language);
    }
    void projectorReadoutsFit()
    {
        QFETCH(QSize, screen);
        QFETCH(QString, language);
        MainWindow window;
        window.setLanguage(language == "en" ? QString() : language, false);
        window.resize(screen.width(), screen.height() - kTitleBar);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        window.setProjectorView(true);
        // Full screen is the test screen's size: the projector's here is the screen's.
        window.setWindowState(Qt::WindowNoState);
        window.resize(screen);
        QTRY_COMPARE(window.projectorView()->size(), screen);
        QStringList found;
        // The robot alone (its readouts), then the cliff lesson's steps of four.
        for (int step = -1; step < 2; ++step) {
            if (step == 0)
                QVERIFY(window.dock<LessonPanel>()->openLesson(":/lessons/cliff_sensors.json"));
            if (step == 1)
                window.fleet().lesson().runner().goToStep(1);
            for (int i = 0; i < 3; ++i) {
                window.refreshDisplay();
                QApplication::processEvents();
            }
            const QList<ValueGauge *> gauges = window.projectorView()->findChildren<ValueGauge *>();
            int shown = 0;
            for (ValueGauge *g : gauges) {
                if (!g->isVisible() || !g->objectName().startsWith("readout_"))
                    continue;
                ++shown;
                auto *title = g->findChild<QLabel *>("title");
                auto *value = g->findChild<QWidget *>("value");
                const QString where = QStringLiteral("step %1, %2 \"%3\"").arg(step + 1).arg(g->objectName(), title->text());
                if (value->height() < value->sizeHint().height())
                    found << where + QStringLiteral(": value %1 px of %2").arg(value->height()).arg(value->sizeHint().height());
                if (title->heightForWidth(title->width()) > title->height())
                    found << where + QStringLiteral(": title %1 px of %2").arg(title->height()).arg(title->heightForWidth(title->width()));
                if (title->geometry().intersects(value->geometry()))
                    found << where + QStringLiteral(": title over the value");
                const QRect at(g->mapTo(window.projectorView(), QPoint(0, 0)), g->size());
                if (!window.projectorView()->rect().contains(at))
                    found << where + QStringLiteral(": outside the view");
            }
            QVERIFY2(shown >= 4, qPrintable(QString::number(shown)));
            QTemporaryDir scratch;
            QVERIFY(window.grab().save(QDir(screenshotDir(scratch))
                                           .filePath(QStringLiteral("projector_readouts_%1x%2_%3_%4.png")
                                                         .arg(screen.width()).arg(screen.height()).arg(language)
                                                         .arg(step + 1))));
        }
        window.setLanguage(QString(), false);
        QVERIFY2(found.isEmpty(), qPrintable(found.join('\n')));
    }
};

QTEST_MAIN(TestScreenFit)
#include "tst_screen_fit.moc"
