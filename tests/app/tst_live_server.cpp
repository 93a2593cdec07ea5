// SPDX-License-Identifier: GPL-3.0-or-later
// View → Live data server…: switched on and off from its dialog, the address
// to paste, the clients counted, beyond loopback said, a bad address said,
// and the window's robots advertised and withdrawn as they come and go.

#include "live_server_actions.h"
#include "main_window.h"

#include <QCheckBox>
#include <QDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTest>
#include <QWebSocket>
#include <QWebSocketHandshakeOptions>

namespace {

QStringList topicsOf(foxglove::Server &server)
{
    QStringList topics;
    for (const foxglove::Channel &c : server.channels())
        topics << c.topic;
    topics.sort();
    return topics;
}

QString texts(QDialog *dialog)
{
    QStringList all;
    for (const QLabel *label : dialog->findChildren<QLabel *>())
        all << label->text();
    return all.join('\n');
}

} // namespace

class TestLiveServer : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void theDialogSwitchesItOnAndSaysWhere()
    {
        MainWindow window;
        LiveServerActions *live = window.liveServer();
        bool inViewMenu = false;
        for (QAction *menu : window.menuBar()->actions())
            if (menu->menu() && menu->menu()->actions().contains(live->action()))
                inViewMenu = menu->text() == "&View";
        QVERIFY(inViewMenu);

        QDialog *dialog = live->dialog();
        auto *serve = dialog->findChild<QCheckBox *>();
        auto *address = dialog->findChild<QLineEdit *>();
        QCOMPARE(address->text(), QString("127.0.0.1:8765")); // the default, on this machine only
        QVERIFY(!live->server().isListening());
        QVERIFY(texts(dialog).contains("Not serving."));

        address->setText("127.0.0.1:0");
        serve->setChecked(true);
        QVERIFY(live->server().isListening());
        const QString url = live->server().url();
        QVERIFY2(url.startsWith("ws://127.0.0.1:"), qPrintable(url));
        QVERIFY(texts(dialog).contains(url));
        QVERIFY(texts(dialog).contains("Only programs on this computer can connect."));
        QVERIFY(texts(dialog).contains("Clients connected: 0"));

        QWebSocket client;
        QWebSocketHandshakeOptions options;
        options.setSubprotocols({foxglove::kSubprotocol});
        client.open(QUrl(url), options);
        QTRY_VERIFY_WITH_TIMEOUT(texts(dialog).contains("Clients connected: 1"), 10000);
        client.close();
        QTRY_VERIFY_WITH_TIMEOUT(texts(dialog).contains("Clients connected: 0"), 10000);

        // Beyond loopback: the user's choice, said.
        address->setText("0.0.0.0:0");
        emit address->editingFinished();
        QVERIFY(live->server().isListening());
        QVERIFY(!live->server().isLoopback());
        QVERIFY(texts(dialog).contains("Reachable from other computers, as asked"));
        QCOMPARE(QSettings().value("liveServer/address").toString(), QString("0.0.0.0:0"));

        // A bad address: said, and what was served is kept.
        const QString before = live->server().url();
        address->setText("localhost:1");
        emit address->editingFinished();
        QVERIFY2(texts(dialog).contains("Still serving on the address before: 'localhost' is not an IP address"),
                 qPrintable(texts(dialog)));
        QCOMPARE(live->server().url(), before);

        address->setText("127.0.0.1:0");
        emit address->editingFinished();
        QVERIFY(live->server().isLoopback());
        QVERIFY(texts(dialog).contains("Only programs on this computer can connect."));
        serve->setChecked(false);
        QVERIFY(!live->server().isListening());
        QVERIFY(texts(dialog).contains("Not serving."));
    }

    // A port another program holds: said in the log, the status bar and the
    // dialog (with the address asked for), and the window goes on; another
    // port then serves.
    void aBusyPortIsSaidAndTheWindowGoesOn()
    {
        QTcpServer holder;
        QVERIFY(holder.listen(QHostAddress::LocalHost, 0));
        MainWindow window;
        LiveServerActions *live = window.liveServer();
        QSignalSpy said(live, &LiveServerActions::message);
        foxglove::ServerAddress busy;
        busy.port = holder.serverPort();
        const QString why =
            QStringLiteral("cannot serve on 127.0.0.1:%1: port %1 is in use by another program").arg(busy.port);
        QTest::ignoreMessage(QtWarningMsg, qPrintable("live data server: " + why
                                                      + "; the dashboard goes on without it"));
        QVERIFY(!live->start(busy));
        QVERIFY(!live->server().isListening());
        QCOMPARE(said.count(), 1);
        QVERIFY2(said.first().first().toString().contains(why), qPrintable(said.first().first().toString()));
        QDialog *dialog = live->dialog();
        QVERIFY2(texts(dialog).contains("Not serving: " + why), qPrintable(texts(dialog)));
        QCOMPARE(dialog->findChild<QLineEdit *>()->text(), busy.toString());
        window.fleet().addRobot(oilink::LinkSettings::serial(QString()), {}, false);
        QVERIFY(topicsOf(live->server()).contains("/r1/telemetry"));
        dialog->findChild<QLineEdit *>()->setText("127.0.0.1:0");
        dialog->findChild<QCheckBox *>()->setChecked(true);
        QVERIFY(live->server().isListening());
        QVERIFY(texts(dialog).contains(live->server().url()));
    }

    void theWindowsRobotsAreAdvertisedAndWithdrawn()
    {
        MainWindow window;
        foxglove::Server &server = window.liveServer()->server();
        QVERIFY(topicsOf(server).isEmpty());
        RobotSession *first = window.fleet().addRobot(oilink::LinkSettings::serial(QString()), {}, false);
        RobotSession *second = window.fleet().addRobot(oilink::LinkSettings::serial(QString()), {}, false);
        QCOMPARE(topicsOf(server).filter("/telemetry"),
                 (QStringList{"/r1/telemetry", "/r1/telemetry_ros2", "/r2/telemetry", "/r2/telemetry_ros2"}));
        QVERIFY(window.fleet().removeRobot(first));
        QVERIFY(!topicsOf(server).join(' ').contains("/r1/"));
        QVERIFY(topicsOf(server).contains("/r2/pose"));
        // The first free number again.
        window.fleet().addRobot(oilink::LinkSettings::serial(QString()), {}, false);
        QVERIFY(topicsOf(server).contains("/r1/pose"));
        Q_UNUSED(second);
    }
};

QTEST_MAIN(TestLiveServer)
#include "tst_live_server.moc"
