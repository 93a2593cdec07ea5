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
    if (m_values.mayBeMoving && !m_values.online)
        return tr("MAY STILL BE MOVING");
    const QString mode = m_values.mode.isEmpty() ? tr("mode not known") : m_values.mode;
    return m_values.modeReason.isEmpty() ? mode : tr("%1: %2").arg(mode, m_values.modeReason);
}

QStringList FleetTile::batteryTexts() const
{
    const QString condition = BatteryHealth::conditionWords(m_values.packCondition).toLower();
    const bool packKnown = m_values.packCondition != BatteryCondition::Unknown;
    const QString pack = !packKnown ? QString()
                         : m_values.packCapacityMah
                             ? tr("pack %1, %2 mAh").arg(condition).arg(*m_values.packCapacityMah)
                             : tr("pack %1").arg(condition);
    const QString shortPack = packKnown ? tr("pack %1").arg(condition) : QString();
    if (!m_values.batteryPercent)
        return pack.isEmpty() ? QStringList{} : QStringList{pack, shortPack};
    const int percent = *m_values.batteryPercent;
    const QString charge = tr("battery %1 %").arg(percent);
    if (pack.isEmpty())
        return {charge};
    QStringList texts{tr("%1 · %2").arg(charge, pack), tr("%1 % · %2").arg(percent).arg(pack),
                      tr("%1 % · %2").arg(percent).arg(shortPack), charge};
    texts.removeDuplicates();
    return texts;
}

QString FleetTile::batteryText() const
{
    const QStringList texts = batteryTexts();
    return texts.isEmpty() ? QString() : texts.first();
}

QString FleetTile::modeText() const
{
    return batteryText().isEmpty() ? modeOnlyText() : tr("%1 · %2").arg(modeOnlyText(), batteryText());
}

QString FleetTile::hazardText() const
{
    // Its last hazards are old news; how to stop it is not.
    if (m_values.mayBeMoving && !m_values.online)
        return tr("pick it up, switch it off");
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
    // Its bridge, not the robot's link, is what failed.
    if (!m_values.online)
        return m_values.bridgeLostAt.isValid()
                   ? tr("bridge offline since %1").arg(m_values.bridgeLostAt.toString(QStringLiteral("HH:mm")))
                   : tr("bridge offline");
    // The bridge runs; its robot does not answer it.
    if (m_values.link == QLatin1String("lost"))
        return tr("robot not answering");
    if (m_values.link == QLatin1String("stale"))
        return tr("robot silent (link stale)"); // no rate: it is the last one's
    const QString link = m_values.link.isEmpty() ? tr("link not known") : tr("link %1").arg(m_values.link);
    return m_values.framesPerSecond ? tr("%1 · %2/s").arg(link).arg(*m_values.framesPerSecond) : link;
}

QString FleetTile::controlText() const
{
    if (!m_values.online && !m_values.cutOffController.isEmpty())
        return m_values.cutOffProgram.isEmpty() ? tr("%1 cut off").arg(m_values.cutOffController)
                                                : tr("%1's program cut off").arg(m_values.cutOffController);
    if (m_values.controller.isEmpty())
        return tr("nobody in control");
    if (!m_values.program.isEmpty())
        return tr("%1's program %2").arg(m_values.controller, m_values.program);
    return tr("driven by %1").arg(m_values.controller);
}

QString FleetTile::bridgeLostText(const FleetTileValues &v)
{
    if (v.online || !v.bridgeLostAt.isValid())
        return {};
    const QString at = v.bridgeLostAt.toString(QStringLiteral("HH:mm"));
    const QString who = v.cutOffController.isEmpty() ? QString()
                        : v.cutOffProgram.isEmpty()  ? tr(", cutting off %1").arg(v.cutOffController)
                                                     : tr(", cutting off %1's program %2").arg(v.cutOffController, v.cutOffProgram);
    if (v.mayBeMoving)
        return tr("%1's bridge went offline at %2 while the robot was driving%3. A real robot keeps its last drive "
                  "when its bridge dies: pick it up and hold its power button to switch it off, then restart the "
                  "bridge on the computer beside it.")
            .arg(v.name, at, who);
    return tr("%1's bridge went offline at %2%3 (the broker is fine): check the bridge on the computer beside the "
              "robot, and restart it.")
        .arg(v.name, at, who);
}

void FleetTile::updateAccessibleText()
{
    setAccessibleName(tr("Robot %1, %2").arg(m_values.name, statusText()));
    setAccessibleDescription(
        QStringList{modeText(), hazardText(), linkText(), controlText()}.join(QStringLiteral(", ")));
    const QString lost = bridgeLostText(m_values);
    setToolTip(lost.isEmpty() ? tr("%1\nClick to select this robot: every dock shows it").arg(m_values.name)
                              : tr("%1\n%2\nClick to select this robot: every dock shows it").arg(m_values.name, lost));
}

QString FleetTile::leftPartShown(const QFontMetrics &metrics, int width, const QString &left, const QString &right)
{
    if (right.isEmpty())
        return metrics.elidedText(left, Qt::ElideRight, width);
    const int room = width - metrics.horizontalAdvance(right) - 2 * metrics.averageCharWidth();
    return metrics.elidedText(left, Qt::ElideRight, room);
}

QList<FleetTile::Line> FleetTile::lines() const
{
    // Offline, a line is coloured only for what the bridge's loss means now.
    const bool online = m_values.online;
    const bool moving = m_values.mayBeMoving && !online;
    const bool lost = !online && m_values.bridgeLostAt.isValid();
    const auto when = [](bool on, display::State s) { return on ? std::optional(s) : std::nullopt; };
    const bool hazard = m_values.bumpLeft || m_values.bumpRight || m_values.cliffs > 0 || m_values.wheelDrop;
    QList<Line> lines;
    // The battery whole at the right, said shorter where the mode would not
    // fit whole beside it; no battery beside "may still be moving".
    lines << Line{{modeOnlyText()}, moving ? QStringList{} : batteryTexts(), when(moving, display::State::Alert)};
    lines << Line{{hazardText()}, {}, when(moving || (online && hazard), display::State::Alert)};
    lines << Line{{linkText()}, {},
                  when(lost || (online && !(m_values.linkHealthy && m_values.brokerReachable)), display::State::Warning)};
    QStringList control{controlText()};
    if (!online && !m_values.cutOffController.isEmpty())
        control << tr("%1 cut off").arg(m_values.cutOffController);
    lines << Line{control, {},
                  !online ? when(!m_values.cutOffController.isEmpty(), display::State::Warning)
                          : when(!m_values.controller.isEmpty(), display::State::Active)};
    return lines;
}

QFont FleetTile::fontOf(const Line &line) const
{
    QFont f = lineFont();
    f.setBold(line.state.has_value());
    return f;
}

std::pair<QString, QString> FleetTile::shown(const Line &line) const
{
    const QFontMetrics metrics(fontOf(line));
    const int width = lineWidth();
    const QStringList rights = line.rights.isEmpty() ? QStringList{QString()} : line.rights;
    // The first left and right that fit whole, the longest first; else the
    // last right kept whole and the last left shortened.
    for (const QString &right : rights)
        for (const QString &left : line.lefts)
            if (leftPartShown(metrics, width, left, right) == left)
                return {left, right};
    return {leftPartShown(metrics, width, line.lefts.last(), rights.last()), rights.last()};
}

QStringList FleetTile::shownLines() const
{
    QStringList texts;
    for (const Line &line : lines()) {
        const auto [left, right] = shown(line);
        texts << (right.isEmpty() ? left : left + QLatin1Char(' ') + right);
    }
    return texts;
}

QString FleetTile::shownModeLine() const
{
    return shownLines().first();
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
    const int width = std::max(28 * line.averageCharWidth(), big.horizontalAdvance(QStringLiteral("robot-10 OFFLINE")));
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

    // One line each; a line that needs attention on its state colour. Its
    // right part, if any, is kept whole at the right end; the left gives way.
    for (const Line &l : lines()) {
        const QRect box(x - 4, y, width + 8, line.height() + 4);
        if (l.state) {
            p.setPen(Qt::NoPen);
            p.setBrush(display::stateColor(*l.state, pal));
            p.drawRoundedRect(box, 4, 4);
            p.setPen(display::textOn(*l.state, pal));
        } else {
            p.setPen(text);
        }
        p.setFont(fontOf(l));
        const auto [left, right] = shown(l);
        if (!right.isEmpty())
            p.drawText(box.adjusted(4, 0, -4, 0), Qt::AlignRight | Qt::AlignVCenter, right);
        p.drawText(box.adjusted(4, 0, -4, 0), Qt::AlignLeft | Qt::AlignVCenter, left);
        y += line.height() + 4;
    }

    if (hasFocus()) {
        QStyleOptionFocusRect option;
        option.initFrom(this);
        option.rect = r.adjusted(5, 5, -5, -5);
        style()->drawPrimitive(QStyle::PE_FrameFocusRect, &option, &p, this);
    }
}

#include "moc_fleet_tile.cpp"
