// SPDX-License-Identifier: GPL-3.0-or-later
#include "motors_panel.h"
#include "typed_command_bytes.h"

#include "keyboard_focus.h"
#include "pseudo_translation.h"
#include "reported_mode.h"

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

Q_DECLARE_METATYPE(oi::ProfileId)

namespace {

QByteArray bytes(std::initializer_list<int> values)
{
    QByteArray out;
    for (int v : values)
        out.append(char(v));
    return out;
}

// Reading order: the next row down, or further right on the same row.
bool comesAfter(QWidget *root, QWidget *a, QWidget *b)
{
    const QPoint ca = a->mapTo(root, a->rect().center());
    const QPoint cb = b->mapTo(root, b->rect().center());
    return cb.y() > ca.y() + 2 || (std::abs(cb.y() - ca.y()) <= 2 && cb.x() > ca.x());
}

} // namespace

class TestMotorsPanel : public QObject {
    Q_OBJECT

    std::unique_ptr<MotorsPanel> m_panel;
    std::unique_ptr<QSignalSpy> m_sent;

    template <typename T>
    T *child(const char *name)
    {
        T *c = m_panel->findChild<T *>(name);
        if (!c)
            qFatal("no child %s", name);
        return c;
    }

    void usePanel(oi::ProfileId id)
    {
        m_panel->setProfile(oi::profile(id));
        m_sent->clear();
    }

    // On the box's indicator: the middle of a stretched check box is not on it.
    static void click(QCheckBox *box) { QTest::mouseClick(box, Qt::LeftButton, {}, QPoint(6, box->height() / 2)); }

    QByteArray lastSent() const
    {
        return m_sent->isEmpty() ? QByteArray() : bytesOfCommands(m_panel->robotProfile(), m_sent->last().at(0));
    }

private slots:
    void init()
    {
        m_panel = std::make_unique<MotorsPanel>();
        m_panel->resize(520, 700);
        m_panel->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_panel.get()));
        m_sent = std::make_unique<QSignalSpy>(m_panel.get(), &MotorsPanel::sendRequested);
    }
    void cleanup()
    {
        m_sent.reset();
        m_panel.reset();
    }

    void motorBits_data()
    {
        QTest::addColumn<oi::ProfileId>("profile");
        QTest::addColumn<QStringList>("clicks");
        QTest::addColumn<QByteArray>("expected");

        for (auto [id, name] : {std::pair{oi::ProfileId::Create2, "create2"}, std::pair{oi::ProfileId::Roomba500, "roomba500"}}) {
            const QByteArray p(name);
            QTest::newRow(p + " main brush") << id << QStringList{"mainBrush"} << bytes({138, 4});
            QTest::newRow(p + " side brush") << id << QStringList{"sideBrush"} << bytes({138, 1});
            QTest::newRow(p + " vacuum") << id << QStringList{"vacuum"} << bytes({138, 2});
            QTest::newRow(p + " side clockwise") << id << QStringList{"sideBrushClockwise"} << bytes({138, 8});
            QTest::newRow(p + " main outward") << id << QStringList{"mainBrushOutward"} << bytes({138, 16});
            QTest::newRow(p + " main + side clockwise") << id << QStringList{"mainBrush", "sideBrushClockwise"}
                                                         << bytes({138, 12});
            // The document's example: main brush, side brush clockwise, side brush on.
            QTest::newRow(p + " document example")
                << id << QStringList{"mainBrush", "sideBrushClockwise", "sideBrush"} << bytes({138, 13});
            QTest::newRow(p + " everything")
                << id << QStringList{"mainBrush", "mainBrushOutward", "sideBrush", "sideBrushClockwise", "vacuum"}
                << bytes({138, 31});
            QTest::newRow(p + " on and off again") << id << QStringList{"vacuum", "mainBrush", "vacuum"}
                                                   << bytes({138, 4});
        }
    }
    void motorBits()
    {
        QFETCH(oi::ProfileId, profile);
        QFETCH(QStringList, clicks);
        QFETCH(QByteArray, expected);
        usePanel(profile);
        for (const QString &name : clicks)
            click(child<QCheckBox>(name.toUtf8().constData()));
        QCOMPARE(m_sent->count(), clicks.size()); // one command per change
        QCOMPARE(lastSent(), expected);
        QCOMPARE(m_panel->lastSentText(), QString("138 %1").arg(quint8(expected.at(1))));
    }

    void pwmMotors_data()
    {
        QTest::addColumn<oi::ProfileId>("profile");
        QTest::addColumn<int>("main");
        QTest::addColumn<int>("side");
        QTest::addColumn<int>("vacuum");
        QTest::addColumn<QByteArray>("expected");
        for (auto [id, name] : {std::pair{oi::ProfileId::Create2, "create2"}, std::pair{oi::ProfileId::Roomba500, "roomba500"}}) {
            const QByteArray p(name);
            QTest::newRow(p + " full forward") << id << 127 << 127 << 127 << bytes({144, 127, 127, 127});
            // Two's complement: -1 is 255, -127 is 129, -100 is 156.
            QTest::newRow(p + " reversed brushes") << id << -127 << -1 << 0 << bytes({144, 129, 255, 0});
            QTest::newRow(p + " mixed") << id << -100 << 50 << 64 << bytes({144, 156, 50, 64});
        }
    }
    void pwmMotors()
    {
        QFETCH(oi::ProfileId, profile);
        QFETCH(int, main);
        QFETCH(int, side);
        QFETCH(int, vacuum);
        QFETCH(QByteArray, expected);
        usePanel(profile);
        QCOMPARE(child<QSlider>("mainBrushDuty")->minimum(), -127);
        QCOMPARE(child<QSlider>("vacuumDuty")->minimum(), 0);
        QCOMPARE(child<QSlider>("vacuumDuty")->maximum(), 127);
        child<QSlider>("mainBrushDuty")->setValue(main);
        child<QSlider>("sideBrushDuty")->setValue(side);
        child<QSlider>("vacuumDuty")->setValue(vacuum);
        QCOMPARE(lastSent(), expected);
    }

    void pwmSliderKeyboard()
    {
        usePanel(oi::ProfileId::Create2);
        QSlider *main = child<QSlider>("mainBrushDuty");
        main->setFocus();
        QTest::keyClick(main, Qt::Key_Left);
        QCOMPARE(lastSent(), bytes({144, 255, 0, 0}));
        QCOMPARE(child<QLabel>("mainBrushDutyValue")->text(), QString("-1"));
    }

    void buttons_data()
    {
        QTest::addColumn<oi::ProfileId>("profile");
        QTest::addColumn<QString>("button");
        QTest::addColumn<int>("bits");
        for (auto [id, name] : {std::pair{oi::ProfileId::Create2, "create2"}, std::pair{oi::ProfileId::Roomba500, "roomba500"}}) {
            const QByteArray p(name);
            QTest::newRow(p + " clean") << id << "buttonClean" << 0x01;
            QTest::newRow(p + " spot") << id << "buttonSpot" << 0x02;
            QTest::newRow(p + " dock") << id << "buttonDock" << 0x04;
            QTest::newRow(p + " minute") << id << "buttonMinute" << 0x08;
            QTest::newRow(p + " hour") << id << "buttonHour" << 0x10;
            QTest::newRow(p + " day") << id << "buttonDay" << 0x20;
            QTest::newRow(p + " schedule") << id << "buttonSchedule" << 0x40;
            QTest::newRow(p + " clock") << id << "buttonClock" << 0x80;
        }
    }
    void buttons()
    {
        QFETCH(oi::ProfileId, profile);
        QFETCH(QString, button);
        QFETCH(int, bits);
        usePanel(profile);
        QTest::mouseClick(child<QPushButton>(button.toUtf8().constData()), Qt::LeftButton);
        QCOMPARE(m_sent->count(), 1);
        QCOMPARE(lastSent(), bytes({165, bits}));
    }

    void createLowSideDrivers()
    {
        usePanel(oi::ProfileId::Create1);
        click(child<QCheckBox>("lowSide0"));
        QCOMPARE(lastSent(), bytes({138, 1}));
        click(child<QCheckBox>("lowSide1"));
        QCOMPARE(lastSent(), bytes({138, 3}));
        click(child<QCheckBox>("lowSide2"));
        QCOMPARE(lastSent(), bytes({138, 7}));
        click(child<QCheckBox>("lowSide0"));
        QCOMPARE(lastSent(), bytes({138, 6}));
        QCOMPARE(m_sent->count(), 4);
    }

    void createPwmLowSideDrivers()
    {
        usePanel(oi::ProfileId::Create1);
        QCOMPARE(child<QSlider>("lowSide2Duty")->maximum(), 128);
        // The command's bytes are LD2, LD1, LD0.
        child<QSlider>("lowSide2Duty")->setValue(128);
        QCOMPARE(lastSent(), bytes({144, 128, 0, 0}));
        child<QSlider>("lowSide0Duty")->setValue(64);
        QCOMPARE(lastSent(), bytes({144, 128, 0, 64}));
        child<QSlider>("lowSide1Duty")->setValue(1);
        QCOMPARE(lastSent(), bytes({144, 128, 1, 64}));
        QCOMPARE(m_panel->lastSentText(), QString("144 128 1 64"));
    }

    void createDigitalOutputs()
    {
        usePanel(oi::ProfileId::Create1);
        click(child<QCheckBox>("digitalOutput2"));
        QCOMPARE(lastSent(), bytes({147, 4}));
        click(child<QCheckBox>("digitalOutput0"));
        QCOMPARE(lastSent(), bytes({147, 5}));
        click(child<QCheckBox>("digitalOutput1"));
        QCOMPARE(lastSent(), bytes({147, 7}));
    }

    void createSendIr_data()
    {
        QTest::addColumn<int>("value");
        QTest::newRow("0") << 0;
        QTest::newRow("129") << 129;
        QTest::newRow("255") << 255;
    }
    void createSendIr()
    {
        QFETCH(int, value);
        usePanel(oi::ProfileId::Create1);
        QCOMPARE(child<QSpinBox>("irByte")->maximum(), 255);
        child<QSpinBox>("irByte")->setValue(value);
        QVERIFY(m_sent->isEmpty()); // only the button sends
        QTest::mouseClick(child<QPushButton>("sendIr"), Qt::LeftButton);
        QCOMPARE(lastSent(), bytes({151, value}));
    }

    void hiddenPerProfile_data()
    {
        QTest::addColumn<oi::ProfileId>("profile");
        QTest::addColumn<QStringList>("shown");
        QTest::addColumn<QStringList>("hidden");
        QTest::addColumn<QStringList>("named"); // in the note on what is missing
        const QStringList roomba{"motorsGroup", "pwmMotorsGroup", "buttonsGroup"};
        const QStringList create{"lowSideGroup", "pwmLowSideGroup", "digitalOutputsGroup", "sendIrGroup"};
        QTest::newRow("create2") << oi::ProfileId::Create2 << roomba << create
                                 << QStringList{"Low Side Drivers (138)", "Digital Outputs (147)", "Send IR (151)"};
        QTest::newRow("roomba500") << oi::ProfileId::Roomba500 << roomba << create
                                   << QStringList{"PWM Low Side Drivers (144)"};
        QTest::newRow("create1") << oi::ProfileId::Create1 << create << roomba
                                 << QStringList{"Motors (138)", "PWM Motors (144)", "Buttons (165)"};
    }
    void hiddenPerProfile()
    {
        QFETCH(oi::ProfileId, profile);
        QFETCH(QStringList, shown);
        QFETCH(QStringList, hidden);
        QFETCH(QStringList, named);
        usePanel(profile);
        for (const QString &name : shown)
            QVERIFY2(child<QGroupBox>(name.toUtf8().constData())->isVisibleTo(m_panel.get()), qPrintable(name));
        for (const QString &name : hidden) {
            QGroupBox *g = child<QGroupBox>(name.toUtf8().constData());
            QVERIFY2(!g->isVisibleTo(m_panel.get()), qPrintable(name));
            QVERIFY2(!g->isEnabled(), qPrintable(name));
        }
        for (const QString &text : named)
            QVERIFY2(m_panel->unavailableText().contains(text), qPrintable(m_panel->unavailableText()));
        QVERIFY(m_panel->unavailableText().contains(QString::fromUtf8(oi::profile(profile).name.data())));
    }

    void allOff_data()
    {
        QTest::addColumn<oi::ProfileId>("profile");
        QTest::addColumn<QString>("checkBox");
        QTest::addColumn<QString>("slider");
        QTest::newRow("create2") << oi::ProfileId::Create2 << "vacuum" << "mainBrushDuty";
        QTest::newRow("roomba500") << oi::ProfileId::Roomba500 << "mainBrush" << "sideBrushDuty";
        QTest::newRow("create1") << oi::ProfileId::Create1 << "lowSide1" << "lowSide0Duty";
    }
    void allOff()
    {
        QFETCH(oi::ProfileId, profile);
        QFETCH(QString, checkBox);
        QFETCH(QString, slider);
        usePanel(profile);
        QCheckBox *box = child<QCheckBox>(checkBox.toUtf8().constData());
        QSlider *duty = child<QSlider>(slider.toUtf8().constData());
        click(box);
        duty->setValue(100);
        m_sent->clear();
        QTest::mouseClick(child<QPushButton>("allOff"), Qt::LeftButton);
        QCOMPARE(m_sent->count(), 1);
        QCOMPARE(lastSent(), bytes({138, 0, 144, 0, 0, 0}));
        QCOMPARE(m_panel->lastSentText(), QString("138 0 144 0 0 0"));
        QVERIFY(!box->isChecked());
        QCOMPARE(duty->value(), 0);
        QCOMPARE(m_sent->count(), 1); // clearing the controls sent nothing more
    }

    // In Passive the robot ignores every command here but Buttons: those
    // groups and All off are disabled, each with its reason; Safe enables them.
    void passiveDisablesWhatTheRobotIgnores_data()
    {
        QTest::addColumn<oi::ProfileId>("profile");
        QTest::newRow("create2") << oi::ProfileId::Create2;
        QTest::newRow("roomba500") << oi::ProfileId::Roomba500;
        QTest::newRow("create1") << oi::ProfileId::Create1;
    }
    void passiveDisablesWhatTheRobotIgnores()
    {
        QFETCH(oi::ProfileId, profile);
        usePanel(profile);
        const std::pair<const char *, const char *> groups[] = {
            {"motorsGroup", "Motors"}, {"pwmMotorsGroup", "PWM Motors"}, {"lowSideGroup", "Low Side Drivers"},
            {"pwmLowSideGroup", "PWM Low Side Drivers"}, {"digitalOutputsGroup", "Digital Outputs"},
            {"sendIrGroup", "Send IR"}};
        m_panel->setMode(reportedMode(m_panel->robotProfile(), oi::OiMode::Passive));
        int shown = 0;
        for (auto [name, title] : groups) {
            auto *g = child<QGroupBox>(name);
            if (!g->isVisibleTo(m_panel.get()))
                continue;
            ++shown;
            QVERIFY2(!g->isEnabled(), name);
            QVERIFY2(g->toolTip().contains(QString("%1 needs Safe or Full mode").arg(title)), qPrintable(g->toolTip()));
            QVERIFY2(g->toolTip().endsWith("Enter Safe first."), qPrintable(g->toolTip()));
        }
        QVERIFY(shown >= 2);
        auto *allOff = child<QPushButton>("allOff");
        QVERIFY(!allOff->isEnabled());
        QVERIFY2(allOff->toolTip().contains("needs Safe or Full mode"), qPrintable(allOff->toolTip()));
        QTest::mouseClick(allOff, Qt::LeftButton);
        QCOMPARE(m_sent->count(), 0);

        // Buttons (165) works in Passive.
        auto *buttons = child<QGroupBox>("buttonsGroup");
        if (buttons->isVisibleTo(m_panel.get())) {
            QVERIFY(buttons->isEnabled());
            QTest::mouseClick(child<QPushButton>("buttonClean"), Qt::LeftButton);
            QCOMPARE(lastSent(), bytes({165, 1}));
        }

        m_panel->setMode(reportedMode(m_panel->robotProfile(), oi::OiMode::Safe));
        for (auto [name, title] : groups) {
            auto *g = child<QGroupBox>(name);
            QCOMPARE(g->isEnabled(), g->isVisibleTo(m_panel.get()));
            QVERIFY2(g->toolTip().isEmpty(), name);
        }
        QVERIFY(allOff->isEnabled());
        QVERIFY(allOff->toolTip().isEmpty());
    }

    // The panel keeps no mode of its own: another robot, selected, comes with
    // its own mode, not the last robot's Passive.
    void theModeComesWithTheRobot()
    {
        usePanel(oi::ProfileId::Create2);
        m_panel->setMode(reportedMode(m_panel->robotProfile(), oi::OiMode::Passive));
        QVERIFY(!child<QGroupBox>("motorsGroup")->isEnabled());
        const oi::RobotProfile &create1 = oi::profile(oi::ProfileId::Create1);
        m_panel->setProfile(create1, reportedMode(create1, oi::OiMode::Safe));
        QVERIFY(child<QGroupBox>("lowSideGroup")->isEnabled());
        QVERIFY(child<QGroupBox>("lowSideGroup")->toolTip().isEmpty());
        QVERIFY(child<QPushButton>("allOff")->isEnabled());
    }

    void setProfileSendsNothingAndClears()
    {
        usePanel(oi::ProfileId::Create2);
        click(child<QCheckBox>("vacuum"));
        QCOMPARE(m_sent->count(), 1);
        m_panel->setProfile(oi::profile(oi::ProfileId::Create1));
        m_panel->setProfile(oi::profile(oi::ProfileId::Create2));
        QCOMPARE(m_sent->count(), 1);
        QVERIFY(!child<QCheckBox>("vacuum")->isChecked());
    }

    void translatesOnTheSpot()
    {
        usePanel(oi::ProfileId::Create2);
        click(child<QCheckBox>("vacuum"));
        child<QSlider>("mainBrushDuty")->setValue(-64);
        const QStringList allowed;
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            QStringList untranslated = untranslatedTexts(m_panel.get(), allowed);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            QVERIFY(child<QCheckBox>("vacuum")->isChecked());

            // The Create 1's groups, and the note naming what it lacks.
            usePanel(oi::ProfileId::Create1);
            click(child<QCheckBox>("lowSide1"));
            QCoreApplication::processEvents();
            untranslated = untranslatedTexts(m_panel.get(), allowed);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            QVERIFY(m_panel->unavailableText().startsWith(kPseudoOpen));
            if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS")) {
                m_panel->adjustSize();
                QVERIFY(m_panel->grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS"))
                                                 .filePath("motors_panel_pseudo.png")));
            }
        }
        QCoreApplication::processEvents();
        QCOMPARE(child<QCheckBox>("lowSide1")->text(), QStringLiteral("LD1"));
        QCOMPARE(child<QGroupBox>("sendIrGroup")->title(), QStringLiteral("IR output — Send IR (151)"));
        QCOMPARE(child<QLabel>("lastSent")->text(), QStringLiteral("Last sent: 138 2"));
        QVERIFY2(m_panel->unavailableText().startsWith(QStringLiteral("Not on the Create, so not shown: Motors (138)")),
                 qPrintable(m_panel->unavailableText()));
    }

    void keyboardReachesEveryControl_data()
    {
        QTest::addColumn<oi::ProfileId>("id");
        QTest::newRow("Create 2") << oi::ProfileId::Create2;
        QTest::newRow("Create") << oi::ProfileId::Create1;
        QTest::newRow("Roomba 500") << oi::ProfileId::Roomba500;
    }
    void keyboardReachesEveryControl()
    {
        QFETCH(oi::ProfileId, id);
        usePanel(id);
        QList<QWidget *> controls;
        for (QWidget *w : m_panel->findChildren<QWidget *>())
            if (w->isVisibleTo(m_panel.get()) && w->isEnabled() && (w->focusPolicy() & Qt::TabFocus)
                && !w->focusProxy() && !qobject_cast<QGroupBox *>(w))
                controls << w;
        QVERIFY(!controls.isEmpty());
        const QList<QWidget *> cycle = tabCycle(m_panel.get(), controls.first());
        for (QWidget *w : controls)
            QVERIFY2(cycle.contains(w), qPrintable(w->objectName() + " is not reached with Tab"));
        QCOMPARE(cycle.size(), controls.size());
        // Tab follows the reading order, wherever the cycle starts.
        qsizetype start = 0;
        for (qsizetype i = 1; i < cycle.size(); ++i)
            if (comesAfter(m_panel.get(), cycle[i], cycle[start]))
                start = i;
        for (qsizetype i = 1; i < cycle.size(); ++i) {
            QWidget *a = cycle[(start + i - 1) % cycle.size()];
            QWidget *b = cycle[(start + i) % cycle.size()];
            QVERIFY2(comesAfter(m_panel.get(), a, b),
                     qPrintable(QStringLiteral("%1 before %2").arg(a->objectName(), b->objectName())));
        }
        // Space presses a focused button, as a click would.
        QWidget *allOff = child<QWidget>("allOff");
        if (allOff->isEnabled()) {
            allOff->setFocus(Qt::TabFocusReason);
            QTest::keyClick(allOff, Qt::Key_Space);
            QCOMPARE(m_sent->count(), 1);
        }
    }

    void screenshots()
    {
        QTemporaryDir temporary;
        const QString dir = qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS")
                                ? qEnvironmentVariable("ROOMBA_SCREENSHOTS")
                                : temporary.path();
        QVERIFY(QDir().mkpath(dir));
        for (auto [id, file] : {std::pair{oi::ProfileId::Create2, "motors_panel_create2.png"},
                                std::pair{oi::ProfileId::Create1, "motors_panel_create1.png"}}) {
            usePanel(id);
            if (id == oi::ProfileId::Create2) {
                click(child<QCheckBox>("mainBrush"));
                click(child<QCheckBox>("sideBrushClockwise"));
                click(child<QCheckBox>("sideBrush"));
                child<QSlider>("mainBrushDuty")->setValue(-64);
            } else {
                click(child<QCheckBox>("lowSide1"));
                child<QSlider>("lowSide2Duty")->setValue(96);
            }
            m_panel->adjustSize();
            const QImage image = m_panel->grab().toImage();
            QVERIFY(!image.isNull());
            const QString path = QDir(dir).filePath(file);
            QVERIFY(image.save(path));
            qInfo("screenshot: %s", qPrintable(path));
        }
        // In Passive: all but Buttons greyed.
        usePanel(oi::ProfileId::Create2);
        m_panel->setMode(reportedMode(m_panel->robotProfile(), oi::OiMode::Passive));
        m_panel->adjustSize();
        const QString passive = QDir(dir).filePath("motors_panel_create2_passive.png");
        QVERIFY(m_panel->grab().save(passive));
        qInfo("screenshot: %s", qPrintable(passive));
    }
};

QTEST_MAIN(TestMotorsPanel)
#include "tst_motors_panel.moc"
