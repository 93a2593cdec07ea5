// SPDX-License-Identifier: GPL-3.0-or-later
// The robot diagram: its state, its scene's geometry and fonts, its status
// chips and their tooltips.
#include "robot_diagram.h"
#include "robot_diagram_scene.h"

#include "oi_text.h"

#include <QEvent>
#include <QFontMetricsF>
#include <QHelpEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

using display::State;

using namespace diagram_scene;

RobotDiagram::RobotDiagram(QWidget *parent)
    : QWidget(parent), m_snapshot(*m_profile)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    retranslateUi();
}

void RobotDiagram::retranslateUi()
{
    setAccessibleName(tr("Robot sensor diagram"));
    updateDescription();
    update();
}

void RobotDiagram::updateDescription()
{
    const QString text = stateSummary();
    if (accessibleDescription() != text)
        setAccessibleDescription(text);
}

QString RobotDiagram::stateSummary() const
{
    const oi::SensorSnapshot &s = m_snapshot;
    QStringList parts;
    if (m_stale)
        parts << (m_replayEnded ? tr("The replay has ended") : tr("Data is stale"));
    if (s.bumpLeft())
        parts << tr("Bump left");
    if (s.bumpRight())
        parts << tr("Bump right");
    if (s.wheelDropLeft())
        parts << tr("Wheel drop left");
    if (s.wheelDropRight())
        parts << tr("Wheel drop right");
    if (caps().casterWheelDrop && s.wheelDropCaster())
        parts << tr("Caster wheel drop");
    const QString cliffNames[] = {tr("Cliff left"), tr("Cliff front left"), tr("Cliff front right"),
                                  tr("Cliff right")};
    for (oi::CliffSensor sensor : kCliffs)
        if (s.cliff(sensor))
            parts << cliffNames[static_cast<int>(sensor)];
    if (s.wall())
        parts << tr("Wall");
    if (caps().lightBumpers && s.has(45))
        for (const oi::BitMeaning &b : m_profile->bits(45))
            if (s.raw(45) & b.mask)
                parts << tr("Light bumper %1").arg(oitext::bitName(b));
    for (const QList<Chip> &row : chipRows())
        for (const Chip &chip : row)
            if (chip.state != State::Idle)
                parts << tr("%1: %2").arg(chip.caption, chip.value);
    if (parts.isEmpty())
        return s.packetCount() == 0 ? tr("No sensor data") : tr("Nothing detected");
    return parts.join(tr("; "));
}

void RobotDiagram::setProfile(const oi::RobotProfile &profile)
{
    if (m_profile == &profile)
        return;
    m_profile = &profile;
    m_snapshot = oi::SensorSnapshot(profile);
    updateDescription();
    update();
}

void RobotDiagram::setSnapshot(const oi::SensorSnapshot &snapshot)
{
    m_snapshot = snapshot;
    updateDescription();
    update();
}

void RobotDiagram::setStale(bool stale, bool replayEnded)
{
    replayEnded = stale && replayEnded;
    if (m_stale == stale && m_replayEnded == replayEnded)
        return;
    m_stale = stale;
    m_replayEnded = replayEnded;
    updateDescription();
    update();
}

QSize RobotDiagram::minimumSizeHint() const { return {240, 240}; }
QSize RobotDiagram::sizeHint() const { return {520, 520}; }

qreal RobotDiagram::sceneTop() const
{
    return caps().lightBumpers ? kSceneTopLightBumps : kSceneTopPlain;
}

qreal RobotDiagram::sceneScale() const
{
    const qreal sceneWidth = caps().lightBumpers ? kSceneWidthLightBumps : kSceneWidthPlain;
    const qreal s = std::min(width() / sceneWidth, height() / (kSceneBottom - sceneTop()));
    return std::max<qreal>(1e-3, s);
}

qreal RobotDiagram::topOffset() const
{
    // On a tall widget, once the chips are as tall as they get, the drawing
    // and the chips sit in the middle rather than at the top.
    const qreal content = kChipTop - sceneTop() + kChipRows * kChipMaxHeight
                          + (kChipRows - 1) * kChipGap + kChipBottomMargin;
    return std::max<qreal>(0, (height() - content * sceneScale()) / 2);
}

QTransform RobotDiagram::sceneToWidget() const
{
    const qreal s = sceneScale();
    QTransform t;
    t.translate(width() / 2.0, topOffset() - sceneTop() * s);
    t.scale(s, s);
    return t;
}

QPointF RobotDiagram::cliffSensorCentre(oi::CliffSensor sensor) const
{
    return sceneToWidget().map(cliffLampPoint(sensor));
}

QRectF RobotDiagram::cliffSignalRect(oi::CliffSensor sensor) const
{
    return sceneToWidget().mapRect(cliffLabelRect(sensor));
}

QPointF RobotDiagram::bumperCentre(bool left) const
{
    // Midway between light bumpers, so the point is bumper and nothing else.
    return sceneToWidget().map(polar((kBumperInner + kBumperOuter) / 2, left ? 120 : 60));
}

QRectF RobotDiagram::bumperRect(bool left) const
{
    const QPainterPath half = left ? ringSegment(kBumperInner, kBumperOuter, 90, kBumperLeftEnd - 90)
                                   : ringSegment(kBumperInner, kBumperOuter, kBumperRightStart,
                                                 90 - kBumperRightStart);
    return sceneToWidget().mapRect(half.boundingRect());
}

QPointF RobotDiagram::lightBumperCentre(oi::LightBumper bumper) const
{
    return sceneToWidget().map(polar((kBumperInner + kBumperOuter) / 2,
                                     kLightBumperAngles[static_cast<std::size_t>(bumper)]));
}

QPointF RobotDiagram::lightBumpSignalPoint(oi::LightBumper bumper, qreal level) const
{
    return sceneToWidget().map(polar(kLightBumpBase + kLightBumpLength * std::clamp(level, 0.0, 1.0),
                                     kLightBumperAngles[static_cast<std::size_t>(bumper)]));
}

QPointF RobotDiagram::wheelCentre(bool left) const
{
    return sceneToWidget().map((left ? kWheelLeft : kWheelRight).center());
}

QPointF RobotDiagram::casterCentre() const { return sceneToWidget().map(kCaster); }

QPointF RobotDiagram::wallCentre() const { return sceneToWidget().map(kWall.center()); }

QRectF RobotDiagram::robotRect() const { return sceneToWidget().mapRect(circleRect(kBodyRadius)); }

QColor RobotDiagram::fill(State state) const
{
    if (!m_stale)
        return display::stateColor(state, palette());
    // Greys only, so nothing looks live; what was lit stays apart from what
    // was not, so the last picture can still be read.
    if (state == State::Idle) {
        const int grey = qGray(display::stateColor(State::Idle, palette()).rgb());
        return QColor(grey, grey, grey);
    }
    return isDark(palette()) ? QColor(150, 150, 150) : QColor(118, 118, 118);
}

QColor RobotDiagram::textColour(State state) const
{
    if (!m_stale)
        return display::textOn(state, palette());
    return fill(state).lightness() > 140 ? QColor(20, 20, 20) : QColor(250, 250, 250);
}

QColor RobotDiagram::inkColour() const
{
    QColor ink = palette().color(QPalette::WindowText);
    if (m_stale)
        ink.setAlpha(150);
    return ink;
}

QFont RobotDiagram::sceneFont(qreal pixelSize, bool bold) const
{
    QFont f = display::valueFont(font());
    f.setBold(bold);
    // Scene units: at least m_leastTextPixels once drawn.
    f.setPixelSize(std::max(1, qCeil(std::max(pixelSize, m_leastTextPixels / sceneScale()))));
    return f;
}

void RobotDiagram::setLeastTextPixels(qreal pixels)
{
    m_leastTextPixels = pixels;
    update();
}

// Captions stay at least 10 px high on the smallest widget.
qreal RobotDiagram::captionSize() const
{
    return std::max(chipRowHeight() * 0.28, std::max(10.0, m_leastTextPixels) / sceneScale());
}

qreal RobotDiagram::captionPixels() const
{
    return sceneFont(captionSize(), false).pixelSize() * sceneScale();
}

QFont RobotDiagram::fittingFont(qreal pixelSize, const QString &text, qreal width) const
{
    // Translated words differ in length; shrink to fit rather than run out of the box.
    QFont f = sceneFont(pixelSize);
    qreal widest = 0;
    for (const QString &line : text.split('\n'))
        widest = std::max(widest, QFontMetricsF(f).horizontalAdvance(line));
    if (widest > width)
        f = sceneFont(std::max(pixelSize * 0.6, pixelSize * width / widest));
    return f;
}

QList<QList<RobotDiagram::Chip>> RobotDiagram::chipRows() const
{
    const oi::SensorSnapshot &s = m_snapshot;
    const QString none = QStringLiteral("\u2014");

    auto irChip = [&](const QString &caption, int packetId, oi::IrCharacter ir) {
        if (!s.has(packetId))
            return Chip{caption, none, State::Idle, {}};
        const bool received = ir.kind != oi::IrCharacter::Kind::None;
        return Chip{caption, oitext::infraredName(ir), received ? State::Active : State::Idle,
                    oitext::infraredShortName(ir)};
    };

    auto bitNames = [&](int packetId) {
        QStringList names;
        for (const oi::BitMeaning &b : m_profile->bits(packetId))
            if (s.raw(packetId) & b.mask)
                names << oitext::bitName(b);
        return names;
    };

    Chip buttons{tr("Buttons"), none, State::Idle, {}};
    if (s.has(18)) {
        const QStringList pressed = bitNames(18);
        if (pressed.isEmpty())
            buttons.value = tr("none");
        else
            buttons = {buttons.caption, pressed.join(" + "), State::Active, {}};
    }

    Chip virtualWall{tr("Virtual wall"), none, State::Idle, {}};
    if (s.has(13)) {
        if (s.virtualWall())
            virtualWall = {virtualWall.caption, tr("seen"), State::Warning, {}};
        else
            virtualWall.value = tr("none");
    }

    Chip overcurrent{tr("Overcurrent"), none, State::Idle, {}};
    if (s.has(14)) {
        const QStringList over = bitNames(14);
        if (over.isEmpty())
            overcurrent.value = tr("none");
        else
            overcurrent = {overcurrent.caption, over.join(", "), State::Alert, {}};
    }

    if (!caps().sideInfrared)
        return {{irChip(tr("IR"), 17, s.irOmni()), virtualWall}, {buttons}, {overcurrent}};

    // ERRATA 5: 2 is the Create 2's dirty stasis wheel, not "moving".
    Chip stasis{tr("Stasis"), none, State::Idle, {}};
    if (s.has(58)) {
        switch (s.stasis()) {
        case oi::Stasis::NotProgressing: stasis.value = tr("not moving"); break;
        case oi::Stasis::Progressing: stasis = {stasis.caption, tr("moving"), State::Active, {}}; break;
        case oi::Stasis::DirtyWheel:
            stasis = {stasis.caption, tr("DIRTY WHEEL"), State::Warning, {}};
            break;
        case oi::Stasis::Reserved: stasis = {stasis.caption, tr("reserved (3)"), State::Alert, {}}; break;
        }
    }
    return {{irChip(tr("IR omni"), 17, s.irOmni()), irChip(tr("IR left"), 52, s.irLeft()),
             irChip(tr("IR right"), 53, s.irRight())},
            {buttons, stasis, virtualWall},
            {overcurrent}};
}

QStringList RobotDiagram::statusTexts() const
{
    QStringList out;
    for (const QList<Chip> &row : chipRows())
        for (const Chip &chip : row)
            out << tr("%1: %2").arg(chip.caption, chip.value);
    return out;
}

void RobotDiagram::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    else if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange)
        update();
    QWidget::changeEvent(event);
}

void RobotDiagram::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.fillRect(rect(), palette().color(QPalette::Window));
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::TextAntialiasing);
    p.setTransform(sceneToWidget());

    paintLightBumpers(p);
    paintBody(p);
    paintBumper(p);
    paintWheels(p);
    paintHighlights(p); // under the cliff sensors' numbers and the wall's label
    paintCliffs(p);
    paintWall(p);
    paintChips(p);
    paintStale(p);
}

void RobotDiagram::setHighlightedParts(const QStringList &parts)
{
    if (parts == m_highlighted)
        return;
    m_highlighted = parts;
    update();
}

std::optional<QPointF> RobotDiagram::partCentre(const QString &part) const
{
    if (const auto centre = scenePartCentre(part))
        return sceneToWidget().map(*centre);
    return std::nullopt;
}

std::optional<QPointF> RobotDiagram::scenePartCentre(const QString &part) const
{
    const qreal bumperMid = (kBumperInner + kBumperOuter) / 2;
    if (part == QLatin1String("bump_left") || part == QLatin1String("bump_right"))
        return polar(bumperMid, part == QLatin1String("bump_left") ? 120 : 60);
    if (part == QLatin1String("wheel_left"))
        return kWheelLeft.center();
    if (part == QLatin1String("wheel_right"))
        return kWheelRight.center();
    if (part == QLatin1String("caster"))
        return caps().casterWheelDrop ? std::optional(kCaster) : std::nullopt;
    if (part == QLatin1String("wall"))
        return kWall.center();
    if (part == QLatin1String("ir_receiver"))
        return kOmniReceiver;
    static const char *const cliffs[] = {"cliff_left", "cliff_front_left", "cliff_front_right", "cliff_right"};
    for (int i = 0; i < 4; ++i)
        if (part == QLatin1String(cliffs[i]))
            return cliffLampPoint(oi::CliffSensor(i));
    static const char *const lights[] = {"light_bump_left", "light_bump_front_left", "light_bump_center_left",
                                         "light_bump_center_right", "light_bump_front_right", "light_bump_right"};
    for (int i = 0; i < 6; ++i)
        if (part == QLatin1String(lights[i]))
            return !caps().lightBumpers ? std::nullopt : std::optional(polar(bumperMid, kLightBumperAngles[std::size_t(i)]));
    return std::nullopt;
}

qreal RobotDiagram::chipRowHeight() const
{
    const qreal bottom = (height() - topOffset()) / sceneScale() + sceneTop() - kChipBottomMargin;
    return std::clamp((bottom - kChipTop - (kChipRows - 1) * kChipGap) / kChipRows, kChipMinHeight,
                      kChipMaxHeight);
}

QList<std::pair<QRectF, RobotDiagram::Chip>> RobotDiagram::placedChips() const
{
    // The chips use the widget's whole width, even where the drawing does not.
    const qreal halfWidth = width() / sceneScale() / 2 - 12;
    const qreal rowHeight = chipRowHeight();
    QList<std::pair<QRectF, Chip>> out;
    qreal top = kChipTop;
    for (const QList<Chip> &row : chipRows()) {
        const qreal chipWidth = (2 * halfWidth - kChipGap * qreal(row.size() - 1)) / qreal(row.size());
        qreal left = -halfWidth;
        for (const Chip &chip : row) {
            out.append({QRectF(left, top, chipWidth, rowHeight), chip});
            left += chipWidth + kChipGap;
        }
        top += rowHeight + kChipGap;
    }
    return out;
}

bool RobotDiagram::event(QEvent *event)
{
    if (event->type() == QEvent::ToolTip) {
        // Long values may be shortened on a small widget; the tooltip has them whole.
        auto *help = static_cast<QHelpEvent *>(event);
        const QPointF at = sceneToWidget().inverted().map(QPointF(help->pos()));
        for (const auto &[r, chip] : placedChips()) {
            if (r.contains(at)) {
                QToolTip::showText(help->globalPos(), tr("%1: %2").arg(chip.caption, chip.value), this);
                return true;
            }
        }
        QToolTip::hideText();
        event->ignore();
        return true;
    }
    return QWidget::event(event);
}

bool RobotDiagram::chipCaptionsBesideValues() const
{
    // Every chip is a row high. Too short for the caption's line above the
    // value's (descenders included), or for two lines of the least readable
    // size: side by side.
    const qreal rowHeight = chipRowHeight();
    const qreal textHeight = chipTextArea(QRectF(0, 0, 0, rowHeight)).height();
    const qreal stackedHeight = captionSize() * 1.25 + QFontMetricsF(sceneFont(rowHeight * 0.44)).height();
    return textHeight * sceneScale() < 2.6 * m_leastTextPixels || stackedHeight > textHeight;
}

#include "moc_robot_diagram.cpp"
