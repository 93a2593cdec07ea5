// SPDX-License-Identifier: GPL-3.0-or-later
// View → Live data server…: switched on and off from its dialog, the address
// to paste, the clients counted, beyond loopback said, a bad address said,
// and the window's robots advertised and withdrawn as they come and go.

#include "live_server_actions.h"
#include "display_tick.h"
#include "main_window.h"
#include "replay_bar.h"
#include "robot_fleet.h"

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
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTimer>
#include <QtEndian>

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

// A client that reads one topic and keeps each message's time.
struct TopicReader {
    QWebSocket socket;
    QString topic;
    QList<quint64> timesNs;

    TopicReader(const QString &url, const QString &topicToRead) : topic(topicToRead)
    {
        QObject::connect(&socket, &QWebSocket::textMessageReceived, [this](const QString &text) {
            const QJsonObject message = QJsonDocument::fromJson(text.toUtf8()).object();
            if (message.value("op").toString() != "advertise")
                return;
            for (const QJsonValue &channel : message.value("channels").toArray())
                if (channel.toObject().value("topic").toString() == topic) {
                    const QJsonObject subscribe{
                        {"op", "subscribe"},
                        {"subscriptions", QJsonArray{QJsonObject{{"id", 1}, {"channelId", channel.toObject().value("id")}}}}};
                    socket.sendTextMessage(QString::fromUtf8(QJsonDocument(subscribe).toJson(QJsonDocument::Compact)));
                }
        });
        QObject::connect(&socket, &QWebSocket::binaryMessageReceived, [this](const QByteArray &message) {
            if (message.size() >= 13 && message.at(0) == 1)
                timesNs << qFromLittleEndian<quint64>(message.constData() + 5);
        });
        QWebSocketHandshakeOptions options;
        options.setSubprotocols({foxglove::kSubprotocol});
        socket.open(QUrl(url), options);
    }
    // Messages a second, by their own times (the frames' read times).
    double rate() const
    {
        return timesNs.size() < 2 ? 0 : (timesNs.size() - 1) / (double(timesNs.last() - timesNs.first()) / 1e9);
    }
};

// The viewer's side of playbackControl: its requests, the server's states.
struct PlaybackState {
    int status = -1;
    quint64 currentNs = 0;
    float speed = 0;
    bool didSeek = false;
    QByteArray requestId;
};
QList<PlaybackState> playbackStates(const QList<QByteArray> &binaries)
{
    QList<PlaybackState> states;
    for (const QByteArray &b : binaries)
        if (b.size() >= 19 && b.at(0) == 5)
            states << PlaybackState{b.at(1), qFromLittleEndian<quint64>(b.constData() + 2),
                                    qFromLittleEndian<float>(b.constData() + 10), b.at(14) != 0, b.mid(19)};
    return states;
}
QByteArray playbackRequest(bool play, float speed, std::optional<quint64> seekNs, const QByteArray &id)
{
    QByteArray m(1 + 1 + 4 + 1 + 8 + 4, '\0');
    m[0] = 3;
    m[1] = play ? 0 : 1;
    qToLittleEndian<float>(speed, m.data() + 2);
    m[6] = seekNs ? 1 : 0;
    qToLittleEndian<quint64>(seekNs.value_or(0), m.data() + 7);
    qToLittleEndian<quint32>(quint32(id.size()), m.data() + 15);
    return m + id;
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

    // A client of the live data gets each frame when the link read it, not
    // the last of each batch the display takes at its tick. With the window
    // held at its quiet pace (a tick every 198 ms, as when nothing moves),
    // display-paced data came at about 12 a second; fed at read time it
    // fills most of the 50 a second the server sends, even on a busy machine.
    void theLiveDataKeepsTheRobotsPaceWhateverTheWindowKeeps()
    {
        MainWindow window;
        window.show();
        foxglove::ServerAddress address;
        address.port = 0;
        QVERIFY(window.liveServer()->start(address));
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(window.fleet().selected() && window.fleet().selected()->isLive(), 10000);
        // The window slows its display when the frames stop changing; here
        // it is held there whatever they do.
        QTimer holdQuiet;
        QObject::connect(&holdQuiet, &QTimer::timeout, [] { DisplayTick::instance().setQuiet(true); });
        holdQuiet.start(20);
        TopicReader reader(window.liveServer()->server().url(), "/r1/telemetry");
        QTRY_VERIFY_WITH_TIMEOUT(reader.timesNs.size() >= 150, 30000);
        QVERIFY(DisplayTick::instance().isQuiet());
        qInfo("%.1f telemetry messages a second at the client", reader.rate());
        QVERIFY2(reader.rate() >= 30, qPrintable(QStringLiteral("%1 messages a second").arg(reader.rate())));
    }

    // A replay served live: the viewer's timeline seeks, pauses, plays and
    // sets the speed as the replay bar does, and the replay bar's own moves
    // and the replay's end are said back.
    void theViewersTimelineDrivesTheReplay()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        MainWindow window;
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        window.startRecording(path);
        QTRY_VERIFY_WITH_TIMEOUT(window.session().recording().bytesWritten > 20000, 20000);
        window.stopRecording();
        QTRY_VERIFY_WITH_TIMEOUT(!window.session().recording().active, 10000);
        RobotSession *recorded = &window.session();
        QString error;
        QVERIFY2(window.openRecording(path, &error), qPrintable(error));
        QVERIFY(window.fleet().removeRobot(recorded)); // the replay alone is served
        QVERIFY(window.session().isReplay());
        QTRY_VERIFY_WITH_TIMEOUT(window.replayBar()->position().durationUs > 2'000'000, 10000);
        foxglove::ServerAddress address;
        address.port = 0;
        QVERIFY(window.liveServer()->start(address));

        const QStringList telemetry = topicsOf(window.liveServer()->server()).filter(QRegularExpression("^/r\\d+/telemetry$"));
        QCOMPARE(telemetry.size(), 1); // the replay's
        TopicReader viewer(window.liveServer()->server().url(), telemetry.first());
        QList<QByteArray> binaries;
        QJsonObject info;
        QObject::connect(&viewer.socket, &QWebSocket::binaryMessageReceived, [&](const QByteArray &b) { binaries << b; });
        QObject::connect(&viewer.socket, &QWebSocket::textMessageReceived, [&](const QString &text) {
            const QJsonObject m = QJsonDocument::fromJson(text.toUtf8()).object();
            if (m.value("op").toString() == "serverInfo")
                info = m;
        });
        QTRY_VERIFY_WITH_TIMEOUT(info.value("capabilities").toArray().contains("playbackControl"), 10000);
        const QJsonObject start = info.value("dataStartTime").toObject();
        const quint64 startNs = quint64(start.value("sec").toInteger()) * 1'000'000'000 + quint64(start.value("nsec").toInteger());
        const QJsonObject end = info.value("dataEndTime").toObject();
        const quint64 endNs = quint64(end.value("sec").toInteger()) * 1'000'000'000 + quint64(end.value("nsec").toInteger());
        QCOMPARE(qint64(endNs - startNs) / 1000, window.replayBar()->position().durationUs);

        // Paused at 1 s: answered, and the next message is the first frame from then.
        const quint64 seekNs = startNs + 1'000'000'000;
        const qsizetype heard = viewer.timesNs.size();
        viewer.socket.sendBinaryMessage(playbackRequest(false, 1, seekNs, "seek-1"));
        const auto answerTo = [&](const QByteArray &id) {
            for (const PlaybackState &state : playbackStates(binaries))
                if (state.requestId == id)
                    return std::optional(state);
            return std::optional<PlaybackState>();
        };
        QTRY_VERIFY_WITH_TIMEOUT(answerTo("seek-1"), 5000);
        QVERIFY(answerTo("seek-1")->didSeek);
        QCOMPARE(answerTo("seek-1")->status, 1); // paused
        QCOMPARE(answerTo("seek-1")->currentNs, seekNs);
        QTRY_VERIFY2_WITH_TIMEOUT(viewer.timesNs.size() > heard && viewer.timesNs.last() >= seekNs,
                                  qPrintable(QStringLiteral("%1 messages, %2 before; the last %3 ms from the seek")
                                                 .arg(viewer.timesNs.size())
                                                 .arg(heard)
                                                 .arg((qint64(viewer.timesNs.value(viewer.timesNs.size() - 1)) - qint64(seekNs)) / 1e6)),
                                  5000);
        QVERIFY2(viewer.timesNs.last() < seekNs + 100'000'000, qPrintable(QString::number(viewer.timesNs.last() - seekNs)));
        QTRY_VERIFY_WITH_TIMEOUT(!window.replayBar()->position().playing
                                     && std::abs(window.replayBar()->position().positionUs - 1'000'000) < 100'000,
                                 5000);

        // Played at 4×: the replay bar says so.
        viewer.socket.sendBinaryMessage(playbackRequest(true, 4, std::nullopt, "play-4"));
        QTRY_VERIFY_WITH_TIMEOUT(window.replayBar()->position().playing && window.replayBar()->position().speed == 4, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(answerTo("play-4"), 5000); // the answer crosses the socket after the bar moved
        QCOMPARE(answerTo("play-4")->speed, 4.0f);

        // The replay bar jumps back: the viewer's panels start afresh.
        const qsizetype states = playbackStates(binaries).size();
        window.session().controlReplay(oilink::ReplayCommand::seek(0));
        QTRY_VERIFY_WITH_TIMEOUT(playbackStates(binaries).size() > states && playbackStates(binaries).last().didSeek, 5000);
        QVERIFY(playbackStates(binaries).last().requestId.isEmpty());

        // Played to its end: said.
        QTRY_VERIFY_WITH_TIMEOUT(playbackStates(binaries).last().status == 3, 20000);
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
