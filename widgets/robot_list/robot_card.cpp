// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_card.h"

#include "display_palette.h"

#include <QMouseEvent>
#include <QPainter>
#include <QStyleOptionFocusRect>

namespace {
constexpr int kColourBar = 8;
constexpr int kPadding = 6;
} // namespace

RobotCard::RobotCard(QWidget *parent) : QAbstractButton(parent)
{
    setCheckable(true);
    setFocusPolicy(Qt::StrongFocus);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void RobotCard::setValues(const RobotCardValues &values)
{
    if (values == m_values)
        return;
    const QString oldDetail = detailText();
    const bool resize = values.name != m_values.name || values.link != m_values.link;
    m_values = values;
    setText(values.name);
    updateAccessibleText();
    if (resize || detailText().size() != oldDetail.size())
        updateGeometry();
    update();
}

QString RobotCard::detailText() const
{
    QStringList parts{m_values.profile};
    if (!m_values.mode.isEmpty())
        parts << m_values.mode;
    if (m_values.batteryPercent)
        parts << tr("%1 %").arg(*m_values.batteryPercent);
    return parts.join(QStringLiteral(" · "));
}

void RobotCard::updateAccessibleText()
{
    setAccessibleName(tr("Robot %1").arg(m_values.name));
    setAccessibleDescription(tr("%1, link %2").arg(detailText(), m_values.link));
    setToolTip(tr("%1\n%2\nLink: %3\nDouble-click to rename").arg(m_values.name, detailText(), m_values.link));
}

QSize RobotCard::sizeHint() const
{
    const QFont bold = display::valueFont(font(), 1.15);
    const QFontMetrics big(bold);
    const QFontMetrics small(font());
    const int lines = big.height() + 2 * small.height();
    const int width = std::max({big.horizontalAdvance(m_values.name), small.horizontalAdvance(detailText()),
                                small.horizontalAdvance(m_values.link), 12 * small.averageCharWidth()});
    return {kColourBar + 4 * kPadding + width + 4, lines + 2 * kPadding};
}

QSize RobotCard::minimumSizeHint() const
{
    // Squeezed by many robots, the lines end in "…"; the tooltip has them whole.
    const QFontMetrics small(font());
    return {std::min(sizeHint().width(), kColourBar + 4 * kPadding + 18 * small.averageCharWidth()),
            sizeHint().height()};
}

void RobotCard::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRect r = rect().adjusted(1, 1, -1, -1);
    const QPalette &pal = palette();
    p.setPen(QPen(isChecked() ? pal.color(QPalette::Highlight) : pal.color(QPalette::Mid), isChecked() ? 3 : 1));
    p.setBrush(isChecked() ? pal.color(QPalette::Base) : pal.color(QPalette::Button));
    p.drawRoundedRect(r, 4, 4);
    p.fillRect(QRect(r.left() + 2, r.top() + 2, kColourBar, r.height() - 3), m_values.colour);

    const int x = r.left() + kColourBar + 2 * kPadding;
    const int width = r.right() - x - kPadding;
    const QFont bold = display::valueFont(font(), 1.15);
    const QFontMetrics big(bold);
    const QFontMetrics small(font());
    int y = r.top() + kPadding;
    p.setPen(pal.color(QPalette::Text));
    p.setFont(bold);
    p.drawText(QRect(x, y, width, big.height()), Qt::AlignLeft | Qt::AlignVCenter,
               big.elidedText(m_values.name, Qt::ElideRight, width));
    y += big.height();
    p.setFont(font());
    p.drawText(QRect(x, y, width, small.height()), Qt::AlignLeft | Qt::AlignVCenter,
               small.elidedText(detailText(), Qt::ElideRight, width));
    y += small.height();
    // The link in the alert colour when no fresh data comes.
    const display::State state = m_values.live ? display::State::Idle : display::State::Alert;
    if (!m_values.live) {
        const QRect badge(x - 2, y, std::min(width + 4, small.horizontalAdvance(m_values.link) + 8), small.height());
        p.fillRect(badge, display::stateColor(state, pal));
        p.setPen(display::textOn(state, pal));
    }
    p.drawText(QRect(x + 2, y, width, small.height()), Qt::AlignLeft | Qt::AlignVCenter,
               small.elidedText(m_values.link, Qt::ElideRight, width));
    if (hasFocus()) {
        QStyleOptionFocusRect option;
        option.initFrom(this);
        option.rect = r.adjusted(3, 3, -3, -3);
        style()->drawPrimitive(QStyle::PE_FrameFocusRect, &option, &p, this);
    }
}

void RobotCard::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton)
        emit renameRequested();
}

#include "moc_robot_card.cpp"
