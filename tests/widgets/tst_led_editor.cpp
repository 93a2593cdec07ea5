// SPDX-License-Identifier: GPL-3.0-or-later
#include "led_editor.h"
#include "typed_command_bytes.h"
#include "pseudo_translation.h"
#include "reported_mode.h"
#include "sensor_scenes.h"
#include "seven_segment_display.h"
#include "seven_segment_font.h"

#include <QApplication>
#include <QCheckBox>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>

using namespace oi;

namespace {

QByteArray bytes(std::initializer_list<int> values)
{
    QByteArray out;
    for (int v : values)
        out.append(static_cast<char>(v));
    return out;
}

// The exact bytes of the commands the editor asked for, on its profile.
QByteArray sent(const LedEditor &editor, const QSignalSpy &spy, int index)
{
    return bytesOfCommands(editor.robotProfile(), spy.at(index).at(0));
}

// The object names of the widgets Tab visits from `first`, each once, in order.
QStringList tabChain(QWidget *first, int presses)
{
    first->setFocus(Qt::TabFocusReason);
    QStringList visited;
    for (int i = 0; i < presses; ++i) {
        QWidget *focus = QApplication::focusWidget();
        if (!focus)
            break;
        if (!visited.contains(focus->objectName()))
            visited << focus->objectName();
        QTest::keyClick(focus, Qt::Key_Tab);
    }
    return visited;
}

} // namespace

class TstLedEditor : public QObject {
    Q_OBJECT

    template <typename T>
    static T *child(LedEditor &editor, const char *name)
    {
        auto *w = editor.findChild<T *>(name);
        if (!w)
            qFatal("no child %s", name);
        return w;
    }

    // Shown, so clicks land as they would for a person.
    static void show(LedEditor &editor)
    {
        editor.resize(editor.sizeHint());
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
    }

private slots:
    void ledsDockGreenHalfIntensity()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Roomba500));
        show(editor);
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        auto *apply = child<QPushButton>(editor, "apply");
        QVERIFY(!apply->isEnabled()); // nothing changed yet

        QTest::mouseClick(child<QCheckBox>(editor, "ledDock"), Qt::LeftButton);
        child<QSlider>(editor, "powerColour")->setValue(0);
        child<QSlider>(editor, "powerIntensity")->setValue(128);
        QCOMPARE(editor.bytePreview(), QString("139 4 0 128"));
        QCOMPARE(spy.count(), 0); // not live: nothing goes out before Apply

        QTest::mouseClick(apply, Qt::LeftButton);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({139, 4, 0, 128}));
        QVERIFY(!apply->isEnabled());
    }

    void ledBitsOnRoombas_data()
    {
        QTest::addColumn<QString>("box");
        QTest::addColumn<int>("bits");
        QTest::newRow("debris") << "ledDebris" << 1;
        QTest::newRow("spot") << "ledSpot" << 2;
        QTest::newRow("dock") << "ledDock" << 4;
        QTest::newRow("check robot") << "ledCheckRobot" << 8;
    }

    void ledBitsOnRoombas()
    {
        QFETCH(QString, box);
        QFETCH(int, bits);
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Create2));
        show(editor);
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        QTest::mouseClick(editor.findChild<QCheckBox *>(box), Qt::LeftButton);
        child<QSlider>(editor, "powerColour")->setValue(255);
        child<QSlider>(editor, "powerIntensity")->setValue(200);
        editor.apply();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({139, bits, 255, 200}));
        QVERIFY(!child<QCheckBox>(editor, "ledPlay")->isVisibleTo(&editor));
        QVERIFY(!child<QCheckBox>(editor, "ledAdvance")->isVisibleTo(&editor));
    }

    // The SCI puts Dirt Detect, Max, Clean and Spot on bits 1, 2, 4, 8: the
    // boxes say so, and send those bits.
    void roomba400NamesItsOwnLeds()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Roomba400));
        show(editor);
        QCOMPARE(child<QCheckBox>(editor, "ledDebris")->text(), QString("Dirt Detect"));
        QCOMPARE(child<QCheckBox>(editor, "ledSpot")->text(), QString("Max"));
        QCOMPARE(child<QCheckBox>(editor, "ledDock")->text(), QString("Clean"));
        QCOMPARE(child<QCheckBox>(editor, "ledCheckRobot")->text(), QString("Spot"));
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        QTest::mouseClick(child<QCheckBox>(editor, "ledCheckRobot"), Qt::LeftButton);
        child<QSlider>(editor, "powerColour")->setValue(0);
        child<QSlider>(editor, "powerIntensity")->setValue(128);
        editor.apply();
        QCOMPARE(sent(editor, spy, 0), bytes({139, 8, 0, 128}));
        // Back on a Create 2, the names are the Open Interface's again.
        editor.setProfile(profile(ProfileId::Create2));
        QCOMPARE(child<QCheckBox>(editor, "ledCheckRobot")->text(), QString("Check Robot"));
    }

    void createShowsPlayAndAdvance()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Create1));
        show(editor);
        for (const char *hidden : {"ledDebris", "ledSpot", "ledDock", "ledCheckRobot"})
            QVERIFY2(!child<QCheckBox>(editor, hidden)->isVisible(), hidden);
        QVERIFY(child<QCheckBox>(editor, "ledPlay")->isVisible());
        QVERIFY(child<QCheckBox>(editor, "ledAdvance")->isVisible());

        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        QTest::mouseClick(child<QCheckBox>(editor, "ledAdvance"), Qt::LeftButton);
        editor.apply();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({139, 8, 0, 128}));
        QTest::mouseClick(child<QCheckBox>(editor, "ledPlay"), Qt::LeftButton);
        editor.apply();
        QCOMPARE(sent(editor, spy, 1), bytes({139, 10, 0, 128}));

        // No digits and no scheduling LEDs, and the reason is given.
        QVERIFY(!child<SevenSegmentDisplay>(editor, "segmentEditor")->isEnabled());
        QVERIFY(!child<SevenSegmentDisplay>(editor, "segmentEditor")->isVisible());
        QVERIFY(!child<QLineEdit>(editor, "asciiText")->isEnabled());
        QVERIFY(child<QLabel>(editor, "digitsReason")->isVisible());
        QVERIFY(child<QLabel>(editor, "digitsReason")->text().contains("164"));
        QVERIFY(!child<QCheckBox>(editor, "weekday0")->isEnabled());
        QVERIFY(child<QLabel>(editor, "schedulingReason")->isVisible());
    }

    void switchingToCreateDropsRoombaLeds()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Roomba500));
        child<QCheckBox>(editor, "ledDebris")->setChecked(true);
        editor.setProfile(profile(ProfileId::Create1));
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        child<QCheckBox>(editor, "ledPlay")->setChecked(true);
        editor.apply();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({139, 2, 0, 128}));
    }

    void asciiText()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Create2));
        show(editor);
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        QTest::keyClicks(child<QLineEdit>(editor, "asciiText"), "ABCD");
        QCOMPARE(editor.bytePreview(), QString("164 65 66 67 68"));
        editor.apply();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({164, 65, 66, 67, 68}));
        const std::array<std::uint8_t, 4> shown{sevenSegmentForAscii('A'), sevenSegmentForAscii('B'),
                                                sevenSegmentForAscii('C'), sevenSegmentForAscii('D')};
        QCOMPARE(child<SevenSegmentDisplay>(editor, "asciiPreview")->masks(), shown);
    }

    void asciiShortTextIsPadded()
    {
        LedEditor editor;
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        child<QLineEdit>(editor, "asciiText")->setText("hi");
        editor.apply();
        QCOMPARE(sent(editor, spy, 0), bytes({164, 'h', 'i', 32, 32}));
        QCOMPARE(child<SevenSegmentDisplay>(editor, "asciiPreview")->masks()[0], sevenSegmentForAscii('H'));
    }

    void asciiBlankCharacters()
    {
        LedEditor editor;
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        child<QLineEdit>(editor, "asciiText")->setText("*+@1");
        QCOMPARE(child<QLabel>(editor, "asciiMessage")->text(),
                 QString("'*', '+', '@' show blank: the robot has no shape for them."));
        const auto masks = child<SevenSegmentDisplay>(editor, "asciiPreview")->masks();
        QCOMPARE(masks[0], std::uint8_t(0));
        QCOMPARE(masks[1], std::uint8_t(0));
        QCOMPARE(masks[2], std::uint8_t(0));
        QCOMPARE(masks[3], sevenSegmentForAscii('1'));
        editor.apply();
        QCOMPARE(sent(editor, spy, 0), bytes({164, 42, 43, 64, 49}));
    }

    void asciiRefusesCharactersOutsideRange_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("tab") << QString("A\tB");
        QTest::newRow("e acute") << QString::fromUtf8("caf\u00e9");
        QTest::newRow("delete") << QString("A") + QChar(127);
    }

    void asciiRefusesCharactersOutsideRange()
    {
        QFETCH(QString, text);
        LedEditor editor;
        show(editor);
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        child<QLineEdit>(editor, "asciiText")->setText(text);
        QVERIFY(child<QLabel>(editor, "asciiMessage")->text().contains("32..126"));
        QVERIFY(!child<QPushButton>(editor, "apply")->isEnabled());
        editor.apply();
        QCOMPARE(spy.count(), 0);
        // A valid edit afterwards is sent as usual.
        child<QLineEdit>(editor, "asciiText")->setText("OK");
        editor.apply();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({164, 'O', 'K', 32, 32}));
    }

    void clickingSegments()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Roomba500));
        show(editor);
        auto *segments = child<SevenSegmentDisplay>(editor, "segmentEditor");
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        // Leftmost is digit 3: A there; B and C on digit 2; G on digit 0.
        QTest::mouseClick(segments, Qt::LeftButton, {}, segments->segmentCentre(0, 0));
        QTest::mouseClick(segments, Qt::LeftButton, {}, segments->segmentCentre(1, 1));
        QTest::mouseClick(segments, Qt::LeftButton, {}, segments->segmentCentre(1, 2));
        QTest::mouseClick(segments, Qt::LeftButton, {}, segments->segmentCentre(3, 6));
        QCOMPARE(editor.bytePreview(), QString("163 1 6 0 64"));
        editor.apply();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({163, 1, 6, 0, 64}));

        // Clicking again switches a segment off.
        QTest::mouseClick(segments, Qt::LeftButton, {}, segments->segmentCentre(1, 1));
        editor.apply();
        QCOMPARE(sent(editor, spy, 1), bytes({163, 1, 4, 0, 64}));
    }

    // The warning after sending raw digits is the window's own, translated
    // message, not the encoder's English beside translated text.
    void warningAfterSendingSpeaksTheLanguage()
    {
        LedEditor editor;
        show(editor);
        ScopedPseudoTranslation pseudo;
        QCoreApplication::processEvents();
        QTest::mouseClick(child<QPushButton>(editor, "clearSegments"), Qt::LeftButton);
        editor.apply();
        QVERIFY(!editor.message().isEmpty());
        for (const QString &line : editor.message().split('\n'))
            QVERIFY2(!looksUntranslated(line), qPrintable(line));
    }

    void everySegmentOfEveryDigit()
    {
        LedEditor editor;
        show(editor);
        auto *segments = child<SevenSegmentDisplay>(editor, "segmentEditor");
        for (int position = 0; position < 4; ++position)
            for (int s = 0; s < 7; ++s)
                QTest::mouseClick(segments, Qt::LeftButton, {}, segments->segmentCentre(position, s));
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        editor.apply();
        QCOMPARE(sent(editor, spy, 0), bytes({163, 127, 127, 127, 127}));
    }

    void rawWarningOnCreate2AndRoomba500()
    {
        LedEditor editor;
        auto *warning = child<QLabel>(editor, "rawWarning");
        for (ProfileId id : {ProfileId::Create2, ProfileId::Roomba500}) {
            editor.setProfile(profile(id));
            QVERIFY(warning->isVisibleTo(&editor));
            QVERIFY(warning->text().contains("does not work in current Create 2 and Roomba 500/600 firmware"));
        }
        editor.setProfile(profile(ProfileId::Create1));
        QVERIFY(!warning->isVisibleTo(&editor));
    }

    void lastDigitEditWins()
    {
        LedEditor editor;
        show(editor);
        auto *segments = child<SevenSegmentDisplay>(editor, "segmentEditor");
        QTest::mouseClick(segments, Qt::LeftButton, {}, segments->segmentCentre(0, 0));
        child<QLineEdit>(editor, "asciiText")->setText("GO");
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        editor.apply();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({164, 'G', 'O', 32, 32}));
    }

    void schedulingLeds()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Create2));
        show(editor);
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        for (const char *name : {"weekday0", "weekday3", "weekday6", "schedSchedule", "schedColon"})
            QTest::mouseClick(child<QCheckBox>(editor, name), Qt::LeftButton);
        QCOMPARE(editor.bytePreview(), QString("162 73 17"));
        editor.apply();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({162, 73, 17}));

        for (const char *name : {"schedSchedule", "schedColon", "schedClock", "schedAm", "schedPm"})
            QTest::mouseClick(child<QCheckBox>(editor, name), Qt::LeftButton);
        editor.apply();
        QCOMPARE(sent(editor, spy, 1), bytes({162, 73, 8 | 4 | 2}));
    }

    void severalChangesGoOutInOrder()
    {
        LedEditor editor;
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        child<QLineEdit>(editor, "asciiText")->setText("1234");
        child<QCheckBox>(editor, "weekday1")->setChecked(true);
        child<QCheckBox>(editor, "ledSpot")->setChecked(true);
        QCOMPARE(editor.bytePreview(), QString("139 2 0 128\n162 2 0\n164 49 50 51 52"));
        editor.apply();
        QCOMPARE(spy.count(), 3);
        QCOMPARE(sent(editor, spy, 0), bytes({139, 2, 0, 128}));
        QCOMPARE(sent(editor, spy, 1), bytes({162, 2, 0}));
        QCOMPARE(sent(editor, spy, 2), bytes({164, 49, 50, 51, 52}));
        editor.apply(); // nothing changed since
        QCOMPARE(spy.count(), 3);
    }

    void liveModeIsRateLimited()
    {
        LedEditor editor;
        show(editor);
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        QTest::mouseClick(child<QCheckBox>(editor, "live"), Qt::LeftButton);
        QVERIFY(editor.liveMode());
        QVERIFY(!child<QPushButton>(editor, "apply")->isEnabled());

        auto *colour = child<QSlider>(editor, "powerColour");
        for (int v = 1; v <= 40; ++v)
            colour->setValue(v * 5);
        QCOMPARE(spy.count(), 0); // coalesced, not one send per change
        QVERIFY(editor.msUntilLiveSend() >= 0);
        QTRY_COMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({139, 0, 200, 128}));

        // Nothing more goes out while nothing changes: no send is pending.
        QCOMPARE(editor.msUntilLiveSend(), -1);
        QCOMPARE(spy.count(), 1);

        child<QSlider>(editor, "powerIntensity")->setValue(10);
        child<QCheckBox>(editor, "ledDebris")->setChecked(true);
        QTRY_COMPARE(spy.count(), 2);
        QCOMPARE(sent(editor, spy, 1), bytes({139, 1, 200, 10}));

        // Leaving live mode stops sending: a change schedules nothing.
        editor.setLiveMode(false);
        colour->setValue(7);
        QCOMPARE(editor.msUntilLiveSend(), -1);
        QCoreApplication::processEvents();
        QCOMPARE(spy.count(), 2);
    }

    // In Passive the robot ignores the LED commands: Apply is disabled with
    // the reason, nothing goes out, and the changes wait for Safe.
    void passiveHoldsTheChanges()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Create2));
        show(editor);
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        auto *apply = child<QPushButton>(editor, "apply");
        editor.setMode(reportedMode(editor.robotProfile(), OiMode::Passive));
        child<QCheckBox>(editor, "ledSpot")->setChecked(true);
        QCOMPARE(editor.bytePreview(), QString("139 2 0 128"));
        QVERIFY(!apply->isEnabled());
        QCOMPARE(apply->toolTip(), QString("LEDs needs Safe or Full mode: the robot ignores it in Passive. Enter Safe "
                                           "first."));
        editor.apply();
        QCOMPARE(spy.count(), 0);
        QCOMPARE(editor.message(), apply->toolTip());
        QCOMPARE(editor.bytePreview(), QString("139 2 0 128")); // still pending

        editor.setMode(reportedMode(editor.robotProfile(), OiMode::Safe));
        QVERIFY(apply->isEnabled());
        QCOMPARE(apply->toolTip(), QString("Send the changes shown under \"Will send\""));
        QTest::mouseClick(apply, Qt::LeftButton);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({139, 2, 0, 128}));
    }

    // Live mode in Passive sends nothing; entering Safe sends what waited.
    void liveModeWaitsForSafe()
    {
        LedEditor editor;
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        editor.setMode(reportedMode(editor.robotProfile(), OiMode::Passive));
        editor.setLiveMode(true);
        child<QCheckBox>(editor, "ledDock")->setChecked(true);
        QCOMPARE(editor.msUntilLiveSend(), -1);
        editor.setMode(reportedMode(editor.robotProfile(), OiMode::Full));
        QVERIFY(editor.msUntilLiveSend() >= 0);
        QTRY_COMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({139, 4, 0, 128}));
    }

    void liveModeKeepsSendingDuringSteadyChanges()
    {
        // A rate limit, not a debounce: a slider dragged without pause
        // still reaches the robot while it moves, because a later change
        // does not push the pending send back.
        LedEditor editor;
        editor.setLiveMode(true);
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        auto *intensity = child<QSlider>(editor, "powerIntensity");
        QCOMPARE(editor.msUntilLiveSend(), -1);
        intensity->setValue(1);
        const int first = editor.msUntilLiveSend();
        QVERIFY2(first > 0 && first <= LedEditor::kLiveIntervalMs, qPrintable(QString::number(first)));
        // Part of the wait goes by.
        QTRY_VERIFY(!spy.isEmpty() || editor.msUntilLiveSend() <= first / 2);
        if (spy.isEmpty()) { // not yet sent: the next change must not restart the wait
            intensity->setValue(2);
            QVERIFY2(editor.msUntilLiveSend() <= first, qPrintable(QString::number(editor.msUntilLiveSend())));
        }
        QTRY_VERIFY(!spy.isEmpty());
        // Changes after a send start a new wait, and the latest state goes out.
        intensity->setValue(20);
        QTRY_VERIFY(bytesOfCommands(editor.robotProfile(), spy.last().at(0)) == bytes({139, 0, 0, 20}));
        QVERIFY2(spy.count() >= 2, qPrintable(QString::number(spy.count())));
    }

    void powerLedColour()
    {
        QCOMPARE(LedEditor::powerLedColor(0, 255), QColor(0, 255, 0));
        QCOMPARE(LedEditor::powerLedColor(255, 255), QColor(255, 0, 0));
        QCOMPARE(LedEditor::powerLedColor(128, 255), QColor(128, 127, 0));
        QCOMPARE(LedEditor::powerLedColor(255, 0), QColor(0, 0, 0));
        QCOMPARE(LedEditor::powerLedColor(0, 51), QColor(0, 51, 0));
    }

    void translatesOnTheSpot()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Create2));
        child<QLineEdit>(editor, "asciiText")->setText("Hi*5");
        child<QCheckBox>(editor, "weekday2")->setChecked(true);
        show(editor);
        const auto masks = child<SevenSegmentDisplay>(editor, "segmentEditor")->masks();
        const QString preview = editor.bytePreview();
        // Nothing here is a brand name or unit; numbers and bytes have no letters.
        const QStringList allowed;
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList untranslated = untranslatedTexts(&editor, allowed);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            // Layout requests climb one level of nesting per pass of the event loop.
            for (int pass = 0; pass < 5; ++pass)
                QCoreApplication::processEvents();
            editor.resize(editor.sizeHint().expandedTo(editor.size())); // room for the longer texts
            sensor_scenes::saveScreenshot(editor, "led_editor_pseudo");
            QVERIFY(child<SevenSegmentDisplay>(editor, "segmentEditor")->accessibleDescription().contains(kPseudoOpen));
            // The user's settings survive the switch.
            QCOMPARE(child<QLineEdit>(editor, "asciiText")->text(), QString("Hi*5"));
            QVERIFY(child<QCheckBox>(editor, "weekday2")->isChecked());
            QVERIFY(child<SevenSegmentDisplay>(editor, "segmentEditor")->masks() == masks);
            QCOMPARE(editor.bytePreview(), preview);
        }
        QCoreApplication::processEvents();
        QCOMPARE(child<QPushButton>(editor, "apply")->text(), QString("Apply"));
        QCOMPARE(child<QGroupBox>(editor, "ledsGroup")->title(), QString("LEDs (139)"));
        QCOMPARE(child<QLabel>(editor, "asciiMessage")->text(), QString("'*' shows blank: the robot has no shape for it."));
    }

    void customWidgetsAreNamedForScreenReaders()
    {
        LedEditor editor;
        for (const char *name : {"segmentEditor", "asciiPreview", "powerSwatch"}) {
            auto *w = child<QWidget>(editor, name);
            QVERIFY2(!w->accessibleName().isEmpty(), name);
            QVERIFY2(!w->accessibleDescription().isEmpty(), name);
        }
        // The preview's description says what it shows, and follows the text.
        const QString before = child<SevenSegmentDisplay>(editor, "asciiPreview")->accessibleDescription();
        child<QLineEdit>(editor, "asciiText")->setText("8");
        const QString after = child<SevenSegmentDisplay>(editor, "asciiPreview")->accessibleDescription();
        QVERIFY2(after != before, qPrintable(after));
        QVERIFY2(after.contains("digit 1 segments ABCDEFG"), qPrintable(after));
        child<QSlider>(editor, "powerColour")->setValue(200);
        QVERIFY(child<QLabel>(editor, "powerSwatch")->accessibleDescription().contains("200"));
    }

    void tabReachesEveryControlInOrder()
    {
        LedEditor editor;
        editor.setProfile(profile(ProfileId::Create2));
        show(editor);
        editor.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&editor));
        child<QCheckBox>(editor, "ledSpot")->setChecked(true); // so Apply has something to send
        QStringList expected{"segmentEditor", "clearSegments", "asciiText", "ledDebris", "ledSpot", "ledDock",
                             "ledCheckRobot", "powerColour", "powerIntensity"};
        for (int day = 0; day < 7; ++day)
            expected << QString("weekday%1").arg(day);
        expected << "schedSchedule" << "schedClock" << "schedAm" << "schedPm" << "schedColon" << "live" << "apply";
        QCOMPARE(tabChain(child<QWidget>(editor, "segmentEditor"), expected.size() + 1), expected);
    }

    void segmentEditorWorksFromTheKeyboard()
    {
        LedEditor editor;
        show(editor);
        auto *segments = child<SevenSegmentDisplay>(editor, "segmentEditor");
        QCOMPARE(segments->focusPolicy(), Qt::StrongFocus);
        segments->setFocus();
        QSignalSpy spy(&editor, &LedEditor::sendRequested);
        QTest::keyClick(segments, Qt::Key_Space); // digit 3, segment A
        QTest::keyClick(segments, Qt::Key_Right);
        QTest::keyClick(segments, Qt::Key_Space); // and B
        QTest::keyClick(segments, Qt::Key_Down);
        QTest::keyClick(segments, Qt::Key_Space); // next digit, B
        QTest::keyClick(segments, Qt::Key_Left);
        QTest::keyClick(segments, Qt::Key_Left);
        QTest::keyClick(segments, Qt::Key_Space); // back to the first digit's last segment, G
        const std::array<std::uint8_t, 4> expected{segment::A | segment::B | segment::G, segment::B, 0, 0};
        QVERIFY(segments->masks() == expected);
        QVERIFY2(segments->accessibleDescription().contains("digit 1 segments ABG"),
                 qPrintable(segments->accessibleDescription()));
        QCOMPARE(editor.bytePreview(), QString("163 67 2 0 0"));
        // Space on the focused Apply button sends it.
        child<QPushButton>(editor, "apply")->setFocus();
        QTest::keyClick(child<QPushButton>(editor, "apply"), Qt::Key_Space);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(sent(editor, spy, 0), bytes({163, 67, 2, 0, 0}));
    }

    void screenshots_data()
    {
        QTest::addColumn<ProfileId>("id");
        QTest::addColumn<QString>("name");
        QTest::newRow("create2") << ProfileId::Create2 << "led_editor_create2";
        QTest::newRow("create1") << ProfileId::Create1 << "led_editor_create1";
    }

    void screenshots()
    {
        QFETCH(ProfileId, id);
        QFETCH(QString, name);
        LedEditor editor;
        editor.setPalette(sensor_scenes::lightPalette());
        editor.setProfile(profile(id));
        if (id != ProfileId::Create1) {
            child<QLineEdit>(editor, "asciiText")->setText("Hi*5");
            child<QCheckBox>(editor, "weekday2")->setChecked(true);
            child<QCheckBox>(editor, "schedClock")->setChecked(true);
        }
        child<QSlider>(editor, "powerColour")->setValue(90);
        child<QSlider>(editor, "powerIntensity")->setValue(220);
        show(editor);
        auto *segments = child<SevenSegmentDisplay>(editor, "segmentEditor");
        if (id != ProfileId::Create1)
            for (int s : {0, 1, 2, 6})
                QTest::mouseClick(segments, Qt::LeftButton, {}, segments->segmentCentre(2, s));
        sensor_scenes::saveScreenshot(editor, name);
    }
};

QTEST_MAIN(TstLedEditor)
#include "tst_led_editor.moc"
