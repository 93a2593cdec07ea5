// SPDX-License-Identifier: GPL-3.0-or-later
#include "connection_bar.h"
#include "robot_address.h"
#include "pseudo_translation.h"
#include "sensor_scenes.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

class TestConnectionBar : public QObject {
    Q_OBJECT
private:
    static void choose(ConnectionBar &bar, const char *combo, int data)
    {
        auto *c = bar.findChild<QComboBox *>(combo);
        c->setCurrentIndex(c->findData(data));
    }
    static void clickConnect(ConnectionBar &bar)
    {
        QTest::mouseClick(bar.findChild<QPushButton *>("connect"), Qt::LeftButton);
    }

private slots:
    void virtualRobotByDefault()
    {
        ConnectionBar bar;
        QSignalSpy spy(&bar, &ConnectionBar::connectRequested);
        clickConnect(bar);
        QCOMPARE(spy.count(), 1);
        const auto r = spy.at(0).at(0).value<ConnectionRequest>();
        QCOMPARE(r.transport, ConnectionRequest::Transport::Virtual);
        QVERIFY(!r.profile.has_value());
        QCOMPARE(r.baud, 0);
    }

    // A robot on a broker (or a recording) is named as it is, not as a
    // virtual robot, and Connect reconnects it; choosing another kind of
    // connection takes its entry away.
    void showsARobotTheBarCannotChoose()
    {
        ConnectionBar bar;
        bar.show();
        bar.showCurrent(QStringLiteral("r1 on the broker"), true);
        auto *transport = bar.findChild<QComboBox *>("transport");
        QCOMPARE(transport->currentText(), QStringLiteral("r1 on the broker"));
        QVERIFY(!bar.findChild<QComboBox *>("profile")->isVisible());
        QVERIFY(!bar.findChild<QComboBox *>("baud")->isVisible());
        QVERIFY(!transport->isEnabled()); // locked while connected
        bar.setConnected(false);
        QSignalSpy spy(&bar, &ConnectionBar::connectRequested);
        clickConnect(bar);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).value<ConnectionRequest>().transport, ConnectionRequest::Transport::Current);

        bar.setRequest(ConnectionRequest{});
        QCOMPARE(transport->count(), 3);
        QCOMPARE(transport->currentText(), QStringLiteral("Virtual robot"));
        QVERIFY(bar.findChild<QComboBox *>("profile")->isVisible());
    }

    void typedSerialPath()
    {
        ConnectionBar bar;
        choose(bar, "transport", int(ConnectionRequest::Transport::Serial));
        choose(bar, "profile", int(oi::ProfileId::Create1));
        choose(bar, "baud", 57600);
        auto *port = bar.findChild<QComboBox *>("port");
        port->setEditText("/dev/pts/7");
        QSignalSpy spy(&bar, &ConnectionBar::connectRequested);
        clickConnect(bar);
        QCOMPARE(spy.count(), 1);
        const auto r = spy.at(0).at(0).value<ConnectionRequest>();
        QCOMPARE(r.portPath, QString("/dev/pts/7"));
        QCOMPARE(r.profile, std::optional<oi::ProfileId>(oi::ProfileId::Create1));
        QCOMPARE(r.baud, 57600);
        QCOMPARE(r.brcLine, oi::BrcLine::Rts); // the default wake line
    }

    // The wake line sits beside the baud for a serial port or a bridge, and
    // goes with the request; the virtual robot has no cable to choose.
    void wakeLineBesideTheBaud()
    {
        ConnectionBar bar;
        bar.show();
        auto *line = bar.findChild<QComboBox *>("brcLine");
        QVERIFY(line);
        QVERIFY(!line->isVisible());
        QVERIFY(!line->accessibleName().isEmpty());
        choose(bar, "transport", int(ConnectionRequest::Transport::Serial));
        QVERIFY(line->isVisible());
        choose(bar, "brcLine", int(oi::BrcLine::Dtr));
        QCOMPARE(line->currentText(), QStringLiteral("Wake: DTR"));
        bar.findChild<QComboBox *>("port")->setEditText("/dev/ttyUSB0");
        QSignalSpy spy(&bar, &ConnectionBar::connectRequested);
        clickConnect(bar);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).value<ConnectionRequest>().brcLine, oi::BrcLine::Dtr);
        ConnectionRequest none;
        none.transport = ConnectionRequest::Transport::Tcp;
        none.brcLine = oi::BrcLine::None;
        bar.setRequest(none);
        QCOMPARE(bar.request().brcLine, oi::BrcLine::None);
        QCOMPARE(line->currentText(), QStringLiteral("Wake: none"));
    }

    void badInputGivesOneInlineError_data()
    {
        QTest::addColumn<int>("transport");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("error");
        QTest::newRow("no serial port") << int(ConnectionRequest::Transport::Serial) << "" << "Choose a serial port";
        QTest::newRow("tcp without port") << int(ConnectionRequest::Transport::Tcp) << "raspberrypi" << "'raspberrypi' is not HOST:PORT with a port from 1 to 65535";
        QTest::newRow("tcp port too big") << int(ConnectionRequest::Transport::Tcp) << "pi:99999" << "1 to 65535";
        QTest::newRow("tcp no host") << int(ConnectionRequest::Transport::Tcp) << ":3333" << "':3333' is not HOST:PORT";
    }
    void badInputGivesOneInlineError()
    {
        QFETCH(int, transport);
        QFETCH(QString, text);
        QFETCH(QString, error);
        ConnectionBar bar;
        choose(bar, "transport", transport);
        if (transport == int(ConnectionRequest::Transport::Tcp))
            bar.findChild<QLineEdit *>("tcp")->setText(text);
        else
            bar.findChild<QComboBox *>("port")->setEditText(text);
        QSignalSpy spy(&bar, &ConnectionBar::connectRequested);
        clickConnect(bar);
        clickConnect(bar);
        QCOMPARE(spy.count(), 0);
        QVERIFY2(bar.errorText().contains(error), qPrintable(bar.errorText()));
        QCOMPARE(bar.errorText().count(error), 1);
    }

    // A bad bridge address gets the same words as on every command line.
    void badBridgeSaysWhatTheCommandLinesSay()
    {
        QString host;
        quint16 port = 0;
        const QString why = oilink::RobotAddress::readHostPort(QStringLiteral("pi"), &host, &port);
        QVERIFY(!why.isEmpty());
        oilink::RobotAddress address;
        QCOMPARE(address.read(QStringLiteral("tcp"), QStringLiteral("pi")), why);
        ConnectionBar bar;
        choose(bar, "transport", int(ConnectionRequest::Transport::Tcp));
        bar.findChild<QLineEdit *>("tcp")->setText(QStringLiteral("pi"));
        clickConnect(bar);
        QCOMPARE(bar.errorText(), why);
    }

    void tcpBridge()
    {
        ConnectionBar bar;
        choose(bar, "transport", int(ConnectionRequest::Transport::Tcp));
        bar.findChild<QLineEdit *>("tcp")->setText("192.168.1.20:3333");
        QSignalSpy spy(&bar, &ConnectionBar::connectRequested);
        clickConnect(bar);
        const auto r = spy.at(0).at(0).value<ConnectionRequest>();
        QCOMPARE(r.host, QString("192.168.1.20"));
        QCOMPARE(r.tcpPort, quint16(3333));
    }

    void requestRoundTrip()
    {
        ConnectionRequest r;
        r.transport = ConnectionRequest::Transport::Tcp;
        r.host = "pi";
        r.tcpPort = 4000;
        r.profile = oi::ProfileId::Roomba500;
        r.baud = 115200;
        ConnectionBar bar;
        bar.setRequest(r);
        QCOMPARE(bar.request().host, r.host);
        QCOMPARE(bar.request().tcpPort, r.tcpPort);
        QCOMPARE(bar.request().profile, r.profile);
        QCOMPARE(bar.request().baud, r.baud);
        QCOMPARE(bar.request().transport, r.transport);
    }

    void connectedState()
    {
        ConnectionBar bar;
        bar.setConnected(true);
        QVERIFY(!bar.findChild<QPushButton *>("connect")->isEnabled());
        QVERIFY(bar.findChild<QPushButton *>("disconnect")->isEnabled());
        QSignalSpy spy(&bar, &ConnectionBar::disconnectRequested);
        QTest::mouseClick(bar.findChild<QPushButton *>("disconnect"), Qt::LeftButton);
        QCOMPARE(spy.count(), 1);
        // The greyed fields say how to change them, beside them and on each.
        bar.show();
        const auto *hint = bar.findChild<QLabel *>("lockedHint");
        QVERIFY(hint->isVisible());
        QCOMPARE(hint->text(), QString("Disconnect to change the port"));
        QCOMPARE(bar.findChild<QComboBox *>("transport")->toolTip(), hint->text());
        bar.setConnected(false);
        QVERIFY(bar.findChild<QPushButton *>("connect")->isEnabled());
        QVERIFY(!hint->isVisible());
        QVERIFY(bar.findChild<QComboBox *>("transport")->toolTip().isEmpty());
        bar.showError("Port busy");
        QCOMPARE(bar.errorText(), QString("Port busy"));
    }

    // Beside "switched off at its power button", a Wake button; pressed, the
    // bar asks for the wake (the window passes it to the robot's link).
    void wakeButtonWhileSwitchedOff()
    {
        ConnectionBar bar;
        bar.show();
        bar.showConnected({ConnectionRequest::Transport::Serial, "/dev/ttyUSB0", {}, 0, oi::ProfileId::Create2, 0});
        auto *wake = bar.findChild<QPushButton *>("wake");
        QVERIFY(wake);
        QVERIFY(!wake->isVisible() && !bar.wakeOffered());
        QSignalSpy asked(&bar, &ConnectionBar::wakeRequested);
        bar.showError("/dev/ttyUSB0: switched off at its power button; press it or use Wake");
        bar.offerWake(true);
        QVERIFY(wake->isVisible() && bar.wakeOffered());
        QCOMPARE(wake->text(), QString("Wake"));
        QTest::mouseClick(wake, Qt::LeftButton);
        QCOMPARE(asked.size(), 1);
        bar.offerWake(false);
        QVERIFY(!wake->isVisible());
    }

    void errorClearsWhenTheLinkRecovers()
    {
        // The adapter is pulled out and plugged back in: the link streams
        // again, and the bar stops saying what went wrong.
        ConnectionBar bar;
        bar.show();
        bar.showConnected({ConnectionRequest::Transport::Serial, "/dev/ttyUSB0", {}, 0, oi::ProfileId::Create2, 0});
        auto *error = bar.findChild<QLabel *>("error");
        QVERIFY(error);
        bar.showError("/dev/ttyUSB0: the port went away");
        bar.showError("/dev/ttyUSB0: no such port");
        QVERIFY(error->isVisible());
        QCOMPARE(bar.errorText(), QString("/dev/ttyUSB0: no such port"));
        bar.clearError();
        QVERIFY(!error->isVisible());
        QCOMPARE(bar.errorText(), QString());
        // Still connected; the next fault is shown again.
        QVERIFY(bar.findChild<QPushButton *>("disconnect")->isEnabled());
        bar.showError("/dev/ttyUSB0: no such port");
        QVERIFY(error->isVisible());

        // An error of the bar's own is gone for good too, in any language.
        bar.setConnected(false);
        choose(bar, "transport", int(ConnectionRequest::Transport::Tcp));
        bar.findChild<QLineEdit *>("tcp")->setText("pi");
        clickConnect(bar);
        QVERIFY(!bar.errorText().isEmpty());
        bar.clearError();
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            QCOMPARE(bar.errorText(), QString());
        }
    }

    void showsWhatIsConnected_data()
    {
        QTest::addColumn<int>("transport");
        QTest::addColumn<QString>("shownTransport");
        QTest::addColumn<QString>("where");
        QTest::newRow("serial") << int(ConnectionRequest::Transport::Serial) << "Serial port" << "/dev/pts/7";
        QTest::newRow("tcp") << int(ConnectionRequest::Transport::Tcp) << "TCP (ser2net)" << "raspberrypi:3333";
        QTest::newRow("virtual") << int(ConnectionRequest::Transport::Virtual) << "Virtual robot" << "";
    }

    void showsWhatIsConnected()
    {
        QFETCH(int, transport);
        QFETCH(QString, shownTransport);
        QFETCH(QString, where);
        // The last choice was a virtual Create 2 over TCP; the command line
        // (--port, --tcp) opened something else.
        ConnectionBar bar;
        bar.show();
        ConnectionRequest last;
        last.transport = transport == int(ConnectionRequest::Transport::Virtual) ? ConnectionRequest::Transport::Serial
                                                                                 : ConnectionRequest::Transport::Virtual;
        last.portPath = "/dev/ttyUSB3";
        last.profile = oi::ProfileId::Create2;
        bar.setRequest(last);

        ConnectionRequest actual;
        actual.transport = ConnectionRequest::Transport(transport);
        if (actual.transport == ConnectionRequest::Transport::Serial)
            actual.portPath = where;
        if (actual.transport == ConnectionRequest::Transport::Tcp) {
            actual.host = where.section(':', 0, 0);
            actual.tcpPort = quint16(where.section(':', 1).toUInt());
        }
        actual.profile = oi::ProfileId::Create1;
        actual.baud = actual.transport == ConnectionRequest::Transport::Virtual ? 0 : 57600;
        bar.showConnected(actual);

        QCOMPARE(bar.request(), actual);
        auto *transportBox = bar.findChild<QComboBox *>("transport");
        QCOMPARE(transportBox->currentText(), shownTransport);
        auto *port = bar.findChild<QComboBox *>("port");
        auto *tcp = bar.findChild<QLineEdit *>("tcp");
        QCOMPARE(port->isVisible(), actual.transport == ConnectionRequest::Transport::Serial);
        QCOMPARE(tcp->isVisible(), actual.transport == ConnectionRequest::Transport::Tcp);
        if (port->isVisible())
            QCOMPARE(port->currentText(), where);
        if (tcp->isVisible())
            QCOMPARE(tcp->text(), where);
        QCOMPARE(bar.findChild<QComboBox *>("profile")->currentText(), QString("Create"));
        // Locked while connected: what it shows is what is connected.
        QVERIFY(!transportBox->isEnabled());
        QVERIFY(!bar.findChild<QPushButton *>("connect")->isEnabled());
        QVERIFY(bar.findChild<QPushButton *>("disconnect")->isEnabled());
    }

    void translatesOnTheSpot()
    {
        ConnectionBar bar;
        choose(bar, "transport", int(ConnectionRequest::Transport::Serial));
        choose(bar, "baud", 57600);
        bar.findChild<QComboBox *>("port")->setEditText(QString());
        clickConnect(bar); // no port: the bar's own error
        bar.show();
        QStringList brands; // robot names are never translated
        for (oi::ProfileId id : oi::allProfiles())
            brands << QString::fromUtf8(oi::profile(id).name.data(), qsizetype(oi::profile(id).name.size()));
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList left = untranslatedTexts(&bar, brands);
            QVERIFY2(left.isEmpty(), qPrintable(left.join('\n')));
            QVERIFY(bar.errorText().contains(kPseudoOpen));
            // The choices survive: same item, same data.
            QCOMPARE(bar.request().transport, ConnectionRequest::Transport::Serial);
            QCOMPARE(bar.request().baud, 57600);
        }
        QCoreApplication::processEvents();
        QCOMPARE(bar.findChild<QPushButton *>("connect")->text(), QString("Connect"));
        QCOMPARE(bar.errorText(), QString("Choose a serial port or type its path."));
        QCOMPARE(bar.findChild<QComboBox *>("transport")->currentText(), QString("Serial port"));
    }

    void keyboardReachesEveryControl()
    {
        ConnectionBar bar;
        choose(bar, "transport", int(ConnectionRequest::Transport::Serial));
        bar.show();
        bar.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&bar));
        auto *transport = bar.findChild<QComboBox *>("transport");
        transport->setFocus(Qt::TabFocusReason);
        QStringList visited;
        while (QWidget *w = QApplication::focusWidget()) {
            // The editable port combo's line edit takes focus on its behalf.
            QWidget *control = w->parentWidget() && w->parentWidget() != &bar ? w->parentWidget() : w;
            if (visited.contains(control->objectName()) || visited.size() > 20)
                break;
            visited << control->objectName();
            QTest::keyClick(w, Qt::Key_Tab);
        }
        // Left to right as laid out; Disconnect is disabled until connected.
        QCOMPARE(visited, QStringList({"transport", "port", "refresh", "profile", "baud", "brcLine", "connect"}));
        // Every control has a name a screen reader can say.
        for (const char *name : {"transport", "port", "tcp", "profile", "baud", "brcLine"})
            QVERIFY2(!bar.findChild<QWidget *>(name)->accessibleName().isEmpty(), name);
        // Enter in the TCP field connects.
        choose(bar, "transport", int(ConnectionRequest::Transport::Tcp));
        auto *tcp = bar.findChild<QLineEdit *>("tcp");
        tcp->setFocus();
        QSignalSpy spy(&bar, &ConnectionBar::connectRequested);
        QTest::keyClicks(tcp, "pi:3333");
        QTest::keyClick(tcp, Qt::Key_Return);
        QCOMPARE(spy.count(), 1);
    }

    void screenshots()
    {
        ConnectionBar bar;
        choose(bar, "transport", int(ConnectionRequest::Transport::Serial));
        clickConnect(bar);
        bar.resize(900, bar.sizeHint().height());
        bar.show();
        sensor_scenes::saveScreenshot(bar, "connection_bar");
        ScopedPseudoTranslation pseudo; // longer texts, as translations are
        QCoreApplication::processEvents();
        sensor_scenes::saveScreenshot(bar, "connection_bar_pseudo");
    }
};

QTEST_MAIN(TestConnectionBar)
#include "tst_connection_bar.moc"
