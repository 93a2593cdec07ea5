// SPDX-License-Identifier: GPL-3.0-or-later
#include "byte_inspector.h"

#include "display_palette.h"
#include "live_label.h"
#include "on_screen.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QEvent>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QSplitter>
#include <QTextBlock>
#include <QTextCursor>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <climits>
#include <span>

namespace {

QColor blend(const QColor &a, const QColor &b, double bShare)
{
    return QColor::fromRgbF(float(a.redF() * (1 - bShare) + b.redF() * bShare),
                            float(a.greenF() * (1 - bShare) + b.greenF() * bShare),
                            float(a.blueF() * (1 - bShare) + b.blueF() * bShare));
}

std::span<const std::uint8_t> asBytes(const QByteArray &bytes)
{
    return {reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size())};
}

} // namespace

ByteInspector::ByteInspector(QWidget *parent)
    : QWidget(parent), m_renderTimer(new QTimer(this))
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
    m_timeBox->setCurrentIndex(m_timeBox->findData(int(m_timeFormat)));
    m_timeBox->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(m_timeBox, &QComboBox::currentIndexChanged, this,
            [this] { setTimeFormat(TimeFormat(m_timeBox->currentData().toInt())); });

    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->setObjectName(QStringLiteral("splitter"));
    m_splitter->setChildrenCollapsible(false);
    m_view = new QPlainTextEdit(m_splitter);
    m_view->setObjectName(QStringLiteral("byteLog"));
    m_view->setReadOnly(true);
    m_view->setTabChangesFocus(true); // a log: Tab moves on to the send field
    m_view->setUndoRedoEnabled(false);
    m_view->setMaximumBlockCount(m_maxEntries);
    m_view->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    m_view->setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    m_view->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));

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

    m_renderTimer->setObjectName(QStringLiteral("renderTimer"));
    m_renderTimer->setSingleShot(true);
    m_renderTimer->setInterval(kRenderIntervalMs);
    connect(m_renderTimer, &QTimer::timeout, this, [this] {
        // Behind another dock's tab: kept, not laid out, until its tab comes up.
        if (isOnScreen(this))
            flushView();
    });
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
    if (format == m_timeFormat)
        return;
    m_timeFormat = format;
    m_timeBox->blockSignals(true);
    m_timeBox->setCurrentIndex(m_timeBox->findData(int(format)));
    m_timeBox->blockSignals(false);
    rebuildView();
}

void ByteInspector::setConnectedAt(qint64 msecs)
{
    if (m_connectedAt == msecs)
        return;
    m_connectedAt = msecs;
    if (m_timeFormat == TimeFormat::SinceConnect)
        rebuildView();
}

void ByteInspector::addSnapshot(double seconds, const oi::SensorSnapshot &snapshot)
{
    m_packets->addSnapshot(seconds, snapshot);
}

void ByteInspector::setMaxEntries(int count)
{
    m_maxEntries = std::max(1, count);
    while (m_entries.size() > std::size_t(m_maxEntries))
        m_entries.pop_front();
    m_unrendered = std::min(m_unrendered, m_entries.size());
    m_view->setMaximumBlockCount(m_maxEntries);
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
    if (!m_connectedAt)
        m_connectedAt = entry.msecs;
    m_entries.push_back(std::move(entry));
    ++m_totalEntries;
    ++m_unrendered;
    while (m_entries.size() > std::size_t(m_maxEntries))
        m_entries.pop_front();
    m_unrendered = std::min(m_unrendered, m_entries.size());
}

void ByteInspector::scheduleRender()
{
    // A hidden log costs nothing to keep; it renders when shown. Whether it
    // is on screen is asked once per tick, not per entry: it is dear to ask.
    if (isVisible() && !m_renderTimer->isActive())
        m_renderTimer->start();
}

void ByteInspector::clear()
{
    m_entries.clear();
    m_unrendered = 0;
    m_totalEntries = 0;
    m_txBytes = 0;
    m_rxBytes = 0;
    m_scanner.reset();
    m_view->clear();
    m_renderedCount = 0;
    m_packets->clear();
    updateStatus();
}

QStringList ByteInspector::lastEntries(int count) const
{
    QStringList out;
    const std::size_t n = std::min(m_entries.size(), std::size_t(std::max(0, count)));
    for (std::size_t i = m_entries.size() - n; i < m_entries.size(); ++i)
        out << entryText(m_entries[i]);
    return out;
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
    if (hex == m_hex)
        return;
    m_hex = hex;
    m_hexBox->blockSignals(true);
    m_hexBox->setChecked(hex);
    m_hexBox->blockSignals(false);
    m_packets->setShowsHex(hex);
    rebuildView();
}

void ByteInspector::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    flushView();
}

void ByteInspector::flushView()
{
    if (!m_paused && m_unrendered > 0) {
        renderEntries(m_entries.size() - m_unrendered, m_entries.size());
        m_unrendered = 0;
    }
    updateStatus();
}

void ByteInspector::rebuildView()
{
    m_view->clear();
    m_renderedCount = 0;
    // While paused the view keeps showing what it showed, in the new form.
    const std::size_t shown = m_entries.size() - (m_paused ? m_unrendered : 0);
    m_unrendered = m_entries.size() - shown;
    renderEntries(0, shown);
}

QString ByteInspector::bytesText(const QByteArray &bytes) const
{
    // By hand, not QString::arg per byte: a visible log shows every frame.
    static constexpr char kHexDigits[] = "0123456789ABCDEF";
    QByteArray text;
    text.reserve(bytes.size() * 4);
    for (char c : bytes) {
        if (!text.isEmpty())
            text += ' ';
        const auto b = static_cast<std::uint8_t>(c);
        if (m_hex) {
            text += kHexDigits[b >> 4];
            text += kHexDigits[b & 0xF];
        } else {
            if (b >= 100)
                text += char('0' + b / 100);
            if (b >= 10)
                text += char('0' + b / 10 % 10);
            text += char('0' + b % 10);
        }
    }
    return QString::fromLatin1(text);
}

QString ByteInspector::timeText(qint64 msecs) const
{
    if (m_timeFormat == TimeFormat::ClockTime)
        return QDateTime::fromMSecsSinceEpoch(msecs).time().toString(QStringLiteral("hh:mm:ss.zzz"));
    return QStringLiteral("%1").arg(QString::number(double(msecs - m_connectedAt.value_or(msecs)) / 1000.0, 'f', 3), 10);
}

const QString &ByteInspector::meaningOf(const Entry &entry)
{
    if (entry.undescribed) {
        RxFrameScanner::describe(*entry.undescribed);
        entry.meaning = std::move(entry.undescribed->meaning);
        entry.undescribed.reset();
    }
    return entry.meaning;
}

QString ByteInspector::entryText(const Entry &entry) const
{
    return QStringLiteral("%1  %2  %3  %4")
        .arg(timeText(entry.msecs))
        .arg(entry.direction == Direction::Tx ? QStringLiteral("TX") : QStringLiteral("RX"))
        .arg(bytesText(entry.bytes), meaningOf(entry));
}

void ByteInspector::renderEntries(std::size_t first, std::size_t end)
{
    const QPalette pal = palette();
    const QColor text = pal.color(QPalette::Text);
    QColor dim = text;
    dim.setAlpha(140);
    const QColor txColor = display::stateColor(display::State::Active, pal);
    // A softer blue than the link colour, for lines that are mostly received.
    const QColor rxColor = blend(pal.color(QPalette::Highlight), text, 0.3);
    // Every other entry on a tinted band, so a wrapped line reads as one entry.
    QTextBlockFormat plainBand, tintedBand;
    tintedBand.setBackground(blend(pal.color(QPalette::Base), text, 0.06));

    QTextCharFormat timeFormat, bytesFormat, txFormat, rxFormat;
    timeFormat.setForeground(dim);
    bytesFormat.setForeground(text);
    txFormat.setForeground(txColor);
    rxFormat.setForeground(rxColor);
    QTextCharFormat txTag = txFormat, rxTag = rxFormat;
    txTag.setFontWeight(QFont::Bold);
    rxTag.setFontWeight(QFont::Bold);
    QTextCharFormat problemFormat, textFormat, otherFormat;
    problemFormat.setForeground(display::stateColor(display::State::Alert, pal));
    textFormat.setForeground(display::stateColor(display::State::Stale, pal));
    otherFormat.setForeground(display::stateColor(display::State::Warning, pal));

    QScrollBar *scroll = m_view->verticalScrollBar();
    const bool atBottom = scroll->value() >= scroll->maximum() - 2;
    QTextCursor cursor(m_view->document());
    cursor.movePosition(QTextCursor::End);
    cursor.beginEditBlock();
    for (std::size_t i = first; i < end; ++i) {
        const Entry &e = m_entries[i];
        const QTextBlockFormat &band = m_renderedCount++ % 2 ? tintedBand : plainBand;
        if (m_view->document()->isEmpty())
            cursor.setBlockFormat(band);
        else
            cursor.insertBlock(band);
        const bool tx = e.direction == Direction::Tx;
        cursor.insertText(timeText(e.msecs) + QStringLiteral("  "), timeFormat);
        cursor.insertText(tx ? QStringLiteral("TX") : QStringLiteral("RX"), tx ? txTag : rxTag);
        cursor.insertText(QStringLiteral("  ") + bytesText(e.bytes) + QStringLiteral("  "), bytesFormat);
        const QTextCharFormat *meaning = tx ? &txFormat : &rxFormat;
        if (e.tone == Tone::Problem)
            meaning = &problemFormat;
        else if (e.tone == Tone::Text)
            meaning = &textFormat;
        else if (e.tone == Tone::Other)
            meaning = &otherFormat;
        cursor.insertText(meaningOf(e), *meaning);
    }
    cursor.endEditBlock();
    // Follow new entries only if the reader was already at the end.
    if (atBottom)
        scroll->setValue(scroll->maximum());
}

void ByteInspector::updateStatus()
{
    const QLocale locale;
    const int entries = int(std::min<quint64>(m_totalEntries, INT_MAX));
    // Both sources, so English reads "1 entry" without a translation file.
    QString status = (entries == 1 ? tr("%Ln entry \u00b7 TX %1 B \u00b7 RX %2 B", nullptr, entries)
                                   : tr("%Ln entries \u00b7 TX %1 B \u00b7 RX %2 B", nullptr, entries))
                         .arg(locale.toString(m_txBytes), locale.toString(m_rxBytes));
    if (m_paused && m_unrendered > 0)
        status += tr(" \u00b7 paused, %Ln new", nullptr, int(std::min<std::size_t>(m_unrendered, INT_MAX)));
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
    if (event->type() == QEvent::PaletteChange) {
        rebuildView();
        showError(m_rawError->text());
    }
}

#include "moc_byte_inspector.cpp"
