// SPDX-License-Identifier: GPL-3.0-or-later
#include "packet_table.h"

#include "display_tick.h"
#include "on_screen.h"

#include <QEvent>
#include <QFontMetrics>
#include <QHeaderView>
#include <QHBoxLayout>
#include <QItemSelectionModel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

PacketTable::PacketTable(QWidget *parent)
    : QWidget(parent), m_model(new PacketTableModel(this))
{
    m_view = new QTableView(this);
    m_view->setObjectName(QStringLiteral("packetTable"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setTabKeyNavigation(false); // Tab moves on to the Plot button
    m_view->setAlternatingRowColors(true);
    m_view->setWordWrap(false);
    // Sizes fixed from sample texts: fitting them to the contents would
    // measure every row at every refresh.
    const QFontMetrics metrics = m_view->fontMetrics();
    QHeaderView *rows = m_view->verticalHeader();
    rows->hide();
    rows->setSectionResizeMode(QHeaderView::Fixed);
    rows->setDefaultSectionSize(metrics.height() + 4);
    QHeaderView *header = m_view->horizontalHeader();
    header->setHighlightSections(false);
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setSectionResizeMode(PacketTableModel::NameColumn, QHeaderView::Stretch);
    const int pad = 2 * metrics.horizontalAdvance(QLatin1Char(' ')) + 4;
    header->resizeSection(PacketTableModel::IdColumn, metrics.horizontalAdvance(QStringLiteral("000")) + pad);
    header->resizeSection(PacketTableModel::ValueColumn, metrics.horizontalAdvance(QStringLiteral("-32768 mAh")) + pad);
    header->resizeSection(PacketTableModel::RawColumn, metrics.horizontalAdvance(QStringLiteral("255 255")) + pad);
    header->resizeSection(PacketTableModel::RateColumn, metrics.horizontalAdvance(QStringLiteral("100.0 Hz")) + pad);
    connect(m_view, &QTableView::doubleClicked, this, &PacketTable::requestPlot);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this, &PacketTable::updatePlotButton);
    connect(m_model, &QAbstractItemModel::modelReset, this, &PacketTable::updatePlotButton);

    m_plotButton = new QPushButton(this);
    m_plotButton->setObjectName(QStringLiteral("plotButton"));
    connect(m_plotButton, &QPushButton::clicked, this, &PacketTable::requestPlot);

    auto *buttons = new QHBoxLayout;
    buttons->setContentsMargins(0, 0, 0, 0);
    buttons->addStretch(1);
    buttons->addWidget(m_plotButton);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    layout->addWidget(m_view, 1);
    layout->addLayout(buttons);

    updatePlotButton();
    retranslateUi();
}

void PacketTable::retranslateUi()
{
    m_view->setAccessibleName(tr("Packets"));
    m_plotButton->setText(tr("Plot"));
    m_plotButton->setToolTip(tr("Plot the chosen packet (or double-click its row)"));
    m_model->retranslate();
}

void PacketTable::addSnapshot(double seconds, const oi::SensorSnapshot &snapshot)
{
    // Hidden, or behind another dock's tab, the table keeps nothing: shown
    // again, it starts afresh. Whether it is on screen is dear to ask, so it
    // is asked once per tick of the display, not once per frame.
    const quint64 tick = DisplayTick::instance().tickCount();
    if (!m_onScreenKnown || tick != m_onScreenAtTick) {
        m_onScreenKnown = true;
        m_onScreenAtTick = tick;
        m_onScreen = isOnScreen(this);
    }
    if (!m_onScreen)
        return;
    m_model->addSnapshot(seconds, snapshot);
    DisplayTick::instance().requestFrame(this, kRefreshIntervalMs, [this] { refresh(); });
}

void PacketTable::refresh()
{
    m_model->refresh();
    updatePlotButton();
}

int PacketTable::currentPacketId() const { return m_model->packetIdAt(m_view->currentIndex().row()); }

void PacketTable::requestPlot()
{
    const int id = currentPacketId();
    if (id >= 0)
        emit plotRequested(id);
}

void PacketTable::updatePlotButton() { m_plotButton->setEnabled(currentPacketId() >= 0); }

void PacketTable::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    m_onScreenKnown = false; // asked again at the next frame
    // The frames missed while hidden would make the next rate too low.
    m_model->restartRates();
}

void PacketTable::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
}

#include "moc_packet_table.cpp"
