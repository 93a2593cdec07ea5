// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-classroom serve, the blocks page's HTTPS and its hub, on a
// classroom that init wrote, with a real mosquitto over TLS and, to drive,
// a real roomba-bridge --sim: the page's files with their types and nothing
// outside them; sign-in through the broker, with the ACL's robots; what
// the broker's ACL refuses does not get through; no student sees another's
// password or messages; the teacher sees who runs what; a closed page
// stops the robot it drove; a client that does not trust the classroom's
// CA gets nothing; bad input gets an error and the session goes on.

#include "blocks_hub_rig.h"
#include "classroom_accounts.h"
#include "fleet_topics.h"
#include "mosquitto_broker.h"
#include "mqtt_client.h"
#include "process_run.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>

using namespace mqtt;

class TestBlocksHub : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    MosquittoBroker m_broker;
    ServeProcess m_hub;
    QString m_class, m_page, m_ca;
    QString m_accounts;

    QString passwordOf(const QString &account) const { return passwordIn(m_accounts, account); }
    static bool writeFile(const QString &path, const QByteArray &contents)
    {
        QDir().mkpath(QFileInfo(path).absolutePath());
        QFile f(path);
        return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(contents) == contents.size();
    }
    BrokerAddress as(const QString &account) const
    {
        return classroomBroker(m_broker.port(), account, passwordOf(account), m_ca);
    }
    // A page signed in as `account`.
    std::unique_ptr<HubClient> signedIn(const QString &account)
    {
        auto page = std::make_unique<HubClient>(m_ca);
        if (!page->open(m_hub.hubUrl()) || page->signIn(account, passwordOf(account)) != QLatin1String("signed-in"))
            return nullptr;
        return page;
    }
    static QStringList robotsOf(const QJsonObject &signedIn)
    {
        QStringList robots;
        for (const QJsonValue &r : signedIn.value(QLatin1String("robots")).toArray())
            robots << r.toString();
        return robots;
    }

private slots:
    void initTestCase()
    {
        // Run as root, init hands the broker to the mosquitto user, which must reach the classroom.
        QFile::setPermissions(m_dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner | QFile::ReadGroup
                                                | QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther);
        m_class = m_dir.filePath(QStringLiteral("class"));
        const ProcessRun init = runProcess(QStringLiteral(ROOMBA_CLASSROOM_PATH),
                                           {"init", m_class, "--robots", "r1,r2", "--students", "alice,bob",
                                            "--spectators", "guest", "--port", QString::number(m_broker.port())});
        QVERIFY2(init.exitCode == 0, init.err.constData());
        m_ca = QDir(m_class).filePath(QStringLiteral("ca.crt"));
        m_accounts = accountsIn(m_class);
        QVERIFY(!m_accounts.isEmpty());
        // alice may drive r1 only: her r2 lines out of the ACL, as a teacher may edit it.
        QFile acl(QDir(m_class).filePath(QStringLiteral("acl")));
        QVERIFY(acl.open(QIODevice::ReadOnly));
        QByteArray rules = acl.readAll();
        acl.close();
        QVERIFY(rules.contains("topic write roomba/r2/command/alice\n"));
        rules.replace("topic write roomba/r2/command/alice\n", "").replace("topic write roomba/r2/control/alice\n", "");
        QVERIFY(acl.open(QIODevice::WriteOnly | QIODevice::Truncate));
        acl.write(rules);
        acl.close();
        QVERIFY2(m_broker.startWith(QDir(m_class).filePath(QStringLiteral("mosquitto.conf"))), qPrintable(m_broker.error()));

        // A page, with a secret beside its folder and a link out of it.
        m_page = m_dir.filePath(QStringLiteral("page"));
        QVERIFY(writeFile(m_page + QStringLiteral("/index.html"), "<!doctype html><title>blocks</title>"));
        QVERIFY(writeFile(m_page + QStringLiteral("/app.js"), "console.log('blocks');"));
        QVERIFY(writeFile(m_page + QStringLiteral("/style.css"), "body {}"));
        QVERIFY(writeFile(m_page + QStringLiteral("/media/sprites.png"), "\x89PNG\r\n"));
        QVERIFY(writeFile(m_page + QStringLiteral("/.hidden"), "hidden"));
        QVERIFY(writeFile(m_dir.filePath(QStringLiteral("secret.txt")), "the secret"));
        QVERIFY(QFile::link(m_dir.filePath(QStringLiteral("secret.txt")), m_page + QStringLiteral("/out.txt")));
        QVERIFY2(m_hub.start({m_class, "--page", m_page, "--blocks", "move,sound"}), m_hub.said().constData());
    }

    void thePageFilesAreServedWithTheirTypes()
    {
        const HttpsReply index = httpsGet(m_hub.port(), m_ca, "/");
        QCOMPARE(index.status, 200);
        QCOMPARE(index.body, QByteArray("<!doctype html><title>blocks</title>"));
        QCOMPARE(index.field("Content-Type"), QByteArray("text/html; charset=utf-8"));
        // The page may speak to itself and its hub alone.
        const QByteArray policy = index.field("Content-Security-Policy");
        QVERIFY2(policy.contains("default-src 'self'"), policy.constData());
        QVERIFY2(policy.contains("connect-src 'self' wss://127.0.0.1:" + QByteArray::number(m_hub.port()) + "/hub"),
                 policy.constData());
        QCOMPARE(index.field("X-Content-Type-Options"), QByteArray("nosniff"));
        for (const auto &[target, type] : {std::pair{"/app.js", "text/javascript; charset=utf-8"},
                                           std::pair{"/style.css", "text/css; charset=utf-8"},
                                           std::pair{"/media/sprites.png", "image/png"},
                                           std::pair{"/app.js?v=2", "text/javascript; charset=utf-8"}}) {
            const HttpsReply r = httpsGet(m_hub.port(), m_ca, target);
            QVERIFY2(r.status == 200, target);
            QCOMPARE(r.field("Content-Type"), QByteArray(type));
        }
        QCOMPARE(httpsGet(m_hub.port(), m_ca, "/nothing.js").status, 404);
    }

    void nothingOutsideThePageAndOnlyGet()
    {
        for (const char *target : {"/../secret.txt", "/%2e%2e/secret.txt", "/media/..%2f..%2fsecret.txt",
                                   "/media%2f..%2f..%2fsecret.txt", "/..%5csecret.txt", "/media/../../secret.txt"}) {
            const HttpsReply r = httpsGet(m_hub.port(), m_ca, target);
            QVERIFY2(r.status == 400, target);
            QVERIFY2(!r.body.contains("the secret"), target);
        }
        const HttpsReply link = httpsGet(m_hub.port(), m_ca, "/out.txt");
        QCOMPARE(link.status, 403);
        QVERIFY(!link.body.contains("the secret"));
        QCOMPARE(httpsGet(m_hub.port(), m_ca, "/.hidden").status, 404);
        const QByteArray host = "Host: 127.0.0.1:" + QByteArray::number(m_hub.port()) + "\r\n";
        for (const QByteArray &method : {QByteArray("POST"), QByteArray("PUT"), QByteArray("HEAD")}) {
            const HttpsReply r = httpsRequest(m_hub.port(), m_ca,
                                              method + " /index.html HTTP/1.1\r\n" + host + "Content-Length: 2\r\n\r\nhi");
            QVERIFY2(r.status == 405, method.constData());
            QCOMPARE(r.field("Allow"), QByteArray("GET"));
        }
        // A head without end is not read for ever.
        const HttpsReply huge = httpsRequest(m_hub.port(), m_ca,
                                             "GET / HTTP/1.1\r\n" + host + "X-Filler: " + QByteArray(9000, 'x') + "\r\n\r\n");
        QCOMPARE(huge.status, 431);
        // A page of another site cannot open the hub from a student's browser.
        const HttpsReply foreign = httpsRequest(m_hub.port(), m_ca,
                                                "GET /hub HTTP/1.1\r\n" + host
                                                    + "Upgrade: websocket\r\nConnection: Upgrade\r\nOrigin: https://evil.example\r\n"
                                                      "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n");
        QCOMPARE(foreign.status, 403);
    }

    void withoutThePageItSaysSo()
    {
        ServeProcess bare;
        QVERIFY2(bare.start({m_class, "--page", m_dir.filePath(QStringLiteral("no-page"))}), bare.said().constData());
        const HttpsReply r = httpsGet(bare.port(), m_ca, "/");
        QCOMPARE(r.status, 503);
        QVERIFY2(r.body.contains("The blocks page is not installed"), r.body.constData());
        QVERIFY(bare.said().contains("the blocks page is not installed"));
    }

    void unknownBlockSetsAreRefusedAtStart()
    {
        const ProcessRun r = runProcess(QStringLiteral(ROOMBA_CLASSROOM_PATH), {"serve", m_class, "--blocks", "move,dance"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("'dance' is no block set; the sets are move, sensors, sound, lights, control"), r.err.constData());
        const ProcessRun none = runProcess(QStringLiteral(ROOMBA_CLASSROOM_PATH), {"serve", m_dir.filePath(QStringLiteral("nowhere"))});
        QCOMPARE(none.exitCode, 1);
        QVERIFY2(none.err.contains("mosquitto.conf"), none.err.constData());
    }

    void signInGoesThroughTheBrokerAndGivesTheAclsRobots()
    {
        HubClient page(m_ca);
        QVERIFY(page.open(m_hub.hubUrl()));
        QCOMPARE(page.signIn(QStringLiteral("alice"), QStringLiteral("not-alices-password")), QStringLiteral("refused"));
        QCOMPARE(page.signedIn().value(QLatin1String("why")).toString(), QStringLiteral("wrong user name or password"));
        // The socket stays open for another try.
        QCOMPARE(page.signIn(QStringLiteral("alice"), passwordOf(QStringLiteral("alice"))), QStringLiteral("signed-in"));
        const QJsonObject welcome = page.signedIn();
        QCOMPARE(welcome.value(QLatin1String("user")).toString(), QStringLiteral("alice"));
        QCOMPARE(robotsOf(welcome), QStringList{QStringLiteral("r1")});
        QCOMPARE(welcome.value(QLatin1String("blocks")).toArray(), QJsonArray({"move", "sound"}));
        QFile table(QStringLiteral(ROOMBA_CLASSROOM_PROTOCOL_JSON));
        QVERIFY(table.open(QIODevice::ReadOnly));
        QCOMPARE(welcome.value(QLatin1String("protocol")).toObject(), QJsonDocument::fromJson(table.readAll()).object());

        const std::unique_ptr<HubClient> bob = signedIn(QStringLiteral("bob"));
        QVERIFY(bob);
        QCOMPARE(robotsOf(bob->signedIn()), QStringList({"r1", "r2"}));
        const std::unique_ptr<HubClient> guest = signedIn(QStringLiteral("guest"));
        QVERIFY(guest);
        QCOMPARE(robotsOf(guest->signedIn()), QStringList());
        // A bridge's account is no person's: it would knock its bridge off the broker.
        HubClient bridge(m_ca);
        QVERIFY(bridge.open(m_hub.hubUrl()));
        QCOMPARE(bridge.signIn(QStringLiteral("bridge-r1"), passwordOf(QStringLiteral("bridge-r1"))), QStringLiteral("refused"));
    }

    void repeatedSignInsAreSlowed()
    {
        HubClient page(m_ca);
        QVERIFY(page.open(m_hub.hubUrl()));
        for (int i = 0; i < 5; ++i)
            QCOMPARE(page.signIn(QStringLiteral("bob"), QStringLiteral("guess-%1").arg(i)), QStringLiteral("refused"));
        // The sixth within the minute is not even tried, the right password included.
        QCOMPARE(page.signIn(QStringLiteral("bob"), passwordOf(QStringLiteral("bob"))), QStringLiteral("refused"));
        QVERIFY2(page.signedIn().value(QLatin1String("why")).toString().startsWith(QLatin1String("too many sign-in attempts")),
                 qPrintable(page.signedIn().value(QLatin1String("why")).toString()));
    }

    void badInputGetsAnErrorAndTheSessionGoesOn()
    {
        HubClient page(m_ca);
        QVERIFY(page.open(m_hub.hubUrl()));
        const auto why = [&page] {
            const std::optional<QJsonObject> a = page.answer();
            return a && a->value(QLatin1String("op")) == QLatin1String("error") ? a->value(QLatin1String("why")).toString()
                                                                                : QStringLiteral("(no error)");
        };
        page.send({{"op", "subscribe"}, {"topic", "roomba/#"}});
        QCOMPARE(why(), QStringLiteral("sign in first"));
        page.sendText(QStringLiteral("{not json"));
        QVERIFY(why().startsWith(QLatin1String("not JSON")));
        page.sendText(QStringLiteral("[1, 2]"));
        QCOMPARE(why(), QStringLiteral("a message to the hub is a JSON object with \"op\""));
        page.send({{"op", "fly"}});
        QCOMPARE(why(), QStringLiteral("unknown op \"fly\""));
        page.sendText(QStringLiteral("{\"op\": \"publish\", \"payload\": \"%1\"}").arg(QString(70 * 1024, QLatin1Char('x'))));
        QCOMPARE(why(), QStringLiteral("a message to the hub is at most 64 KiB"));
        page.socket().sendBinaryMessage("\x01\x02");
        QCOMPARE(why(), QStringLiteral("the hub reads text frames of JSON, not binary ones"));

        QCOMPARE(page.signIn(QStringLiteral("bob"), passwordOf(QStringLiteral("bob"))), QStringLiteral("signed-in"));
        page.send({{"op", "subscribe"}, {"topic", "roomba/#/x"}});
        QCOMPARE(why(), QStringLiteral("\"topic\" must be an MQTT topic filter"));
        page.send({{"op", "publish"}, {"topic", "roomba/+/control/bob"}, {"payload", "{}"}});
        QCOMPARE(why(), QStringLiteral("\"topic\" must be an MQTT topic, without wildcards"));
        page.send({{"op", "publish"}, {"topic", "roomba/r2/control/bob"}, {"payload", "{}"}, {"qos", 2}});
        QCOMPARE(why(), QStringLiteral("\"qos\" must be 0 or 1"));
        page.send({{"op", "publish"}, {"topic", "roomba/r2/control/bob"}, {"payload", QString(9000, QLatin1Char('x'))}});
        QVERIFY(why().startsWith(QLatin1String("too big for the classroom's broker")));
        page.send({{"op", "sign-in"}, {"user", "bob"}, {"password", "x"}});
        QCOMPARE(why(), QStringLiteral("already signed in as bob"));

        // Still relaying: what the teacher sends on r2 reaches bob's page.
        page.send({{"op", "subscribe"}, {"topic", "roomba/r2/control/teacher"}});
        MqttClient teacher(QStringLiteral("teacher"));
        QVERIFY(teacher.connectToBroker(as(QStringLiteral("teacher"))));
        std::optional<QJsonObject> message;
        QTimer again; // the subscription is made when the broker has it, which the page is not told
        connect(&again, &QTimer::timeout, &teacher, [&teacher] {
            teacher.publish(topics::control(QStringLiteral("r2"), QStringLiteral("teacher")), "{\"action\": \"release\"}");
        });
        again.start(100);
        message = page.next(QStringLiteral("message"));
        QVERIFY(message);
        QCOMPARE(message->value(QLatin1String("topic")).toString(), QStringLiteral("roomba/r2/control/teacher"));
        QCOMPARE(message->value(QLatin1String("payload")).toString(), QStringLiteral("{\"action\": \"release\"}"));
    }

    void whatTheAclRefusesDoesNotGetThrough()
    {
        const std::unique_ptr<HubClient> alice = signedIn(QStringLiteral("alice"));
        QVERIFY(alice);
        MqttClient watcher(QStringLiteral("teacher"));
        QSignalSpy seen(&watcher, &MqttClient::messageReceived);
        watcher.subscribe(QStringLiteral("roomba/#"));
        QSignalSpy subscribed(&watcher, &MqttClient::subscribed);
        QVERIFY(watcher.connectToBroker(as(QStringLiteral("teacher"))));
        QTRY_VERIFY_WITH_TIMEOUT(!subscribed.isEmpty(), 15000);
        // r2 is not hers, bob's lane is not hers: the broker drops both. Her
        // own lane on r1, sent after them on the same connection, comes
        // after anything they would have let through.
        const QByteArray take = "{\"action\": \"take\"}";
        alice->send({{"op", "publish"}, {"topic", "roomba/r2/control/alice"}, {"payload", QString::fromLatin1(take)}, {"qos", 1}});
        alice->send({{"op", "publish"}, {"topic", "roomba/r1/control/bob"}, {"payload", QString::fromLatin1(take)}, {"qos", 1}});
        alice->send({{"op", "publish"}, {"topic", "roomba/fleet/stop"}, {"payload", "{}"}, {"qos", 1}});
        alice->send({{"op", "publish"}, {"topic", "roomba/r1/command/alice"}, {"payload", "barrier"}, {"qos", 1}});
        QTRY_VERIFY_WITH_TIMEOUT(std::any_of(seen.cbegin(), seen.cend(),
                                             [](const QList<QVariant> &m) { return m[0] == "roomba/r1/command/alice"; }),
                                 15000);
        QStringList topicsSeen;
        for (const QList<QVariant> &m : seen)
            topicsSeen << m[0].toString();
        QVERIFY2(!topicsSeen.contains(QStringLiteral("roomba/r2/control/alice")), qPrintable(topicsSeen.join(' ')));
        QVERIFY2(!topicsSeen.contains(QStringLiteral("roomba/r1/control/bob")), qPrintable(topicsSeen.join(' ')));
        QVERIFY2(!topicsSeen.contains(QStringLiteral("roomba/fleet/stop")), qPrintable(topicsSeen.join(' ')));
    }

    void noStudentSeesAnothersPasswordOrMessages()
    {
        const std::unique_ptr<HubClient> alice = signedIn(QStringLiteral("alice"));
        const std::unique_ptr<HubClient> bob = signedIn(QStringLiteral("bob"));
        QVERIFY(alice && bob);
        alice->send({{"op", "subscribe"}, {"topic", "roomba/r2/command/teacher"}});
        bob->send({{"op", "subscribe"}, {"topic", "roomba/r2/control/teacher"}});
        MqttClient teacher(QStringLiteral("teacher"));
        QVERIFY(teacher.connectToBroker(as(QStringLiteral("teacher"))));
        QTimer again;
        QString topic = topics::control(QStringLiteral("r2"), QStringLiteral("teacher"));
        QByteArray payload = "for bob";
        connect(&again, &QTimer::timeout, &teacher, [&] { teacher.publish(topic, payload); });
        again.start(100);
        QVERIFY(bob->next(QStringLiteral("message")));
        // Anything the hub wrongly gave alice of bob's went to her socket
        // before what it gives her from now on.
        topic = topics::command(QStringLiteral("r2"), QStringLiteral("teacher"));
        payload = "for alice";
        QVERIFY(alice->next(QStringLiteral("message")));
        again.stop();
        for (const QJsonObject &m : alice->received())
            QVERIFY2(m.value(QLatin1String("payload")) != QLatin1String("for bob"), "alice got bob's message");
        // Who runs what is the teacher's to see.
        alice->send({{"op", "runs"}});
        QCOMPARE(alice->next(QStringLiteral("error"))->value(QLatin1String("why")).toString(),
                 QStringLiteral("only the teacher sees who runs what"));
        for (const QString &account : {QStringLiteral("alice"), QStringLiteral("bob")}) {
            QVERIFY(!alice->everything().contains(passwordOf(QStringLiteral("bob"))));
            QVERIFY(!bob->everything().contains(passwordOf(QStringLiteral("alice"))));
            QVERIFY2(!m_hub.said().contains(passwordOf(account).toUtf8()), "a password in the hub's output");
        }
        for (int i = 0; i < 5; ++i)
            QVERIFY(!m_hub.said().contains(QStringLiteral("guess-%1").arg(i).toUtf8()));
        QVERIFY(!m_hub.said().contains("not-alices-password"));
    }

    void theTeacherSeesWhoRunsWhat()
    {
        const std::unique_ptr<HubClient> alice = signedIn(QStringLiteral("alice"));
        const std::unique_ptr<HubClient> teacher = signedIn(QStringLiteral("teacher"));
        QVERIFY(alice && teacher);
        QCOMPARE(robotsOf(teacher->signedIn()), QStringList({"r1", "r2"}));
        teacher->send({{"op", "runs"}});
        QCOMPARE(teacher->next(QStringLiteral("runs"))->value(QLatin1String("runs")).toArray(), QJsonArray());
        alice->send({{"op", "running"}, {"robot", "r2"}, {"program", "print(1)"}});
        QCOMPARE(alice->next(QStringLiteral("error"))->value(QLatin1String("why")).toString(),
                 QStringLiteral("\"robot\" must be a robot you may drive"));
        alice->send({{"op", "running"}, {"robot", "r1"}, {"program", "from roomba import Robot\n\nr = Robot('r1')\nr.forward(500)\nr.turn(90)\n"}});
        // Each change comes to the teacher's page as it happens, and to the terminal.
        const std::optional<QJsonObject> runs = teacher->next(QStringLiteral("runs"));
        QVERIFY(runs);
        const QJsonArray rows = runs->value(QLatin1String("runs")).toArray();
        QCOMPARE(rows.size(), 1);
        QCOMPARE(rows[0][QLatin1String("user")].toString(), QStringLiteral("alice"));
        QCOMPARE(rows[0][QLatin1String("robot")].toString(), QStringLiteral("r1"));
        QCOMPARE(rows[0][QLatin1String("program")].toString(), QStringLiteral("from roomba import Robot\nr = Robot('r1')\nr.forward(500)"));
        QVERIFY(QDateTime::fromString(rows[0][QLatin1String("since")].toString(), Qt::ISODateWithMs).isValid());
        QVERIFY(m_hub.waitToSay("alice runs a program on r1: from roomba import Robot | r = Robot('r1') | r.forward(500)"));
        alice->send({{"op", "ended"}, {"robot", "r1"}, {"why", "finished"}});
        QCOMPARE(teacher->next(QStringLiteral("runs"))->value(QLatin1String("runs")).toArray(), QJsonArray());
        QVERIFY(m_hub.waitToSay("alice's program on r1 ended: finished"));
        // A page that closes ends what it ran.
        alice->send({{"op", "running"}, {"robot", "r1"}, {"program", "r.spin()"}});
        QCOMPARE(teacher->next(QStringLiteral("runs"))->value(QLatin1String("runs")).toArray().size(), 1);
        alice->socket().close();
        QCOMPARE(teacher->next(QStringLiteral("runs"))->value(QLatin1String("runs")).toArray(), QJsonArray());
        QVERIFY(m_hub.waitToSay("alice's program on r1 ended: the page closed"));
    }

    void aClosedPageStopsTheRobotItDrove()
    {
        QProcess bridge;
        QByteArray bridgeSaid;
        bridge.setProcessChannelMode(QProcess::MergedChannels);
        connect(&bridge, &QProcess::readyRead, this, [&] { bridgeSaid += bridge.readAll(); });
        bridge.start(QStringLiteral(ROOMBA_BRIDGE_PATH),
                     {QStringLiteral("--config"), QDir(m_class).filePath(QStringLiteral("bridges/r1.conf")), QStringLiteral("--sim")});
        QVERIFY(bridge.waitForStarted());
        MqttClient watcher(QStringLiteral("teacher"));
        QList<QJsonObject> replies;
        bool online = false;
        connect(&watcher, &MqttClient::messageReceived, this, [&](const QString &topic, const QByteArray &payload) {
            const QJsonObject o = QJsonDocument::fromJson(payload).object();
            if (topic == topics::reply(QStringLiteral("r1"), QStringLiteral("alice")))
                replies << o;
            else if (topic == topics::state(QStringLiteral("r1")))
                online = o.value(QLatin1String("online")).toBool() && o.value(QLatin1String("link")) == QLatin1String("streaming");
        });
        watcher.subscribe(topics::reply(QStringLiteral("r1"), QStringLiteral("alice")));
        watcher.subscribe(topics::state(QStringLiteral("r1")));
        QVERIFY(watcher.connectToBroker(as(QStringLiteral("teacher"))));
        QTRY_VERIFY_WITH_TIMEOUT(online, 30000);

        const std::unique_ptr<HubClient> alice = signedIn(QStringLiteral("alice"));
        QVERIFY(alice);
        const auto publish = [&alice](const QString &topic, const QByteArray &payload) {
            alice->send({{"op", "publish"}, {"topic", topic}, {"payload", QString::fromUtf8(payload)}});
        };
        const QString control = topics::control(QStringLiteral("r1"), QStringLiteral("alice"));
        const QString command = topics::command(QStringLiteral("r1"), QStringLiteral("alice"));
        const auto replyTo = [&replies](const QString &id) {
            for (const QJsonObject &r : replies)
                if (r.value(QLatin1String("id")) == id)
                    return r;
            return QJsonObject();
        };
        // Heartbeats at twice the rate asked, so that a busy machine's pause does not lapse control.
        QTimer keep;
        connect(&keep, &QTimer::timeout, this, [&] { publish(control, "{\"action\": \"keep\"}"); });
        publish(control, "{\"action\": \"take\", \"program\": \"blocks\"}");
        keep.start(50);
        QTRY_VERIFY_WITH_TIMEOUT(replyTo(QStringLiteral("control")).value(QLatin1String("ok")).toBool(), 15000);
        publish(command, "{\"v\": 2, \"id\": \"safe\", \"command\": \"safe\"}");
        QTRY_VERIFY_WITH_TIMEOUT(replyTo(QStringLiteral("safe")).value(QLatin1String("ok")).toBool(), 15000);
        publish(command, "{\"v\": 2, \"id\": \"m\", \"command\": \"straight\", \"fields\": {\"distance\": 3000, \"speed\": 100}}");
        QTRY_VERIFY_WITH_TIMEOUT(bridgeSaid.contains("straight"), 15000);
        QVERIFY2(replyTo(QStringLiteral("m")).isEmpty(), "the move ended before the page closed");

        // The tab closes: the hub ends alice's connection at once, and her heartbeats with it.
        keep.stop();
        alice->socket().close();
        QTRY_VERIFY_WITH_TIMEOUT(!replyTo(QStringLiteral("m")).isEmpty(), 15000);
        QCOMPARE(replyTo(QStringLiteral("m")).value(QLatin1String("stop")).toString(), QStringLiteral("heartbeat"));
        QVERIFY(m_hub.waitToSay("alice signed out (the page closed)"));
        bridge.terminate();
        QVERIFY(bridge.waitForFinished(10000));
    }

    void aClientThatDoesNotTrustTheClassroomsCaGetsNothing()
    {
        const QString other = m_dir.filePath(QStringLiteral("other"));
        const ProcessRun init = runProcess(QStringLiteral(ROOMBA_CLASSROOM_PATH),
                                           {"init", other, "--robots", "r1", "--students", "eve"});
        QVERIFY2(init.exitCode == 0, init.err.constData());
        HubClient page(QDir(other).filePath(QStringLiteral("ca.crt")));
        QSignalSpy sslErrors(&page.socket(), &QWebSocket::sslErrors);
        QSignalSpy connected(&page.socket(), &QWebSocket::connected);
        QSignalSpy disconnected(&page.socket(), &QWebSocket::disconnected);
        page.socket().open(QUrl(m_hub.hubUrl()));
        QTRY_VERIFY_WITH_TIMEOUT(!disconnected.isEmpty(), 15000);
        QVERIFY(!sslErrors.isEmpty());
        QCOMPARE(connected.count(), 0);
        QVERIFY(page.received().isEmpty());
        QCOMPARE(httpsGet(m_hub.port(), QDir(other).filePath(QStringLiteral("ca.crt")), "/").status, 0);
    }
};

QTEST_GUILESS_MAIN(TestBlocksHub)
#include "tst_blocks_hub.moc"
