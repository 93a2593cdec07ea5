// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_diagram.h"

#include "oi_text.h"

#include <QEvent>
#include <QFontMetricsF>
#include <QHelpEvent>
#include <QPainter>
#include <QtMath>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

using display::State;

namespace {

// The scene is 1000 units wide with the robot's centre at the origin; y
// grows towards the back of the robot. The body's radius of 250 units stands
// for the real 170 mm. The status chips fill whatever height is left below.
constexpr qreal kSceneWidthLightBumps = 1000;
constexpr qreal kSceneWidthPlain = 900;
constexpr qreal kSceneTopLightBumps = -470; // room for the light-bump bars
constexpr qreal kSceneTopPlain = -320;
constexpr qreal kBodyRadius = 250;
constexpr qreal kBumperInner = 252;
constexpr qreal kBumperOuter = 282;
constexpr qreal kBumperOuterBumped = 298;
constexpr qreal kBumperGapDegrees = 1.5;
constexpr qreal kBumperRightStart = -12; // degrees, 0 = robot's right, 90 = front
constexpr qreal kBumperLeftEnd = 192;
constexpr qreal kLightBumpBase = 306;
constexpr qreal kLightBumpLength = 122;
constexpr qreal kLightBumpLabelRadius = 452;
constexpr qreal kLightBumpHalfWidthDegrees = 7;
constexpr qreal kCliffLampRadius = 26;
constexpr QSizeF kCliffLabelSize(98, 58);
constexpr qreal kChipTop = 272;
constexpr qreal kChipMinHeight = 80;
constexpr qreal kChipMaxHeight = 118;
constexpr qreal kChipGap = 10;
constexpr qreal kChipRows = 3;
constexpr qreal kChipBottomMargin = 8;
constexpr qreal kSceneBottom = kChipTop + kChipRows * (kChipMinHeight + kChipGap);
constexpr qreal kSignalMax = 4095;

// Left to right across the front, as bits 0..5 of packet 45 run.
constexpr std::array<qreal, 6> kLightBumperAngles = {168, 136, 104, 76, 44, 12};

QPointF polar(qreal radius, qreal degrees)
{
    const qreal a = degrees * std::numbers::pi / 180.0;
    return {radius * std::cos(a), -radius * std::sin(a)};
}

QRectF circleRect(qreal radius) { return {-radius, -radius, 2 * radius, 2 * radius}; }

// A ring segment between two radii, from `startDegrees` counter-clockwise
// through `sweepDegrees`.
QPainterPath ringSegment(qreal inner, qreal outer, qreal startDegrees, qreal sweepDegrees)
{
    QPainterPath path;
    path.arcMoveTo(circleRect(outer), startDegrees);
    path.arcTo(circleRect(outer), startDegrees, sweepDegrees);
    path.arcTo(circleRect(inner), startDegrees + sweepDegrees, -sweepDegrees);
    path.closeSubpath();
    return path;
}

QPointF cliffLampPoint(oi::CliffSensor sensor)
{
    switch (sensor) {
    case oi::CliffSensor::Left: return {-195, -80};
    case oi::CliffSensor::FrontLeft: return {-80, -205};
    case oi::CliffSensor::FrontRight: return {80, -205};
    case oi::CliffSensor::Right: return {195, -80};
    }
    return {};
}

// The number and bar sit beside the lamp, towards the middle of the robot.
QRectF cliffLabelRect(oi::CliffSensor sensor)
{
    QPointF centre;
    switch (sensor) {
    case oi::CliffSensor::Left: centre = {-115, -80}; break;
    case oi::CliffSensor::FrontLeft: centre = {-80, -145}; break;
    case oi::CliffSensor::FrontRight: centre = {80, -145}; break;
    case oi::CliffSensor::Right: centre = {115, -80}; break;
    }
    return {centre - QPointF(kCliffLabelSize.width() / 2, kCliffLabelSize.height() / 2),
            kCliffLabelSize};
}

constexpr std::array<oi::CliffSensor, 4> kCliffs = {
    oi::CliffSensor::Left, oi::CliffSensor::FrontLeft, oi::CliffSensor::FrontRight,
    oi::CliffSensor::Right};

constexpr QRectF kWheelLeft(-195, -30, 44, 110);
constexpr QRectF kWheelRight(151, -30, 44, 110);
constexpr QPointF kCaster(0, -18); // Create 1, drawn between the cliff labels
constexpr qreal kCasterRadius = 24;
constexpr QPointF kOmniReceiver(0, -228);
constexpr QRectF kWall(316, -10, 18, 160);
constexpr QRectF kCargoBay(-125, 62, 250, 146);

bool isDark(const QPalette &palette) { return palette.color(QPalette::Window).lightness() < 128; }

// The colour of signal strengths, matching the bars in SignalBars.
QColor cliffSignalColour(const QPalette &palette)
{
    return isDark(palette) ? QColor(70, 200, 200) : QColor(0, 130, 140);
}
QColor lightBumpSignalColour(const QPalette &palette)
{
    return isDark(palette) ? QColor(110, 160, 245) : QColor(40, 100, 200);
}

QString signalText(const oi::SensorSnapshot &s, int packetId)
{
    return s.has(packetId) ? QString::number(s.raw(packetId)) : QStringLiteral("\u2014");
}

} // namespace

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
    if (isCreate1() && s.wheelDropCaster())
        parts << tr("Caster wheel drop");
    const QString cliffNames[] = {tr("Cliff left"), tr("Cliff front left"), tr("Cliff front right"),
                                  tr("Cliff right")};
    for (oi::CliffSensor sensor : kCliffs)
        if (s.cliff(sensor))
            parts << cliffNames[static_cast<int>(sensor)];
    if (s.wall())
        parts << tr("Wall");
    if (!isCreate1() && s.has(45))
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
    return isCreate1() ? kSceneTopPlain : kSceneTopLightBumps;
}

qreal RobotDiagram::sceneScale() const
{
    const qreal sceneWidth = isCreate1() ? kSceneWidthPlain : kSceneWidthLightBumps;
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

    if (isCreate1())
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
        return isCreate1() ? std::optional(kCaster) : std::nullopt;
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
            return isCreate1() ? std::nullopt : std::optional(polar(bumperMid, kLightBumperAngles[std::size_t(i)]));
    return std::nullopt;
}

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

    if (isCreate1()) {
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

    if (isCreate1())
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
    if (isCreate1())
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

    if (isCreate1()) {
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

#include "moc_robot_diagram.cpp"
