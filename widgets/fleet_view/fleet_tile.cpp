// SPDX-License-Identifier: GPL-3.0-or-later
#include "fleet_tile.h"

#include "display_palette.h"

#include <QEvent>
#include <QFontInfo>
#include <QPainter>
#include <QStyleOptionFocusRect>

namespace {
constexpr int kPadding = 10;
constexpr qreal kNameScale = 2.1;
constexpr qreal kLineScale = 1.55;
} // namespace

FleetTile::FleetTile(QWidget *parent) : QAbstractButton(parent)
{
    setCheckable(true);
    setAutoExclusive(false);
    setFocusPolicy(Qt::StrongFocus);
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    updateAccessibleText();
}

void FleetTile::setValues(const FleetTileValues &values)
{
    if (values == m_values)
        return;
    m_values = values;
    setText(values.name);
    updateAccessibleText();
    update();
}

QString FleetTile::statusText() const
{
    if (!m_values.brokerReachable)
        return tr("NO BROKER");
    return m_values.online ? tr("ONLINE") : tr("OFFLINE");
}

QString FleetTile::modeOnlyText() const
{
    const QString mode = m_values.mode.isEmpty() ? tr("mode not known") : m_values.mode;
    return m_values.modeReason.isEmpty() ? mode : tr("%1: %2").arg(mode, m_values.modeReason);
}

QString FleetTile::batteryText() const
{
    return m_values.batteryPercent ? tr("battery %1 %").arg(*m_values.batteryPercent) : QString();
}

QString FleetTile::modeText() const
{
    return m_values.batteryPercent ? tr("%1 · %2").arg(modeOnlyText(), batteryText()) : modeOnlyText();
}

QString FleetTile::hazardText() const
{
    QStringList parts;
    if (m_values.bumpLeft && m_values.bumpRight)
        parts << tr("BUMP both");
    else if (m_values.bumpLeft)
        parts << tr("BUMP left");
    else if (m_values.bumpRight)
        parts << tr("BUMP right");
    if (m_values.cliffs > 0)
        parts << tr("CLIFF ×%1").arg(m_values.cliffs);
    if (m_values.wheelDrop)
        parts << tr("WHEEL DROP");
    return parts.isEmpty() ? tr("no bump, no cliff") : parts.join(QStringLiteral(" · "));
}

QString FleetTile::linkText() const
{
    // The robot and its bridge are most likely fine: only this window cannot hear them.
    if (!m_values.brokerReachable)
        return tr("broker unreachable");
    const QString link = m_values.link.isEmpty() ? tr("link not known") : tr("link %1").arg(m_values.link);
    return m_values.framesPerSecond ? tr("%1 · %2/s").arg(link).arg(*m_values.framesPerSecond) : link;
}

QString FleetTile::controlText() const
{
    if (m_values.controller.isEmpty())
        return tr("nobody in control");
    if (!m_values.program.isEmpty())
        return tr("%1's program %2").arg(m_values.controller, m_values.program);
    return tr("driven by %1").arg(m_values.controller);
}

void FleetTile::updateAccessibleText()
{
    setAccessibleName(tr("Robot %1, %2").arg(m_values.name, statusText()));
    setAccessibleDescription(
        QStringList{modeText(), hazardText(), linkText(), controlText()}.join(QStringLiteral(", ")));
    setToolTip(tr("%1\nClick to select this robot: every dock shows it").arg(m_values.name));
}

QString FleetTile::leftPartShown(const QFontMetrics &metrics, int width, const QString &left, const QString &right)
{
    if (right.isEmpty())
        return metrics.elidedText(left, Qt::ElideRight, width);
    const int room = width - metrics.horizontalAdvance(right) - 2 * metrics.averageCharWidth();
    return metrics.elidedText(left, Qt::ElideRight, room);
}

QString FleetTile::shownModeLine() const
{
    const QString battery = batteryText();
    const QString left = leftPartShown(QFontMetrics(lineFont()), lineWidth(), modeOnlyText(), battery);
    return battery.isEmpty() ? left : left + QLatin1Char(' ') + battery;
}

int FleetTile::smallestTextPixels() const
{
    return QFontInfo(lineFont()).pixelSize();
}

QFont FleetTile::lineFont() const
{
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * kLineScale);
    return f;
}

int FleetTile::lineWidth() const
{
    return rect().adjusted(2, 2, -2, -2).width() - 2 * kPadding;
}

QSize FleetTile::sizeHint() const
{
    const QFontMetrics big(display::valueFont(font(), kNameScale));
    const QFontMetrics line(display::valueFont(font(), kLineScale));
    const int width = std::max(26 * line.averageCharWidth(), big.horizontalAdvance(QStringLiteral("robot-10 OFFLINE")));
    return {width + 2 * kPadding, big.height() + 4 * (line.height() + 4) + 3 * kPadding};
}

void FleetTile::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        updateAccessibleText();
        update();
    }
    QAbstractButton::changeEvent(event);
}

void FleetTile::paintEvent(QPaintEvent *)
{
    ++m_paints;
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette &pal = palette();
    const QRect r = rect().adjusted(2, 2, -2, -2);
    const QColor text = m_values.online ? pal.color(QPalette::Text) : pal.color(QPalette::Disabled, QPalette::Text);
    p.setPen(QPen(isChecked() ? pal.color(QPalette::Highlight) : pal.color(QPalette::Mid), isChecked() ? 5 : 1));
    p.setBrush(m_values.online ? pal.color(QPalette::Base) : pal.color(QPalette::Window));
    p.drawRoundedRect(r, 8, 8);

    const QFont nameFont = display::valueFont(font(), kNameScale);
    const QFont lineFont = this->lineFont();
    const QFontMetrics big(nameFont);
    const QFontMetrics line(lineFont);
    const int x = r.left() + kPadding;
    const int width = lineWidth();
    int y = r.top() + kPadding;

    // The status badge at the right of the name: green online, red offline.
    const QFont badgeFont = display::valueFont(font(), kLineScale);
    const QFontMetrics badgeMetrics(badgeFont);
    const display::State status = !m_values.brokerReachable ? display::State::Warning
                                  : m_values.online         ? display::State::Active
                                                            : display::State::Alert;
    const int badgeWidth = badgeMetrics.horizontalAdvance(statusText()) + 12;
    const QRect badge(r.right() - kPadding - badgeWidth, y + (big.height() - badgeMetrics.height()) / 2 - 2, badgeWidth,
                      badgeMetrics.height() + 4);
    p.setPen(Qt::NoPen);
    p.setBrush(display::stateColor(status, pal));
    p.drawRoundedRect(badge, 4, 4);
    p.setFont(badgeFont);
    p.setPen(display::textOn(status, pal));
    p.drawText(badge, Qt::AlignCenter, statusText());

    p.setFont(nameFont);
    p.setPen(text);
    const int nameWidth = width - badgeWidth - kPadding;
    p.drawText(QRect(x, y, nameWidth, big.height()), Qt::AlignLeft | Qt::AlignVCenter,
               big.elidedText(m_values.name, Qt::ElideRight, nameWidth));
    y += big.height() + kPadding;

    // One line each; a line that needs attention on its state colour.
    // `right`, if any, is kept whole at the right end; `s` gives way to it.
    const auto drawLine = [&](const QString &s, std::optional<display::State> state, const QString &right = {}) {
        const QRect box(x - 4, y, width + 8, line.height() + 4);
        p.setFont(lineFont);
        if (state && m_values.online) {
            p.setPen(Qt::NoPen);
            p.setBrush(display::stateColor(*state, pal));
            p.drawRoundedRect(box, 4, 4);
            p.setPen(display::textOn(*state, pal));
            QFont bold = lineFont;
            bold.setBold(true);
            p.setFont(bold);
        } else {
            p.setPen(text);
        }
        if (!right.isEmpty())
            p.drawText(box.adjusted(4, 0, -4, 0), Qt::AlignRight | Qt::AlignVCenter, right);
        p.drawText(box.adjusted(4, 0, -4, 0), Qt::AlignLeft | Qt::AlignVCenter,
                   leftPartShown(QFontMetrics(p.font()), width, s, right));
        y += line.height() + 4;
    };
    drawLine(modeOnlyText(), std::nullopt, batteryText());
    const bool hazard = m_values.bumpLeft || m_values.bumpRight || m_values.cliffs > 0 || m_values.wheelDrop;
    drawLine(hazardText(), hazard ? std::optional(display::State::Alert) : std::nullopt);
    drawLine(linkText(), m_values.linkHealthy && m_values.brokerReachable ? std::nullopt
                                                                          : std::optional(display::State::Warning));
    drawLine(controlText(), m_values.controller.isEmpty() ? std::nullopt : std::optional(display::State::Active));

    if (hasFocus()) {
        QStyleOptionFocusRect option;
        option.initFrom(this);
        option.rect = r.adjusted(5, 5, -5, -5);
        style()->drawPrimitive(QStyle::PE_FrameFocusRect, &option, &p, this);
    }
}

#include "moc_fleet_tile.cpp"
