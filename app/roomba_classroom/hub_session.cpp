// SPDX-License-Identifier: GPL-3.0-or-later
#include "hub_session.h"

#include "fleet_topics.h"
#include "hub_log.h"
#include "mqtt_client.h"
#include "run_table.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QWebSocket>

namespace classroom {

namespace {

constexpr qint64 kMinuteMs = 60 * 1000;
constexpr int kMaxPasswordChars = 256;
constexpr int kMaxWhyChars = 200;

} // namespace

HubSession::HubSession(QWebSocket *socket, const HubSettings &settings, RunTable &runs, QObject *parent)
    : QObject(parent), m_socket(socket), m_settings(settings), m_runs(runs)
{
    m_socket->setParent(this);
    m_clock.start();
    connect(m_socket, &QWebSocket::textMessageReceived, this, &HubSession::onText);
    connect(m_socket, &QWebSocket::binaryMessageReceived, this,
            [this] { error(QStringLiteral("the hub reads text frames of JSON, not binary ones")); });
    connect(m_socket, &QWebSocket::disconnected, this, [this] {
        endMqtt(QStringLiteral("the page closed"));
        emit closed();
    });
}

HubSession::~HubSession()
{
    m_socket->disconnect(this);
    endMqtt(QStringLiteral("the hub stopped"));
}

QString HubSession::peer() const
{
    return m_socket->peerAddress().toString();
}

void HubSession::send(const QJsonObject &message)
{
    m_socket->sendTextMessage(QString::fromUtf8(QJsonDocument(message).toJson(QJsonDocument::Compact)));
}

void HubSession::error(const QString &why)
{
    send({{QStringLiteral("op"), QStringLiteral("error")}, {QStringLiteral("why"), why}});
}

void HubSession::onText(const QString &text)
{
    if (text.size() > kMaxMessageBytes || text.toUtf8().size() > kMaxMessageBytes)
        return error(QStringLiteral("a message to the hub is at most %1 KiB").arg(kMaxMessageBytes / 1024));
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(text.toUtf8(), &parseError);
    if (!document.isObject())
        return error(document.isNull() ? QStringLiteral("not JSON: %1").arg(parseError.errorString())
                                       : QStringLiteral("a message to the hub is a JSON object with \"op\""));
    const QJsonObject message = document.object();
    const QString op = message.value(QLatin1String("op")).toString();
    if (op == QLatin1String("sign-in"))
        return signIn(message);
    static const QStringList known{QStringLiteral("subscribe"), QStringLiteral("unsubscribe"), QStringLiteral("publish"),
                                   QStringLiteral("running"), QStringLiteral("ended"), QStringLiteral("runs")};
    if (!known.contains(op))
        return error(op.isEmpty() ? QStringLiteral("a message to the hub names its \"op\"")
                                  : QStringLiteral("unknown op \"%1\"").arg(op.left(64)));
    if (m_state != State::SignedIn)
        return error(QStringLiteral("sign in first"));
    if (op == QLatin1String("publish"))
        return publish(message);
    if (op == QLatin1String("running"))
        return running(message);
    if (op == QLatin1String("ended"))
        return ended(message);
    if (op == QLatin1String("runs"))
        return sendRuns();
    const QString topic = message.value(QLatin1String("topic")).toString();
    if (!mqtt::MqttClient::isValidTopicFilter(topic))
        return error(QStringLiteral("\"topic\" must be an MQTT topic filter"));
    if (op == QLatin1String("subscribe"))
        m_mqtt->subscribe(topic);
    else
        m_mqtt->unsubscribe(topic);
}

void HubSession::signIn(const QJsonObject &message)
{
    if (m_state == State::SigningIn)
        return error(QStringLiteral("a sign-in is under way"));
    if (m_state == State::SignedIn)
        return error(QStringLiteral("already signed in as %1").arg(m_user));
    const QString user = message.value(QLatin1String("user")).toString();
    const QString password = message.value(QLatin1String("password")).toString();
    if (!mqtt::topics::isValidName(user) || password.isEmpty() || password.size() > kMaxPasswordChars)
        return error(QStringLiteral("sign-in takes \"user\" (an account's name) and \"password\""));
    const qint64 now = m_clock.elapsed();
    m_signIns.removeIf([now](qint64 at) { return now - at >= kMinuteMs; });
    if (m_signIns.size() >= kSignInsPerMinute) {
        hubLog(QStringLiteral("sign-in as %1 from %2 refused: too many attempts").arg(user, peer()));
        return refuse(QStringLiteral("too many sign-in attempts: try again in %1 s")
                          .arg((kMinuteMs - (now - m_signIns.first())) / 1000 + 1));
    }
    m_signIns.append(now);
    m_user = user;
    // Only people sign in here: a bridge's account would knock its bridge off the broker.
    if (!m_settings.classroom.isPerson(user)) {
        hubLog(QStringLiteral("sign-in as %1 from %2 refused: no such person in the classroom").arg(user, peer()));
        return refuse(QStringLiteral("wrong user name or password"));
    }
    mqtt::BrokerAddress address = m_settings.classroom.broker();
    address.username = user;
    address.password = password;
    m_state = State::SigningIn;
    const int attempt = ++m_attempt;
    m_mqtt = std::make_unique<mqtt::MqttClient>(user);
    m_mqtt->setMaxPayloadBytes(kMaxMessageBytes);
    connect(m_mqtt.get(), &mqtt::MqttClient::connected, this, &HubSession::signedIn);
    connect(m_mqtt.get(), &mqtt::MqttClient::loginRefused, this, [this] {
        hubLog(QStringLiteral("sign-in as %1 from %2 refused by the broker").arg(m_user, peer()));
        refuse(QStringLiteral("wrong user name or password"));
    });
    // Any other error before the broker accepts ends the sign-in, after a
    // refused login has had its say (loginRefused follows errorOccurred).
    connect(m_mqtt.get(), &mqtt::MqttClient::errorOccurred, this, [this, attempt](const QString &why) {
        QMetaObject::invokeMethod(this, [this, attempt, why] {
            if (m_state != State::SigningIn || attempt != m_attempt)
                return;
            hubLog(QStringLiteral("sign-in as %1 from %2: %3").arg(m_user, peer(), why));
            refuse(QStringLiteral("the classroom's broker did not let you in: %1")
                       .arg(QString(why).remove(QStringLiteral(" Still trying."))));
        }, Qt::QueuedConnection);
    });
    connect(m_mqtt.get(), &mqtt::MqttClient::disconnected, this, [this](const QString &why) {
        if (m_state != State::SignedIn)
            return;
        const QString reason = why.isEmpty() ? QStringLiteral("the broker ended the connection") : why;
        hubLog(QStringLiteral("%1's connection to the broker ended: %2").arg(m_user, reason));
        endMqtt(reason);
        send({{QStringLiteral("op"), QStringLiteral("broker-lost")}, {QStringLiteral("why"), reason}});
    });
    connect(m_mqtt.get(), &mqtt::MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload) {
                if (m_socket->bytesToWrite() > kMaxQueuedBytes) {
                    if (m_dropped++ % 1000 == 0)
                        hubLog(QStringLiteral("%1's page reads too slowly: %2 messages dropped").arg(m_user).arg(m_dropped));
                    return;
                }
                send({{QStringLiteral("op"), QStringLiteral("message")},
                      {QStringLiteral("topic"), topic},
                      {QStringLiteral("payload"), QString::fromUtf8(payload)}});
            });
    if (!m_mqtt->connectToBroker(address) && m_state == State::SigningIn)
        refuse(QStringLiteral("the hub cannot connect to the classroom's broker"));
}

void HubSession::dropMqtt()
{
    if (!m_mqtt)
        return;
    m_mqtt->disconnect(this);
    m_mqtt->disconnectFromBroker();
    // Later: this may be in one of its signals.
    m_mqtt.release()->deleteLater();
}

void HubSession::refuse(const QString &why)
{
    dropMqtt();
    m_state = State::SignedOut;
    send({{QStringLiteral("op"), QStringLiteral("refused")}, {QStringLiteral("why"), why}});
}

void HubSession::signedIn()
{
    if (m_state != State::SigningIn)
        return;
    m_state = State::SignedIn;
    hubLog(QStringLiteral("%1 signed in from %2").arg(m_user, peer()));
    send({{QStringLiteral("op"), QStringLiteral("signed-in")},
          {QStringLiteral("user"), m_user},
          {QStringLiteral("robots"), QJsonArray::fromStringList(m_settings.classroom.robotsFor(m_user))},
          {QStringLiteral("blocks"), QJsonArray::fromStringList(m_settings.blocks)},
          {QStringLiteral("protocol"), m_settings.protocol}});
    if (m_user == m_settings.classroom.teacher())
        connect(&m_runs, &RunTable::changed, this, &HubSession::sendRuns);
}

void HubSession::endMqtt(const QString &why)
{
    m_runs.disconnect(this);
    m_runs.endAll(this, why);
    if (m_state == State::SignedIn)
        hubLog(QStringLiteral("%1 signed out (%2)").arg(m_user, why));
    dropMqtt();
    m_state = State::SignedOut;
}

void HubSession::publish(const QJsonObject &message)
{
    const QString topic = message.value(QLatin1String("topic")).toString();
    const QJsonValue payload = message.value(QLatin1String("payload"));
    const QJsonValue qos = message.value(QLatin1String("qos"));
    const QJsonValue retain = message.value(QLatin1String("retain"));
    if (!mqtt::MqttClient::isValidTopic(topic))
        return error(QStringLiteral("\"topic\" must be an MQTT topic, without wildcards"));
    if (!payload.isString())
        return error(QStringLiteral("\"payload\" must be text"));
    if (!qos.isUndefined() && qos != QJsonValue(0) && qos != QJsonValue(1))
        return error(QStringLiteral("\"qos\" must be 0 or 1"));
    if (!retain.isUndefined() && !retain.isBool())
        return error(QStringLiteral("\"retain\" must be true or false"));
    const QByteArray bytes = payload.toString().toUtf8();
    // A packet over the broker's limit would cost the student the connection.
    const int max = m_settings.classroom.maxPacketBytes();
    if (max > 0 && bytes.size() + topic.toUtf8().size() + 16 > max)
        return error(QStringLiteral("too big for the classroom's broker: a message is at most %1 bytes").arg(max - 16));
    if (!m_mqtt->publish(topic, bytes, qos.toInt(0), retain.toBool(false)))
        error(QStringLiteral("the broker connection cannot take it now"));
}

void HubSession::running(const QJsonObject &message)
{
    const QString robot = message.value(QLatin1String("robot")).toString();
    const QJsonValue program = message.value(QLatin1String("program"));
    if (!program.isString())
        return error(QStringLiteral("\"program\" must be the program's text"));
    if (!m_settings.classroom.robotsFor(m_user).contains(robot))
        return error(QStringLiteral("\"robot\" must be a robot you may drive"));
    m_runs.running(this, m_user, robot, program.toString());
}

void HubSession::ended(const QJsonObject &message)
{
    const QString robot = message.value(QLatin1String("robot")).toString();
    QString why = message.value(QLatin1String("why")).toString().simplified();
    if (why.size() > kMaxWhyChars)
        why = why.left(kMaxWhyChars - 1) + QChar(0x2026);
    if (!m_runs.ended(m_user, robot, why.isEmpty() ? QStringLiteral("(no reason given)") : why))
        error(QStringLiteral("you run nothing on \"%1\"").arg(robot.left(64)));
}

void HubSession::sendRuns()
{
    if (m_user != m_settings.classroom.teacher())
        return error(QStringLiteral("only the teacher sees who runs what"));
    send({{QStringLiteral("op"), QStringLiteral("runs")}, {QStringLiteral("runs"), m_runs.toJson()}});
}

} // namespace classroom
