// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_list.h"

#include <QButtonGroup>
#include <QEvent>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QMenu>
#include <QScrollArea>
#include <QScrollBar>
#include <QToolButton>

#include <algorithm>

RobotList::RobotList(QWidget *parent) : QWidget(parent)
{
    setObjectName("robotList");
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);

    auto *strip = new QWidget;
    m_cardLayout = new QHBoxLayout(strip);
    m_cardLayout->setContentsMargins(0, 0, 0, 0);
    m_cardLayout->addStretch();
    m_scroll = new QScrollArea;
    m_scroll->setObjectName("robotStrip");
    m_scroll->setWidget(strip);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_scroll->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    layout->addWidget(m_scroll, 1);

    m_group = new QButtonGroup(this);
    m_group->setExclusive(true);
    connect(m_group, &QButtonGroup::idClicked, this, &RobotList::selectRequested);

    m_addMenu = new QMenu(this);
    m_addVirtual = m_addMenu->addAction(QString(), this, [this] { emit addRequested(AddKind::VirtualRobot); });
    m_addConnection = m_addMenu->addAction(QString(), this, [this] { emit addRequested(AddKind::Connection); });
    m_addRecording = m_addMenu->addAction(QString(), this, [this] { emit addRequested(AddKind::Recording); });
    m_add = new QToolButton;
    m_add->setObjectName("addRobot");
    m_add->setMenu(m_addMenu);
    m_add->setPopupMode(QToolButton::InstantPopup);
    m_rename = new QToolButton;
    m_rename->setObjectName("renameRobot");
    connect(m_rename, &QToolButton::clicked, this, [this] { beginRename(selected()); });
    m_remove = new QToolButton;
    m_remove->setObjectName("removeRobot");
    connect(m_remove, &QToolButton::clicked, this, [this] {
        if (selected() >= 0)
            emit removeRequested(selected());
    });
    for (QToolButton *b : {m_add, m_rename, m_remove}) {
        b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        layout->addWidget(b);
    }

    m_renameEditor = new QLineEdit(this);
    m_renameEditor->setObjectName("robotNameEditor");
    m_renameEditor->setMaxLength(40);
    m_renameEditor->hide();
    connect(m_renameEditor, &QLineEdit::editingFinished, this, &RobotList::finishRename);

    retranslateUi();
}

void RobotList::setCards(const QList<RobotCardValues> &cards)
{
    // Called a few times a second with what mostly has not changed.
    if (cards.size() == m_cards.size()
        && std::equal(cards.cbegin(), cards.cend(), m_cards.cbegin(),
                      [](const RobotCardValues &values, const RobotCard *card) { return values == card->values(); }))
        return;
    while (m_cards.size() > cards.size()) {
        RobotCard *card = m_cards.takeLast();
        m_group->removeButton(card);
        delete card;
    }
    while (m_cards.size() < cards.size()) {
        auto *card = new RobotCard;
        const int index = int(m_cards.size());
        card->setObjectName(QStringLiteral("robotCard%1").arg(index));
        m_group->addButton(card, index);
        connect(card, &RobotCard::renameRequested, this, [this, index] { beginRename(index); });
        m_cardLayout->insertWidget(index, card);
        m_cards << card;
    }
    for (qsizetype i = 0; i < cards.size(); ++i)
        m_cards[i]->setValues(cards[i]);
    m_remove->setEnabled(m_cards.size() > 1);
    // Room below the cards for the scroll bar that more robots bring, so
    // that it never covers a card.
    const int cardHeight = m_cards.isEmpty() ? 0 : m_cards.first()->sizeHint().height();
    m_scroll->setFixedHeight(cardHeight + m_scroll->horizontalScrollBar()->sizeHint().height());
}

void RobotList::setSelected(int index)
{
    RobotCard *card = m_cards.value(index);
    if (card && !card->isChecked()) {
        card->setChecked(true);
        // A robot chosen elsewhere (the fleet view) comes into view.
        m_cardLayout->activate();
        m_scroll->ensureWidgetVisible(card, 0, 0);
    }
}

int RobotList::selected() const
{
    return m_group->checkedId();
}

void RobotList::beginRename(int index)
{
    RobotCard *card = m_cards.value(index);
    if (!card)
        return;
    m_renaming = index;
    m_renameEditor->setText(card->values().name);
    m_renameEditor->setGeometry(QRect(card->mapTo(this, QPoint(0, 0)), card->size()).adjusted(10, 4, -4, -4)
                                    .intersected(rect()));
    m_renameEditor->show();
    m_renameEditor->raise();
    m_renameEditor->selectAll();
    m_renameEditor->setFocus(Qt::OtherFocusReason);
}

void RobotList::finishRename()
{
    if (m_renaming < 0)
        return;
    const int index = std::exchange(m_renaming, -1);
    const QString name = m_renameEditor->text().trimmed();
    m_renameEditor->hide();
    if (!name.isEmpty() && m_cards.value(index) && name != m_cards[index]->values().name)
        emit renameRequested(index, name);
}

void RobotList::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void RobotList::retranslateUi()
{
    m_add->setText(tr("Add robot"));
    m_add->setToolTip(tr("Add a robot to the window: a virtual one, a serial port or TCP bridge, or a recording"));
    m_addVirtual->setText(tr("Virtual robot"));
    m_addConnection->setText(tr("Serial port or TCP bridge…"));
    m_addRecording->setText(tr("Recording…"));
    m_rename->setText(tr("Rename"));
    m_rename->setToolTip(tr("Rename the selected robot (or double-click its card)"));
    m_remove->setText(tr("Remove"));
    m_remove->setToolTip(tr("Stop the selected robot, leave it in Passive and remove it from the window"));
    m_renameEditor->setAccessibleName(tr("Robot name"));
}

#include "moc_robot_list.cpp"
