// SPDX-License-Identifier: GPL-3.0-or-later
// The status bar says the line's errors once there are any, and keeps its
// room for the rest while the line is clean.
#include "robot_status_bar.h"

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
};

QTEST_MAIN(TestRobotStatusBar)
#include "tst_robot_status_bar.moc"
