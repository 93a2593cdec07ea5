// SPDX-License-Identifier: GPL-3.0-or-later
#include "pseudo_translation.h"
#include "schedule_editor.h"
#include "typed_command_bytes.h"
#include "sensor_scenes.h"

#include <QApplication>
#include <QCheckBox>
#include <QGroupBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QTimeEdit>

using namespace oi;

namespace {

QByteArray bytes(std::initializer_list<int> values)
{
    QByteArray out;
    for (int v : values)
        out.append(static_cast<char>(v));
    return out;
}

// Saturday 21 November 2026, 18:30 local time.
QDateTime saturdayEvening() { return QDateTime(QDate(2026, 11, 21), QTime(18, 30)); }

} // namespace

class TstScheduleEditor : public QObject {
    Q_OBJECT

    template <typename T>
    static T *child(ScheduleEditor &editor, const QString &name)
    {
        auto *w = editor.findChild<T *>(name);
        if (!w)
            qFatal("no child %s", qPrintable(name));
        return w;
    }

    static void show(ScheduleEditor &editor)
    {
        editor.resize(editor.sizeHint());
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
    }

    // Ticks a day and sets its time through the grid's own widgets.
    static void plan(ScheduleEditor &editor, int day, QTime time)
    {
        QTest::mouseClick(child<QCheckBox>(editor, QString("day%1").arg(day)), Qt::LeftButton);
        child<QTimeEdit>(editor, QString("time%1").arg(day))->setTime(time);
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("RoombaDashboardTests");
        QCoreApplication::setApplicationName("tst_schedule_editor");
        QVERIFY(QSettings().fileName().contains(".qttest"));
    }

    void init()
    {
        QSettings().clear();
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedKingdom)); // 24-hour
    }

    void cleanupTestCase() { QLocale::setDefault(QLocale::system()); }

    void documentExample()
    {
        ScheduleEditor editor;
        editor.setProfile(profile(ProfileId::Roomba500));
        editor.setClock(saturdayEvening);
        show(editor);
        QVERIFY(editor.lastSent().startsWith("Nothing sent yet"));
        QSignalSpy spy(&editor, &ScheduleEditor::sendRequested);
        plan(editor, 3, QTime(15, 0));
        plan(editor, 5, QTime(10, 36));
        QCOMPARE(editor.schedulePreview(), QString("167 40 0 0 0 0 0 0 15 0 0 0 10 36 0 0"));
        QCOMPARE(spy.count(), 0);

        QTest::mouseClick(child<QPushButton>(editor, "sendSchedule"), Qt::LeftButton);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(bytesOfCommands(editor.robotProfile(), spy.at(0).at(0)),
                 bytes({167, 40, 0, 0, 0, 0, 0, 0, 15, 0, 0, 0, 10, 36, 0, 0}));
        QCOMPARE(editor.lastSent(), QString("Last sent: wed 15:00, fri 10:36 at 18:30"));
    }

    void uncheckedDaysKeepTheirTimeOutOfTheBytes()
    {
        ScheduleEditor editor;
        QSignalSpy spy(&editor, &ScheduleEditor::sendRequested);
        plan(editor, 0, QTime(23, 59));
        plan(editor, 6, QTime(7, 5));
        child<QTimeEdit>(editor, "time2")->setTime(QTime(9, 9)); // Tuesday not ticked
        editor.sendSchedule();
        QCOMPARE(bytesOfCommands(editor.robotProfile(), spy.at(0).at(0)),
                 bytes({167, 65, 23, 59, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 7, 5}));
    }

    void disableAll()
    {
        ScheduleEditor editor;
        editor.setClock(saturdayEvening);
        show(editor);
        plan(editor, 1, QTime(8, 0));
        plan(editor, 4, QTime(20, 15));
        QSignalSpy spy(&editor, &ScheduleEditor::sendRequested);
        QTest::mouseClick(child<QPushButton>(editor, "disableAll"), Qt::LeftButton);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(bytesOfCommands(editor.robotProfile(), spy.at(0).at(0)), bytes({167, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
        QVERIFY(editor.schedule().isOff());
        QVERIFY(!child<QCheckBox>(editor, "day1")->isChecked());
        QVERIFY(editor.lastSent().startsWith("Last sent: off at "));
    }

    void timesFollowTheLocale_data()
    {
        QTest::addColumn<QLocale>("locale");
        QTest::addColumn<bool>("twelveHour");
        QTest::addColumn<QString>("shown");
        QTest::newRow("en_US") << QLocale(QLocale::English, QLocale::UnitedStates) << true << "3:05 PM";
        QTest::newRow("en_GB") << QLocale(QLocale::English, QLocale::UnitedKingdom) << false << "15:05";
        QTest::newRow("de_DE") << QLocale(QLocale::German, QLocale::Germany) << false << "15:05";
    }

    // A time typed whole lands whole, in the schedule's and the clock's
    // boxes, wherever the click put the cursor and whatever the display.
    void typedTimesAreTaken_data()
    {
        timesFollowTheLocale_data();
        QTest::newRow("es_ES") << QLocale(QLocale::Spanish, QLocale::Spain) << false << "15:05";
    }
    void typedTimesAreTaken()
    {
        QFETCH(QLocale, locale);
        QFETCH(bool, twelveHour);
        QLocale::setDefault(locale);
        ScheduleEditor editor;
        show(editor);
        for (const QString &name : {QString("time3"), QString("clockTime")}) {
            auto *edit = child<QTimeEdit>(editor, name);
            edit->setEnabled(true);
            QVERIFY(edit->isVisible());
            struct Typed { QString keys; QTime time; };
            QList<Typed> typed{{"15:30", QTime(15, 30)}, {"0745", QTime(7, 45)}, {"9:05", QTime(9, 5)}};
            if (twelveHour)
                typed << Typed{"3:30 pm", QTime(15, 30)} << Typed{"12:10 am", QTime(0, 10)};
            for (const Typed &t : typed) {
                // Clicked in the minutes (the right of the box), then typed.
                QTest::mouseClick(edit, Qt::LeftButton, {}, QPoint(edit->width() * 2 / 3, edit->height() / 2));
                QTest::keyClicks(edit, t.keys);
                QTest::keyClick(edit, Qt::Key_Tab);
                QVERIFY2(edit->time() == t.time, qPrintable(name + ": " + t.keys + " gave " + edit->time().toString()));
            }
        }
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedKingdom));
    }

    void timesFollowTheLocale()
    {
        QFETCH(QLocale, locale);
        QFETCH(bool, twelveHour);
        QFETCH(QString, shown);
        QLocale::setDefault(locale);
        ScheduleEditor editor;
        for (const QString &name : {QString("time3"), QString("clockTime")}) {
            auto *edit = child<QTimeEdit>(editor, name);
            QCOMPARE(edit->displayFormat().contains("AP", Qt::CaseInsensitive), twelveHour);
            QVERIFY(!edit->displayFormat().contains('s')); // the robot keeps no seconds
            edit->setTime(QTime(15, 5));
            QCOMPARE(edit->text().replace(QChar(0x202F), ' '), shown);
        }
        // Whatever the display, the robot gets 24-hour values.
        QSignalSpy spy(&editor, &ScheduleEditor::sendRequested);
        child<QCheckBox>(editor, "day3")->setChecked(true);
        editor.sendSchedule();
        editor.sendChosenDayTime();
        QCOMPARE(bytesOfCommands(editor.robotProfile(), spy.at(0).at(0)), bytes({167, 8, 0, 0, 0, 0, 0, 0, 15, 5, 0, 0, 0, 0, 0, 0}));
        QCOMPARE(bytesOfCommands(editor.robotProfile(), spy.at(1).at(0)), bytes({168, 0, 15, 5}));
    }

    void presetsSurviveANewEditor()
    {
        CleaningSchedule weekdays;
        for (int day = 1; day <= 5; ++day)
            weekdays.days[day] = ClockTime{9, 30};
        {
            ScheduleEditor editor;
            show(editor);
            editor.setSchedule(weekdays);
            QTest::keyClicks(child<QLineEdit>(editor, "presetName"), "Weekdays");
            QTest::mouseClick(child<QPushButton>(editor, "savePreset"), Qt::LeftButton);
            QCOMPARE(editor.presetNames(), QStringList{"Weekdays"});
            editor.setSchedule(CleaningSchedule{});
            QVERIFY(editor.savePreset("Nothing"));
        }
        ScheduleEditor again;
        show(again);
        QCOMPARE(again.presetNames(), (QStringList{"Nothing", "Weekdays"}));
        QCOMPARE(child<QComboBox>(again, "presetList")->count(), 2);
        QSignalSpy spy(&again, &ScheduleEditor::sendRequested);
        child<QComboBox>(again, "presetList")->setCurrentText("Weekdays");
        QTest::mouseClick(child<QPushButton>(again, "loadPreset"), Qt::LeftButton);
        QCOMPARE(again.schedule(), weekdays);
        QCOMPARE(spy.count(), 0); // loading only fills the grid

        QTest::mouseClick(child<QPushButton>(again, "deletePreset"), Qt::LeftButton);
        QCOMPARE(again.presetNames(), QStringList{"Nothing"});
        ScheduleEditor third;
        QCOMPARE(third.presetNames(), QStringList{"Nothing"});
        QVERIFY(third.loadPreset("Nothing"));
        QVERIFY(third.schedule().isOff());
    }

    void badPresetsAreRefused()
    {
        ScheduleEditor editor;
        QSignalSpy spy(&editor, &ScheduleEditor::sendRequested);
        QVERIFY(!editor.savePreset("   "));
        QVERIFY(editor.message().contains("name"));
        QVERIFY(editor.presetNames().isEmpty());
        QVERIFY(!child<QPushButton>(editor, "loadPreset")->isEnabled());

        QSettings().setValue("scheduleEditor/presets", QVariantMap{{"Broken", "thu 25:00"}});
        CleaningSchedule before;
        before.days[2] = ClockTime{6, 45};
        editor.setSchedule(before);
        QVERIFY(!editor.loadPreset("Broken"));
        QVERIFY(editor.message().contains("damaged"));
        QCOMPARE(editor.schedule(), before);
        QVERIFY(!editor.loadPreset("Missing"));
        QVERIFY(!editor.deletePreset("Missing"));
        QCOMPARE(spy.count(), 0);
    }

    void setChosenDayTime_data()
    {
        QTest::addColumn<int>("day");
        QTest::addColumn<QTime>("time");
        QTest::addColumn<QByteArray>("expected");
        QTest::newRow("wednesday 15:00") << 3 << QTime(15, 0) << bytes({168, 3, 15, 0});
        QTest::newRow("saturday 23:59") << 6 << QTime(23, 59) << bytes({168, 6, 23, 59});
        QTest::newRow("sunday 00:01") << 0 << QTime(0, 1) << bytes({168, 0, 0, 1});
    }

    void setChosenDayTime()
    {
        QFETCH(int, day);
        QFETCH(QTime, time);
        QFETCH(QByteArray, expected);
        ScheduleEditor editor;
        show(editor);
        child<QComboBox>(editor, "clockDay")->setCurrentIndex(day);
        child<QTimeEdit>(editor, "clockTime")->setTime(time);
        QSignalSpy spy(&editor, &ScheduleEditor::sendRequested);
        QTest::mouseClick(child<QPushButton>(editor, "setDayTime"), Qt::LeftButton);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(bytesOfCommands(editor.robotProfile(), spy.at(0).at(0)), expected);
        QStringList decimal;
        for (char b : expected)
            decimal << QString::number(static_cast<std::uint8_t>(b));
        QCOMPARE(editor.clockPreview(), decimal.join(' '));
    }

    void setDayTimeFromComputer()
    {
        ScheduleEditor editor;
        editor.setClock(saturdayEvening);
        show(editor);
        QSignalSpy spy(&editor, &ScheduleEditor::sendRequested);
        QTest::mouseClick(child<QPushButton>(editor, "setFromComputer"), Qt::LeftButton);
        editor.setClock([] { return QDateTime(QDate(2026, 11, 22), QTime(7, 5, 59)); }); // Sunday
        editor.setDayTimeFromComputer();
        QCOMPARE(spy.count(), 2);
        QCOMPARE(bytesOfCommands(editor.robotProfile(), spy.at(0).at(0)), bytes({168, 6, 18, 30}));
        QCOMPARE(bytesOfCommands(editor.robotProfile(), spy.at(1).at(0)), bytes({168, 0, 7, 5}));
    }

    void createHasNoSchedule()
    {
        ScheduleEditor editor;
        editor.setProfile(profile(ProfileId::Create1));
        show(editor);
        QVERIFY(child<QLabel>(editor, "reason")->isVisible());
        QVERIFY(child<QLabel>(editor, "reason")->text().contains("167"));
        QVERIFY(!child<QPushButton>(editor, "sendSchedule")->isEnabled());
        QVERIFY(!child<QPushButton>(editor, "setDayTime")->isEnabled());
        QSignalSpy spy(&editor, &ScheduleEditor::sendRequested);
        editor.sendSchedule();
        editor.disableAll();
        editor.setDayTimeFromComputer();
        editor.sendChosenDayTime();
        QCOMPARE(spy.count(), 0);
        QVERIFY(editor.message().startsWith("Not sent"));
        QVERIFY(editor.lastSent().startsWith("Nothing sent yet"));

        editor.setProfile(profile(ProfileId::Create2));
        QVERIFY(!child<QLabel>(editor, "reason")->isVisible());
        editor.sendChosenDayTime();
        QCOMPARE(spy.count(), 1);
    }

    void translatesOnTheSpot()
    {
        ScheduleEditor editor;
        editor.setClock(saturdayEvening);
        editor.savePreset("School days"); // a name the user chose: never translated
        show(editor);
        plan(editor, 3, QTime(15, 0));
        child<QPushButton>(editor, "sendSchedule")->click();
        const oi::CleaningSchedule before = editor.schedule();
        const QStringList allowed{"School days"};
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList untranslated = untranslatedTexts(&editor, allowed);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            // Layout requests climb one level of nesting per pass of the event loop.
            for (int pass = 0; pass < 5; ++pass)
                QCoreApplication::processEvents();
            editor.resize(editor.sizeHint().expandedTo(editor.size())); // room for the longer texts
            sensor_scenes::saveScreenshot(editor, "schedule_editor_pseudo");
            // The sentence is new, the facts in it are not.
            QVERIFY2(editor.lastSent().contains("wed 15:00 at 18:30"), qPrintable(editor.lastSent()));
            QVERIFY(editor.schedule().days == before.days);
            QCOMPARE(editor.schedulePreview(), QString("167 8 0 0 0 0 0 0 15 0 0 0 0 0 0 0"));
            QCOMPARE(child<QComboBox>(editor, "presetList")->currentText(), QString("School days"));
        }
        QCoreApplication::processEvents();
        QCOMPARE(child<QPushButton>(editor, "sendSchedule")->text(), QString("Send Schedule"));
        QCOMPARE(child<QCheckBox>(editor, "day3")->text(), QString("Wednesday"));
        QCOMPARE(editor.lastSent(), QString("Last sent: wed 15:00 at 18:30"));
        QCOMPARE(editor.message(), QString("Schedule sent."));
    }

    void clockDayKeepsItsChoiceAcrossLanguages()
    {
        ScheduleEditor editor;
        editor.setChosenDayTime(Weekday::Thursday, QTime(9, 30));
        auto *day = child<QComboBox>(editor, "clockDay");
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            QCOMPARE(day->currentIndex(), 4);
            QCOMPARE(day->currentData().toInt(), 4);
            QVERIFY(day->currentText().contains(kPseudoOpen));
        }
        QCoreApplication::processEvents();
        QCOMPARE(day->currentText(), QString("Thursday"));
        QCOMPARE(editor.clockPreview(), QString("168 4 9 30"));
    }

    void controlsWithoutLabelsHaveAccessibleNames()
    {
        ScheduleEditor editor;
        for (int day = 0; day < 7; ++day)
            QVERIFY(!child<QTimeEdit>(editor, QString("time%1").arg(day))->accessibleName().isEmpty());
        for (const char *name : {"presetList", "presetName", "clockDay", "clockTime"})
            QVERIFY2(!child<QWidget>(editor, name)->accessibleName().isEmpty(), name);
    }

    void tabReachesEveryControlInOrder()
    {
        ScheduleEditor editor;
        editor.savePreset("Weekdays"); // so Load and Delete are enabled
        for (int day = 0; day < 7; ++day)
            child<QCheckBox>(editor, QString("day%1").arg(day))->setChecked(true); // times enabled
        show(editor);
        editor.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&editor));
        QStringList expected;
        for (int day = 0; day < 7; ++day)
            expected << QString("day%1").arg(day) << QString("time%1").arg(day);
        expected << "sendSchedule" << "disableAll" << "presetList" << "loadPreset" << "deletePreset"
                 << "presetName" << "savePreset" << "setFromComputer" << "clockDay" << "clockTime" << "setDayTime";
        child<QCheckBox>(editor, "day0")->setFocus(Qt::TabFocusReason);
        QStringList visited;
        // Tab also steps through the hour and minute of a time before leaving it.
        for (int i = 0; i <= 2 * expected.size(); ++i) {
            QWidget *focus = QApplication::focusWidget();
            QVERIFY(focus);
            if (!visited.contains(focus->objectName()))
                visited << focus->objectName();
            QTest::keyClick(focus, Qt::Key_Tab);
        }
        QCOMPARE(visited.join(' '), expected.join(' '));
    }

    void scheduleFromTheKeyboard()
    {
        ScheduleEditor editor;
        editor.setClock(saturdayEvening);
        show(editor);
        editor.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&editor));
        QSignalSpy spy(&editor, &ScheduleEditor::sendRequested);
        auto *monday = child<QCheckBox>(editor, "day1");
        monday->setFocus(Qt::TabFocusReason);
        QTest::keyClick(monday, Qt::Key_Space);
        QVERIFY(monday->isChecked());
        QTest::keyClick(monday, Qt::Key_Tab);
        auto *time = child<QTimeEdit>(editor, "time1");
        QCOMPARE(QApplication::focusWidget(), time);
        QTest::keyClick(time, Qt::Key_Up); // the hour section comes first
        QCOMPARE(time->time(), QTime(1, 0));
        auto *send = child<QPushButton>(editor, "sendSchedule");
        send->setFocus(Qt::TabFocusReason);
        QTest::keyClick(send, Qt::Key_Space);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(bytesOfCommands(editor.robotProfile(), spy.at(0).at(0)), bytes({167, 2, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
    }

    void screenshots_data()
    {
        QTest::addColumn<ProfileId>("id");
        QTest::addColumn<QString>("name");
        QTest::newRow("create2") << ProfileId::Create2 << "schedule_editor_create2";
        QTest::newRow("create1") << ProfileId::Create1 << "schedule_editor_create1";
    }

    void screenshots()
    {
        QFETCH(ProfileId, id);
        QFETCH(QString, name);
        ScheduleEditor editor;
        editor.setPalette(sensor_scenes::lightPalette());
        editor.setProfile(profile(id));
        editor.setClock(saturdayEvening);
        CleaningSchedule s;
        s.days[3] = ClockTime{15, 0};
        s.days[5] = ClockTime{10, 36};
        editor.setSchedule(s);
        editor.savePreset("School days");
        if (id != ProfileId::Create1)
            editor.sendSchedule();
        show(editor);
        sensor_scenes::saveScreenshot(editor, name);
    }
};

QTEST_MAIN(TstScheduleEditor)
#include "tst_schedule_editor.moc"
