// SPDX-License-Identifier: GPL-3.0-or-later
// A settings file that is damaged or from another version is kept aside
// under a new name, never read and never overwritten; the dashboard starts
// with defaults and says so once.
#include "settings_file.h"

#include "saved_brokers.h"
#include "saved_robots.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

class TestSettingsFile : public QObject {
    Q_OBJECT
private:
    QString m_path;

    void writeFile(const QByteArray &content)
    {
        QVERIFY(QDir().mkpath(QFileInfo(m_path).path()));
        QFile f(m_path);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(content);
    }
    QByteArray fileContent(const QString &path)
    {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }
    QStringList keptAside() const
    {
        const QFileInfo info(m_path);
        return QDir(info.path()).entryList({info.fileName() + ".bad-*"}, QDir::Files);
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true); // ~/.qttest, not the user's settings
        QCoreApplication::setOrganizationName("RoombaDashboardTest");
        QCoreApplication::setApplicationName("tst_settings_file");
        m_path = QSettings().fileName();
    }
    void init()
    {
        QDir dir(QFileInfo(m_path).path());
        for (const QString &name : dir.entryList({QFileInfo(m_path).fileName() + "*"}, QDir::Files))
            QVERIFY(dir.remove(name));
    }

    // An array's size is read from the file as it says it: brokers/size=100000000
    // kept the window from ever opening. At most the first entries each list
    // keeps are read, and the file and the limit are named.
    void aListIsReadOnlyAsFarAsItsLimit()
    {
        const auto fileWith = [](int size) {
            QByteArray ini = "[brokers]\nsize=" + QByteArray::number(size) + "\n";
            QByteArray robots = "[robots]\nsize=" + QByteArray::number(size) + "\n";
            for (int i = 1; i <= 120; ++i) {
                ini += QByteArray::number(i) + "\\host=broker" + QByteArray::number(i) + "\n";
                robots += QByteArray::number(i) + "\\name=Robot " + QByteArray::number(i) + "\n"
                          + QByteArray::number(i) + "\\transport=2\n";
            }
            return ini + robots;
        };
        for (const int size : {120, 100000000}) {
            writeFile(fileWith(size));
            QSettings settings;
            QTest::ignoreMessage(QtWarningMsg, qPrintable(QString("%1: brokers/size is %2; the first %3 are read")
                                                              .arg(m_path).arg(size).arg(kMaxSavedBrokers)));
            const QList<SavedBroker> brokers = loadSavedBrokers(settings);
            QCOMPARE(brokers.size(), kMaxSavedBrokers);
            QCOMPARE(brokers.last().address.host, QString("broker%1").arg(kMaxSavedBrokers));
            QTest::ignoreMessage(QtWarningMsg, qPrintable(QString("%1: robots/size is %2; the first %3 are read")
                                                              .arg(m_path).arg(size).arg(kMaxSavedRobots)));
            const QList<SavedRobot> robots = loadSavedRobots(settings);
            QCOMPARE(robots.size(), kMaxSavedRobots);
            QCOMPARE(robots.last().name, QString("Robot %1").arg(kMaxSavedRobots));
        }
        // The file is read, not written: nothing it holds is lost.
        QCOMPARE(fileContent(m_path), fileWith(100000000));
    }

    void noFileIsNoNews()
    {
        const SettingsFile::Check check = SettingsFile::check();
        QVERIFY(check.notice.isEmpty());
        QVERIFY(keptAside().isEmpty());
    }

    void aGoodFileIsKeptAndGainsTheVersion()
    {
        writeFile("[General]\nlanguage=de\n");
        QVERIFY(SettingsFile::check().notice.isEmpty());
        QSettings settings;
        QCOMPARE(settings.value("language").toString(), QString("de"));
        QCOMPARE(settings.value(SettingsFile::kVersionKey).toInt(), SettingsFile::kVersion);
        QVERIFY(keptAside().isEmpty());
    }

    void badFileIsKeptAsideOnce_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("reason");
        QTest::newRow("damaged") << QByteArray("[General\nlanguage=de\n\x00\xff garbage", 24) << "damaged";
        QByteArray noise;
        for (int i = 0; i < 300; ++i)
            noise.append(char((i * 7919 + 13) % 256)); // any bytes, a NUL among them
        QTest::newRow("not text") << noise << "damaged";
        QTest::newRow("another version") << QByteArray("[General]\nsettingsVersion=7\nlanguage=es\n")
                                         << "settings version 7, not 1";
    }
    void badFileIsKeptAsideOnce()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, reason);
        writeFile(content);
        const SettingsFile::Check check = SettingsFile::check();
        QVERIFY2(check.notice.contains(reason), qPrintable(check.notice));
        QVERIFY2(check.notice.contains(QFileInfo(check.keptAs).fileName()), qPrintable(check.notice));
        // The bad file is where the notice says, byte for byte.
        QCOMPARE(keptAside(), QStringList{QFileInfo(check.keptAs).fileName()});
        QCOMPARE(fileContent(check.keptAs), content);
        // Defaults now, in a file of this version; said once only.
        QSettings settings;
        QVERIFY(!settings.contains("language"));
        QCOMPARE(settings.value(SettingsFile::kVersionKey).toInt(), SettingsFile::kVersion);
        settings.sync();
        QVERIFY(SettingsFile::check().notice.isEmpty());
        QCOMPARE(keptAside().size(), 1);
    }

    void twoBadFilesInOneSecondAreBothKept()
    {
        // Sizes unlike each other and unlike the fresh file each check writes
        // ("settingsVersion=1"): QSettings rereads a file only when its size
        // or time changed, and writes within one millisecond share a time.
        writeFile("[General]\nsettingsVersion=22\n");
        const QString first = SettingsFile::check().keptAs;
        writeFile("[General]\nsettingsVersion=333\n");
        const QString second = SettingsFile::check().keptAs;
        QVERIFY(!first.isEmpty());
        QVERIFY(!second.isEmpty());
        QVERIFY(first != second);
        QCOMPARE(fileContent(first), QByteArray("[General]\nsettingsVersion=22\n"));
        QCOMPARE(fileContent(second), QByteArray("[General]\nsettingsVersion=333\n"));
    }
};

QTEST_GUILESS_MAIN(TestSettingsFile)
#include "tst_settings_file.moc"
