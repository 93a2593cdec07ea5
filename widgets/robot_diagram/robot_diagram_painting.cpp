// SPDX-License-Identifier: GPL-3.0-or-later
// How the robot diagram paints: the body, bumper, light bumpers, wheels,
// cliff sensors, wall sensor, status chips and the stale banner.
#include "robot_diagram.h"
#include "robot_diagram_scene.h"

#include "oi_text.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

using display::State;
using namespace diagram_scene;

// A thick ring in the palette's highlight colour, with a thin outline so it
// stands out on light and dark fills alike.
void RobotDiagram::paintHighlights(QPainter &p) const
{
    const QColor ring = palette().color(QPalette::Highlight);
    for (const QString &part : m_highlighted) {
        const auto centre = scenePartCentre(part);
        if (!centre)
            continue;
        // Round the lamp, clear of the cliff signal's number below it.
        const qreal radius = part.startsWith(QLatin1String("wheel")) ? 78
                             : part.startsWith(QLatin1String("cliff")) ? kCliffLampRadius + 10
                                                                         : 46;
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(inkColour(), 16));
        p.drawEllipse(*centre, radius, radius);
        p.setPen(QPen(ring, 10));
        p.drawEllipse(*centre, radius, radius);
    }
}

void RobotDiagram::paintBody(QPainter &p) const
{
    const QColor outline = inkColour();
    p.setPen(QPen(outline, 5));
    p.setBrush(palette().color(QPalette::Base));
    p.drawEllipse(circleRect(kBodyRadius));

    if (caps().cargoBay) {
        // The cargo bay, with its connector at the front.
        p.setPen(QPen(outline, 3));
        p.setBrush(palette().color(QPalette::Window));
        p.drawRoundedRect(kCargoBay, 18, 18);
        p.setPen(inkColour());
        p.setFont(sceneFont(26, false));
        p.drawText(kCargoBay.adjusted(0, 40, 0, 0), Qt::AlignHCenter | Qt::AlignTop,
                   tr("CARGO BAY"));
        p.setBrush(outline);
        p.setPen(Qt::NoPen);
        p.drawRoundedRect(QRectF(-40, kCargoBay.top() + 10, 80, 16), 4, 4);
    }

    // The omnidirectional IR receiver on top, at the front.
    const bool ir = m_snapshot.has(17) && m_snapshot.irOmni().kind != oi::IrCharacter::Kind::None;
    p.setPen(QPen(outline, 3));
    p.setBrush(fill(ir ? State::Active : State::Idle));
    p.drawEllipse(kOmniReceiver, 15, 15);
}

void RobotDiagram::paintBumper(QPainter &p) const
{
    const QColor outline = inkColour();
    auto half = [&](bool left, bool bumped) {
        const qreal outer = bumped ? kBumperOuterBumped : kBumperOuter;
        const QPainterPath path =
            left ? ringSegment(kBumperInner, outer, 90 + kBumperGapDegrees,
                               kBumperLeftEnd - 90 - kBumperGapDegrees)
                 : ringSegment(kBumperInner, outer, kBumperRightStart,
                               90 - kBumperGapDegrees - kBumperRightStart);
        p.setPen(QPen(outline, 3));
        p.setBrush(fill(bumped ? State::Alert : State::Idle));
        p.drawPath(path);
    };
    half(true, m_snapshot.bumpLeft());
    half(false, m_snapshot.bumpRight());

    if (!caps().lightBumpers)
        return;
    // The light bumpers sit in the bumper; a lit one has seen an obstacle.
    for (std::size_t i = 0; i < kLightBumperAngles.size(); ++i) {
        const bool on = m_snapshot.lightBumper(static_cast<oi::LightBumper>(i));
        p.setPen(QPen(outline, 3));
        p.setBrush(fill(on ? State::Warning : State::Idle));
        p.drawEllipse(polar((kBumperInner + kBumperOuter) / 2, kLightBumperAngles[i]), 13, 13);
    }
}

void RobotDiagram::paintLightBumpers(QPainter &p) const
{
    if (!caps().lightBumpers)
        return;
    const QColor signal = m_stale ? fill(State::Idle).darker(140) : lightBumpSignalColour(palette());
    QColor track = inkColour();
    track.setAlpha(m_stale ? 60 : 90);
    p.setFont(sceneFont(32));
    const QFontMetricsF fm(p.font());
    for (std::size_t i = 0; i < kLightBumperAngles.size(); ++i) {
        const auto bumper = static_cast<oi::LightBumper>(i);
        const qreal angle = kLightBumperAngles[i];
        const int packetId = 46 + static_cast<int>(i);
        const bool on = m_snapshot.lightBumper(bumper);

        p.setPen(QPen(track, 3));
        p.setBrush(Qt::NoBrush);
        p.drawPath(ringSegment(kLightBumpBase, kLightBumpBase + kLightBumpLength,
                               angle - kLightBumpHalfWidthDegrees, 2 * kLightBumpHalfWidthDegrees));
        p.setPen(Qt::NoPen);
        if (m_snapshot.has(packetId)) {
            const qreal level = std::clamp(m_snapshot.raw(packetId) / kSignalMax, 0.0, 1.0);
            p.setBrush(on ? fill(State::Warning) : signal);
            p.drawPath(ringSegment(kLightBumpBase, kLightBumpBase + kLightBumpLength * level,
                                   angle - kLightBumpHalfWidthDegrees,
                                   2 * kLightBumpHalfWidthDegrees));
        }

        const QString text = signalText(m_snapshot, packetId);
        const QPointF at = polar(kLightBumpLabelRadius, angle);
        const QRectF box(at.x() - 60, at.y() - fm.height() / 2, 120, fm.height());
        p.setPen(on ? fill(State::Warning) : inkColour());
        p.drawText(box, Qt::AlignCenter, text);
    }
}

void RobotDiagram::paintWheels(QPainter &p) const
{
    const QColor outline = inkColour();
    const QColor tyre = m_stale ? fill(State::Idle).darker(130)
                                : (isDark(palette()) ? QColor(125, 129, 136) : QColor(55, 57, 60));
    p.setFont(fittingFont(30, tr("DROP"), 100));
    auto wheel = [&](const QRectF &r, bool dropped, bool left) {
        p.setPen(QPen(outline, 3));
        p.setBrush(dropped ? fill(State::Alert) : tyre);
        p.drawRoundedRect(r, 10, 10);
        if (!dropped)
            return;
        p.setPen(fill(State::Alert));
        const QRectF label = left ? QRectF(r.right() + 8, r.center().y() - 20, 100, 40)
                                  : QRectF(r.left() - 108, r.center().y() - 20, 100, 40);
        p.drawText(label, (left ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter, tr("DROP"));
    };
    wheel(kWheelLeft, m_snapshot.wheelDropLeft(), true);
    wheel(kWheelRight, m_snapshot.wheelDropRight(), false);

    if (caps().casterWheelDrop) {
        const bool dropped = m_snapshot.wheelDropCaster();
        p.setPen(QPen(outline, 3));
        p.setBrush(dropped ? fill(State::Alert) : tyre);
        p.drawEllipse(kCaster, kCasterRadius, kCasterRadius);
        if (dropped) {
            p.setPen(fill(State::Alert));
            p.drawText(QRectF(kCaster.x() - 60, kCaster.y() - kCasterRadius - 40, 120, 36),
                       Qt::AlignCenter, tr("DROP"));
        }
    }
}

void RobotDiagram::paintCliffs(QPainter &p) const
{
    const QColor outline = inkColour();
    const QFont numberFont = sceneFont(38);
    const QColor signal = m_stale ? fill(State::Idle).darker(140) : cliffSignalColour(palette());
    QColor track = inkColour();
    track.setAlpha(m_stale ? 30 : 50);
    for (oi::CliffSensor sensor : kCliffs) {
        const bool cliff = m_snapshot.cliff(sensor);
        p.setPen(QPen(outline, 3));
        p.setBrush(fill(cliff ? State::Alert : State::Idle));
        p.drawEllipse(cliffLampPoint(sensor), kCliffLampRadius, kCliffLampRadius);

        const QRectF label = cliffLabelRect(sensor);
        const int packetId = 28 + static_cast<int>(sensor);
        const QRectF numberBox(label.left(), label.top(), label.width(), label.height() - 14);
        p.setFont(numberFont);
        // On a small diagram the number can be wider than its box: a backdrop
        // keeps it readable where it runs over the lamp's ring.
        const QString number = signalText(m_snapshot, packetId);
        const QRectF ink = p.boundingRect(numberBox, Qt::AlignCenter | Qt::TextDontClip, number);
        if (ink.width() > numberBox.width()) {
            p.setPen(Qt::NoPen);
            p.setBrush(palette().color(QPalette::Window));
            p.drawRoundedRect(ink.adjusted(-3, 0, 3, 0), 4, 4);
        }
        p.setPen(cliff ? fill(State::Alert) : inkColour());
        p.drawText(numberBox, Qt::AlignCenter | Qt::TextDontClip, number);

        const QRectF bar(label.left() + 6, label.bottom() - 12, label.width() - 12, 10);
        p.setPen(Qt::NoPen);
        p.setBrush(track);
        p.drawRoundedRect(bar, 3, 3);
        if (m_snapshot.has(packetId)) {
            const qreal level = std::clamp(m_snapshot.raw(packetId) / kSignalMax, 0.0, 1.0);
            p.setBrush(signal);
            p.drawRoundedRect(QRectF(bar.left(), bar.top(), bar.width() * level, bar.height()), 3, 3);
        }
    }
}

void RobotDiagram::paintWall(QPainter &p) const
{
    // The wall sensor looks out of the robot's right side.
    const bool wall = m_snapshot.wall();
    p.setPen(QPen(inkColour(), 3));
    p.setBrush(fill(wall ? State::Warning : State::Idle));
    p.drawRoundedRect(kWall, 5, 5);

    // The label gets the room up to the widget's right edge, at most 150 units.
    const qreal room = std::min<qreal>(150, width() / sceneScale() / 2 - kWall.right() - 14);
    const QString label = tr("WALL") + '\n' + signalText(m_snapshot, 27);
    p.setFont(fittingFont(28, label, room));
    p.setPen(wall ? fill(State::Warning) : inkColour());
    const QRectF text(kWall.right() + 10, kWall.top(), room, kWall.height());
    p.drawText(text, Qt::AlignLeft | Qt::AlignVCenter, label);
}

void RobotDiagram::paintChips(QPainter &p) const
{
    const qreal rowHeight = chipRowHeight();
    const qreal captionSize = this->captionSize();
    const QFont captionFont = sceneFont(captionSize, false);
    const bool besideValues = chipCaptionsBesideValues();
    for (const auto &[r, chip] : placedChips()) {
        p.setPen(QPen(inkColour(), 2));
        p.setBrush(fill(chip.state));
        p.drawRoundedRect(r, 14, 14);

        QColor text = textColour(chip.state);
        const QRectF inner = chipTextArea(r);
        if (besideValues) {
            QFont bold = sceneFont(captionSize);
            const QFontMetricsF boldMetrics(bold);
            // The whole value where it fits beside the caption in its share
            // of the chip, else its short form ("Red + Green"), else elided.
            const bool wholeFits =
                boldMetrics.horizontalAdvance(chip.caption + QStringLiteral("  ") + chip.value) <= inner.width()
                && boldMetrics.horizontalAdvance(chip.value) <= inner.width() * 0.6;
            const QString value = wholeFits || chip.shortValue.isEmpty() ? chip.value : chip.shortValue;
            const qreal valueWidth = std::min(boldMetrics.horizontalAdvance(value), inner.width() * 0.6);
            p.setPen(text);
            p.setFont(bold);
            p.drawText(inner, Qt::AlignRight | Qt::AlignVCenter,
                       boldMetrics.elidedText(value, Qt::ElideRight, valueWidth));
            text.setAlphaF(0.8);
            p.setPen(text);
            p.setFont(captionFont);
            const qreal captionWidth = inner.width() - valueWidth - QFontMetricsF(captionFont).averageCharWidth();
            p.drawText(inner, Qt::AlignLeft | Qt::AlignVCenter,
                       QFontMetricsF(captionFont).elidedText(chip.caption, Qt::ElideRight, captionWidth));
            continue;
        }
        const QRectF captionRect(inner.left(), inner.top(), inner.width(), captionSize * 1.25);
        const QRectF valueRect(inner.left(), captionRect.bottom(), inner.width(),
                               inner.bottom() - captionRect.bottom());
        // The value shrinks to fit rather than lose its end, down to a
        // size that still reads; then its short form (the tooltip has it
        // whole), which shrinks the same way; past that it is elided.
        const auto fitting = [&](const QString &value, qreal smallest) {
            QFont f = sceneFont(rowHeight * 0.44);
            for (qreal size = rowHeight * 0.44; size > smallest; size -= 2) {
                f = sceneFont(size);
                if (QFontMetricsF(f).horizontalAdvance(value) <= inner.width())
                    return std::pair{f, true};
            }
            return std::pair{f, false};
        };
        QString value = chip.value;
        auto [valueFont, fits] = fitting(value, chip.shortValue.isEmpty() ? rowHeight * 0.25 : rowHeight * 0.33);
        if (!fits && !chip.shortValue.isEmpty()) {
            value = chip.shortValue;
            valueFont = fitting(value, rowHeight * 0.25).first;
        }
        p.setPen(text);
        p.setFont(valueFont);
        p.drawText(valueRect, Qt::AlignCenter,
                   QFontMetricsF(valueFont).elidedText(value, Qt::ElideRight, inner.width()));
        text.setAlphaF(0.8);
        p.setPen(text);
        p.setFont(captionFont);
        p.drawText(captionRect, Qt::AlignHCenter | Qt::AlignVCenter,
                   QFontMetricsF(captionFont).elidedText(chip.caption, Qt::ElideRight, inner.width()));
    }
}

void RobotDiagram::paintStale(QPainter &p) const
{
    if (!m_stale)
        return;
    const QRectF banner(-kBodyRadius + 20, 95, 2 * kBodyRadius - 40, 90);
    p.setPen(QPen(display::textOn(State::Stale, palette()), 4));
    p.setBrush(display::stateColor(State::Stale, palette()));
    p.drawRoundedRect(banner, 16, 16);
    const QString word = m_replayEnded ? tr("ENDED") : tr("STALE");
    p.setFont(fittingFont(64, word, banner.width() - 30));
    p.setPen(display::textOn(State::Stale, palette()));
    p.drawText(banner, Qt::AlignCenter, word);
}
