// SPDX-License-Identifier: GPL-3.0-or-later
#include "marker_list.h"

#include "replay_bar.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTextDocument>
#include <QVBoxLayout>

namespace {
enum Column { TimeColumn, NoteColumn };
} // namespace

MarkerList::MarkerList(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_hint = new QLabel(this);
    m_hint->setObjectName("markerHint");
    m_hint->setWordWrap(true);
    m_table = new QTableWidget(0, 2, this);
    m_table->setObjectName("markerTable");
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(TimeColumn, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    // Not on any key: M, comma and full stop are the window's marker keys.
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                             | QAbstractItemView::SelectedClicked);
    auto *buttons = new QHBoxLayout;
    m_jump = new QPushButton(this);
    m_jump->setObjectName("markerJump");
    m_delete = new QPushButton(this);
    m_delete->setObjectName("markerDelete");
    buttons->addWidget(m_jump);
    buttons->addWidget(m_delete);
    buttons->addStretch(1);
    layout->addWidget(m_hint);
    layout->addWidget(m_table, 1);
    layout->addLayout(buttons);

    connect(m_table, &QTableWidget::itemChanged, this, [this](QTableWidgetItem *item) {
        if (m_filling || item->column() != NoteColumn)
            return;
        const int id = item->data(Qt::UserRole).toInt();
        emit renameRequested(id, item->text());
    });
    connect(m_table, &QTableWidget::cellDoubleClicked, this, [this](int row, int column) {
        if (column == TimeColumn && m_jumpable && row < m_markers.size())
            emit jumpRequested(m_markers[row].id);
    });
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &MarkerList::showButtons);
    connect(m_jump, &QPushButton::clicked, this, [this] {
        if (const int id = selectedId())
            emit jumpRequested(id);
    });
    connect(m_delete, &QPushButton::clicked, this, [this] {
        if (const int id = selectedId())
            emit deleteRequested(id);
    });
    retranslateUi();
}

void MarkerList::setMarkers(const QList<oilink::RecordingMarker> &markers)
{
    if (markers == m_markers)
        return;
    const int selected = selectedId();
    m_markers = markers;
    m_filling = true;
    m_table->setRowCount(int(markers.size()));
    for (int row = 0; row < markers.size(); ++row) {
        const oilink::RecordingMarker &m = markers[row];
        auto *time = new QTableWidgetItem(ReplayBar::clock(m.timeUs));
        time->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
        time->setData(Qt::UserRole, m.id);
        auto *note = new QTableWidgetItem(m.note);
        note->setData(Qt::UserRole, m.id);
        // As written: a tooltip is rich text when it looks like it.
        note->setToolTip(Qt::convertFromPlainText(m.label()));
        note->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled | (m_editable ? Qt::ItemIsEditable : Qt::NoItemFlags));
        m_table->setItem(row, TimeColumn, time);
        m_table->setItem(row, NoteColumn, note);
    }
    m_filling = false;
    if (selected)
        select(selected);
    showButtons();
}

void MarkerList::setEditable(bool editable, const QString &why)
{
    m_hint->setText(why);
    m_hint->setVisible(!editable && !why.isEmpty());
    if (editable == m_editable)
        return;
    m_editable = editable;
    const QList<oilink::RecordingMarker> markers = m_markers;
    m_markers.clear();
    setMarkers(markers); // the notes' flags follow
}

void MarkerList::setJumpable(bool jumpable)
{
    m_jumpable = jumpable;
    showButtons();
}

void MarkerList::select(int id)
{
    for (int row = 0; row < m_markers.size(); ++row)
        if (m_markers[row].id == id) {
            m_table->selectRow(row);
            return;
        }
}

int MarkerList::selectedId() const
{
    const QList<QTableWidgetItem *> items = m_table->selectedItems();
    return items.isEmpty() ? 0 : items.first()->data(Qt::UserRole).toInt();
}

void MarkerList::showButtons()
{
    const bool selected = selectedId() != 0;
    m_jump->setEnabled(selected && m_jumpable);
    m_delete->setEnabled(selected && m_editable);
}

void MarkerList::retranslateUi()
{
    m_table->setHorizontalHeaderLabels({tr("Time"), tr("Note")});
    m_jump->setText(tr("&Jump"));
    m_jump->setToolTip(tr("Go to the selected marker in the replay"));
    m_delete->setText(tr("&Delete"));
    m_delete->setToolTip(tr("Delete the selected marker"));
}

void MarkerList::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

#include "moc_marker_list.cpp"
