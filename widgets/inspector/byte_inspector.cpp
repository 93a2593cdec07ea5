// SPDX-License-Identifier: GPL-3.0-or-later
#include "byte_inspector.h"

#include "byte_log_view.h"
#include "display_palette.h"
#include "display_tick.h"
#include "live_label.h"
#include "on_screen.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSplitter>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <climits>
#include <span>

namespace {

std::span<const std::uint8_t> asBytes(const QByteArray &bytes)
{
    return {reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size())};
}

} // namespace

ByteInspector::ByteInspector(QWidget *parent)
    : QWidget(parent), m_log(new ByteLogModel(this))
{
    m_pauseButton = new QToolButton(this);
    m_pauseButton->setObjectName(QStringLiteral("pauseButton"));
    m_pauseButton->setCheckable(true);
    connect(m_pauseButton, &QToolButton::toggled, this, &ByteInspector::setPaused);

    m_clearButton = new QToolButton(this);
    m_clearButton->setObjectName(QStringLiteral("clearButton"));
    connect(m_clearButton, &QToolButton::clicked, this, &ByteInspector::clear);

    m_hexBox = new QCheckBox(this);
    m_hexBox->setObjectName(QStringLiteral("hexBox"));
    connect(m_hexBox, &QCheckBox::toggled, this, &ByteInspector::setShowsHex);

    m_timeBox = new QComboBox(this);
    m_timeBox->setObjectName(QStringLiteral("timeFormat"));
    m_timeBox->addItem(QString(), int(TimeFormat::ClockTime));
    m_timeBox->addItem(QString(), int(TimeFormat::SinceConnect));
    m_timeBox->setCurrentIndex(m_timeBox->findData(int(m_log->timeFormat())));
    m_timeBox->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(m_timeBox, &QComboBox::currentIndexChanged, this,
            [this] { setTimeFormat(TimeFormat(m_timeBox->currentData().toInt())); });

    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("status"));
    // Not selectable: its counts change twice a second, faster than a
    // selection could be made, and a selectable label lays out a whole text
    // document each time it is painted.

    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->setObjectName(QStringLiteral("splitter"));
    m_splitter->setChildrenCollapsible(false);
    m_view = new ByteLogView(m_splitter);
    m_view->setObjectName(QStringLiteral("byteLog"));
    m_view->setLogModel(m_log);

    m_packets = new PacketTable(m_splitter);
    m_packets->setObjectName(QStringLiteral("packets"));
    connect(m_packets, &PacketTable::plotRequested, this, &ByteInspector::plotRequested);
    m_splitter->addWidget(m_view);
    m_splitter->addWidget(m_packets);
    // The log, with its long meanings, takes the larger share.
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);

    m_rawInput = new QLineEdit(this);
    m_rawInput->setObjectName(QStringLiteral("rawInput"));
    m_rawInput->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_rawInput->setClearButtonEnabled(true);
    connect(m_rawInput, &QLineEdit::returnPressed, this, &ByteInspector::submitRaw);
    connect(m_rawInput, &QLineEdit::textEdited, this, [this] { showError(QString()); });

    m_sendButton = new QPushButton(this);
    m_sendButton->setObjectName(QStringLiteral("sendButton"));
    connect(m_sendButton, &QPushButton::clicked, this, &ByteInspector::submitRaw);

    m_rawError = new QLabel(this);
    m_rawError->setObjectName(QStringLiteral("rawError"));
    m_rawError->setWordWrap(true);
    m_rawError->setVisible(false);

    auto *bar = new QHBoxLayout;
    bar->setContentsMargins(0, 0, 0, 0);
    bar->addWidget(m_pauseButton);
    bar->addWidget(m_clearButton);
    bar->addSpacing(8);
    bar->addWidget(m_hexBox);
    bar->addWidget(m_timeBox);
    bar->addSpacing(8);
    bar->addWidget(m_status, 1);

    auto *send = new QHBoxLayout;
    send->setContentsMargins(0, 0, 0, 0);
    send->addWidget(m_rawInput, 1);
    send->addWidget(m_sendButton);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    layout->addLayout(bar);
    layout->addWidget(m_splitter, 1);
    layout->addLayout(send);
    layout->addWidget(m_rawError);

    showError(QString());
    retranslateUi();
}

void ByteInspector::retranslateUi()
{
    m_pauseButton->setText(m_paused ? tr("Resume") : tr("Pause"));
    m_pauseButton->setToolTip(tr("Stop scrolling new bytes into view; they are still recorded"));
    m_clearButton->setText(tr("Clear"));
    m_clearButton->setToolTip(tr("Forget every entry and reset the counts"));
    m_hexBox->setText(tr("Hex"));
    m_hexBox->setToolTip(tr("Show bytes in hexadecimal instead of decimal"));
    m_timeBox->setItemText(m_timeBox->findData(int(TimeFormat::ClockTime)), tr("Clock time"));
    m_timeBox->setItemText(m_timeBox->findData(int(TimeFormat::SinceConnect)), tr("Since connect"));
    m_timeBox->setAccessibleName(tr("Time format"));
    m_timeBox->setToolTip(tr("Show each entry's time of day, or the seconds since the link was opened"));
    m_view->setAccessibleName(tr("Byte log"));
    m_rawInput->setPlaceholderText(tr("Raw bytes to send, e.g. 128 131 or 0x80 0x83"));
    m_rawInput->setAccessibleName(tr("Raw bytes to send"));
    m_sendButton->setText(tr("Send"));
    m_sendButton->setToolTip(tr("Check the bytes and send them to the robot"));
    // The last refusal, said again in the new language.
    if (!m_rawError->isHidden()) {
        QString error;
        parseRawBytes(m_rejected, &error);
        showError(error);
    }
    updateStatus();
}

void ByteInspector::setProfile(const oi::RobotProfile &profile)
{
    m_decoder.setProfile(profile);
    m_scanner.setProfile(profile);
    m_packets->setProfile(profile);
}

void ByteInspector::setTimeFormat(TimeFormat format)
{
    m_log->setTimeFormat(format);
    m_timeBox->blockSignals(true);
    m_timeBox->setCurrentIndex(m_timeBox->findData(int(format)));
    m_timeBox->blockSignals(false);
}

void ByteInspector::addSnapshot(double seconds, const oi::SensorSnapshot &snapshot)
{
    m_packets->addSnapshot(seconds, snapshot);
}

void ByteInspector::expectReplies(const std::vector<oi::OiCommand> &commands, qint64 msecs)
{
    // Tell the scanner what the robot is about to answer.
    for (const oi::OiCommand &command : commands) {
        if (command.command == oi::Command::Sensors && !command.fields.empty())
            m_scanner.expectReply({std::uint8_t(command.fields[0])}, msecs);
        else if (command.command == oi::Command::QueryList)
            m_scanner.expectReply(command.data, msecs);
    }
}

void ByteInspector::appendTx(const QByteArray &bytes, qint64 msecs)
{
    if (bytes.isEmpty())
        return;
    m_txBytes += quint64(bytes.size());
    const auto all = asBytes(bytes);
    std::size_t at = 0;
    for (CommandDecoder::Decoded &d : m_decoder.decode(all)) {
        Entry e;
        e.msecs = msecs;
        e.direction = Direction::Tx;
        e.tone = d.status == CommandDecoder::Status::Complete ? Tone::Command : Tone::Problem;
        e.bytes = bytes.mid(qsizetype(at), qsizetype(d.length));
        e.meaning = std::move(d.meaning);
        record(std::move(e));
        at += d.length;
    }
    scheduleRender();
}

void ByteInspector::appendRx(const QByteArray &bytes, qint64 msecs)
{
    if (bytes.isEmpty())
        return;
    m_rxBytes += quint64(bytes.size());
    for (RxFrameScanner::Piece &piece : m_scanner.feed(asBytes(bytes), msecs)) {
        Entry e;
        e.msecs = msecs;
        e.direction = Direction::Rx;
        switch (piece.kind) {
        case RxFrameScanner::Kind::StreamFrame:
        case RxFrameScanner::Kind::Reply:
            e.tone = Tone::Frame;
            break;
        case RxFrameScanner::Kind::Text:
            e.tone = Tone::Text;
            break;
        case RxFrameScanner::Kind::Bytes:
            e.tone = Tone::Other;
            break;
        }
        e.bytes = piece.bytes;
        e.undescribed = std::move(piece);
        record(std::move(e));
    }
    scheduleRender();
}

void ByteInspector::record(Entry entry)
{
    m_log->record(std::move(entry));
    ++m_totalEntries;
}

void ByteInspector::scheduleRender()
{
    // A hidden log, or one behind another dock's tab, costs nothing to keep;
    // it renders when shown. Whether it is on screen is asked once per tick,
    // not per entry: it is dear to ask.
    if (m_offScreen || !isVisible())
        return;
    // On the display's tick, with the other views.
    DisplayTick::instance().requestFrame(this, kRenderIntervalMs, [this] {
        // Behind another dock's tab: kept, not laid out, and no frame
        // either, until it is shown or painted again.
        if (isOnScreen(this))
            flushView();
        else
            m_offScreen = true;
    });
}

void ByteInspector::clear()
{
    m_log->clear();
    m_totalEntries = 0;
    m_txBytes = 0;
    m_rxBytes = 0;
    m_scanner.reset();
    m_packets->clear();
    updateStatus();
}

void ByteInspector::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    m_pauseButton->blockSignals(true);
    m_pauseButton->setChecked(paused);
    m_pauseButton->blockSignals(false);
    m_pauseButton->setText(paused ? tr("Resume") : tr("Pause"));
    if (!paused)
        flushView();
    updateStatus();
}

void ByteInspector::setShowsHex(bool hex)
{
    if (hex == m_log->showsHex())
        return;
    m_log->setShowsHex(hex);
    m_hexBox->blockSignals(true);
    m_hexBox->setChecked(hex);
    m_hexBox->blockSignals(false);
    m_packets->setShowsHex(hex);
}

void ByteInspector::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    m_offScreen = false;
    flushView();
}

void ByteInspector::paintEvent(QPaintEvent *event)
{
    QWidget::paintEvent(event);
    if (m_offScreen) { // on screen again, by whatever way
        m_offScreen = false;
        scheduleRender();
    }
}

void ByteInspector::flushView()
{
    if (!m_paused)
        m_view->showPending();
    // The counts change with every entry: shown twice a second, which reads
    // better than ten times and costs a fifth, and the last ones always.
    DisplayTick::instance().requestFrame(m_status, kStatusIntervalMs, [this] { updateStatus(); });
}

void ByteInspector::updateStatus()
{
    const QLocale locale;
    const int entries = int(std::min<quint64>(m_totalEntries, INT_MAX));
    // Both sources, so English reads "1 entry" without a translation file.
    QString status = (entries == 1 ? tr("%Ln entry \u00b7 TX %1 B \u00b7 RX %2 B", nullptr, entries)
                                   : tr("%Ln entries \u00b7 TX %1 B \u00b7 RX %2 B", nullptr, entries))
                         .arg(locale.toString(m_txBytes), locale.toString(m_rxBytes));
    if (m_paused && m_log->pendingCount() > 0)
        status += tr(" \u00b7 paused, %Ln new", nullptr, m_log->pendingCount());
    else if (m_paused)
        status += tr(" \u00b7 paused");
    setLiveText(m_status, status);
}

void ByteInspector::submitRaw()
{
    QString error;
    const std::optional<QByteArray> bytes = parseRawBytes(m_rawInput->text(), &error);
    if (!bytes) {
        m_rejected = m_rawInput->text();
        showError(error);
        m_rawInput->setFocus();
        return;
    }
    showError(QString());
    m_rawInput->clear();
    // Checked whole, so they decode: the commands the person typed.
    const auto commands = oi::decodeCommands(m_decoder.robotProfile(),
                                             {reinterpret_cast<const std::uint8_t *>(bytes->constData()),
                                              std::size_t(bytes->size())});
    emit sendRequested(*commands);
}

void ByteInspector::showError(const QString &message)
{
    m_rawError->setText(message);
    m_rawError->setVisible(!message.isEmpty());
    const QColor alert = display::stateColor(display::State::Alert, palette());
    m_rawError->setStyleSheet(QStringLiteral("QLabel { color: %1; font-weight: bold; }").arg(alert.name()));
}

void ByteInspector::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    // The log takes its colours from the palette as it paints.
    if (event->type() == QEvent::PaletteChange)
        showError(m_rawError->text());
}

#include "moc_byte_inspector.cpp"
