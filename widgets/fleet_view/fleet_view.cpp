// SPDX-License-Identifier: GPL-3.0-or-later
#include "fleet_view.h"

#include "display_palette.h"
#include "screen_fit.h"
#include "stop_all_button.h"

#include <QComboBox>
#include <QEvent>
#include <QFontInfo>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>

namespace {
constexpr int kSpacing = 12;
// Tiles no larger than this many times the desktop's type, however few, and
// no smaller than this, however many (more scroll).
constexpr qreal kMaxScale = 3;
constexpr qreal kMinScale = 0.8;
constexpr QSize kFullHd(1920, 1080);
constexpr int kLeastPixels = 14;
}

FleetView::FleetView(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_broker = new QLabel(this);
    m_broker->setObjectName("fleetBroker");
    m_broker->setTextFormat(Qt::PlainText);
    // A long error takes more lines, never a wider window.
    m_broker->setWordWrap(true);
    m_broker->setMinimumWidth(1);
    m_connect = new QPushButton(this);
    m_connect->setObjectName("fleetConnect");
    connect(m_connect, &QPushButton::clicked, this, &FleetView::connectRequested);
    // Stop all where the class looks: on the projector, readable from the
    // back row, the key in its label. The keys stay with the tiles.
    m_stopAll = new StopAllButton(this);
    m_stopAll->setObjectName("fleetStopAll");
    m_stopAll->setFocusPolicy(Qt::NoFocus);
    connect(m_stopAll, &QPushButton::clicked, this, &FleetView::stopAllRequested);
    m_orderBox = new QComboBox(this);
    m_orderBox->setObjectName("fleetOrder");
    m_orderBox->addItems({QString(), QString()});
    connect(m_orderBox, &QComboBox::activated, this, [this](int index) { setOrder(Order(index)); });
    auto *header = new QHBoxLayout;
    header->addWidget(m_broker, 1);
    header->addWidget(m_orderBox);
    header->addWidget(m_connect);
    header->addWidget(m_stopAll);
    layout->addLayout(header);
    m_stopped = new QLabel(this);
    m_stopped->setObjectName("fleetStopped");
    m_stopped->setWordWrap(true);
    m_stopped->hide();
    layout->addWidget(m_stopped);
    m_empty = new QLabel(this);
    m_empty->setObjectName("fleetEmpty");
    m_empty->setWordWrap(true);
    m_empty->setAlignment(Qt::AlignCenter);
    layout->addWidget(m_empty, 1);
    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_canvas = new QWidget(m_scroll);
    m_grid = new QGridLayout(m_canvas);
    m_grid->setSpacing(kSpacing);
    m_grid->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_scroll->setWidget(m_canvas);
    // The columns follow the room the tiles have, known once the viewport is sized.
    m_scroll->viewport()->installEventFilter(this);
    layout->addWidget(m_scroll, 1);
    m_scroll->hide();
    retranslateUi();
}

void FleetView::retranslateUi()
{
    setAccessibleName(tr("Fleet view"));
    m_orderBox->setItemText(int(Order::Name), tr("By name"));
    m_orderBox->setItemText(int(Order::PackHealth), tr("By pack health"));
    m_orderBox->setToolTip(tr("The order of the tiles: by name, or by the health of each robot's battery pack, the "
                              "one to replace first."));
    const bool offer = m_brokerText.isEmpty() && !m_reconnectOffer.isEmpty();
    // Connected, the same dialog changes the broker.
    m_connect->setText(offer ? tr("Reconnect…") : m_connected ? tr("Another broker…") : tr("Connect to broker…"));
    m_broker->setText(!m_brokerText.isEmpty() ? m_brokerText
                      : offer                 ? m_reconnectOffer
                                              : tr("Not connected to a broker"));
    m_empty->setText(m_brokerText.isEmpty()
                         ? tr("Connect to a broker to see every robot whose bridge publishes there.")
                         : tr("No robot on this broker yet. Each appears as its bridge starts."));
}

void FleetView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

QPushButton *FleetView::stopAllButton() const { return m_stopAll; }

void FleetView::resizeEvent(QResizeEvent *event)
{
    // 2.4 times the desktop's type on a 1920×1080 screen, in proportion on
    // a smaller one, never under 1.8 times (a 1280×720 projector).
    const qreal scale = screenfit::scaleFor(size(), kFullHd, 0.75, 1.25);
    m_stopAll->setTypeScale(2.4 * scale);
    // Readable from the back of the room: never under 14 px, however small the screen.
    QFont broker = display::valueFont(font(), 1.6 * scale);
    broker.setPixelSize(std::max(kLeastPixels, QFontInfo(broker).pixelSize()));
    m_broker->setFont(broker);
    m_stopped->setFont(broker);
    m_connect->setFont(broker);
    m_orderBox->setFont(broker);
    m_empty->setFont(broker);
    QWidget::resizeEvent(event);
}

void FleetView::setReconnectOffer(const QString &text)
{
    m_reconnectOffer = text;
    retranslateUi();
}

void FleetView::setBrokerText(const QString &text, bool connected)
{
    if (text == m_brokerText && connected == m_connected)
        return;
    m_brokerText = text;
    m_connected = connected;
    // The line in the warning colour while the broker is out of reach.
    const display::State state = connected ? display::State::Idle : display::State::Warning;
    m_broker->setAutoFillBackground(!connected);
    QPalette pal = palette();
    if (!connected) {
        pal.setColor(QPalette::Window, display::stateColor(state, palette()));
        pal.setColor(QPalette::WindowText, display::textOn(state, palette()));
    }
    m_broker->setPalette(pal);
    retranslateUi();
}

namespace {

QStringView withoutLeadingZeros(QStringView number)
{
    while (number.size() > 1 && number.front() == u'0')
        number = number.mid(1);
    return number;
}

// Robot names (letters, digits, '-', '_'), numbers compared as numbers and
// letters without case: r2 before r10, whatever the locale.
bool namesInOrder(const QString &a, const QString &b)
{
    qsizetype i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (a[i].isDigit() && b[j].isDigit()) {
            const qsizetype i0 = i, j0 = j;
            while (i < a.size() && a[i].isDigit())
                ++i;
            while (j < b.size() && b[j].isDigit())
                ++j;
            const QStringView x = withoutLeadingZeros(QStringView(a).mid(i0, i - i0));
            const QStringView y = withoutLeadingZeros(QStringView(b).mid(j0, j - j0));
            if (x.size() != y.size())
                return x.size() < y.size();
            if (x != y)
                return x < y;
            continue;
        }
        const QChar x = a[i].toCaseFolded(), y = b[j].toCaseFolded();
        if (x != y)
            return x < y;
        ++i;
        ++j;
    }
    if (a.size() - i != b.size() - j)
        return a.size() - i < b.size() - j;
    return a < b;
}

} // namespace

FleetTile *FleetView::tile(const QString &name) const
{
    for (FleetTile *t : m_tiles)
        if (t->values().name == name)
            return t;
    return nullptr;
}

void FleetView::setStopReport(const QString &text)
{
    m_stopped->setText(text);
    m_stopped->setVisible(!text.isEmpty());
}

QString FleetView::stopReport() const { return m_stopped->text(); }

void FleetView::setTiles(const QList<FleetTileValues> &tiles)
{
    bool added = false, healthChanged = false;
    for (const FleetTileValues &v : tiles) {
        FleetTile *t = tile(v.name);
        if (!t) {
            t = new FleetTile(m_canvas);
            t->setObjectName(QStringLiteral("fleetTile-") + v.name);
            connect(t, &FleetTile::clicked, this, [this, t] { emit robotClicked(t->values().name); });
            m_tiles << t;
            added = true;
        }
        healthChanged = healthChanged || t->values().packCondition != v.packCondition
                        || t->values().packCapacityMah != v.packCapacityMah;
        t->setValues(v);
    }
    if (added || (healthChanged && m_order == Order::PackHealth)) {
        sortTiles();
        m_empty->setVisible(m_tiles.isEmpty());
        m_scroll->setVisible(!m_tiles.isEmpty());
        relayout(true);
    }
}

void FleetView::removeTile(const QString &name)
{
    FleetTile *t = tile(name);
    if (!t)
        return;
    m_tiles.removeOne(t);
    delete t;
    m_empty->setVisible(m_tiles.isEmpty());
    m_scroll->setVisible(!m_tiles.isEmpty());
    relayout(true);
}

void FleetView::setOrder(Order order)
{
    m_order = order;
    m_orderBox->setCurrentIndex(int(order));
    sortTiles();
    relayout(true);
}

void FleetView::sortTiles()
{
    // In the order of their names, numbers as numbers (r2 before r10),
    // however the bridges came online: the class finds its robot. By
    // health, the worst pack first, the least capacity first among equals.
    const auto rank = [](BatteryCondition c) { return c == BatteryCondition::Unknown ? 0 : int(c); };
    std::stable_sort(m_tiles.begin(), m_tiles.end(), [&](const FleetTile *a, const FleetTile *b) {
        const FleetTileValues &x = a->values(), &y = b->values();
        if (m_order == Order::PackHealth) {
            if (rank(x.packCondition) != rank(y.packCondition))
                return rank(x.packCondition) > rank(y.packCondition);
            if (x.packCapacityMah.value_or(1 << 30) != y.packCapacityMah.value_or(1 << 30))
                return x.packCapacityMah.value_or(1 << 30) < y.packCapacityMah.value_or(1 << 30);
        }
        return namesInOrder(x.name, y.name);
    });
}

void FleetView::setSelected(const QString &name)
{
    for (FleetTile *t : m_tiles)
        t->setChecked(!name.isEmpty() && t->values().name == name);
}

bool FleetView::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_scroll->viewport() && event->type() == QEvent::Resize)
        relayout();
    return QWidget::eventFilter(watched, event);
}

void FleetView::relayout(bool force)
{
    if (m_tiles.isEmpty())
        return;
    // The tile's size at the desktop's type; it grows with its type.
    FleetTile *first = m_tiles.first();
    const QFont base = font();
    const QSize unit = [&] {
        const QFont now = first->font();
        first->setFont(base);
        const QSize size = first->sizeHint();
        first->setFont(now);
        return size;
    }();
    const QMargins margins = m_grid->contentsMargins();
    const int roomWidth = m_scroll->viewport()->width() - margins.left() - margins.right();
    const int roomHeight = m_scroll->viewport()->height() - margins.top() - margins.bottom();
    // The number of columns that lets the tiles be largest, all in view.
    const int count = int(m_tiles.size());
    int columns = 1;
    qreal scale = 0;
    for (int c = 1; c <= count; ++c) {
        const int rows = (count + c - 1) / c;
        const qreal s = std::min(qreal(roomWidth - (c - 1) * kSpacing) / (c * unit.width()),
                                 qreal(roomHeight - (rows - 1) * kSpacing) / (rows * unit.height()));
        if (s > scale) {
            scale = s;
            columns = c;
        }
    }
    if (scale < kMinScale) {
        // Too many for the screen at the smallest type: that type, and scroll.
        scale = kMinScale;
        columns = std::max(1, int((roomWidth + kSpacing) / (unit.width() * scale + kSpacing)));
    }
    scale = std::min(scale * 0.98, kMaxScale); // a little room for rounding
    if (std::abs(scale - m_scale) > 0.02 || force) {
        m_scale = scale;
        QFont f = base;
        f.setPointSizeF(base.pointSizeF() * scale);
        for (FleetTile *t : m_tiles)
            t->setFont(f);
    }
    if (columns == m_columns && !force)
        return;
    m_columns = columns;
    for (FleetTile *t : m_tiles)
        m_grid->removeWidget(t);
    for (qsizetype i = 0; i < m_tiles.size(); ++i) {
        m_grid->addWidget(m_tiles[i], int(i / columns), int(i % columns));
        m_tiles[i]->show();
    }
}

#include "moc_fleet_view.cpp"
