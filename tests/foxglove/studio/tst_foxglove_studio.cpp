// SPDX-License-Identifier: GPL-3.0-or-later
// The live data server and the MCAP export in Foxglove Studio 1.48 itself:
// the app @foxglove/studio-base ships prebuilt, served on loopback and opened
// in Debian's Chromium by studio_check.js (playwright-core), against a bridge
// on a virtual robot and against the dashboard with two.

#include "npm_packages.h" // tests/common

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>

class TestFoxgloveStudio : public QObject {
    Q_OBJECT
private:
    QString m_studioDir;

    void check(const char *scenario)
    {
        if (!QFile::exists(QDir(m_studioDir).filePath("node_modules/@foxglove/studio-base/package.json")))
            QSKIP("Foxglove Studio is not installed: see installStudio");
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QElapsedTimer timer;
        timer.start();
        const ProcessRun r = runProcess(
            QStringLiteral("node"),
            {QDir(m_studioDir).filePath("studio_check.js"), QLatin1String(scenario), dir.path(),
             QStringLiteral("layout=" STUDIO_LAYOUT), QStringLiteral("artefacts=%1").arg(m_studioDir + "/artefacts"),
             QStringLiteral("bridge=" ROOMBA_BRIDGE_PATH), QStringLiteral("dashboard=" ROOMBA_DASHBOARD_PATH),
             QStringLiteral("ctl=" ROOMBA_CTL_PATH), QStringLiteral("mosquitto=/usr/sbin/mosquitto")},
            m_studioDir, 240000);
        qInfo("%s (%.1f s): %s", scenario, timer.elapsed() / 1000.0, r.out.trimmed().constData());
        QVERIFY2(r.exitCode == 0, r.err.constData());
    }

private slots:
    void installStudio()
    {
        m_studioDir = QStringLiteral(STUDIO_DIR);
        QVERIFY2(QFile::exists(QStringLiteral("/usr/bin/chromium")),
                 "Debian's chromium is not installed (.ci/install-deps installs it)");
        QElapsedTimer timer;
        timer.start();
        const NpmInstall npm = installNpmPackages(
            m_studioDir, QStringLiteral(STUDIO_SOURCE), {"package.json", "index.html", "studio_page.js", "studio_check.js"},
            {"@foxglove/studio-base", "react", "react-dom", "playwright-core"});
        if (!npm.unreachable.isEmpty())
            QSKIP(qPrintable(QStringLiteral("npm cannot reach its registry (%1), so Foxglove Studio is not installed "
                                            "and no real Studio opens the live data or the MCAP. Run the test again "
                                            "with the registry reachable.")
                                 .arg(npm.unreachable)));
        QVERIFY2(npm.error.isEmpty(), qPrintable(npm.error));
        qInfo("Foxglove Studio ready in %s in %.1f s", qPrintable(m_studioDir), timer.elapsed() / 1000.0);
    }

    // A bridge on a virtual robot, recording: every channel listed in Studio,
    // the telemetry at >= 30 a second (45 on a quiet machine), the battery
    // legend (and the ROS 2 twin's voltage) equal to the recording's CSV, no panel in error; then
    // the recording's MCAP export opened from HTTP shows the CSV's values.
    void bridgeAndItsMcapInStudio() { check("bridge"); }
    // The dashboard with two virtual robots, the first recorded: the same,
    // for each robot's telemetry rate.
    void dashboardInStudio() { check("dashboard"); }
};

QTEST_GUILESS_MAIN(TestFoxgloveStudio)
#include "tst_foxglove_studio.moc"
