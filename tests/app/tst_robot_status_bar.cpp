// SPDX-License-Identifier: GPL-3.0-or-later
// The status bar says the line's errors once there are any, and keeps its
// room for the rest while the line is clean.
#include "robot_status_bar.h"

#include <QLabel>
#include <QStatusBar>
#include <QTest>

class TestRobotStatusBar : public QObject {
    Q_OBJECT
private slots:
    void lineErrorsAreSaidOnceThereAreAny()
    {
        QStatusBar bar;
        RobotStatusBar status(&bar);
        bar.show();
        status.showState(oilink::LinkState::Streaming);
        oilink::LinkStats stats;
        stats.framesPerSecond = 66.7;
        status.showStatistics(stats);
        QVERIFY(status.text().contains(QStringLiteral("66.7 frames/s")));
        QVERIFY2(!status.text().contains(QStringLiteral("checksum failures")), qPrintable(status.text()));
        stats.checksumFailures = 2;
        status.showStatistics(stats);
        QVERIFY2(status.text().contains(QStringLiteral("checksum failures 2, resyncs 0")), qPrintable(status.text()));
        stats.checksumFailures = 0;
        stats.resyncs = 1;
        status.showStatistics(stats);
        QVERIFY2(status.text().contains(QStringLiteral("checksum failures 0, resyncs 1")), qPrintable(status.text()));
    }

    // A temporary message is painted where the left labels are: while it is
    // up they are hidden, whatever comes meanwhile, so no two texts overlap.
    void oneMessageAtATime()
    {
        QStatusBar bar;
        RobotStatusBar status(&bar);
        bar.resize(1280, 30);
        bar.show();
        QVERIFY(QTest::qWaitForWindowExposed(&bar));
        auto *reason = bar.findChild<QLabel *>("modeReason");
        auto *stale = bar.findChild<QLabel *>("staleIndicator");
        status.showModeReason(QStringLiteral("Cleaning (its own program) · Space stops it"));
        QVERIFY(reason->isVisible());
        bar.showMessage(QStringLiteral("Recording saved: /tmp/class.oirec"));
        QVERIFY(!reason->isVisible());
        // A reason or a banner that changes under the message waits for it to go.
        status.showModeReason(QStringLiteral("A cliff (front left) dropped it to Passive at 12:03:04."));
        status.showLive(false, false);
        QVERIFY(!reason->isVisible());
        QVERIFY(!stale->isVisible());
        bar.clearMessage();
        QVERIFY(reason->isVisible());
        QVERIFY(stale->isVisible());
        QVERIFY2(status.text().contains(QStringLiteral("A cliff (front left)")), qPrintable(status.text()));
    }

    // A message too long to stand beside the link's labels is not cut off
    // against them: they give way while it is up, and come back after.
    void aLongMessageIsNotCutAgainstTheLinkLabels()
    {
        QStatusBar bar;
        RobotStatusBar status(&bar);
        bar.resize(1000, 30);
        bar.show();
        QVERIFY(QTest::qWaitForWindowExposed(&bar));
        status.showState(oilink::LinkState::Streaming);
        status.showFirmware(QStringLiteral("r3_robot/tags/release-3.4.1:5823 CLEAN"));
        auto *state = bar.findChild<QLabel *>("linkState");
        QVERIFY(state->isVisible());
        bar.showMessage(QStringLiteral("Recording saved"));
        QVERIFY(state->isVisible()); // a short one fits beside them
        // Longer than the room beside the labels, shorter than the bar.
        const int room = bar.width() - bar.findChild<QWidget *>("linkLabels")->width();
        QString along = QStringLiteral("The broker at mqtt://127.0.0.1:18932 stopped answering at 06:41:13");
        while (bar.fontMetrics().horizontalAdvance(along) <= room - 10)
            along += QStringLiteral(" · is it running?");
        QVERIFY(bar.fontMetrics().horizontalAdvance(along) < bar.width() - 20);
        bar.showMessage(along);
        QVERIFY(!state->isVisible());
        bar.clearMessage();
        QVERIFY(state->isVisible());
    }
};

QTEST_MAIN(TestRobotStatusBar)
#include "tst_robot_status_bar.moc"
