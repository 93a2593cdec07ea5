// SPDX-License-Identifier: GPL-3.0-or-later
#include "comparison_bar.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QStyle>
#include <QToolButton>

ComparisonBar::ComparisonBar(QWidget *parent) : QWidget(parent)
{
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(4, 0, 4, 0);
    m_label = new QLabel(this);
    m_label->setObjectName("comparisonLabel");
    m_label->setTextFormat(Qt::PlainText); // the file's name, as written
    m_align = new QComboBox(this);
    m_align->setObjectName("comparisonAlignment");
    m_align->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_close = new QToolButton(this);
    m_close->setObjectName("comparisonClose");
    m_close->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_close->setIcon(style()->standardIcon(QStyle::SP_DialogCloseButton));
    row->addWidget(m_label);
    row->addWidget(m_align);
    row->addWidget(m_close);
    connect(m_align, &QComboBox::activated, this,
            [this](int i) { emit alignRequested(i == 0 ? QString() : m_align->itemData(i).toString()); });
    connect(m_close, &QToolButton::clicked, this, &ComparisonBar::closeRequested);
    retranslateUi();
}

void ComparisonBar::showRun(const QString &fileName, const QStringList &markers, const QString &alignedAt)
{
    m_fileName = fileName;
    const QSignalBlocker quiet(m_align);
    m_align->clear();
    m_align->addItem(QString());
    for (const QString &marker : markers)
        m_align->addItem(QString(), marker);
    retranslateUi();
    m_align->setCurrentIndex(alignedAt.isEmpty() ? 0 : std::max(0, m_align->findData(alignedAt)));
}

void ComparisonBar::retranslateUi()
{
    m_label->setText(tr("Compared with %1").arg(m_fileName));
    if (m_align->count() > 0)
        m_align->setItemText(0, tr("aligned at the start"));
    for (int i = 1; i < m_align->count(); ++i)
        m_align->setItemText(i, tr("aligned at “%1”").arg(m_align->itemData(i).toString()));
    m_align->setToolTip(tr("Where the two runs line up in time: their starts, or a marker both hold"));
    m_close->setText(tr("Close comparison"));
}

void ComparisonBar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

#include "moc_comparison_bar.cpp"
