// SPDX-License-Identifier: GPL-3.0-or-later
// The classroom protocol's table (protocol/mqtt/classroom_protocol.json) as
// the bridge and the dashboard are built from it: every goal command of the
// file is one the bridge takes, refuses each field just past its range with
// the file's range and unit, and plans a move's time as the Python library
// does on the same examples (python/tests/test_protocol.py).

#include "classroom_protocol.h"
#include "fleet_directory.h"
#include "goal_command.h"
#include "motion_goal.h"
#include "network_transport.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

// The dashboard's heartbeat and its wait before a last will (protocol/classroom)
// are the table's.
static_assert(NetworkTransport::kHeartbeatMs == classroom::kHeartbeatMs);
static_assert(FleetDirectory::kWillGraceMs == classroom::kWillGraceMs);

namespace {

QJsonObject table()
{
    QFile file(QStringLiteral(ROOMBA_CLASSROOM_PROTOCOL_JSON));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", ROOMBA_CLASSROOM_PROTOCOL_JSON);
    return QJsonDocument::fromJson(file.readAll()).object();
}

mqtt::CommandMessage goalMessage(const QString &command, const QJsonObject &fields)
{
    mqtt::CommandMessage m;
    m.command = command;
    m.fields = fields;
    return m;
}

// Every field of `row` at the middle of its range.
QJsonObject middleFields(const QJsonObject &row)
{
    QJsonObject fields;
    for (const QJsonValue f : row.value(QLatin1String("fields")).toArray()) {
        const QJsonObject o = f.toObject();
        fields.insert(o.value(QLatin1String("field")).toString(),
                      (o.value(QLatin1String("min")).toDouble() + o.value(QLatin1String("max")).toDouble()) / 2);
    }
    return fields;
}

} // namespace

class TestClassroomProtocol : public QObject {
    Q_OBJECT
private slots:
    void theBridgeTakesEveryGoalCommandOfTheFile()
    {
        const QJsonArray rows = table().value(QLatin1String("goal_commands")).toArray();
        QCOMPARE(rows.size(), qsizetype(std::size(classroom::kGoalCommands)));
        for (const QJsonValue r : rows) {
            const QString command = r.toObject().value(QLatin1String("command")).toString();
            QVERIFY2(isGoalCommand(command), qPrintable(command));
            QString error;
            QVERIFY2(goalFromMessage(goalMessage(command, middleFields(r.toObject())), &error), qPrintable(error));
        }
        QVERIFY(!isGoalCommand(QStringLiteral("drive")));
    }

    void eachFieldJustPastItsRangeIsRefusedWithTheFilesRange()
    {
        for (const QJsonValue r : table().value(QLatin1String("goal_commands")).toArray()) {
            const QString command = r.toObject().value(QLatin1String("command")).toString();
            for (const QJsonValue f : r.toObject().value(QLatin1String("fields")).toArray()) {
                const QJsonObject o = f.toObject();
                const QString field = o.value(QLatin1String("field")).toString();
                const double min = o.value(QLatin1String("min")).toDouble(), max = o.value(QLatin1String("max")).toDouble();
                for (const double wrong : {min - 1, max + 1}) {
                    QJsonObject fields = middleFields(r.toObject());
                    fields.insert(field, wrong);
                    QString error;
                    QVERIFY(!goalFromMessage(goalMessage(command, fields), &error));
                    const QString expected = QStringLiteral("%1: %2 is outside %3..%4 %5")
                                                 .arg(field)
                                                 .arg(wrong)
                                                 .arg(min)
                                                 .arg(max)
                                                 .arg(o.value(QLatin1String("unit")).toString());
                    QCOMPARE(error, expected);
                }
            }
        }
    }

    void aMoveTakesTheTimeTheFileGivesForIt()
    {
        for (const QJsonValue e : table().value(QLatin1String("move_time_examples")).toArray()) {
            const QJsonObject example = e.toObject();
            QString error;
            const std::optional<MotionGoal> goal =
                goalFromMessage(goalMessage(example.value(QLatin1String("command")).toString(),
                                            example.value(QLatin1String("fields")).toObject()),
                                &error);
            QVERIFY2(goal, qPrintable(error));
            const double seconds = example.value(QLatin1String("kinematic_seconds")).toDouble();
            QVERIFY2(std::abs(goal->kinematicSeconds() - seconds) < 1e-3,
                     qPrintable(QStringLiteral("%1 s, not %2").arg(goal->kinematicSeconds()).arg(seconds)));
            QCOMPARE(goal->timeLimitSeconds(),
                     classroom::kTimeLimitFactor * goal->kinematicSeconds() + classroom::kTimeLimitExtraS);
        }
    }
};

QTEST_GUILESS_MAIN(TestClassroomProtocol)
#include "tst_classroom_protocol.moc"
