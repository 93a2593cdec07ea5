// SPDX-License-Identifier: GPL-3.0-or-later
// "Connect to broker…": what it refuses, what it keeps in the settings (the
// password only when asked to), the brokers used before, and every text
// translated.

#include "broker_dialog.h"
#include "pseudo_translation.h"
#include "saved_brokers.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryFile>
#include <QTest>

class TestBrokerDialog : public QObject {
    Q_OBJECT

private:
    static QPushButton *ok(BrokerDialog &d)
    {
        return d.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    }

private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void refusesWhatCannotConnect()
    {
        BrokerDialog d({});
        QVERIFY(ok(d)->isEnabled()); // 127.0.0.1:1883, anonymous
        auto *host = d.findChild<QComboBox *>("brokerHost");
        host->setCurrentText(QString());
        QVERIFY(!ok(d)->isEnabled());
        QVERIFY(d.problem().contains("host"));
        host->setCurrentText("pi.local");
        d.findChild<QLineEdit *>("brokerPassword")->setText("s3cret");
        QVERIFY(!ok(d)->isEnabled());
        QVERIFY(d.problem().contains("user name"));
        d.findChild<QLineEdit *>("brokerUser")->setText("teacher");
        QVERIFY(ok(d)->isEnabled());
        d.findChild<QCheckBox *>("brokerTls")->setChecked(true);
        d.findChild<QLineEdit *>("brokerCaFile")->setText("/nonexistent/ca.pem");
        QVERIFY(!ok(d)->isEnabled());
        QVERIFY(d.problem().contains("/nonexistent/ca.pem"));
        QTemporaryFile ca;
        QVERIFY(ca.open());
        d.findChild<QLineEdit *>("brokerCaFile")->setText(ca.fileName());
        QVERIFY(ok(d)->isEnabled());
        d.findChild<QLineEdit *>("brokerCaFile")->setText("/nonexistent/ca.pem");
        if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS")) {
            d.show();
            QVERIFY(d.grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("broker_dialog.png")));
        }
        d.findChild<QLineEdit *>("brokerCaFile")->setText(ca.fileName());
        const SavedBroker b = d.broker();
        QCOMPARE(b.address.host, QStringLiteral("pi.local"));
        QCOMPARE(b.address.username, QStringLiteral("teacher"));
        QCOMPARE(b.address.password, QStringLiteral("s3cret"));
        QVERIFY(b.address.tls);
        QCOMPARE(b.address.caFile, ca.fileName());
    }

    void thePasswordIsKeptOnlyWhenAsked()
    {
        SavedBroker kept;
        kept.address.host = "pi.local";
        kept.address.port = 1884;
        kept.address.username = "teacher";
        kept.address.password = "s3cret";
        kept.rememberPassword = true;
        SavedBroker notKept = kept;
        notKept.address.host = "other";
        notKept.rememberPassword = false;
        {
            QSettings s;
            saveBrokers(s, {kept, notKept});
        }
        QSettings s;
        QVERIFY(!s.allKeys().filter("password").isEmpty());
        const QList<SavedBroker> loaded = loadSavedBrokers(s);
        QCOMPARE(loaded.size(), 2);
        QCOMPARE(loaded[0], kept);
        QCOMPARE(loaded[1].address.password, QString());
        QCOMPARE(loaded[1].address.username, QStringLiteral("teacher"));
        // Only one password in the file: the one asked for.
        int passwords = 0;
        for (const QString &key : s.allKeys())
            passwords += key.endsWith("password") && !s.value(key).toString().isEmpty();
        QCOMPARE(passwords, 1);

        // The most recent first, the same host and port once.
        const auto recent = withRecentBroker(loaded, notKept);
        QCOMPARE(recent.size(), 2);
        QCOMPARE(recent[0].address.host, QStringLiteral("other"));

        // The dialog offers the last one.
        BrokerDialog d(loaded);
        QCOMPARE(d.broker(), kept);
        QCOMPARE(d.findChild<QSpinBox *>("brokerPort")->value(), 1884);
    }

    void everyTextTranslated()
    {
        BrokerDialog d({});
        d.findChild<QComboBox *>("brokerHost")->setCurrentText(QString()); // shows a problem
        ScopedPseudoTranslation pseudo;
        BrokerDialog translated({});
        translated.findChild<QComboBox *>("brokerHost")->setCurrentText(QString());
        translated.show();
        const QStringList untranslated = untranslatedTexts(&translated, {"127.0.0.1"});
        QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
    }
};

QTEST_MAIN(TestBrokerDialog)
#include "tst_broker_dialog.moc"
