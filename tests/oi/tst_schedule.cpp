// SPDX-License-Identifier: GPL-3.0-or-later
#include "schedule.h"

#include <QTest>

#include <vector>

namespace oi {
// Lets QCOMPARE print a schedule that differs.
char *toString(const CleaningSchedule &schedule)
{
    return qstrdup(formatSchedule(schedule).c_str());
}
} // namespace oi

using namespace oi;

namespace {

QString qs(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QByteArray toByteArray(const std::array<std::uint8_t, 15> &bytes)
{
    return QByteArray(reinterpret_cast<const char *>(bytes.data()), static_cast<qsizetype>(bytes.size()));
}

QByteArray bytesOf(std::initializer_list<int> values)
{
    QByteArray out;
    for (int v : values)
        out.append(static_cast<char>(v));
    return out;
}

Result<CleaningSchedule> fromByteArray(const QByteArray &bytes)
{
    return scheduleFromBytes(std::span(reinterpret_cast<const std::uint8_t *>(bytes.constData()),
                                       static_cast<std::size_t>(bytes.size())));
}

// The document's example: 3:00 PM Wednesday and 10:36 AM Friday.
CleaningSchedule documentExample()
{
    CleaningSchedule schedule;
    schedule.days[static_cast<std::size_t>(Weekday::Wednesday)] = ClockTime{15, 0};
    schedule.days[static_cast<std::size_t>(Weekday::Friday)] = ClockTime{10, 36};
    return schedule;
}

} // namespace

class TestSchedule : public QObject {
    Q_OBJECT
private slots:
    void weekdayNames_data()
    {
        QTest::addColumn<int>("day");
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("shortName");
        QTest::newRow("0") << 0 << "Sunday" << "sun";
        QTest::newRow("1") << 1 << "Monday" << "mon";
        QTest::newRow("2") << 2 << "Tuesday" << "tue";
        QTest::newRow("3") << 3 << "Wednesday" << "wed";
        QTest::newRow("4") << 4 << "Thursday" << "thu";
        QTest::newRow("5") << 5 << "Friday" << "fri";
        QTest::newRow("6") << 6 << "Saturday" << "sat";
    }
    void weekdayNames()
    {
        QFETCH(int, day);
        QFETCH(QString, name);
        QFETCH(QString, shortName);
        const auto weekday = static_cast<Weekday>(day);
        QCOMPARE(qs(weekdayName(weekday)), name);
        QCOMPARE(qs(weekdayShortName(weekday)), shortName);
        // Every spelling reads back.
        QCOMPARE(static_cast<int>(parseWeekday(name.toStdString()).value_or(Weekday(99))), day);
        QCOMPARE(static_cast<int>(parseWeekday(shortName.toStdString()).value_or(Weekday(99))), day);
        QCOMPARE(static_cast<int>(parseWeekday(shortName.left(2).toUpper().toStdString()).value_or(Weekday(99))),
                 day);
        QCOMPARE(static_cast<int>(parseWeekday(QString::number(day).toStdString()).value_or(Weekday(99))), day);
    }

    void parseWeekdaySpellings_data()
    {
        // -1 stands for "refused".
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("day");
        QTest::newRow("full lower") << "wednesday" << 3;
        QTest::newRow("full upper") << "FRIDAY" << 5;
        QTest::newRow("short mixed") << "Thu" << 4;
        QTest::newRow("two letters") << "sa" << 6;
        QTest::newRow("two letters mixed") << "Tu" << 2;
        QTest::newRow("padded") << " mon " << 1;
        QTest::newRow("digit 7") << "7" << -1;
        QTest::newRow("negative") << "-1" << -1;
        QTest::newRow("two digits") << "03" << -1;
        QTest::newRow("empty") << "" << -1;
        QTest::newRow("one letter") << "s" << -1;
        QTest::newRow("four letters") << "wedn" << -1;
        QTest::newRow("plural") << "sundays" << -1;
        QTest::newRow("junk") << "xyz" << -1;
    }
    void parseWeekdaySpellings()
    {
        QFETCH(QString, text);
        QFETCH(int, day);
        const std::optional<Weekday> parsed = parseWeekday(text.toStdString());
        QCOMPARE(parsed ? static_cast<int>(*parsed) : -1, day);
    }

    void parseClockTimeValid_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("hour");
        QTest::addColumn<int>("minute");
        QTest::newRow("HH:MM") << "15:00" << 15 << 0;
        QTest::newRow("H:MM") << "9:05" << 9 << 5;
        QTest::newRow("leading zero") << "09:05" << 9 << 5;
        QTest::newRow("midnight") << "0:00" << 0 << 0;
        QTest::newRow("last minute") << "23:59" << 23 << 59;
        QTest::newRow("whole hour") << "15" << 15 << 0;
        QTest::newRow("whole hour one digit") << "7" << 7 << 0;
        QTest::newRow("padded") << " 10:36 " << 10 << 36;
    }
    void parseClockTimeValid()
    {
        QFETCH(QString, text);
        QFETCH(int, hour);
        QFETCH(int, minute);
        const Result<ClockTime> time = parseClockTime(text.toStdString());
        QVERIFY2(time.ok(), time.error().describe().c_str());
        QCOMPARE(time->hour, hour);
        QCOMPARE(time->minute, minute);
    }

    void parseClockTimeErrors_data()
    {
        // value is -1 when the error has no range.
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("field");
        QTest::addColumn<qlonglong>("value");
        QTest::newRow("empty") << "" << "time" << -1LL;
        QTest::newRow("blank") << "   " << "time" << -1LL;
        QTest::newRow("seconds") << "12:00:00" << "time" << -1LL;
        QTest::newRow("24:00") << "24:00" << "hour" << 24LL;
        QTest::newRow("hour 99") << "99" << "hour" << 99LL;
        QTest::newRow("junk") << "noon" << "hour" << -1LL;
        QTest::newRow("no hour") << ":30" << "hour" << -1LL;
        QTest::newRow("three-digit hour") << "123:00" << "hour" << -1LL;
        QTest::newRow("negative hour") << "-1:00" << "hour" << -1LL;
        QTest::newRow("12:60") << "12:60" << "minute" << 60LL;
        QTest::newRow("minute 99") << "12:99" << "minute" << 99LL;
        QTest::newRow("one-digit minute") << "9:5" << "minute" << -1LL;
        QTest::newRow("three-digit minute") << "9:005" << "minute" << -1LL;
        QTest::newRow("no minute") << "9:" << "minute" << -1LL;
        QTest::newRow("junk minute") << "9:x5" << "minute" << -1LL;
    }
    void parseClockTimeErrors()
    {
        QFETCH(QString, text);
        QFETCH(QString, field);
        QFETCH(qlonglong, value);
        const Result<ClockTime> time = parseClockTime(text.toStdString());
        QVERIFY(!time.ok());
        const OiError &error = time.error();
        QCOMPARE(qs(error.field), field);
        QVERIFY(qs(error.describe()).startsWith(field + ": "));
        if (value < 0) {
            QVERIFY(!error.value.has_value());
            QVERIFY(!error.message.empty());
        } else {
            QCOMPARE(error.value.value_or(-1), value);
            QCOMPARE(error.min.value_or(-1), 0LL);
            QCOMPARE(error.max.value_or(-1), field == "hour" ? 23LL : 59LL);
        }
    }

    void formatClockTimeIsTwoDigit_data()
    {
        QTest::addColumn<int>("hour");
        QTest::addColumn<int>("minute");
        QTest::addColumn<QString>("text");
        QTest::newRow("midnight") << 0 << 0 << "00:00";
        QTest::newRow("morning") << 9 << 5 << "09:05";
        QTest::newRow("afternoon") << 15 << 0 << "15:00";
        QTest::newRow("last") << 23 << 59 << "23:59";
    }
    void formatClockTimeIsTwoDigit()
    {
        QFETCH(int, hour);
        QFETCH(int, minute);
        QFETCH(QString, text);
        QCOMPARE(QString::fromStdString(formatClockTime({hour, minute})), text);
        QCOMPARE(*parseClockTime(text.toStdString()), (ClockTime{hour, minute}));
    }

    void parseScheduleSpellings_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("formatted");
        QTest::newRow("example") << "wed 15:00, fri 10:36" << "wed 15:00, fri 10:36";
        QTest::newRow("equals") << "wed=15:00 fri=10:36" << "wed 15:00, fri 10:36";
        QTest::newRow("equals and comma") << "wed=15:00,fri=10:36" << "wed 15:00, fri 10:36";
        QTest::newRow("spaced equals") << "wed = 15:00, fri = 10:36" << "wed 15:00, fri 10:36";
        QTest::newRow("full names") << "Wednesday 15:00, Friday 10:36" << "wed 15:00, fri 10:36";
        QTest::newRow("out of order") << "fri 10:36 wed 15" << "wed 15:00, fri 10:36";
        QTest::newRow("digits") << "3 15:00, 5 10:36" << "wed 15:00, fri 10:36";
        QTest::newRow("two letters") << "WE 15:00 FR 10:36" << "wed 15:00, fri 10:36";
        QTest::newRow("week ends") << "sat 9:30, sun 8:00" << "sun 08:00, sat 09:30";
        QTest::newRow("off") << "off" << "off";
        QTest::newRow("OFF padded") << "  OFF " << "off";
        QTest::newRow("every day") << "sun 0:00 mon 1:01 tue 2:02 wed 3:03 thu 4:04 fri 5:05 sat 23:59"
                                   << "sun 00:00, mon 01:01, tue 02:02, wed 03:03, thu 04:04, fri 05:05, sat 23:59";
    }
    void parseScheduleSpellings()
    {
        QFETCH(QString, text);
        QFETCH(QString, formatted);
        const Result<CleaningSchedule> schedule = parseSchedule(text.toStdString());
        QVERIFY2(schedule.ok(), schedule.error().describe().c_str());
        QCOMPARE(QString::fromStdString(formatSchedule(*schedule)), formatted);
        // The formatted text reads back to the same schedule.
        const Result<CleaningSchedule> again = parseSchedule(formatted.toStdString());
        QVERIFY2(again.ok(), again.error().describe().c_str());
        QCOMPARE(*again, *schedule);
    }

    void parseExampleFields()
    {
        const Result<CleaningSchedule> schedule = parseSchedule("wed 15:00, fri 10:36");
        QVERIFY2(schedule.ok(), schedule.error().describe().c_str());
        QCOMPARE(*schedule, documentExample());
        QCOMPARE(int(schedule->dayBits()), 40);
        QVERIFY(!schedule->isOff());
        QVERIFY(!schedule->days[0].has_value());

        const Result<CleaningSchedule> off = parseSchedule("off");
        QVERIFY(off.ok());
        QCOMPARE(*off, CleaningSchedule{});
        QVERIFY(off->isOff());
        QCOMPARE(int(off->dayBits()), 0);
    }

    void parseScheduleErrors_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("describe");
        QTest::newRow("empty") << "" << "schedule"
                               << "schedule: is empty; write \"off\" or entries such as \"wed 15:00, fri 10:36\"";
        QTest::newRow("blank") << "  " << "schedule"
                               << "schedule: is empty; write \"off\" or entries such as \"wed 15:00, fri 10:36\"";
        QTest::newRow("day twice") << "wed 15:00, fri 10:36, Wednesday 16:00" << "wed"
                                   << "wed: Wednesday is named twice";
        QTest::newRow("unknown day") << "wed 15:00, xyz 10:00" << "day"
                                     << "day: \"xyz\" is not a weekday; use e.g. wed, Wednesday, we or 3";
        QTest::newRow("off and more") << "off wed 15:00" << "day"
                                      << "day: \"off\" is not a weekday; use e.g. wed, Wednesday, we or 3";
        QTest::newRow("time first") << "15:00 wed" << "day"
                                    << "day: \"15:00\" is not a weekday; use e.g. wed, Wednesday, we or 3";
        QTest::newRow("no time") << "wed" << "wed" << "wed: has no time; write e.g. \"wed 15:00\"";
        QTest::newRow("last has no time") << "wed 15:00, fri" << "fri" << "fri: has no time; write e.g. \"fri 15:00\"";
        QTest::newRow("equals without time") << "wed=" << "wed" << "wed: has no time; write e.g. \"wed 15:00\"";
        QTest::newRow("hour 24") << "wed 24:00" << "wed hour" << "wed hour: 24 is outside 0..23";
        QTest::newRow("minute 60") << "fri 10:60" << "fri minute" << "fri minute: 60 is outside 0..59";
        QTest::newRow("one-digit minute") << "sat 9:5" << "sat minute"
                                          << "sat minute: \"5\" is not a minute; use two digits 00..59";
        QTest::newRow("seconds") << "sun 9:00:00" << "sun time"
                                 << "sun time: \"9:00:00\" has more than one ':'; use H:MM or HH:MM";
        QTest::newRow("junk hour") << "mon noon" << "mon hour"
                                   << "mon hour: \"noon\" is not an hour; use one or two digits 0..23";
    }
    void parseScheduleErrors()
    {
        QFETCH(QString, text);
        QFETCH(QString, field);
        QFETCH(QString, describe);
        const Result<CleaningSchedule> schedule = parseSchedule(text.toStdString());
        QVERIFY(!schedule.ok());
        QCOMPARE(QString::fromStdString(schedule.error().field), field);
        QCOMPARE(QString::fromStdString(schedule.error().describe()), describe);
    }

    void formatOff()
    {
        QCOMPARE(QString::fromStdString(formatSchedule(CleaningSchedule{})), QStringLiteral("off"));
        QCOMPARE(QString::fromStdString(formatSchedule(documentExample())), QStringLiteral("wed 15:00, fri 10:36"));
    }

    void scheduleBytesFromText_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("document example")
            << "wed 15:00, fri 10:36" << bytesOf({40, 0, 0, 0, 0, 0, 0, 15, 0, 0, 0, 10, 36, 0, 0});
        QTest::newRow("off is all zeros") << "off" << bytesOf({0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
        QTest::newRow("sunday midnight") << "sun 0:00" << bytesOf({1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
        QTest::newRow("saturday") << "sat 23:59" << bytesOf({64, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 23, 59});
        QTest::newRow("every day")
            << "sun 1:02 mon 3:04 tue 5:06 wed 7:08 thu 9:10 fri 11:12 sat 13:14"
            << bytesOf({127, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14});
    }
    void scheduleBytesFromText()
    {
        QFETCH(QString, text);
        QFETCH(QByteArray, bytes);
        const Result<CleaningSchedule> schedule = parseSchedule(text.toStdString());
        QVERIFY2(schedule.ok(), schedule.error().describe().c_str());
        QCOMPARE(toByteArray(scheduleBytes(*schedule)), bytes);
        // And back.
        const Result<CleaningSchedule> decoded = fromByteArray(bytes);
        QVERIFY2(decoded.ok(), decoded.error().describe().c_str());
        QCOMPARE(*decoded, *schedule);
    }

    void bytesOfClearDaysAreIgnored()
    {
        // Monday's bit is clear, so its 9:30 is not a cleaning time.
        const Result<CleaningSchedule> decoded =
            fromByteArray(bytesOf({8, 0, 0, 9, 30, 0, 0, 15, 0, 0, 0, 99, 99, 0, 0}));
        QVERIFY2(decoded.ok(), decoded.error().describe().c_str());
        QCOMPARE(QString::fromStdString(formatSchedule(*decoded)), QStringLiteral("wed 15:00"));
        QVERIFY(!decoded->days[static_cast<std::size_t>(Weekday::Monday)].has_value());
    }

    void scheduleFromBytesErrors_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("describe");
        QTest::newRow("none") << QByteArray() << "schedule: needs exactly 15 bytes, got 0";
        QTest::newRow("14 bytes") << bytesOf({40, 0, 0, 0, 0, 0, 0, 15, 0, 0, 0, 10, 36, 0})
                                  << "schedule: needs exactly 15 bytes, got 14";
        QTest::newRow("16 bytes") << bytesOf({40, 0, 0, 0, 0, 0, 0, 15, 0, 0, 0, 10, 36, 0, 0, 0})
                                  << "schedule: needs exactly 15 bytes, got 16";
        QTest::newRow("reserved bit") << bytesOf({128 + 40, 0, 0, 0, 0, 0, 0, 15, 0, 0, 0, 10, 36, 0, 0})
                                      << "days: bit 7 is reserved and must be 0, got 168";
        QTest::newRow("wednesday hour 24") << bytesOf({40, 0, 0, 0, 0, 0, 0, 24, 0, 0, 0, 10, 36, 0, 0})
                                           << "wed hour: 24 is outside 0..23";
        QTest::newRow("friday minute 60") << bytesOf({40, 0, 0, 0, 0, 0, 0, 15, 0, 0, 0, 10, 60, 0, 0})
                                          << "fri minute: 60 is outside 0..59";
        QTest::newRow("saturday hour 255") << bytesOf({64, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 255, 0})
                                           << "sat hour: 255 is outside 0..23";
    }
    void scheduleFromBytesErrors()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, describe);
        const Result<CleaningSchedule> decoded = fromByteArray(bytes);
        QVERIFY(!decoded.ok());
        QCOMPARE(QString::fromStdString(decoded.error().describe()), describe);
    }

    void rangeErrorsCarryTheRange()
    {
        const OiError error = fromByteArray(bytesOf({40, 0, 0, 0, 0, 0, 0, 24, 0, 0, 0, 10, 36, 0, 0})).error();
        QCOMPARE(QString::fromStdString(error.field), QStringLiteral("wed hour"));
        QCOMPARE(error.value.value_or(-1), 24LL);
        QCOMPARE(error.min.value_or(-1), 0LL);
        QCOMPARE(error.max.value_or(-1), 23LL);
    }
};

QTEST_GUILESS_MAIN(TestSchedule)
#include "tst_schedule.moc"
