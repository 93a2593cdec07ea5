// SPDX-License-Identifier: GPL-3.0-or-later
// Keys go where a person types: with a text field focused (the connection
// bar's port box, any line edit, editable combo box, spin box or text editor
// of the window) W A S D, the arrows and Space type and never drive; the
// status bar says once where the key went. Esc, or a click on the robot
// diagram, gives the keys back to driving. Real key events; the robot's
// bytes read at a recording transport.
#include "connection_bar.h"
#include "main_window.h"
#include "recording_transport.h"
#include "robot_diagram.h"
#include "sent_before_barrier.h"
#include "teleop_controller.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>
#include <QTextEdit>

#include <limits>

namespace {

// Counts the key presses that reach a widget (past the window's filters).
class KeysArriving : public QObject {
public:
    explicit KeysArriving(QWidget *w) : m_widget(w) { w->installEventFilter(this); }
    ~KeysArriving() override
    {
        if (m_widget)
            m_widget->removeEventFilter(this);
    }
    int presses = 0;

protected:
    bool eventFilter(QObject *, QEvent *event) override
    {
        if (event->type() == QEvent::KeyPress)
            ++presses;
        return false;
    }

private:
    QPointer<QWidget> m_widget;
};

// The one robot of the window, streaming in Safe mode (where the keys would
// drive it) on a recording transport.
struct OneRobot {
    Recording recording;
    MainWindow window;

    OneRobot()
    {
        recording.mode = int(oi::OiMode::Safe);
        window.fleet().setTransportFactory(
            [this](const oilink::LinkSettings &) { return new RecordingTransport(&recording); });
        window.resize(1280, 720);
        window.show();
        window.activateWindow();
        window.start(oilink::LinkSettings::serial("/dev/recording", oi::ProfileId::Create2));
    }
    bool ready()
    {
        return QTest::qWaitForWindowActive(&window) && QTest::qWaitFor([this] {
            return window.session().isLive() && window.session().latest().oiMode() == oi::OiMode::Safe;
        }, 10000);
    }
    // Every write since last asked, as "137 0 200 128 0 | ..." ("" for nothing).
    QString sent() { return sentBeforeBarrier(window.session(), recording); }
    // Nothing was sent and nothing waits to be.
    bool still() { return sent().isEmpty() && !window.teleop().hasPendingMotion() && !window.teleop().isMoving(); }
    // Gives `w` the focus the way a click would; false if it did not take it.
    static bool focus(QWidget *w)
    {
        w->setFocus(Qt::MouseFocusReason);
        return QTest::qWaitFor([w] {
            QWidget *f = QApplication::focusWidget();
            return f && (f == w || w->isAncestorOf(f));
        }, 2000);
    }
};

QPushButton *button(const MainWindow &window, const QString &text)
{
    for (QPushButton *b : window.dock<ConnectionBar>()->findChildren<QPushButton *>())
        if (b->text() == text && b->isVisible())
            return b;
    return nullptr;
}

QLineEdit *visibleLineEdit(QWidget *in)
{
    for (QLineEdit *edit : in->findChildren<QLineEdit *>())
        if (edit->isVisible() && edit->isEnabled() && !edit->isReadOnly())
            return edit;
    return nullptr;
}

QComboBox *portBox(const MainWindow &window)
{
    for (QComboBox *combo : window.dock<ConnectionBar>()->findChildren<QComboBox *>())
        if (combo->isEditable() && combo->isVisible())
            return combo;
    return nullptr;
}

// What a person types into: Qt's text fields, a line edit inside a combo
// box or spin box counting as its owner.
bool isTextField(QWidget *w)
{
    if (auto *combo = qobject_cast<QComboBox *>(w))
        return combo->isEditable();
    if (qobject_cast<QLineEdit *>(w))
        return !qobject_cast<QComboBox *>(w->parentWidget()) && !qobject_cast<QAbstractSpinBox *>(w->parentWidget());
    if (auto *text = qobject_cast<QTextEdit *>(w))
        return !text->isReadOnly();
    if (auto *plain = qobject_cast<QPlainTextEdit *>(w))
        return !plain->isReadOnly();
    return qobject_cast<QAbstractSpinBox *>(w);
}

// The text a field shows, where typed letters land as they are (up to
// `*limit` characters); false for fields that take digits only or follow a
// mask.
bool freeText(QWidget *w, QString *text, int *limit = nullptr)
{
    if (limit)
        *limit = std::numeric_limits<int>::max();
    if (auto *plain = qobject_cast<QPlainTextEdit *>(w)) {
        *text = plain->toPlainText();
        return true;
    }
    if (auto *rich = qobject_cast<QTextEdit *>(w)) {
        *text = rich->toPlainText();
        return true;
    }
    auto *edit = qobject_cast<QLineEdit *>(w);
    if (!edit)
        edit = w->findChild<QLineEdit *>();
    if (!edit || qobject_cast<QAbstractSpinBox *>(w) || edit->validator() || !edit->inputMask().isEmpty()
        || edit->isReadOnly())
        return false;
    *text = edit->text();
    if (limit)
        *limit = edit->maxLength();
    return true;
}

} // namespace

class TestTypingKeys : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // A port typed into the connection bar stays whole, the robot does not
    // move, and the status bar says where the keys went; from the diagram W
    // drives again.
    void aPortTypedIsWholeAndDrivesNothing()
    {
        OneRobot rig;
        QVERIFY(rig.ready());
        rig.sent(); // Start and the stream request
        // The port box takes a port while the robot is disconnected.
        QTest::mouseClick(button(rig.window, QStringLiteral("Disconnect")), Qt::LeftButton);
        QComboBox *port = portBox(rig.window);
        QVERIFY(port);
        QTRY_VERIFY(port->isEnabled());
        QVERIFY(rig.focus(port));
        for (const QString &path : {QStringLiteral("/dev/ttyUSB0"), QStringLiteral("/dev/pts/0")}) {
            QTest::keyClick(QApplication::focusWidget(), Qt::Key_A, Qt::ControlModifier);
            QTest::keyClick(QApplication::focusWidget(), Qt::Key_Backspace);
            QTest::keyClicks(QApplication::focusWidget(), path);
            QCOMPARE(port->currentText(), path);
            QVERIFY(!rig.window.teleop().isMoving() && !rig.window.teleop().hasPendingMotion());
        }
        // Arrows and Space there are the field's too.
        for (const Qt::Key key : {Qt::Key_Left, Qt::Key_Right, Qt::Key_Space, Qt::Key_Backspace}) {
            QTest::keyPress(QApplication::focusWidget(), key);
            QTest::keyRelease(QApplication::focusWidget(), key);
            QVERIFY(!rig.window.teleop().isMoving() && !rig.window.teleop().hasPendingMotion());
        }
        QCOMPARE(port->currentText(), QStringLiteral("/dev/pts/0"));
        const QString said = rig.window.statusBar()->currentMessage();
        QVERIFY2(said.contains(QStringLiteral("Typed into")) && said.contains(port->accessibleName())
                     && said.contains(QStringLiteral("Esc")),
                 qPrintable(said));
        // Connected again (the test's transport, whatever the port): the
        // robot was sent its opening and no motion.
        QTest::mouseClick(button(rig.window, QStringLiteral("Connect")), Qt::LeftButton);
        QVERIFY(rig.ready());
        const QString opening = rig.sent();
        // Stops (closing, opening) but no Drive, Drive Direct or Drive PWM that moves.
        static const QRegularExpression motion(QStringLiteral("\\b(137|145|146) (?!0 0 0 0\\b)"));
        QVERIFY2(!motion.match(opening).hasMatch(), qPrintable(opening));

        // A click on the robot diagram: W drives, its release stops.
        QTest::mouseClick(rig.window.robotDiagram(), Qt::LeftButton);
        QCOMPARE(QApplication::focusWidget(), rig.window.robotDiagram());
        QTest::keyPress(rig.window.robotDiagram(), Qt::Key_W);
        QTRY_VERIFY_WITH_TIMEOUT(rig.recording.count() > 0, 5000);
        QCOMPARE(rig.sent(), QStringLiteral("137 0 200 128 0"));
        QTest::keyRelease(rig.window.robotDiagram(), Qt::Key_W);
        QCOMPARE(rig.sent(), QStringLiteral("137 0 0 0 0 138 0"));

        // Esc in a text field (the LED digits' text, the port box being
        // locked while connected) stops the robot and gives the keys back.
        QDockWidget *leds = rig.window.findChild<QDockWidget *>("ledsDock");
        leds->raise();
        QLineEdit *field = nullptr;
        QTRY_VERIFY((field = visibleLineEdit(leds)));
        QVERIFY(rig.focus(field));
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
        QCOMPARE(rig.sent(), QStringLiteral("137 0 0 0 0 138 0"));
        QCOMPARE(QApplication::focusWidget(), rig.window.robotDiagram());
        QTest::keyPress(QApplication::focusWidget(), Qt::Key_D);
        QTRY_VERIFY_WITH_TIMEOUT(rig.recording.count() > 0, 5000);
        QVERIFY(rig.window.teleop().isMoving());
        QTest::keyRelease(QApplication::focusWidget(), Qt::Key_D);
        QVERIFY(rig.sent().endsWith(QStringLiteral("137 0 0 0 0 138 0")));
    }

    // Every text field the window shows, dock by dock: "wasd " reaches the
    // field (as typed, where it takes letters) and the robot never moves.
    void everyTextFieldTypes()
    {
        OneRobot rig;
        QVERIFY(rig.ready());
        rig.sent();
        QList<QWidget *> tried;
        QStringList problems;
        for (QDockWidget *dock : rig.window.findChildren<QDockWidget *>()) {
            dock->show();
            dock->raise();
            QVERIFY(QTest::qWaitFor([dock] { return dock->widget()->isVisible(); }, 2000));
            for (QWidget *w : dock->findChildren<QWidget *>()) {
                if (!isTextField(w) || !w->isVisible() || !w->isEnabled() || tried.contains(w))
                    continue;
                tried << w;
                const QString name = dock->objectName() + '/' + w->metaObject()->className() + ' '
                    + (w->accessibleName().isEmpty() ? w->objectName() : w->accessibleName());
                if (!rig.focus(w)) {
                    problems << name + ": takes no focus";
                    continue;
                }
                QWidget *focus = QApplication::focusWidget();
                KeysArriving arriving(focus);
                QString before;
                int limit = 0;
                const bool free = freeText(w, &before, &limit);
                QTest::keyClicks(focus, QStringLiteral("wasd "));
                QString after;
                freeText(w, &after);
                if (arriving.presses != 5)
                    problems << name + QStringLiteral(": %1 of 5 keys arrived").arg(arriving.presses);
                if (free && after != (before + QStringLiteral("wasd ")).left(limit))
                    problems << name + ": shows “" + after + "”";
                if (const QString s = rig.sent(); !s.isEmpty() || rig.window.teleop().isMoving())
                    problems << name + ": the robot was sent " + s;
            }
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
        // The editors' fields at least (the port box waits for a disconnect).
        QVERIFY2(tried.size() >= 5, qPrintable(QString::number(tried.size())));
    }
};

QTEST_MAIN(TestTypingKeys)
#include "tst_typing_keys.moc"
