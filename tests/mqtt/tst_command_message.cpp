// SPDX-License-Identifier: GPL-3.0-or-later
// The command message of docs/mqtt.md, without a broker: every typed command
// survives its JSON form, both versions read into the same typed command,
// and each bad message is refused with an error naming what is wrong.

#include "command_catalog.h"
#include "command_message.h"

#include <QJsonDocument>
#include <QTest>

Q_DECLARE_METATYPE(oi::OiCommand)

namespace {

QByteArray json(const QJsonObject &o) { return QJsonDocument(o).toJson(QJsonDocument::Compact); }

// Reads a payload into a typed command for a Create 2, or says why not.
std::optional<oi::OiCommand> read(const QByteArray &payload, QString *error, QString *id = nullptr,
                                  const oi::RobotProfile &profile = oi::profile(oi::ProfileId::Create2))
{
    QString gotId;
    const std::optional<mqtt::CommandMessage> m = mqtt::CommandMessage::fromJson(payload, &gotId, error);
    if (id)
        *id = gotId;
    return m ? m->toCommand(profile, error) : std::nullopt;
}

} // namespace

class TestCommandMessage : public QObject {
    Q_OBJECT

private slots:
    // Field values need not be in range here: ranges are the encoder's.
    void everyCommandSurvivesItsMessage()
    {
        for (const oi::CommandSpec &spec : oi::allCommandSpecs()) {
            oi::OiCommand command{spec.command, {}, {}};
            for (std::size_t i = 0; i < oi::commandFieldNames(spec.command).size(); ++i)
                command.fields.push_back(int(i) * 37 - 20);
            if (spec.layout == "*")
                command.data = {7, 0, 255};
            const QJsonObject message = mqtt::commandToJson(command, QStringLiteral("9"));
            QCOMPARE(message.value(QLatin1String("v")).toInt(), mqtt::kCommandVersion);
            QCOMPARE(message.value(QLatin1String("command")).toString().toStdString(), std::string(spec.name));
            QString error, id;
            const std::optional<oi::OiCommand> back = read(json(message), &error, &id);
            QVERIFY2(back, qPrintable(QString::fromUtf8(spec.name.data(), qsizetype(spec.name.size())) + ": " + error));
            QVERIFY2(*back == command, spec.name.data());
            QCOMPARE(id, QStringLiteral("9"));
        }
        // As written on the wire.
        const oi::OiCommand drive{oi::Command::DriveDirect, {200, -150}, {}};
        QCOMPARE(json(mqtt::commandToJson(drive, QStringLiteral("3"))),
                 QByteArray(R"({"command":"drive-direct","fields":{"left-velocity":-150,"right-velocity":200},"id":"3","v":2})"));
    }

    void messages_data()
    {
        QTest::addColumn<QByteArray>("payload");
        QTest::addColumn<QString>("id");
        QTest::addColumn<oi::OiCommand>("command");
        QTest::addColumn<QString>("error");
        using C = oi::Command;
        const oi::OiCommand none;
        // Version 2: the typed form.
        QTest::newRow("v2 drive-direct")
            << QByteArray(R"({"v":2,"id":"17","command":"drive-direct","fields":{"right-velocity":200,"left-velocity":150}})")
            << "17" << oi::OiCommand{C::DriveDirect, {200, 150}, {}} << "";
        QTest::newRow("v2 song") << QByteArray(R"({"v":2,"command":"song","fields":{"song-number":1},"data":[60,32,62,16]})")
                                 << "" << oi::OiCommand{C::Song, {1}, {60, 32, 62, 16}} << "";
        QTest::newRow("v2 no fields") << QByteArray(R"({"v":2,"id":5,"command":"safe"})") << "5"
                                      << oi::OiCommand{C::Safe, {}, {}} << "";
        QTest::newRow("v2 unknown command") << QByteArray(R"({"v":2,"id":"1","command":"fly"})") << "1" << none
                                            << "\"fly\" is not a command";
        QTest::newRow("v2 unknown field")
            << QByteArray(R"({"v":2,"command":"drive","fields":{"speed":100,"radius":0}})") << "" << none
            << "drive has no field \"speed\": its fields are velocity, radius";
        QTest::newRow("v2 field of a command without") << QByteArray(R"({"v":2,"command":"safe","fields":{"x":1}})")
                                                       << "" << none << "safe has no fields, so not \"x\"";
        QTest::newRow("v2 missing field") << QByteArray(R"({"v":2,"command":"drive","fields":{"velocity":100}})") << ""
                                          << none << "drive needs \"radius\"";
        QTest::newRow("v2 word") << QByteArray(R"({"v":2,"command":"drive","fields":{"velocity":"fast","radius":0}})")
                                 << "" << none << "\"velocity\" must be a whole number, not \"fast\"";
        QTest::newRow("v2 fraction") << QByteArray(R"({"v":2,"command":"drive","fields":{"velocity":1.5,"radius":0}})")
                                     << "" << none << "\"velocity\" must be a whole number, not 1.5";
        QTest::newRow("v2 fields a list") << QByteArray(R"({"v":2,"command":"drive","fields":[100,0]})") << "" << none
                                          << "\"fields\" must be an object";
        QTest::newRow("v2 data where none") << QByteArray(R"({"v":2,"command":"safe","data":[1]})") << "" << none
                                            << "safe has no \"data\"";
        QTest::newRow("v2 data not a byte")
            << QByteArray(R"({"v":2,"command":"stream","data":[7,300]})") << "" << none
            << "\"data\" item 2 must be a byte from 0 to 255, not 300";
        QTest::newRow("v2 args") << QByteArray(R"({"v":2,"command":"drive","args":[100,0]})") << "" << none
                                 << "\"args\" is the text form of version 1";
        QTest::newRow("version 3") << QByteArray(R"({"v":3,"id":"4","command":"safe"})") << "4" << none
                                   << "\"v\" is 3: this bridge reads command messages of version 1 and 2";
        QTest::newRow("version as text") << QByteArray(R"({"v":"2","command":"safe"})") << "" << none
                                         << "\"v\" is \"2\"";
        // Version 1: the text form, read by the same text encoder as
        // `roomba-ctl encode` and scripts, into the same typed command.
        QTest::newRow("v1 drive") << QByteArray(R"({"id":"17","command":"drive","args":[200,"straight"]})") << "17"
                                  << oi::OiCommand{C::Drive, {200, oi::kRadiusStraight}, {}} << "";
        QTest::newRow("v1 song") << QByteArray(R"({"command":"song","args":[1,"C4:32","D4:16"]})") << ""
                                 << oi::OiCommand{C::Song, {1}, {60, 32, 62, 16}} << "";
        QTest::newRow("v1 no args") << QByteArray(R"({"command":"safe"})") << "" << oi::OiCommand{C::Safe, {}, {}} << "";
        QTest::newRow("v1 numeric id") << QByteArray(R"({"id":5,"command":"safe"})") << "5"
                                       << oi::OiCommand{C::Safe, {}, {}} << "";
        QTest::newRow("v1 negative") << QByteArray(R"({"command":"drive-direct","args":[-500,500]})") << ""
                                     << oi::OiCommand{C::DriveDirect, {-500, 500}, {}} << "";
        QTest::newRow("v1 out of range") << QByteArray(R"({"command":"drive","args":[900,0]})") << "" << none
                                         << "velocity";
        QTest::newRow("v1 fraction") << QByteArray(R"({"command":"drive","args":[1.5,0]})") << "" << none << "1.5";
        QTest::newRow("v1 unknown") << QByteArray(R"({"command":"fly"})") << "" << none << "'fly' is not a command";
        QTest::newRow("v1 fields") << QByteArray(R"({"command":"drive","fields":{"velocity":1,"radius":0}})") << ""
                                   << none << "\"fields\" is for version 2 messages: add \"v\": 2";
        QTest::newRow("not json") << QByteArray("drive 200 0") << "" << none << "not JSON";
        QTest::newRow("array") << QByteArray("[1]") << "" << none << "not a JSON object";
        QTest::newRow("no command") << QByteArray(R"({"id":"1"})") << "1" << none << "\"command\"";
        QTest::newRow("args not a list") << QByteArray(R"({"id":"2","command":"drive","args":"200 0"})") << "2" << none
                                         << "\"args\"";
        QTest::newRow("object arg") << QByteArray(R"({"command":"drive","args":[{},0]})") << "" << none << "argument 1";
    }
    void messages()
    {
        QFETCH(QByteArray, payload);
        QFETCH(QString, id);
        QFETCH(oi::OiCommand, command);
        QFETCH(QString, error);
        QString gotId, gotError;
        const std::optional<oi::OiCommand> got = read(payload, &gotError, &gotId);
        QCOMPARE(gotId, id);
        QVERIFY2(got.has_value() == error.isEmpty(), qPrintable(gotError));
        if (got)
            QVERIFY(*got == command);
        else
            QVERIFY2(gotError.contains(error), qPrintable(gotError));
    }

    // "stop" in either version is the bridge's stop, on any profile (the
    // Create has no OI Stop).
    void stopIsTheBridgesStop()
    {
        for (const QByteArray &payload : {QByteArray(R"({"command":"stop"})"), QByteArray(R"({"v":2,"command":"stop"})"),
                                         json(mqtt::commandToJson(oi::OiCommand{oi::Command::Stop, {}, {}}, {}))}) {
            QString id, error;
            const auto m = mqtt::CommandMessage::fromJson(payload, &id, &error);
            QVERIFY2(m, qPrintable(error));
            QVERIFY(m->isStop());
        }
        QString id, error;
        QVERIFY(!mqtt::CommandMessage::fromJson(R"({"v":2,"command":"drive"})", &id, &error)->isStop());
    }

    // A value the message takes is still judged by the encoder, which
    // names the field.
    void rangesAreTheEncoders()
    {
        QString error;
        const auto drive = read(R"({"v":2,"command":"drive","fields":{"velocity":900,"radius":0}})", &error);
        QVERIFY2(drive, qPrintable(error));
        const oi::EncodeResult bytes = oi::encodeCommand(oi::CommandEncoder(oi::profile(oi::ProfileId::Create2)), *drive);
        QVERIFY(!bytes);
        QVERIFY2(bytes.error().describe().find("velocity") != std::string::npos, bytes.error().describe().c_str());
    }
};

QTEST_GUILESS_MAIN(TestCommandMessage)
#include "tst_command_message.moc"
