// SPDX-License-Identifier: GPL-3.0-or-later
#include "pseudo_translation.h"
#include "robot_session.h"
#include "sensor_scenes.h"
#include "robot_profile.h"
#include "script_editor.h"
#include "script_lines.h"
#include "transport_factory.h"
#include "typed_command_bytes.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

namespace {

QString spaced(const QByteArray &bytes)
{
    QStringList numbers;
    for (char b : bytes)
        numbers << QString::number(quint8(b));
    return numbers.join(u' ');
}

QByteArray bytes(std::initializer_list<int> values)
{
    QByteArray out;
    for (int v : values)
        out.append(char(quint8(v)));
    return out;
}

const oi::RobotProfile &create1() { return oi::profile(oi::ProfileId::Create1); }

// The first example's body ("drive 300 straight; wait-distance 400; drive 0 0"),
// as the robot holds it once uploaded (RobotSession::uploadedScript()).
const QByteArray kExampleBody = QByteArray::fromHex("89012c80009c01908900000000");

// The sent messages of a spy, as spaced decimal text.
QStringList sent(const QSignalSpy &spy)
{
    QStringList out;
    for (const QList<QVariant> &args : spy)
        out << spaced(bytesOfCommands(create1(), args.at(0)));
    return out;
}

} // namespace

class TestScriptEditor : public QObject {
    Q_OBJECT
private slots:
    void statementLines()
    {
        QCOMPARE(script_lines::statementNumber("statement 3 (drive)"), std::optional<int>(3));
        QCOMPARE(script_lines::statementNumber("statement 12 (leds)"), std::optional<int>(12));
        QCOMPARE(script_lines::statementNumber("script"), std::nullopt);
        QCOMPARE(script_lines::statementNumber("statement x"), std::nullopt);

        const QString text = "# heading\n"
                             "drive 300 0; wait-distance 400\n"
                             "\n"
                             "   # only a comment; drive 1 1\n"
                             "song 0 C#4:32 ; ;\n"
                             "play-script";
        QCOMPARE(script_lines::lineOfStatement(text, 1), std::optional<int>(2));
        QCOMPARE(script_lines::lineOfStatement(text, 2), std::optional<int>(2));
        QCOMPARE(script_lines::lineOfStatement(text, 3), std::optional<int>(5));
        QCOMPARE(script_lines::lineOfStatement(text, 4), std::optional<int>(6));
        QCOMPARE(script_lines::lineOfStatement(text, 5), std::nullopt);
        QCOMPARE(script_lines::lineOfStatement(text, 0), std::nullopt);
    }

    void documentExamples_data()
    {
        QTest::addColumn<int>("index");
        QTest::addColumn<QString>("expected");
        QTest::newRow("drive 40 cm") << 0 << "152 13 137 1 44 128 0 156 1 144 137 0 0 0 0";
        QTest::newRow("toggle led") << 1 << "152 17 158 5 158 251 139 2 0 0 158 5 158 251 139 0 0 0 153";
        QTest::newRow("square") << 2 << "152 17 137 1 44 128 0 156 1 144 137 1 44 0 1 157 0 90 153";
    }

    void documentExamples()
    {
        QFETCH(int, index);
        QFETCH(QString, expected);
        ScriptEditor editor;
        editor.setProfile(create1());
        QCOMPARE(ScriptEditor::exampleTitles().size(), 3);
        // Load through the combo, as a user would.
        auto *combo = editor.findChild<QComboBox *>("examples");
        QVERIFY(combo);
        QCOMPARE(combo->count(), 4);
        combo->setCurrentIndex(index + 1);
        emit combo->activated(index + 1);
        QCOMPARE(combo->currentIndex(), 0);
        QVERIFY2(editor.errorText().isEmpty(), qPrintable(editor.errorText()));
        QSignalSpy spy(&editor, &ScriptEditor::sendRequested);
        QVERIFY(editor.button("upload")->isEnabled());
        QTest::mouseClick(editor.button("upload"), Qt::LeftButton);
        QCOMPARE(sent(spy), QStringList{expected});
    }

    void typedStatements()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        editor.setScriptText("drive 300 0; wait-distance 400 # go\nwait-event -5\nwait-event not-bump\nplay-script");
        QSignalSpy spy(&editor, &ScriptEditor::sendRequested);
        QTest::mouseClick(editor.button("upload"), Qt::LeftButton);
        QCOMPARE(sent(spy), QStringList{"152 13 137 1 44 0 0 156 1 144 158 251 158 251 153"});
        QCOMPARE(editor.byteCountText(), QString("13 / 100 bytes"));
        // Upload says what it stored; Play what the robot now does.
        QCOMPARE(editor.showScriptText(),
                 QString("Uploaded (152): 13 / 100 bytes. Play (153) runs the script; Show Script (154) reads it back."));
        // Play goes to the robot's session (playAsksTheRobot).
        QSignalSpy play(&editor, &ScriptEditor::playRequested);
        QTest::mouseClick(editor.button("play"), Qt::LeftButton);
        QCOMPARE(play.count(), 1);
        QVERIFY2(editor.showScriptText().startsWith("Play (153) sent. While the script waits (155–158) the Create "
                                                    "hears no command, not even a stop"),
                 qPrintable(editor.showScriptText()));
    }

    void byteCountFollowsTyping()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        QCOMPARE(editor.byteCountText(), QString("0 / 100 bytes"));
        auto *text = editor.findChild<QPlainTextEdit *>("scriptText");
        QVERIFY(text);
        text->setFocus();
        QTest::keyClicks(text, "drive 100 straight");
        // Debounced: the count follows after the typing pause.
        QTRY_COMPARE(editor.byteCountText(), QString("5 / 100 bytes"));
        QTest::keyClick(text, Qt::Key_Return);
        QTest::keyClicks(text, "play-script");
        QTRY_COMPARE(editor.byteCountText(), QString("6 / 100 bytes"));
    }

    void errorLineReported()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        editor.setScriptText("# a comment line\ndrive 300 straight\nwait-distance 400; drive 900 0\ndrive 0 0");
        QCOMPARE(editor.errorLine(), std::optional<int>(3));
        QVERIFY2(editor.errorText().startsWith("Line 3: statement 3 (drive)"), qPrintable(editor.errorText()));
        QVERIFY(editor.errorText().contains("900"));
        QVERIFY(!editor.button("upload")->isEnabled());
        auto *text = editor.findChild<QPlainTextEdit *>("scriptText");
        QCOMPARE(text->extraSelections().size(), 1);
        QCOMPARE(text->extraSelections().first().cursor.blockNumber(), 2);

        QSignalSpy spy(&editor, &ScriptEditor::sendRequested);
        QTest::mouseClick(editor.button("upload"), Qt::LeftButton);
        QCOMPARE(spy.count(), 0);

        editor.setScriptText("# a comment line\ndrive 300 straight\nwait-distance 400; drive 0 0");
        QCOMPARE(editor.errorLine(), std::nullopt);
        QVERIFY(editor.errorText().isEmpty());
        QVERIFY(editor.button("upload")->isEnabled());
        QVERIFY(text->extraSelections().isEmpty());
    }

    void tooLongRefused()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        // 20 drives of 5 bytes are exactly 100; one more wait-event makes 102,
        // one play-script makes 101.
        QString text;
        for (int i = 0; i < 20; ++i)
            text += "drive 100 straight\n";
        editor.setScriptText(text);
        QCOMPARE(editor.byteCountText(), QString("100 / 100 bytes"));
        QVERIFY(editor.button("upload")->isEnabled());

        editor.setScriptText(text + "play-script\n");
        QCOMPARE(editor.byteCountText(), QString("101 / 100 bytes"));
        QVERIFY(!editor.button("upload")->isEnabled());
        QVERIFY2(editor.errorText().contains("at most 100"), qPrintable(editor.errorText()));
        QSignalSpy spy(&editor, &ScriptEditor::sendRequested);
        QTest::mouseClick(editor.button("upload"), Qt::LeftButton);
        QCOMPARE(spy.count(), 0);
    }

    // Show Script is asked of the robot's link, which pauses its own stream
    // around it; the editor shows what comes back.
    static void askForScript(ScriptEditor &editor)
    {
        QSignalSpy asked(&editor, &ScriptEditor::showScriptRequested);
        QTest::mouseClick(editor.button("show"), Qt::LeftButton);
        QCOMPARE(asked.count(), 1);
        QVERIFY(!editor.button("show")->isEnabled());
        QVERIFY(editor.showScriptText().contains("Asking"));
    }

    void showScriptMatches()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        editor.loadExample(0);
        QSignalSpy spy(&editor, &ScriptEditor::sendRequested);
        QTest::mouseClick(editor.button("upload"), Qt::LeftButton);
        askForScript(editor);
        // Asking sends nothing itself: the link does.
        QCOMPARE(sent(spy), (QStringList{"152 13 137 1 44 128 0 156 1 144 137 0 0 0 0"}));
        editor.showScriptReply(bytes({137, 1, 44, 128, 0, 156, 1, 144, 137, 0, 0, 0, 0}), kExampleBody);
        QVERIFY2(editor.showScriptText().contains("matches what was sent"), qPrintable(editor.showScriptText()));
        QVERIFY(editor.showScriptText().contains("drive 300 straight; wait-distance 400; drive 0 0"));
        QVERIFY(editor.button("show")->isEnabled());

        // A reply nobody asked for is not read.
        editor.showScriptReply(bytes({153}), kExampleBody);
        QVERIFY(editor.showScriptText().contains("matches what was sent"));
        QCOMPARE(spy.count(), 1);
    }

    void showScriptDiffers()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        editor.loadExample(0);
        QTest::mouseClick(editor.button("upload"), Qt::LeftButton);
        askForScript(editor);
        editor.showScriptReply(bytes({157, 0, 90}), kExampleBody);
        const QString result = editor.showScriptText();
        QVERIFY2(result.contains("differs"), qPrintable(result));
        QVERIFY(!result.contains("matches"));
        QVERIFY(result.contains("On the robot: wait-angle 90"));
        QVERIFY(result.contains("Sent: drive 300 straight; wait-distance 400; drive 0 0"));
    }

    void showScriptFailureIsShown()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        askForScript(editor);
        editor.showScriptFailed("/dev/ttyUSB0: no reply to Show Script");
        QVERIFY2(editor.showScriptText().contains("no reply to Show Script"), qPrintable(editor.showScriptText()));
        QVERIFY(editor.button("show")->isEnabled());
        // A late reply is ignored.
        editor.showScriptReply(bytes({153, 153, 153}), std::nullopt);
        QVERIFY(editor.showScriptText().contains("no reply"));
    }

    void profileChangeCancelsReply()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        askForScript(editor);
        editor.setProfile(oi::profile(oi::ProfileId::Create2));
        editor.setProfile(create1());
        editor.showScriptReply(bytes({153}), std::nullopt);
        QVERIFY(editor.showScriptText().isEmpty());
        QVERIFY(editor.button("show")->isEnabled());
    }

    void demos_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("label");
        QTest::addColumn<QString>("expected");
        QTest::newRow("cover") << "demo-0" << "0  Cover" << "136 0";
        QTest::newRow("figure eight") << "demo-4" << "4  Drive Figure Eight" << "136 4";
        QTest::newRow("banjo") << "demo-9" << "9  Banjo" << "136 9";
        QTest::newRow("abort") << "abort-demo" << "Abort demo" << "136 255";
    }

    void demos()
    {
        QFETCH(QString, name);
        QFETCH(QString, label);
        QFETCH(QString, expected);
        ScriptEditor editor;
        editor.setProfile(create1());
        QPushButton *b = editor.button(name);
        QVERIFY(b);
        QCOMPARE(b->text(), label);
        QSignalSpy spy(&editor, &ScriptEditor::sendRequested);
        QTest::mouseClick(b, Qt::LeftButton);
        QCOMPARE(sent(spy), QStringList{expected});
    }

    // Play asks the robot's session, which enters Safe first in Passive
    // (RobotSession::playScript()); the editor sends nothing itself.
    void playAsksTheRobot()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        QSignalSpy sent(&editor, &ScriptEditor::sendRequested);
        QSignalSpy play(&editor, &ScriptEditor::playRequested);
        QTest::mouseClick(editor.button("play"), Qt::LeftButton);
        QCOMPARE(play.count(), 1);
        QCOMPARE(sent.count(), 0);
    }

    // The uploaded script is the robot's, not the editor's: an editor made
    // after the upload (the dock closed and opened again), and a second
    // one, compare the robot's script with it and agree.
    void theUploadIsTheRobots()
    {
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        {
            ScriptEditor editor;
            editor.setProfile(create1());
            editor.loadExample(0);
            connect(&editor, &ScriptEditor::sendRequested, &robot,
                    [&robot](const std::vector<oi::OiCommand> &commands) { robot.send(commands); });
            QTest::mouseClick(editor.button("upload"), Qt::LeftButton);
        }
        QCOMPARE(robot.uploadedScript(), std::optional(kExampleBody));
        ScriptEditor again, second;
        for (ScriptEditor *editor : {&again, &second}) {
            editor->setProfile(create1());
            // As the window wires it: the robot's reply beside the robot's upload.
            connect(&robot, &RobotSession::scriptShown, editor,
                    [editor, &robot](const QByteArray &script) { editor->showScriptReply(script, robot.uploadedScript()); });
            askForScript(*editor);
        }
        robot.showScript();
        QTRY_VERIFY_WITH_TIMEOUT(!again.showScriptText().contains("Asking"), 5000);
        QVERIFY2(again.showScriptText().contains("matches what was sent"), qPrintable(again.showScriptText()));
        QCOMPARE(second.showScriptText(), again.showScriptText());
    }

    void disabledOnCreate2()
    {
        ScriptEditor editor;
        editor.setProfile(oi::profile(oi::ProfileId::Create2));
        QVERIFY2(editor.disabledReason().contains("original Create only"), qPrintable(editor.disabledReason()));
        QVERIFY(editor.disabledReason().contains("Roomba 600 / Create 2"));
        QVERIFY(editor.findChild<QLabel *>("disabledReason")->isEnabled());
        QSignalSpy spy(&editor, &ScriptEditor::sendRequested);
        for (const char *name : {"upload", "play", "show", "demo-0", "abort-demo"}) {
            QVERIFY2(!editor.button(name)->isEnabled(), name);
            QTest::mouseClick(editor.button(name), Qt::LeftButton);
        }
        QVERIFY(!editor.findChild<QPlainTextEdit *>("scriptText")->isEnabled());
        QCOMPARE(spy.count(), 0);

        QCOMPARE(editor.byteCountText(), QString("? / 100 bytes"));

        editor.setProfile(create1());
        QVERIFY(editor.disabledReason().isEmpty());
        QVERIFY(editor.button("play")->isEnabled());
    }

    void translatesOnTheSpot()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        const QString script = "drive 300 straight\nbogus 1\n";
        editor.setScriptText(script);
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        QCOMPARE(editor.errorLine(), std::optional<int>(2));
        const QStringList allowed; // script keywords live only in the user's text
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList untranslated = untranslatedTexts(&editor, allowed);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            // Layout requests climb one level of nesting per pass of the event loop.
            for (int pass = 0; pass < 5; ++pass)
                QCoreApplication::processEvents();
            editor.resize(editor.sizeHint().expandedTo(editor.size())); // room for the longer texts
            sensor_scenes::saveScreenshot(editor, "script_editor_pseudo");
            // The framing of the error is translated; the line stays marked.
            QVERIFY2(editor.errorText().startsWith(kPseudoOpen + QString("Line 2: ")), qPrintable(editor.errorText()));
            QCOMPARE(editor.errorLine(), std::optional<int>(2));
            QCOMPARE(editor.scriptText(), script);
            QVERIFY(editor.findChild<QPlainTextEdit *>("scriptText")->placeholderText().contains(kPseudoOpen));
            // Example titles are translated in place; the first entry is still the prompt.
            auto *examples = editor.findChild<QComboBox *>("examples");
            QCOMPARE(examples->count(), 1 + int(ScriptEditor::exampleTitles().size()));
            QCOMPARE(examples->currentIndex(), 0);
        }
        QCoreApplication::processEvents();
        QCOMPARE(editor.button("upload")->text(), QString("Upload (152)"));
        QVERIFY2(editor.errorText().startsWith("Line 2: "), qPrintable(editor.errorText()));
        QCOMPARE(editor.scriptText(), script);

        editor.setProfile(oi::profile(oi::ProfileId::Create2));
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            QVERIFY2(editor.disabledReason().startsWith(kPseudoOpen), qPrintable(editor.disabledReason()));
        }
    }

    void editorIsNamedForScreenReaders()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        editor.setScriptText("drive 100 straight");
        auto *text = editor.findChild<QPlainTextEdit *>("scriptText");
        QVERIFY(!text->accessibleName().isEmpty());
        QCOMPARE(text->accessibleDescription(), QString("5 / 100 bytes"));
        editor.setScriptText("drive 100 straight\nbogus");
        QVERIFY2(text->accessibleDescription().contains("Line 2"), qPrintable(text->accessibleDescription()));
    }

    void tabReachesEveryControlInOrder()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        editor.setScriptText("drive 100 straight"); // so Upload is enabled
        editor.show();
        editor.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&editor));
        QStringList expected{"examples", "scriptText", "upload", "play", "show"};
        for (int demo = 0; demo <= 9; ++demo)
            expected << QString("demo-%1").arg(demo);
        expected << "abort-demo";
        editor.findChild<QComboBox *>("examples")->setFocus(Qt::TabFocusReason);
        QStringList visited;
        for (int i = 0; i <= expected.size(); ++i) {
            QWidget *focus = QApplication::focusWidget();
            QVERIFY(focus);
            if (!visited.contains(focus->objectName()))
                visited << focus->objectName();
            QTest::keyClick(focus, Qt::Key_Tab);
        }
        QCOMPARE(visited, expected);
    }

    void scriptFromTheKeyboard()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        editor.show();
        editor.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&editor));
        auto *text = editor.findChild<QPlainTextEdit *>("scriptText");
        text->setFocus(Qt::TabFocusReason);
        QTest::keyClicks(text, "drive 0 0");
        editor.reassemble();
        QCOMPARE(editor.byteCountText(), QString("5 / 100 bytes"));
        // Tab leaves the editor instead of typing a tab character.
        QTest::keyClick(text, Qt::Key_Tab);
        QCOMPARE(editor.scriptText(), QString("drive 0 0"));
        QCOMPARE(QApplication::focusWidget(), editor.button("upload"));
        QSignalSpy spy(&editor, &ScriptEditor::sendRequested);
        QTest::keyClick(editor.button("upload"), Qt::Key_Space);
        QCOMPARE(sent(spy), QStringList{"152 5 137 0 0 0 0"});
    }

    void screenshot()
    {
        ScriptEditor editor;
        editor.setProfile(create1());
        editor.loadExample(2);
        QString text = editor.scriptText();
        text.replace("wait-angle 90", "wait-angle 90; wait-event bumpp");
        editor.setScriptText(text);
        QCOMPARE(editor.errorLine(), std::optional<int>(5));
        QSignalSpy spy(&editor, &ScriptEditor::sendRequested);
        editor.resize(editor.sizeHint().expandedTo(QSize(560, 560)));
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));

        QTemporaryDir temporary;
        const QByteArray env = qgetenv("ROOMBA_SCREENSHOTS");
        const QDir dir(env.isEmpty() ? temporary.path() : QString::fromLocal8Bit(env));
        QVERIFY(dir.exists());
        const QImage image = editor.grab().toImage();
        QVERIFY(!image.isNull());
        QVERIFY(image.save(dir.filePath("script_editor.png")));

        // With a Show Script reply that differs from the upload.
        editor.loadExample(0);
        QTest::mouseClick(editor.button("upload"), Qt::LeftButton);
        askForScript(editor);
        editor.showScriptReply(bytes({137, 1, 44, 128, 0, 156, 1, 144}), kExampleBody);
        QVERIFY(editor.showScriptText().contains("differs"));
        QVERIFY(editor.errorText().isEmpty());
        editor.resize(editor.size().expandedTo(editor.sizeHint()));
        // The whole comparison is visible, not cut to its first line, once
        // the layout has taken the longer text in.
        auto *result = editor.findChild<QLabel *>("showScriptResult");
        QTRY_VERIFY(result->height() >= result->heightForWidth(result->width()));
        QVERIFY(editor.grab().save(dir.filePath("script_editor_show.png")));

        // On the Create 2: everything greyed, the reason on top.
        editor.setProfile(oi::profile(oi::ProfileId::Create2));
        QCoreApplication::processEvents(); // the layout requests the change posted
        QVERIFY(editor.grab().save(dir.filePath("script_editor_create2.png")));
        QVERIFY(editor.findChild<QLabel *>("disabledReason")->isVisible());
        editor.setProfile(create1());

        // Every button shows its whole label.
        for (QPushButton *b : editor.findChildren<QPushButton *>())
            QVERIFY2(b->width() >= b->sizeHint().width(), qPrintable(b->text()));
    }
};

QTEST_MAIN(TestScriptEditor)
#include "tst_script_editor.moc"
