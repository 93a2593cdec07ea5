// SPDX-License-Identifier: GPL-3.0-or-later
#include "byte_inspector.h"
#include "command_decoder.h"
#include "display_palette.h"
#include "display_tick.h"
#include "typed_command_bytes.h"
#include "pseudo_translation.h"
#include "sensor_scenes.h"
#include "rx_frame_scanner.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QAbstractItemView>
#include <QClipboard>
#include <QPushButton>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>

#include <cmath>

namespace {

QByteArray bytesOf(std::initializer_list<int> values)
{
    QByteArray out;
    for (int v : values)
        out.append(char(v));
    return out;
}

QByteArray bytesFromText(const QString &text)
{
    QByteArray out;
    for (const QString &t : text.split(QLatin1Char(' '), Qt::SkipEmptyParts))
        out.append(char(t.toInt()));
    return out;
}

// A stream frame for these id/value bytes, with the checksum that makes
// the sum of every byte, header included, zero (ERRATA 1).
QByteArray frame(const QByteArray &payload)
{
    QByteArray f;
    f.append(char(19));
    f.append(char(payload.size()));
    f.append(payload);
    int sum = 0;
    for (char c : f)
        sum += static_cast<unsigned char>(c);
    f.append(char((256 - (sum & 0xFF)) & 0xFF));
    return f;
}

// The log as its view shows it: rows, and the text of the last one.
QAbstractItemView *byteLogOf(const ByteInspector &inspector)
{
    return inspector.findChild<QAbstractItemView *>(QStringLiteral("byteLog"));
}

int rowsOf(const QAbstractItemView *view)
{
    return view->model()->rowCount();
}

QString lastRowOf(const QAbstractItemView *view)
{
    const QAbstractItemModel *model = view->model();
    return model->index(model->rowCount() - 1, 0).data().toString();
}

} // namespace

class TestByteInspector : public QObject {
    Q_OBJECT
private slots:
    void decodesSentCommands_data()
    {
        QTest::addColumn<QString>("bytes");
        QTest::addColumn<QString>("meaning");
        QTest::newRow("drive") << "137 255 56 1 244" << "Drive velocity -200 radius 500";
        QTest::newRow("drive straight") << "137 0 200 128 0" << "Drive velocity 200 radius 32768 (straight)";
        QTest::newRow("drive spin") << "137 0 100 255 255" << "Drive velocity 100 radius -1 (turn in place clockwise)";
        QTest::newRow("stream group 100") << "148 1 100" << "Stream 1 packet: group 100 (packets 7..58)";
        QTest::newRow("stream two") << "148 2 22 23" << "Stream 2 packets: Voltage (22), Current (23)";
        QTest::newRow("start") << "128" << "Start";
        QTest::newRow("safe") << "131" << "Safe";
        QTest::newRow("drive direct") << "145 0 200 255 56" << "Drive Direct right velocity 200 left velocity -200";
        QTest::newRow("sensors") << "142 22" << "Sensors Voltage (22)";
        QTest::newRow("baud") << "129 11" << "Baud code 11 (115200 bps)";
        QTest::newRow("song") << "140 0 2 60 32 62 16" << "Song slot 0, 2 notes: C4/32 D4/16";
        QTest::newRow("resume") << "150 1" << "Pause/Resume Stream: resume";
        QTest::newRow("leds") << "139 4 0 255" << "LEDs led bits 4 power led colour 0 power led intensity 255";
        QTest::newRow("digits") << "164 72 73 33 32" << "Digit LEDs ASCII \"HI! \"";
        QTest::newRow("day time") << "168 3 15 5" << "Set Day/Time Wednesday 15:05";
        QTest::newRow("unknown") << "99 1 2" << "not a command of the Roomba 600 / Create 2";
        QTest::newRow("too short") << "137 1" << "Drive, incomplete: 1 of 4 data bytes";
        QTest::newRow("no count byte") << "148" << "Stream, incomplete: its count byte is missing";
        // Shown as the robot reads it, even where the encoder would refuse it.
        QTest::newRow("too fast") << "137 3 232 0 0" << "Drive velocity 1000 radius 0";
        QTest::newRow("pwm motors") << "144 255 1 127" << "PWM Motors main brush pwm -1 side brush pwm 1 vacuum pwm 127";
    }

    void decodesSentCommands()
    {
        QFETCH(QString, bytes);
        QFETCH(QString, meaning);
        ByteInspector inspector;
        inspector.setConnectedAt(0);
        inspector.appendTx(bytesFromText(bytes), 12345);
        QCOMPARE(inspector.entryCount(), 1);
        QCOMPARE(inspector.lastEntries(1).front(),
                 QStringLiteral("    12.345  TX  %1  %2").arg(bytes, meaning));
    }

    void splitsSeveralCommandsInOneWrite()
    {
        ByteInspector inspector;
        inspector.appendTx(bytesOf({128, 131, 137, 0, 0, 0, 0}), 1000);
        const QStringList entries = inspector.lastEntries(10);
        QCOMPARE(entries.size(), 3);
        QVERIFY(entries[0].endsWith(QStringLiteral("TX  128  Start")));
        QVERIFY(entries[1].endsWith(QStringLiteral("TX  131  Safe")));
        QVERIFY(entries[2].endsWith(QStringLiteral("TX  137 0 0 0 0  Drive velocity 0 radius 0")));
        QCOMPARE(inspector.txBytes(), quint64(7));
    }

    void hexBytes()
    {
        ByteInspector inspector;
        inspector.appendTx(bytesOf({137, 255, 56, 1, 244}), 0);
        inspector.setShowsHex(true);
        QVERIFY(inspector.lastEntries(1).front().endsWith(
            QStringLiteral("TX  89 FF 38 01 F4  Drive velocity -200 radius 500")));
    }

    void marksStreamFrames()
    {
        ByteInspector inspector;
        inspector.setConnectedAt(0);
        // The documents' example: cliff front left signal 537, virtual wall 0.
        inspector.appendRx(bytesOf({19, 5, 29, 2, 25, 13, 0, 163}), 2000);
        QCOMPARE(inspector.lastEntries(1).front(),
                 QStringLiteral("     2.000  RX  19 5 29 2 25 13 0 163  stream frame: "
                                "Cliff Front Left Signal 537, Virtual Wall 0"));
    }

    void frameSplitAcrossReadsAndJunkBeforeIt()
    {
        ByteInspector inspector;
        const QByteArray f = frame(bytesOf({22, 0x39, 0xE4, 23, 0xFF, 0x06}));
        inspector.appendRx(bytesOf({1, 2}) + f.left(3), 10);
        QCOMPARE(inspector.entryCount(), 1); // the junk; the frame's start is held
        QVERIFY(inspector.lastEntries(1).front().endsWith(QStringLiteral("RX  1 2  outside any stream frame")));
        inspector.appendRx(f.mid(3), 25);
        QCOMPARE(inspector.entryCount(), 2);
        QVERIFY(inspector.lastEntries(1).front().endsWith(
            QStringLiteral("stream frame: Voltage 14820 mV, Current -250 mA")));
        QCOMPARE(inspector.rxBytes(), quint64(2 + f.size()));

        // A bad checksum is no frame.
        QByteArray bad = frame(bytesOf({22, 0x39, 0xE4}));
        bad[bad.size() - 1] = char(bad.back() + 1);
        inspector.appendRx(bad, 40);
        QVERIFY(inspector.lastEntries(1).front().endsWith(QStringLiteral("outside any stream frame")));
    }

    void readsRepliesToRequests()
    {
        ByteInspector inspector;
        // The bytes of a request alone are shown, not read for what they ask.
        inspector.appendTx(bytesOf({142, 22}), 50);
        inspector.appendRx(bytesOf({0x39, 0xE4}), 62);
        QVERIFY(inspector.lastEntries(1).front().endsWith(QStringLiteral("outside any stream frame")));
        // The link's typed commands say what was asked.
        inspector.expectReplies({{oi::Command::Sensors, {22}, {}}}, 100);
        inspector.appendTx(bytesOf({142, 22}), 100);
        inspector.appendRx(bytesOf({0x39, 0xE4}), 112);
        QVERIFY(inspector.lastEntries(1).front().endsWith(QStringLiteral("RX  57 228  reply: Voltage 14820 mV")));
        inspector.expectReplies({{oi::Command::Start, {}, {}}, {oi::Command::QueryList, {}, {21, 24}}}, 200);
        inspector.appendTx(bytesOf({149, 2, 21, 24}), 200);
        inspector.appendRx(bytesOf({2}), 210);
        inspector.appendRx(bytesOf({23}), 215);
        QVERIFY(inspector.lastEntries(1).front().endsWith(
            QStringLiteral("RX  2 23  reply: Charging State 2, Temperature 23 \u00b0C")));
        // Long after a request, bytes are not taken for its reply.
        inspector.expectReplies({{oi::Command::Sensors, {22}, {}}}, 300);
        inspector.appendTx(bytesOf({142, 22}), 300);
        inspector.appendRx(bytesOf({0x39, 0xE4}), 300 + RxFrameScanner::kReplyTimeoutMs + 1);
        QVERIFY(inspector.lastEntries(1).front().endsWith(QStringLiteral("outside any stream frame")));
    }

    void showsTheBannerAsText()
    {
        ByteInspector inspector;
        inspector.appendRx(QByteArray("bl-start\r\n"), 0);
        QVERIFY(inspector.lastEntries(1).front().endsWith(QStringLiteral("text \"bl-start\\r\\n\"")));
    }

    // A docked Roomba's status line between two frames, in one read.
    void showsTheDockedStatusLineBetweenFrames()
    {
        ByteInspector inspector;
        const QByteArray f = frame(bytesOf({22, 0x39, 0xE4}));
        inspector.appendRx(f + QByteArray("bat:   min 0  sec 12  mV 16421  mA 1500\r\n") + f, 0);
        const QStringList entries = inspector.lastEntries(3);
        QCOMPARE(entries.size(), 3);
        QVERIFY(entries[0].contains(QStringLiteral("stream frame: Voltage 14820 mV")));
        QVERIFY2(entries[1].endsWith(QStringLiteral("text \"bat:   min 0  sec 12  mV 16421  mA 1500\\r\\n\"")),
                 qPrintable(entries[1]));
        QVERIFY(entries[2].contains(QStringLiteral("stream frame: Voltage 14820 mV")));
    }

    void keepsABoundedLog()
    {
        ByteInspector inspector;
        QCOMPARE(inspector.maxEntries(), ByteInspector::kDefaultMaxEntries);
        for (int i = 0; i < 6000; ++i)
            inspector.appendTx(bytesOf({128}), i);
        QCOMPARE(inspector.entryCount(), 5000);
        QCOMPARE(inspector.totalEntries(), quint64(6000));
        QVERIFY(inspector.lastEntries(5000).front().startsWith(QStringLiteral("     1.000  TX")));
        inspector.flushView();
        auto *view = byteLogOf(inspector);
        QVERIFY(view);
        QCOMPARE(rowsOf(view), 5000);
        for (int i = 0; i < 100; ++i)
            inspector.appendTx(bytesOf({131}), 6000 + i);
        inspector.flushView();
        QCOMPARE(rowsOf(view), 5000);
        QVERIFY(lastRowOf(view).endsWith(QStringLiteral("131  Safe")));

        inspector.setMaxEntries(10);
        QCOMPARE(inspector.entryCount(), 10);
        inspector.clear();
        QCOMPARE(inspector.entryCount(), 0);
        QCOMPARE(inspector.totalEntries(), quint64(0));
        QVERIFY(rowsOf(view) == 0);
    }

    // A full log moves on at its ends: the oldest rows go from the front, the
    // new ones come at the back, and the view is never told to start over.
    void fullLogDropsRowsAtTheFrontNotAReset()
    {
        ByteInspector inspector;
        for (int i = 0; i < 5000; ++i)
            inspector.appendTx(bytesOf({128}), i);
        inspector.flushView();
        QAbstractItemView *view = byteLogOf(inspector);
        QAbstractItemModel *model = view->model();
        QCOMPARE(model->rowCount(), 5000);
        QSignalSpy removed(model, &QAbstractItemModel::rowsRemoved);
        QSignalSpy inserted(model, &QAbstractItemModel::rowsInserted);
        QSignalSpy reset(model, &QAbstractItemModel::modelReset);
        QSignalSpy layout(model, &QAbstractItemModel::layoutChanged);
        for (int i = 0; i < 100; ++i)
            inspector.appendTx(bytesOf({131}), 5000 + i);
        QCOMPARE(inserted.size(), 0); // recorded, not shown until the view draws
        inspector.flushView();
        QCOMPARE(removed.size(), 1);
        QCOMPARE(removed.front().at(1).toInt(), 0);
        QCOMPARE(removed.front().at(2).toInt(), 99);
        QCOMPARE(inserted.size(), 1);
        QCOMPARE(inserted.front().at(1).toInt(), 4900);
        QCOMPARE(inserted.front().at(2).toInt(), 4999);
        QCOMPARE(reset.size(), 0);
        QCOMPARE(layout.size(), 0);
        QCOMPARE(model->rowCount(), 5000);
        QCOMPARE(model->index(0, 0).data().toString(), QStringLiteral("     0.100  TX  128  Start"));
        QCOMPARE(lastRowOf(view), QStringLiteral("     5.099  TX  131  Safe"));
    }

    // The log follows the newest entries while the reader is at the end;
    // scrolled up, the rows being read stay in sight as old ones drop off.
    void followsTheEndUnlessScrolledUp()
    {
        ByteInspector inspector;
        inspector.setMaxEntries(1000);
        inspector.resize(900, 400);
        inspector.show();
        QVERIFY(QTest::qWaitForWindowExposed(&inspector));
        QAbstractItemView *view = byteLogOf(inspector);
        QScrollBar *scroll = view->verticalScrollBar();
        int at = 0;
        const auto append = [&](int count) {
            for (int i = 0; i < count; ++i, ++at)
                inspector.appendTx(bytesOf({128}), at);
            inspector.flushView();
            view->doItemsLayout(); // as before the next paint
        };
        append(1000);
        QVERIFY(scroll->maximum() > 0);
        QCOMPARE(scroll->value(), scroll->maximum());
        append(30);
        QCOMPARE(scroll->value(), scroll->maximum());
        // The newest row is the last one in sight (below it, less than a
        // row's height of the viewport may stay empty, by the font's height).
        const QRect newest = view->visualRect(view->model()->index(999, 0));
        QVERIFY(view->viewport()->rect().contains(newest.topLeft()));
        QVERIFY(newest.bottom() + newest.height() > view->viewport()->rect().bottom());

        scroll->setValue(scroll->maximum() / 2);
        const QString reading = view->indexAt(QPoint(5, 5)).data().toString();
        append(50); // 50 old rows drop off the front
        QCOMPARE(view->indexAt(QPoint(5, 5)).data().toString(), reading);
        QVERIFY(scroll->value() < scroll->maximum());

        view->scrollToBottom();
        append(10);
        QCOMPARE(scroll->value(), scroll->maximum());
        QCOMPARE(lastRowOf(view), inspector.lastEntries(1).front());
    }

    // Selected rows copy as the log shows them, whole, one line each.
    void copiesTheSelectedRows()
    {
        ByteInspector inspector;
        inspector.setConnectedAt(0);
        inspector.show();
        inspector.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&inspector));
        // A script as one long write: its song runs far past the view's edge.
        QByteArray song = bytesOf({140, 0, 16});
        for (int i = 0; i < 16; ++i)
            song += bytesOf({60 + i, 16});
        inspector.appendTx(bytesOf({128, 131}), 1000);
        inspector.appendTx(song, 1500);
        inspector.flushView();
        QAbstractItemView *view = byteLogOf(inspector);
        view->setFocus();
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(view->model()->index(1, 0)).center());
        QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::ShiftModifier,
                          view->visualRect(view->model()->index(2, 0)).center());
        QGuiApplication::clipboard()->clear();
        QTest::keyClick(view, Qt::Key_C, Qt::ControlModifier);
        const QStringList lines = inspector.lastEntries(2);
        QVERIFY(lines.back().contains(QStringLiteral("Song slot 0, 16 notes")));
        QCOMPARE(QGuiApplication::clipboard()->text(), lines.join('\n'));
        // The long line is cut in the view; its tooltip shows it whole.
        QCOMPARE(view->model()->index(2, 0).data(Qt::ToolTipRole).toString(), lines.back());
        QVERIFY(view->fontMetrics().horizontalAdvance(lines.back()) > view->viewport()->width());
    }

    // Each part of a row in its colour: a sent command in the link's
    // colour, a command the robot cannot read in the alert colour, and so
    // on a dark palette too.
    void coloursFollowWhatEachEntryIsAndThePalette()
    {
        ByteInspector inspector;
        inspector.resize(900, 300);
        inspector.show();
        QVERIFY(QTest::qWaitForWindowExposed(&inspector));
        inspector.appendTx(bytesOf({128}), 0);    // Start: a command
        inspector.appendTx(bytesOf({99, 1}), 10); // no command: a problem
        inspector.flushView();
        QAbstractItemView *view = byteLogOf(inspector);
        const auto hasColour = [view](int row, const QColor &colour) {
            const QImage image = view->viewport()->grab().toImage();
            const QRect rect = view->visualRect(view->model()->index(row, 0));
            for (int y = rect.top(); y <= rect.bottom(); ++y)
                for (int x = rect.left(); x <= rect.right(); ++x)
                    if (image.pixelColor(x * image.width() / view->viewport()->width(),
                                         y * image.height() / view->viewport()->height()) == colour)
                        return true;
            return false;
        };
        for (const QPalette &palette : {QApplication::palette(), sensor_scenes::darkPalette()}) {
            inspector.setPalette(palette);
            const QColor command = display::stateColor(display::State::Active, palette);
            const QColor alert = display::stateColor(display::State::Alert, palette);
            QVERIFY(hasColour(0, command));
            QVERIFY(!hasColour(0, alert));
            QVERIFY(hasColour(1, alert));
        }
    }

    void rendersOnATimerNotPerAppend()
    {
        ByteInspector inspector;
        inspector.show();
        auto *view = byteLogOf(inspector);
        inspector.appendTx(bytesOf({128}), 0);
        inspector.appendTx(bytesOf({131}), 1);
        QVERIFY(rowsOf(view) == 0); // nothing drawn yet
        QVERIFY(DisplayTick::instance().hasFrameFor(&inspector)); // on the display's tick
        QTRY_COMPARE(rowsOf(view), 2);
    }

    // The counts follow on the display's tick, not with every render, and
    // end on the last entry's.
    void countsShowTheLastEntries()
    {
        ByteInspector inspector;
        inspector.show();
        auto *status = inspector.findChild<QLabel *>(QStringLiteral("status"));
        for (int i = 0; i < 5; ++i) {
            inspector.appendTx(bytesOf({128}), i);
            inspector.flushView();
        }
        QVERIFY(DisplayTick::instance().hasFrameFor(status));
        QTRY_COMPARE(status->text(), QString("5 entries \u00b7 TX 5 B \u00b7 RX 0 B"));
        QTRY_VERIFY(!DisplayTick::instance().hasFrameFor(status));
    }

    void hiddenLogRendersWhenShown()
    {
        ByteInspector inspector;
        auto *view = byteLogOf(inspector);
        inspector.appendTx(bytesOf({128}), 0);
        inspector.appendTx(bytesOf({131}), 1);
        // Hidden: nothing laid out, and nothing scheduled to be.
        QVERIFY(!DisplayTick::instance().hasFrameFor(&inspector));
        QVERIFY(rowsOf(view) == 0);
        QCOMPARE(inspector.entryCount(), 2); // but kept
        inspector.show();
        QCOMPARE(rowsOf(view), 2);
    }

    void pauseFreezesTheViewButKeepsCounting()
    {
        ByteInspector inspector;
        auto *view = byteLogOf(inspector);
        inspector.appendTx(bytesOf({128}), 0);
        inspector.flushView();
        inspector.setPaused(true);
        inspector.appendTx(bytesOf({131}), 1);
        inspector.appendTx(bytesOf({132}), 2);
        inspector.flushView();
        QCOMPARE(rowsOf(view), 1);
        QCOMPARE(inspector.entryCount(), 3);
        QCOMPARE(inspector.totalEntries(), quint64(3));
        inspector.setPaused(false);
        QCOMPARE(rowsOf(view), 3);
        QVERIFY(lastRowOf(view).endsWith(QStringLiteral("132  Full")));
    }

    void timesReadAsClockTimeOrSinceConnect()
    {
        ByteInspector inspector;
        auto *view = byteLogOf(inspector);
        const qint64 at = QDateTime(QDate(2026, 11, 23), QTime(14, 3, 12, 345)).toMSecsSinceEpoch();
        // Until the connect time is given, times count from the first entry.
        inspector.appendTx(bytesOf({128}), at - 500);
        inspector.appendTx(bytesOf({131}), at);
        QCOMPARE(inspector.timeFormat(), ByteInspector::TimeFormat::SinceConnect);
        QCOMPARE(inspector.lastEntries(2),
                 QStringList({"     0.000  TX  128  Start", "     0.500  TX  131  Safe"}));
        inspector.setConnectedAt(at - 12'000);
        QCOMPARE(inspector.lastEntries(1).front(), QStringLiteral("    12.000  TX  131  Safe"));
        inspector.flushView();
        QCOMPARE(lastRowOf(view), QStringLiteral("    12.000  TX  131  Safe"));

        // The choice in the bar shows the time of day, in the log as well.
        auto *choice = inspector.findChild<QComboBox *>(QStringLiteral("timeFormat"));
        QVERIFY(choice);
        choice->setCurrentIndex(choice->findData(int(ByteInspector::TimeFormat::ClockTime)));
        QCOMPARE(inspector.timeFormat(), ByteInspector::TimeFormat::ClockTime);
        QCOMPARE(inspector.lastEntries(2),
                 QStringList({"14:03:11.845  TX  128  Start", "14:03:12.345  TX  131  Safe"}));
        QCOMPARE(lastRowOf(view), QStringLiteral("14:03:12.345  TX  131  Safe"));
        inspector.setTimeFormat(ByteInspector::TimeFormat::SinceConnect);
        QCOMPARE(choice->currentData().toInt(), int(ByteInspector::TimeFormat::SinceConnect));
        QCOMPARE(lastRowOf(view), QStringLiteral("    12.000  TX  131  Safe"));
    }

    void packetTableShowsEachPacket()
    {
        ByteInspector inspector;
        inspector.show();
        PacketTable *table = inspector.packetTable();
        PacketTableModel *model = table->model();
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        const oi::SensorSnapshot s = sensor_scenes::decoded(create2, sensor_scenes::quietValues(create2));
        // 68 frames, 15 ms apart: 67 in the first whole second after the first.
        for (int i = 0; i <= 67; ++i)
            inspector.addSnapshot(i * 0.015, s);
        table->refresh();
        QCOMPARE(model->rowCount(), 58 - 7 + 1); // group 100: packets 7..58
        QCOMPARE(model->packetIdAt(0), 7);
        const int voltage = model->rowOfPacket(22);
        const int current = model->rowOfPacket(23);
        QVERIFY(voltage >= 0 && current >= 0);
        const auto cell = [model](int row, int column) { return model->index(row, column).data().toString(); };
        QCOMPARE(cell(voltage, PacketTableModel::IdColumn), QStringLiteral("22"));
        QCOMPARE(cell(voltage, PacketTableModel::NameColumn), QStringLiteral("Voltage"));
        QCOMPARE(cell(voltage, PacketTableModel::ValueColumn), QStringLiteral("15120 mV"));
        QCOMPARE(cell(voltage, PacketTableModel::RawColumn), QStringLiteral("59 16"));
        QCOMPARE(cell(current, PacketTableModel::ValueColumn), QStringLiteral("-210 mA"));
        QCOMPARE(cell(current, PacketTableModel::RawColumn), QStringLiteral("255 46"));
        QCOMPARE(cell(model->rowOfPacket(35), PacketTableModel::RawColumn), QStringLiteral("2")); // one byte
        QVERIFY(qAbs(model->rate(22) - 67 / 1.005) < 1e-9);
        QCOMPARE(cell(voltage, PacketTableModel::RateColumn), QStringLiteral("66.7 Hz"));
        // The header says what each column is.
        QCOMPARE(model->headerData(PacketTableModel::RateColumn, Qt::Horizontal).toString(), QStringLiteral("Rate"));

        // The hex choice of the log applies to the raw bytes too.
        inspector.setShowsHex(true);
        QCOMPARE(cell(voltage, PacketTableModel::RawColumn), QStringLiteral("3B 10"));
        QCOMPARE(cell(current, PacketTableModel::RawColumn), QStringLiteral("FF 2E"));

        // A packet that stops coming drops to 0 Hz at the next window.
        oi::SensorSnapshot onlyMode(create2);
        onlyMode.set(35, 3);
        for (int i = 68; i <= 136; ++i)
            inspector.addSnapshot(i * 0.015, onlyMode);
        table->refresh();
        QCOMPARE(model->rate(22), 0.0);
        QVERIFY(qAbs(model->rate(35) - 67.0 / 1.005) < 1e-9);
        QCOMPARE(cell(model->rowOfPacket(35), PacketTableModel::ValueColumn), QStringLiteral("3"));
        QCOMPARE(cell(voltage, PacketTableModel::ValueColumn), QStringLiteral("15120 mV")); // the last one kept

        // Another robot's packets are other packets: the table starts again.
        inspector.setProfile(oi::profile(oi::ProfileId::Create1));
        QCOMPARE(model->rowCount(), 0);
        // An IR byte reads as the character it is, not a bare number.
        inspector.setProfile(create2);
        oi::SensorSnapshot wall = s;
        wall.set(17, 162);
        inspector.addSnapshot(100.0, wall);
        table->refresh();
        QCOMPARE(cell(model->rowOfPacket(17), PacketTableModel::ValueColumn), QStringLiteral("162 Virtual Wall"));
    }

    void packetTableInsertsRowsOnceAndUpdatesCells()
    {
        ByteInspector inspector;
        inspector.show();
        PacketTable *table = inspector.packetTable();
        PacketTableModel *model = table->model();
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        std::map<int, int> values = sensor_scenes::quietValues(create2);
        QSignalSpy inserted(model, &QAbstractItemModel::rowsInserted);
        QSignalSpy reset(model, &QAbstractItemModel::modelReset);
        QSignalSpy layout(model, &QAbstractItemModel::layoutChanged);
        QSignalSpy changed(model, &QAbstractItemModel::dataChanged);

        // A reply with two packets, then the stream with all of them.
        oi::SensorSnapshot reply(create2);
        reply.set(22, 15000);
        reply.set(25, 2000);
        inspector.addSnapshot(0, reply);
        QTRY_COMPARE(model->rowCount(), 2); // at display rate, from the table's own timer
        QCOMPARE(inserted.size(), 2);
        for (int i = 1; i <= 300; ++i) {
            values[22] = 15000 - i;
            inspector.addSnapshot(i * 0.015, sensor_scenes::decoded(create2, values));
            if (i % 3 == 0)
                table->refresh(); // a display tick every third frame
        }
        QCOMPARE(model->rowCount(), 52);
        QCOMPARE(inserted.size(), 2 + 50); // each packet's row once
        QCOMPARE(reset.size(), 0);
        QCOMPARE(layout.size(), 0);
        // Only the changed cells: the voltage row, and the rates once a second.
        // Only the changed rows: the voltage's at each tick, the charge's once
        // (the stream's value after the reply's), and every rate once a second.
        int voltage = 0, charge = 0, rates = 0;
        for (const QList<QVariant> &args : std::as_const(changed)) {
            const QModelIndex top = args.at(0).toModelIndex(), bottom = args.at(1).toModelIndex();
            QVERIFY(top.column() == PacketTableModel::ValueColumn && bottom.column() == PacketTableModel::RateColumn);
            if (top.row() == 0 && bottom.row() == model->rowCount() - 1)
                ++rates;
            else if (top.row() == model->rowOfPacket(22) && bottom.row() == top.row())
                ++voltage;
            else if (top.row() == model->rowOfPacket(25) && bottom.row() == top.row())
                ++charge;
            else
                QFAIL(qPrintable(QStringLiteral("rows %1 to %2 said changed").arg(top.row()).arg(bottom.row())));
        }
        QCOMPARE(rates, 1);
        QCOMPARE(voltage, 99);
        QCOMPARE(charge, 1);
        QCOMPARE(model->index(model->rowOfPacket(22), PacketTableModel::ValueColumn).data().toString(),
                 QStringLiteral("14700 mV"));
        // A refresh with nothing new says nothing.
        changed.clear();
        table->refresh();
        QCOMPARE(changed.size(), 0);
        // Two rows apart change: each is said alone, and the rows between
        // them are not repainted.
        values[7] = 1;
        values[25] = 1999;
        inspector.addSnapshot(301 * 0.015, sensor_scenes::decoded(create2, values));
        table->refresh();
        QCOMPARE(changed.size(), 2);
        QCOMPARE(changed.at(0).at(0).toModelIndex().row(), model->rowOfPacket(7));
        QCOMPARE(changed.at(0).at(1).toModelIndex().row(), model->rowOfPacket(7));
        QCOMPARE(changed.at(1).at(0).toModelIndex().row(), model->rowOfPacket(25));
        QCOMPARE(changed.at(1).at(1).toModelIndex().row(), model->rowOfPacket(25));
    }

    void hiddenPacketTableTakesNothing()
    {
        ByteInspector inspector;
        PacketTable *table = inspector.packetTable();
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        const oi::SensorSnapshot s = sensor_scenes::decoded(create2, sensor_scenes::quietValues(create2));
        for (int i = 0; i < 100; ++i)
            inspector.addSnapshot(i * 0.015, s);
        QVERIFY(!DisplayTick::instance().hasFrameFor(table)); // no frame of the display's tick
        table->refresh();
        QCOMPARE(table->model()->rowCount(), 0); // and nothing kept for one
        inspector.show();
        inspector.addSnapshot(2.0, s);
        QVERIFY(DisplayTick::instance().hasFrameFor(table));
        QTRY_COMPARE(table->model()->rowCount(), 52);
    }

    void plotButtonAndDoubleClickAskForAPlot()
    {
        ByteInspector inspector;
        inspector.resize(1000, 500);
        inspector.show();
        QVERIFY(QTest::qWaitForWindowExposed(&inspector));
        QSignalSpy plot(&inspector, &ByteInspector::plotRequested);
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        inspector.addSnapshot(0, sensor_scenes::decoded(create2, sensor_scenes::quietValues(create2)));
        inspector.packetTable()->refresh();
        auto *view = inspector.findChild<QTableView *>(QStringLiteral("packetTable"));
        auto *button = inspector.findChild<QPushButton *>(QStringLiteral("plotButton"));
        QVERIFY(view && button);
        QVERIFY(!button->isEnabled()); // no packet chosen yet
        const int row = inspector.packetTable()->model()->rowOfPacket(22);
        view->selectRow(row);
        QVERIFY(button->isEnabled());
        QTest::mouseClick(button, Qt::LeftButton);
        QCOMPARE(plot.size(), 1);
        QCOMPARE(plot.last().at(0).toInt(), 22);

        const int cliff = inspector.packetTable()->model()->rowOfPacket(29);
        view->scrollTo(view->model()->index(cliff, PacketTableModel::NameColumn));
        const QRect cell = view->visualRect(view->model()->index(cliff, PacketTableModel::NameColumn));
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, cell.center());
        QCOMPARE(plot.size(), 1); // one click chooses
        QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, cell.center());
        QCOMPARE(plot.size(), 2);
        QCOMPARE(plot.last().at(0).toInt(), 29);
    }

    void refusesBadRawInput_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("error");
        QTest::newRow("not a byte") << "300" << "Byte 1: 300 is outside 0..255.";
        QTest::newRow("not a number") << "abc" << "Byte 1: \u201cabc\u201d is not a number.";
        QTest::newRow("too short") << "137 1" << "Drive (137) takes 4 data bytes; got 1.";
        QTest::newRow("negative") << "128 -1" << "Byte 2: -1 is outside 0..255.";
        QTest::newRow("no opcode") << "99" << "Byte 1: 99 is not an opcode of the Roomba 600 / Create 2.";
        QTest::newRow("second command short") << "128 145 0" << "Drive Direct (145) takes 4 data bytes; got 1.";
        QTest::newRow("empty") << "" << "Type the bytes to send, for example 128 131 or 0x80 0x83.";
        QTest::newRow("too fast") << "137 7 208 0 0" << "Drive (137): velocity: 2000 is outside -500..500";
        QTest::newRow("stream count") << "148 2 22" << "Stream (148) takes 3 data bytes; got 2.";
    }

    void refusesBadRawInput()
    {
        QFETCH(QString, text);
        QFETCH(QString, error);
        ByteInspector inspector;
        inspector.show();
        QVERIFY(QTest::qWaitForWindowExposed(&inspector));
        QSignalSpy spy(&inspector, &ByteInspector::sendRequested);
        auto *input = inspector.findChild<QLineEdit *>(QStringLiteral("rawInput"));
        auto *message = inspector.findChild<QLabel *>(QStringLiteral("rawError"));
        QVERIFY(input && message);
        QTest::keyClicks(input, text);
        QTest::keyClick(input, Qt::Key_Return);
        QCOMPARE(spy.count(), 0);
        QVERIFY(message->isVisible());
        QCOMPARE(message->text(), error);
        QCOMPARE(input->text(), text); // kept for correcting
        QTest::keyClick(input, Qt::Key_End);
        QTest::keyClicks(input, QStringLiteral(" "));
        QVERIFY(!message->isVisible()); // editing clears the message
    }

    void sendsGoodRawInput_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("start safe") << "128 131" << bytesOf({128, 131});
        QTest::newRow("hex") << "0x80 0x83" << bytesOf({128, 131});
        QTest::newRow("commas") << "128, 131" << bytesOf({128, 131});
        QTest::newRow("drive") << "137 255 56 1 244" << bytesOf({137, 255, 56, 1, 244});
        QTest::newRow("stream") << "148 1 100" << bytesOf({148, 1, 100});
        QTest::newRow("song") << "140 0 1 60 32" << bytesOf({140, 0, 1, 60, 32});
    }

    void sendsGoodRawInput()
    {
        QFETCH(QString, text);
        QFETCH(QByteArray, bytes);
        ByteInspector inspector;
        inspector.show();
        QVERIFY(QTest::qWaitForWindowExposed(&inspector));
        QSignalSpy spy(&inspector, &ByteInspector::sendRequested);
        auto *input = inspector.findChild<QLineEdit *>(QStringLiteral("rawInput"));
        auto *send = inspector.findChild<QPushButton *>(QStringLiteral("sendButton"));
        QTest::keyClicks(input, text);
        QTest::mouseClick(send, Qt::LeftButton);
        QCOMPARE(spy.count(), 1);
        // Typed commands, whose bytes are the ones typed.
        QCOMPARE(bytesOfCommands(oi::profile(oi::ProfileId::Create2), spy.front().front()), bytes);
        QVERIFY(input->text().isEmpty());
        QVERIFY(inspector.findChild<QLabel *>(QStringLiteral("rawError"))->isHidden());
    }

    void rawCheckFollowsTheProfile()
    {
        ByteInspector inspector;
        QString error;
        // 143 is Seek Dock on a Create 2 and Cover and Dock on a Create 1;
        // 147 (Digital Outputs) exists only on the Create 1.
        QVERIFY(!inspector.parseRawBytes(QStringLiteral("147 1"), &error));
        inspector.setProfile(oi::profile(oi::ProfileId::Create1));
        QCOMPARE(inspector.parseRawBytes(QStringLiteral("147 1"), &error), bytesOf({147, 1}));
        inspector.appendTx(bytesOf({138, 7}), 0);
        QVERIFY(inspector.lastEntries(1).front().endsWith(QStringLiteral("Low Side Drivers driver bits 7")));
    }

    void snapshot()
    {
        // Into ROOMBA_WIDGET_SNAPSHOT_DIR for a person to look at, else a scratch folder.
        QTemporaryDir scratch;
        QByteArray dir = qgetenv("ROOMBA_WIDGET_SNAPSHOT_DIR");
        if (dir.isEmpty())
            dir = scratch.path().toLocal8Bit();
        ByteInspector inspector;
        inspector.resize(1200, 600);
        inspector.show();
        QVERIFY(QTest::qWaitForWindowExposed(&inspector));
        qint64 ms = 81'000;
        inspector.appendTx(bytesOf({7}), ms);
        inspector.appendRx(QByteArray("bl-start\r\n2015-01-07-2130-L   \r\nbattery-current-zero 252\r\n"), ms += 40);
        inspector.appendTx(bytesOf({128}), ms += 900);
        inspector.appendTx(bytesOf({131}), ms += 20);
        inspector.expectReplies({{oi::Command::Sensors, {22}, {}}}, ms += 30);
        inspector.appendTx(bytesOf({142, 22}), ms);
        inspector.appendRx(bytesOf({0x39, 0xE4}), ms += 12);
        inspector.appendTx(bytesOf({148, 4, 7, 22, 23, 46}), ms += 30);
        for (int i = 0; i < 24; ++i) {
            ms += 15;
            const int volts = 14820 - i, amps = -250 - 7 * (i % 5), light = 40 + 60 * i;
            QByteArray payload = bytesOf({7, i == 9 ? 2 : 0, 22, volts >> 8, volts & 0xFF, 23,
                                          (amps >> 8) & 0xFF, amps & 0xFF, 46, light >> 8, light & 0xFF});
            const QByteArray f = frame(payload);
            if (i == 5) { // a read that splits a frame, and a little line noise
                inspector.appendRx(bytesOf({0, 255}) + f.left(6), ms);
                inspector.appendRx(f.mid(6), ms + 2);
            } else {
                inspector.appendRx(f, ms);
            }
            if (i == 8)
                inspector.appendTx(bytesOf({137, 255, 56, 1, 244}), ms + 3);
            if (i == 16)
                inspector.appendTx(bytesOf({137, 0, 0, 0, 0}), ms + 3);
        }
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        const oi::SensorSnapshot busy = sensor_scenes::decoded(create2, sensor_scenes::busyValues(create2));
        for (int i = 0; i <= 80; ++i)
            inspector.addSnapshot(i * 0.015, busy);
        inspector.packetTable()->refresh();
        inspector.appendTx(bytesOf({140, 0, 4, 60, 16, 64, 16, 67, 16, 72, 32}), ms += 20);
        inspector.appendTx(bytesOf({141, 0}), ms += 20);
        inspector.appendTx(bytesOf({99, 4}), ms += 20);
        inspector.flushView();
        auto *input = inspector.findChild<QLineEdit *>(QStringLiteral("rawInput"));
        QTest::keyClicks(input, QStringLiteral("137 1"));
        QTest::keyClick(input, Qt::Key_Return);
        QCoreApplication::processEvents();
        QVERIFY(inspector.grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("byte_inspector.png"))));
        // The start of the log, in hexadecimal.
        inspector.setShowsHex(true);
        byteLogOf(inspector)->verticalScrollBar()->setValue(0);
        QCoreApplication::processEvents();
        QVERIFY(inspector.grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("byte_inspector_top.png"))));
    }

    void translatesOnTheSpot()
    {
        ByteInspector inspector;
        inspector.show();
        inspector.appendTx(bytesOf({128, 131}), 1000);
        inspector.flushView();
        inspector.setPaused(true);
        inspector.appendTx(bytesOf({132}), 1100);
        auto *input = inspector.findChild<QLineEdit *>(QStringLiteral("rawInput"));
        QTest::keyClicks(input, QStringLiteral("300"));
        QTest::keyClick(input, Qt::Key_Return); // an error to say again
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        inspector.addSnapshot(0, sensor_scenes::decoded(create2, sensor_scenes::quietValues(create2)));
        inspector.packetTable()->refresh();
        const PacketTableModel *model = inspector.packetTable()->model();
        const QModelIndex voltageName = model->index(model->rowOfPacket(22), PacketTableModel::NameColumn);
        QSignalSpy headers(model, &QAbstractItemModel::headerDataChanged);
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList left = untranslatedTexts(&inspector);
            QVERIFY2(left.isEmpty(), qPrintable(left.join('\n')));
            // The table's headers and packet names too, and its views are told.
            QVERIFY(!headers.isEmpty());
            for (int c = 0; c < PacketTableModel::ColumnCount; ++c) {
                const QString header = model->headerData(c, Qt::Horizontal).toString();
                QVERIFY2(!looksUntranslated(header), qPrintable(header));
            }
            QVERIFY2(!looksUntranslated(voltageName.data().toString()), qPrintable(voltageName.data().toString()));
        }
        QCOMPARE(voltageName.data().toString(), QStringLiteral("Voltage"));
        QCoreApplication::processEvents();
        QCOMPARE(inspector.findChild<QToolButton *>(QStringLiteral("pauseButton"))->text(), QString("Resume"));
        QCOMPARE(inspector.findChild<QLabel *>(QStringLiteral("rawError"))->text(),
                 QString("Byte 1: 300 is outside 0..255."));
        QCOMPARE(inspector.findChild<QLabel *>(QStringLiteral("status"))->text(),
                 QString("3 entries \u00b7 TX 3 B \u00b7 RX 0 B \u00b7 paused, 1 new"));
    }

    void keyboardReachesEveryControl()
    {
        ByteInspector inspector;
        inspector.show();
        inspector.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&inspector));
        auto *pause = inspector.findChild<QWidget *>(QStringLiteral("pauseButton"));
        pause->setFocus(Qt::TabFocusReason);
        QStringList visited;
        while (QWidget *w = QApplication::focusWidget()) {
            if (visited.contains(w->objectName()) || visited.size() > 20)
                break;
            visited << w->objectName();
            QTest::keyClick(w, Qt::Key_Tab);
        }
        // Top to bottom, left to right, as laid out.
        QCOMPARE(visited, QStringList({"pauseButton", "clearButton", "hexBox", "timeFormat", "byteLog", "packetTable",
                                       "rawInput", "sendButton"}));
        // Space works the focused controls.
        QTest::keyClick(pause, Qt::Key_Space);
        QVERIFY(inspector.isPaused());
        auto *hex = inspector.findChild<QCheckBox *>(QStringLiteral("hexBox"));
        hex->setFocus();
        QTest::keyClick(hex, Qt::Key_Space);
        QVERIFY(inspector.showsHex());
        for (const char *name : {"byteLog", "packetTable", "timeFormat", "rawInput"})
            QVERIFY2(!inspector.findChild<QWidget *>(name)->accessibleName().isEmpty(), name);
    }

    void screenshots()
    {
        ByteInspector inspector;
        inspector.resize(640, 360);
        inspector.show();
        inspector.appendTx(bytesOf({128, 131, 137, 255, 56, 1, 244}), 1000);
        inspector.appendRx(frame(bytesOf({22, 0x3A, 0x98, 7, 1})), 1015);
        inspector.appendRx(QByteArray("bat-min 12\r\n"), 1030);
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        inspector.addSnapshot(0, sensor_scenes::decoded(create2, sensor_scenes::quietValues(create2)));
        inspector.packetTable()->refresh();
        inspector.flushView();
        sensor_scenes::saveScreenshot(inspector, "byte_inspector");
        ScopedPseudoTranslation pseudo; // longer texts, as translations are
        QCoreApplication::processEvents();
        sensor_scenes::saveScreenshot(inspector, "byte_inspector_pseudo");
    }
};

QTEST_MAIN(TestByteInspector)
#include "tst_byte_inspector.moc"
