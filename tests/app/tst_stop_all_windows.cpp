// SPDX-License-Identifier: GPL-3.0-or-later
// Stop all wherever the class looks: the fleet view (a window of its own, for
// the projector) and the projector view each show a large red Stop all, and
// Shift+Esc stops every robot with either in front. Seen at the robots: the
// stop's bytes on each local robot's transport, and roomba/fleet/stop on a
// real mosquitto for every bridge.
#include "command_encoder.h"
#include "fake_bridge.h"
#include "fleet_console.h"
#include "fleet_view.h"
#include "main_window.h"
#include "mosquitto_broker.h"
#include "projector_view.h"
#include "recording_transport.h"
#include "robot_diagram.h"
#include "robot_session.h"
#include "sent_before_barrier.h"

#include <QApplication>
#include <QLabel>
#include <QRegularExpression>
#include <QStatusBar>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include <map>
#include <memory>
#include <vector>

namespace {

const char *const kPorts[] = {"/dev/robotA", "/dev/robotB"};

// A window with two robots streaming in Safe mode on recording transports,
// one per port, so that each robot's bytes are read apart.
struct TwoRobots {
    std::map<QString, Recording> recordings;
    MainWindow window;

    TwoRobots()
    {
        for (const char *port : kPorts)
            recordings[port].mode = int(oi::OiMode::Safe);
        window.fleet().setTransportFactory([this](const oilink::LinkSettings &s) -> oilink::Transport * {
            return new RecordingTransport(&recordings.at(s.portPath));
        });
    }
    bool start()
    {
        window.resize(1280, 720);
        window.show();
        window.activateWindow();
        window.start(oilink::LinkSettings::serial(kPorts[0], oi::ProfileId::Create2));
        window.fleet().addRobot(oilink::LinkSettings::serial(kPorts[1], oi::ProfileId::Create2));
        return QTest::qWaitFor([this] {
            for (RobotSession *r : window.fleet().robots())
                if (!r->isLive() || r->latest().oiMode() != oi::OiMode::Safe)
                    return false;
            return window.fleet().count() == 2;
        }, 10000);
    }
    // What robot `i` was sent since last asked ("" for nothing).
    QString sent(int i)
    {
        return sentBeforeBarrier(*window.fleet().robots().value(i), recordings.at(kPorts[i]));
    }
};

QString stopBytes()
{
    const oi::Bytes b = oi::CommandEncoder(oi::profile(oi::ProfileId::Create2)).stopMotion();
    return byteText(QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size())));
}

// Large, whole and in view: its type at least `factor` times the desktop's.
QString unmissable(const QPushButton *button, const QWidget *view, qreal factor)
{
    if (!button->isVisible())
        return QStringLiteral("hidden");
    if (!view->rect().contains(QRect(button->mapTo(view, QPoint(0, 0)), button->size())))
        return QStringLiteral("not wholly in view");
    if (button->width() < button->sizeHint().width())
        return QStringLiteral("its label is cut: %1 px of %2").arg(button->width()).arg(button->sizeHint().width());
    if (button->font().pointSizeF() < factor * QApplication::font().pointSizeF())
        return QStringLiteral("type %1 pt, not %2 times %3 pt")
            .arg(button->font().pointSizeF())
            .arg(factor)
            .arg(QApplication::font().pointSizeF());
    if (!button->text().contains(QStringLiteral("Shift+Esc")))
        return QStringLiteral("its label does not name Shift+Esc: ") + button->text();
    return {};
}

} // namespace

class TestStopAllWindows : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // With the fleet view in front: its button and Shift+Esc stop both
    // local robots and publish the fleet's stop to every bridge; Space and
    // Esc stop the selected robot.
    void theFleetViewStopsEveryRobot()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        std::vector<std::unique_ptr<FakeBridge>> bridges;
        for (const char *name : {"r1", "r2"}) {
            bridges.push_back(std::make_unique<FakeBridge>(QString::fromLatin1(name)));
            QVERIFY(bridges.back()->start(broker.port()));
            bridges.back()->publishState();
        }
        TwoRobots rig;
        QVERIFY(rig.start());
        QVERIFY(rig.window.connectToBroker(*mqtt::BrokerAddress::fromUrl(broker.url(), nullptr)));
        FleetView &view = *rig.window.fleetView();
        // The window's own two robots beside the broker's two.
        QTRY_COMPARE_WITH_TIMEOUT(view.tiles().size(), 4, 5000);
        for (const RobotSession *own : rig.window.fleet().robots())
            QVERIFY2(view.tile(own->name()), qPrintable(own->name()));
        view.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&view));
        QVERIFY(!rig.window.isActiveWindow());
        const QString stop = stopBytes();
        rig.sent(0); // the opening
        rig.sent(1);
        const auto stopsPublished = [&](qsizetype count) {
            return QTest::qWaitFor([&] {
                for (const auto &b : bridges)
                    if (b->receivedOn(mqtt::topics::Kind::StopAll).size() != count)
                        return false;
                return true;
            }, 5000);
        };

        for (const auto &[w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}}) {
            view.resize(w, h);
            QTRY_COMPARE(view.size(), QSize(w, h));
            // Once laid out again for its new type.
            QTRY_VERIFY2(unmissable(view.stopAllButton(), &view, w > 1280 ? 2.4 : 1.8).isEmpty(),
                         qPrintable(QStringLiteral("%1×%2: %3")
                                        .arg(w)
                                        .arg(h)
                                        .arg(unmissable(view.stopAllButton(), &view, w > 1280 ? 2.4 : 1.8))));
        }

        QTest::mouseClick(view.stopAllButton(), Qt::LeftButton);
        QCOMPARE(rig.sent(0), stop);
        QCOMPARE(rig.sent(1), stop);
        QVERIFY(stopsPublished(1));
        // Confirmed where it was pressed, and in the window's status bar.
        QVERIFY2(QRegularExpression("^Stopped all 4 robots at \\d\\d:\\d\\d$").match(view.stopReport()).hasMatch(),
                 qPrintable(view.stopReport()));
        QVERIFY(view.findChild<QLabel *>("fleetStopped")->isVisible());
        QCOMPARE(rig.window.statusBar()->currentMessage(), view.stopReport());
        QCOMPARE(bridges.front()->receivedOn(mqtt::topics::Kind::StopAll).first().payload.value("client").toString(),
                 rig.window.fleetConsole()->directory().clientName());

        QTest::keyClick(&view, Qt::Key_Escape, Qt::ShiftModifier);
        QCOMPARE(rig.sent(0), stop);
        QCOMPARE(rig.sent(1), stop);
        QVERIFY(stopsPublished(2));

        // A tile's focus, as after a click: the keys reach the view there too.
        view.tiles().last()->setFocus();
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape, Qt::ShiftModifier);
        QCOMPARE(rig.sent(0), stop);
        QCOMPARE(rig.sent(1), stop);
        QVERIFY(stopsPublished(3));

        // Space and Esc stop the selected robot, and only it.
        QCOMPARE(rig.window.fleet().selected(), rig.window.fleet().robots().first());
        for (const Qt::Key key : {Qt::Key_Space, Qt::Key_Escape}) {
            QTest::keyClick(QApplication::focusWidget(), key);
            QCOMPARE(rig.sent(0), stop);
            QCOMPARE(rig.sent(1), QString());
        }
        QVERIFY(view.isVisible());
        QVERIFY(stopsPublished(3));
    }

    // In the projector view: its button and Shift+Esc stop both robots, and
    // the view stays; Space stops the selected robot, Esc too and leaves.
    void theProjectorViewStopsEveryRobot()
    {
        TwoRobots rig;
        QVERIFY(rig.start());
        QVERIFY(QTest::qWaitForWindowActive(&rig.window));
        QTest::keyClick(rig.window.robotDiagram(), Qt::Key_F11);
        QVERIFY(rig.window.isProjectorView());
        ProjectorView *view = rig.window.projectorView();
        QTRY_COMPARE(QApplication::focusWidget(), view);
        const QString stop = stopBytes();
        rig.sent(0); // whatever going full screen caused
        rig.sent(1);

        QTest::mouseClick(view->stopAllButton(), Qt::LeftButton);
        QCOMPARE(rig.sent(0), stop);
        QCOMPARE(rig.sent(1), stop);
        QTest::keyClick(view, Qt::Key_Escape, Qt::ShiftModifier);
        QCOMPARE(rig.sent(0), stop);
        QCOMPARE(rig.sent(1), stop);
        QVERIFY(rig.window.isProjectorView());

        QTest::keyClick(view, Qt::Key_Space);
        QCOMPARE(rig.sent(0), stop);
        QCOMPARE(rig.sent(1), QString());
        QVERIFY(rig.window.isProjectorView());
        QTest::keyClick(view, Qt::Key_Escape);
        QCOMPARE(rig.sent(0), stop);
        QCOMPARE(rig.sent(1), QString());
        QVERIFY(!rig.window.isProjectorView());
    }

    // The projector view's Stop all at a 1280×720 and a 1920×1080 projector:
    // large, whole and in view beside the header.
    void theProjectorViewsButtonFitsEachScreen_data()
    {
        QTest::addColumn<QSize>("screen");
        QTest::addColumn<qreal>("factor");
        QTest::newRow("1280x720") << QSize(1280, 720) << 1.8;
        QTest::newRow("1920x1080") << QSize(1920, 1080) << 2.6;
    }
    void theProjectorViewsButtonFitsEachScreen()
    {
        QFETCH(QSize, screen);
        QFETCH(qreal, factor);
        QWidget window;
        ProjectorView view(&window);
        view.setRobot(QStringLiteral("Robot 1"), oi::profile(oi::ProfileId::Create2), nullptr);
        window.resize(screen);
        window.show();
        view.show();
        QTRY_COMPARE(view.size(), screen);
        QTRY_VERIFY2(unmissable(view.stopAllButton(), &view, factor).isEmpty(),
                     qPrintable(unmissable(view.stopAllButton(), &view, factor)));
    }
};

QTEST_MAIN(TestStopAllWindows)
#include "tst_stop_all_windows.moc"
