// SPDX-License-Identifier: GPL-3.0-or-later
#include "fleet_view.h"

#include "display_palette.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace {
constexpr int kSpacing = 12;
}

FleetView::FleetView(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_broker = new QLabel(this);
    m_broker->setObjectName("fleetBroker");
    m_broker->setFont(display::valueFont(font(), 1.2));
    m_broker->setTextFormat(Qt::PlainText);
    m_connect = new QPushButton(this);
    m_connect->setObjectName("fleetConnect");
    connect(m_connect, &QPushButton::clicked, this, &FleetView::connectRequested);
    auto *header = new QHBoxLayout;
    header->addWidget(m_broker, 1);
    header->addWidget(m_connect);
    layout->addLayout(header);
    m_empty = new QLabel(this);
    m_empty->setObjectName("fleetEmpty");
    m_empty->setWordWrap(true);
    m_empty->setAlignment(Qt::AlignCenter);
    m_empty->setFont(display::valueFont(font(), 1.3));
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
    m_connect->setText(tr("Connect to broker…"));
    m_broker->setText(m_brokerText.isEmpty() ? tr("Not connected to a broker") : m_brokerText);
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

FleetTile *FleetView::tile(const QString &name) const
{
    for (FleetTile *t : m_tiles)
        if (t->values().name == name)
            return t;
    return nullptr;
}

void FleetView::setTiles(const QList<FleetTileValues> &tiles)
{
    bool added = false;
    for (const FleetTileValues &v : tiles) {
        FleetTile *t = tile(v.name);
        if (!t) {
            t = new FleetTile(m_canvas);
            t->setObjectName(QStringLiteral("fleetTile-") + v.name);
            connect(t, &FleetTile::clicked, this, [this, t] { emit robotClicked(t->values().name); });
            m_tiles << t;
            added = true;
        }
        t->setValues(v);
    }
    if (added) {
        m_empty->setVisible(m_tiles.isEmpty());
        m_scroll->setVisible(!m_tiles.isEmpty());
        relayout(true);
    }
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
    const int tileWidth = m_tiles.first()->sizeHint().width();
    const int room = m_scroll->viewport()->width() - m_grid->contentsMargins().left()
                     - m_grid->contentsMargins().right();
    const int columns = std::max(1, (room + kSpacing) / (tileWidth + kSpacing));
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
