// SPDX-License-Identifier: GPL-3.0-or-later
// The live data server as the protocol's own client sees it
// (client/live_check.js, with @foxglove/ws-protocol's FoxgloveClient and
// @foxglove/rosmsg2-serialization from npm), against live_rig.

#include "npm_packages.h" // tests/common

#include <QTemporaryDir>
#include <QTest>

class TestFoxgloveLive : public QObject {
    Q_OBJECT
private:
    QString m_clientDir;

    void check(const char *scenario)
    {
        if (!QFile::exists(QDir(m_clientDir).filePath("node_modules/@foxglove/ws-protocol/package.json")))
            QSKIP("@foxglove/ws-protocol is not installed: see installTheProtocolsClient");
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const ProcessRun r = runProcess(QStringLiteral("node"),
                                        {QDir(m_clientDir).filePath("live_check.js"), QLatin1String(scenario),
                                         QStringLiteral(LIVE_RIG_PATH), dir.path(), QStringLiteral(LIVE_LAYOUT)},
                                        m_clientDir, 200000);
        qInfo("%s: %s", scenario, r.out.trimmed().constData());
        QVERIFY2(r.exitCode == 0, r.err.constData());
    }

private slots:
    void installTheProtocolsClient()
    {
        m_clientDir = QStringLiteral(LIVE_CLIENT_DIR);
        const NpmInstall npm = installNpmPackages(
            m_clientDir, QStringLiteral(LIVE_CLIENT_SOURCE), {"package.json", "live_check.js"},
            {"@foxglove/ws-protocol", "@foxglove/rosmsg", "@foxglove/rosmsg2-serialization", "ws"});
        if (!npm.unreachable.isEmpty())
            QSKIP(qPrintable(QStringLiteral("npm cannot reach its registry (%1), so @foxglove/ws-protocol, the "
                                            "protocol's own client, is not installed and no independent client "
                                            "checks the server. Run the test again with the registry reachable.")
                                 .arg(npm.unreachable)));
        QVERIFY2(npm.error.isEmpty(), qPrintable(npm.error));
    }

    // Each subprotocol name; the channels and schemas; a minute of a driving
    // virtual robot (six seconds of wall time) where every JSON field and
    // every decoded ROS 2 field equals the recording's CSV, at most 50 a second.
    void telemetryEqualsTheRecording() { check("telemetry"); }
    // A replay at 4x: the protocol's time runs four times the wall clock.
    void replayTimeRunsAtItsSpeed() { check("replay"); }
    // An unknown subprotocol refused; robots added and removed advertised and withdrawn.
    void robotsComeAndGo() { check("fleet"); }
    // A client that stops reading is kept, within the limit, and gets the
    // newest frame when it reads again; the one that reads keeps its rate.
    void slowClientGetsTheNewest() { check("slow"); }
};

QTEST_GUILESS_MAIN(TestFoxgloveLive)
#include "tst_foxglove_live.moc"
