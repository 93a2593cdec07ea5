// SPDX-License-Identifier: GPL-3.0-or-later
#include "odometry_map.h"

#include "display_palette.h"
#include "display_tick.h"
#include "on_screen.h"
#include "room_edit_tool.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QLabel>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRobotDiameterMm = 340;
constexpr double kZoomStep = 1.25;
// How near the pointer must come to a wall or a handle, in pixels: big
// enough for a finger-sized touchpad tap.
constexpr double kGripPx = 9;

} // namespace

OdometryMap::OdometryMap(QWidget *parent) : QWidget(parent)
{
    setMinimumSize(360, 280);
    setMouseTracking(false);
    setFocusPolicy(Qt::ClickFocus); // Delete and Esc reach the selection

    m_controls = new QWidget(this);
    m_controls->setObjectName("controls");
    m_controls->setAutoFillBackground(true);
    // Two rows: the view's buttons, then the wheels; one row of both
    // would not fit a column beside the diagram on a laptop screen.
    auto *rows = new QVBoxLayout(m_controls);
    rows->setContentsMargins(4, 4, 4, 4);
    auto *controls = new QHBoxLayout;
    auto *wheels = new QHBoxLayout;
    rows->addLayout(controls);
    rows->addLayout(wheels);

    const auto addButton = [this, controls](const char *name, const QString &text) {
        auto *b = new QPushButton(text, m_controls);
        b->setObjectName(name);
        controls->addWidget(b);
        return b;
    };
    // Symbols, not words: their names and tool tips come from retranslateUi().
    m_zoomIn = addButton("zoomIn", QStringLiteral("+"));
    m_zoomOut = addButton("zoomOut", QStringLiteral("−"));
    // Square symbol buttons leave the bar's width to the translated words.
    for (QPushButton *b : {m_zoomIn, m_zoomOut})
        b->setFixedWidth(b->sizeHint().height() * 3 / 2);
    m_centre = addButton("centre", QString());
    m_reset = addButton("reset", QString());
    m_edit = addButton("editRoom", QString());
    m_edit->setCheckable(true);
    m_edit->setVisible(false); // until there is a room to edit
    m_editTool = new RoomEditTool(this);
    connect(m_edit, &QPushButton::toggled, m_editTool, &RoomEditTool::setEditing);
    connect(m_editTool, &RoomEditTool::editRequested, this, &OdometryMap::worldEditRequested);
    connect(m_editTool, &RoomEditTool::changed, this, qOverload<>(&QWidget::update));
    connect(m_editTool, &RoomEditTool::editingChanged, this, [this](bool editing) {
        setMouseTracking(editing); // the cursor shows what can be taken
        const QSignalBlocker blocker(m_edit);
        m_edit->setChecked(editing);
        emit editingChanged(editing);
    });
    connect(m_zoomIn, &QPushButton::clicked, this, &OdometryMap::zoomIn);
    connect(m_zoomOut, &QPushButton::clicked, this, &OdometryMap::zoomOut);
    connect(m_centre, &QPushButton::clicked, this, &OdometryMap::centreOnRobot);
    connect(m_reset, &QPushButton::clicked, this, &OdometryMap::reset);

    m_wheelBase = new QDoubleSpinBox(m_controls);
    m_wheelBase->setObjectName("wheelBase");
    m_wheelBase->setRange(100, 600);
    m_wheelBase->setDecimals(1);
    m_wheelBase->setSuffix(" mm");
    m_wheelBase->setValue(oi::kWheelBaseMm);
    m_wheelDiameter = new QDoubleSpinBox(m_controls);
    m_wheelDiameter->setObjectName("wheelDiameter");
    m_wheelDiameter->setRange(20, 200);
    m_wheelDiameter->setDecimals(2);
    m_wheelDiameter->setSuffix(" mm");
    m_wheelDiameter->setValue(kDefaultWheelDiameterMm);
    m_wheelBaseTitle = new QLabel(m_controls);
    m_wheelBaseTitle->setBuddy(m_wheelBase);
    m_wheelDiameterTitle = new QLabel(m_controls);
    m_wheelDiameterTitle->setBuddy(m_wheelDiameter);
    controls->addStretch();
    wheels->addWidget(m_wheelBaseTitle);
    wheels->addWidget(m_wheelBase);
    wheels->addSpacing(8);
    wheels->addWidget(m_wheelDiameterTitle);
    wheels->addWidget(m_wheelDiameter);
    wheels->addStretch();
    connect(m_wheelBase, &QDoubleSpinBox::valueChanged, this, &OdometryMap::applyGeometry);
    connect(m_wheelDiameter, &QDoubleSpinBox::valueChanged, this, &OdometryMap::applyGeometry);

    m_poseLabel = new QLabel(this);
    m_poseLabel->setObjectName("poseLabel");
    m_poseLabel->setFont(display::valueFont(font(), 1.2));
    m_poseLabel->setAutoFillBackground(true);
    m_poseLabel->setContentsMargins(6, 2, 6, 2);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_controls);
    layout->addStretch();
    layout->addWidget(m_poseLabel, 0, Qt::AlignLeft);

    retranslateUi();
}

// The map follows the display's tick only while it is on screen: a map in a
// hidden or tabbed-away dock costs nothing, and catches up when shown (its
// dock's tab coming up sends a show event) or painted.
void OdometryMap::followDisplay()
{
    DisplayTick::instance().listen(this, [this] {
        if (!isOnScreen(this)) {
            DisplayTick::instance().stopListening(this); // tabbed away
            return;
        }
        if (m_dirty || (m_odometry && m_odometry->revision() != m_shownRevision))
            refresh();
    });
}

void OdometryMap::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    followDisplay();
    refresh();
}

void OdometryMap::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    DisplayTick::instance().stopListening(this);
}

void OdometryMap::retranslateUi()
{
    m_zoomIn->setToolTip(tr("Zoom in"));
    m_zoomIn->setAccessibleName(tr("Zoom in"));
    m_zoomOut->setToolTip(tr("Zoom out"));
    m_zoomOut->setAccessibleName(tr("Zoom out"));
    m_centre->setText(tr("Centre"));
    m_centre->setToolTip(tr("Centre the map on the robot"));
    m_reset->setText(tr("Reset"));
    m_reset->setToolTip(tr("Clear the trail and start the odometry again at the origin"));
    m_edit->setText(tr("Edit room"));
    m_edit->setToolTip(tr("Move, add and delete the walls, stage edges, the dock and the virtual wall"));
    m_wheelBaseTitle->setText(tr("Wheel base"));
    m_wheelDiameterTitle->setText(tr("Wheel Ø"));
    updateGeometryTips();
    setAccessibleName(tr("Odometry map"));
    refresh(); // the pose text, its description and the painted labels
}

void OdometryMap::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void OdometryMap::updateGeometryTips()
{
    // The Create 1 has no encoders: it reports distance and angle itself.
    if (m_profile->id == oi::ProfileId::Create1) {
        const QString tip = tr("The %1 has no wheel encoders; it reports distance and angle itself")
                                .arg(QString::fromUtf8(m_profile->name.data(), qsizetype(m_profile->name.size())));
        m_wheelBase->setToolTip(tip);
        m_wheelDiameter->setToolTip(tip);
    } else {
        m_wheelBase->setToolTip(tr("Distance between the wheels' contact points"));
        m_wheelDiameter->setToolTip(tr("Wheel diameter; 508.8 encoder counts are one turn"));
    }
}

void OdometryMap::setProfile(const oi::RobotProfile &profile)
{
    if (m_profile == &profile)
        return;
    m_profile = &profile;
    const bool encoders = profile.id != oi::ProfileId::Create1;
    for (QDoubleSpinBox *box : {m_wheelBase, m_wheelDiameter})
        box->setEnabled(encoders);
    updateGeometryTips();
    refresh();
}

void OdometryMap::setOdometry(RobotOdometry *odometry)
{
    m_odometry = odometry;
    if (odometry) {
        const QSignalBlocker base(m_wheelBase);
        const QSignalBlocker diameter(m_wheelDiameter);
        m_wheelBase->setValue(odometry->wheelBaseMm());
        m_wheelDiameter->setValue(odometry->wheelDiameterMm());
    }
    refresh();
}

void OdometryMap::reset()
{
    if (m_odometry)
        m_odometry->reset();
    refresh();
}

void OdometryMap::setTruePoses(const QList<TruePose> &poses)
{
    const auto same = [](const TruePose &a, const TruePose &b) {
        return a.robot == b.robot && a.pose.xMm == b.pose.xMm && a.pose.yMm == b.pose.yMm
               && a.pose.thetaRad == b.pose.thetaRad && a.colour == b.colour && a.lifted == b.lifted;
    };
    // A robot at rest costs no repaint.
    if (std::equal(poses.begin(), poses.end(), m_truePoses.begin(), m_truePoses.end(), same))
        return;
    m_truePoses = poses;
    m_dirty = true;
}

void OdometryMap::setSelectedRobot(std::optional<int> robot)
{
    if (robot == m_selected)
        return; // set on every display tick: the same one costs no repaint
    m_selected = robot;
    m_dirty = true;
}

std::optional<oi::Pose> OdometryMap::selectedTruePose() const
{
    for (const TruePose &t : m_truePoses)
        if (m_selected == t.robot)
            return t.pose;
    return std::nullopt;
}

QColor OdometryMap::robotColour(int index)
{
    // Apart from one another and from the trail's highlight blue, on light
    // and dark bases alike.
    static const QColor colours[] = {QColor(0x2e, 0x9e, 0x44), QColor(0xd9, 0x6c, 0x06), QColor(0x9c, 0x3f, 0xc4),
                                     QColor(0x00, 0x97, 0xa7), QColor(0xd8, 0x1b, 0x60), QColor(0x8d, 0x6e, 0x63)};
    const int n = int(std::size(colours));
    return colours[((index % n) + n) % n];
}

void OdometryMap::setOdometryColour(const QColor &colour)
{
    if (colour == m_odometryColour)
        return;
    m_odometryColour = colour;
    update();
}

QColor OdometryMap::odometryColour() const
{
    return m_odometryColour.isValid() ? m_odometryColour : palette().color(QPalette::Highlight);
}

QColor OdometryMap::truePoseColour(qsizetype index) const
{
    const QColor &chosen = m_truePoses[index].colour;
    return chosen.isValid() ? chosen : robotColour(int(index));
}

void OdometryMap::setWorld(std::optional<sim::World> world)
{
    m_world = std::move(world);
    m_edit->setVisible(m_world.has_value());
    m_editTool->setWorld(m_world ? &*m_world : nullptr);
    update();
}

void OdometryMap::setEditing(bool editing) { m_editTool->setEditing(editing); }
bool OdometryMap::isEditing() const { return m_editTool->isEditing(); }
std::optional<sim::WorldItem> OdometryMap::selectedItem() const { return m_editTool->selectedItem(); }
void OdometryMap::setSelectedItem(std::optional<sim::WorldItem> item) { m_editTool->setSelectedItem(item); }

double OdometryMap::gripToleranceMm() const { return kGripPx / m_scale; }

void OdometryMap::setWheelBaseMm(double mm) { m_wheelBase->setValue(mm); }
void OdometryMap::setWheelDiameterMm(double mm) { m_wheelDiameter->setValue(mm); }
double OdometryMap::wheelBaseMm() const { return m_wheelBase->value(); }
double OdometryMap::wheelDiameterMm() const { return m_wheelDiameter->value(); }

void OdometryMap::applyGeometry()
{
    // The spin boxes' ranges keep both positive, so this cannot be refused.
    if (m_odometry)
        m_odometry->setGeometry(m_wheelBase->value(), m_wheelDiameter->value());
}

void OdometryMap::setScale(double pixelsPerMm)
{
    m_scale = std::clamp(pixelsPerMm, kMinScale, kMaxScale);
    update();
}

void OdometryMap::setViewCentreMm(QPointF mm)
{
    m_centreMm = mm;
    update();
}

void OdometryMap::zoomIn() { zoomBy(kZoomStep, QRectF(mapRect()).center()); }
void OdometryMap::zoomOut() { zoomBy(1 / kZoomStep, QRectF(mapRect()).center()); }

void OdometryMap::zoomBy(double factor, QPointF anchorWidget)
{
    // Keep the floor point under the anchor where it is.
    const QPointF c = QRectF(mapRect()).center();
    const QPointF anchorMm = floorPointFor(anchorWidget);
    m_scale = std::clamp(m_scale * factor, kMinScale, kMaxScale);
    m_centreMm = QPointF(anchorMm.x() - (anchorWidget.x() - c.x()) / m_scale,
                         anchorMm.y() + (anchorWidget.y() - c.y()) / m_scale);
    update();
}

void OdometryMap::centreOnRobot() { setViewCentreMm(QPointF(pose().xMm, pose().yMm)); }

QRect OdometryMap::mapRect() const
{
    const int top = m_controls->isVisible() ? m_controls->geometry().bottom() + 1 : 0;
    return QRect(0, top, width(), height() - top);
}

QPointF OdometryMap::widgetPointFor(QPointF mm) const
{
    // +x (forward at the start) to the right, +y (left) up.
    const QPointF c = QRectF(mapRect()).center();
    return QPointF(c.x() + (mm.x() - m_centreMm.x()) * m_scale, c.y() - (mm.y() - m_centreMm.y()) * m_scale);
}

QPolygonF OdometryMap::widgetPolygon(const QList<QPointF> &pointsMm) const
{
    QPolygonF line;
    line.reserve(pointsMm.size());
    for (const QPointF &p : pointsMm)
        line << widgetPointFor(p);
    return line;
}

QString OdometryMap::notIdentifiedText() const
{
    return tr("Robot not yet identified: a Roomba 500 or a Create 2? Until it is named, its wheel counts "
              "may read mirrored, so no path is drawn.");
}

QString OdometryMap::poseText() const
{
    if (m_odometry && !m_odometry->isIdentified())
        return notIdentifiedText();
    const oi::Pose &p = pose();
    QString text = tr("x %1 mm   y %2 mm   θ %3°")
                       .arg(p.xMm, 0, 'f', 0)
                       .arg(p.yMm, 0, 'f', 0)
                       .arg(p.thetaRad * 180 / kPi, 0, 'f', 1);
    if (const auto truth = selectedTruePose())
        text += tr("   drift %1 mm").arg(std::hypot(p.xMm - truth->xMm, p.yMm - truth->yMm), 0, 'f', 0);
    return text;
}

QString OdometryMap::spokenPose() const
{
    if (m_odometry && !m_odometry->isIdentified())
        return notIdentifiedText();
    const oi::Pose &p = pose();
    QString text = tr("Robot at x %1 mm, y %2 mm, heading %3 degrees")
                       .arg(p.xMm, 0, 'f', 0)
                       .arg(p.yMm, 0, 'f', 0)
                       .arg(p.thetaRad * 180 / kPi, 0, 'f', 0);
    if (const auto truth = selectedTruePose())
        text += tr("; %1 mm from the true pose").arg(std::hypot(p.xMm - truth->xMm, p.yMm - truth->yMm), 0, 'f', 0);
    return text;
}

void OdometryMap::refresh()
{
    m_dirty = false;
    m_shownRevision = m_odometry ? m_odometry->revision() : ~0ull;
    m_poseLabel->setText(poseText());
    // Only a change is announced, so set it only when it differs.
    const QString spoken = spokenPose();
    if (accessibleDescription() != spoken)
        setAccessibleDescription(spoken);
    update();
}

double OdometryMap::gridSpacingMm() const
{
    // 1, 2 or 5 times a power of ten, at least 40 pixels apart.
    const double minimum = 40 / m_scale;
    double power = std::pow(10.0, std::floor(std::log10(minimum)));
    for (double step : {1.0, 2.0, 5.0, 10.0})
        if (step * power >= minimum)
            return step * power;
    return 10 * power;
}

void OdometryMap::paintEvent(QPaintEvent *)
{
    if (!DisplayTick::instance().isListening(this))
        followDisplay(); // on screen again, by whatever way
    QPainter painter(this);
    const QRect area = mapRect();
    painter.fillRect(area, palette().base());
    painter.setClipRect(area);
    painter.setRenderHint(QPainter::Antialiasing);

    paintGrid(painter, area);
    if (m_world)
        paintWorld(painter);
    m_editTool->paintSelection(painter, *this);

    const bool identified = !m_odometry || m_odometry->isIdentified();
    const QList<QPointF> trail = this->trail();
    if (identified && trail.size() > 1) {
        painter.setPen(QPen(odometryColour(), 2));
        painter.drawPolyline(widgetPolygon(trail));
    }
    if (m_comparisonPath.size() > 1) {
        painter.setPen(comparisonPen());
        painter.drawPolyline(widgetPolygon(m_comparisonPath));
    }
    paintTruePoses(painter);
    if (identified)
        paintRobot(painter, pose(), odometryColour(), false);
    paintScaleBar(painter, area);

    painter.setClipping(false);
    paintLegend(painter);
    if (m_editTool->isEditing())
        paintEditBanner(painter, area);
}

void OdometryMap::setComparisonPath(const QVector<QPointF> &pointsMm, const QString &label)
{
    m_comparisonPath = pointsMm;
    m_comparisonLabel = pointsMm.isEmpty() ? QString() : label;
    update();
}

QPen OdometryMap::comparisonPen() const
{
    // Neither a robot's colour nor a solid or dashed line: another run.
    QColor colour = palette().color(QPalette::Text);
    colour.setAlpha(170);
    QPen pen(colour, 2.5, Qt::DashDotLine);
    pen.setCapStyle(Qt::FlatCap);
    return pen;
}

QList<OdometryMap::LegendEntry> OdometryMap::legend() const
{
    // Everything the map draws, drawn as the map draws it.
    QList<LegendEntry> entries;
    entries << LegendEntry{tr("odometry"), QPen(odometryColour(), 2)};
    if (!m_truePoses.isEmpty()) {
        // The selected robot's, or the first robot's: in the dashboard the
        // odometry's own colour, dashed.
        qsizetype index = 0;
        for (qsizetype i = 0; i < m_truePoses.size(); ++i)
            if (m_truePoses[i].robot == m_selected)
                index = i;
        entries << LegendEntry{tr("true pose"), QPen(truePoseColour(index), 2, Qt::DashLine)};
    }
    if (m_comparisonPath.size() > 1)
        entries << LegendEntry{m_comparisonLabel.isEmpty() ? tr("comparison run") : m_comparisonLabel,
                               comparisonPen()};
    if (m_world) {
        if (!m_world->walls.empty())
            entries << LegendEntry{tr("wall"), wallPen()};
        if (!m_world->dropOffs.empty()) {
            const QColor drop = display::stateColor(display::State::Alert, palette());
            entries << LegendEntry{tr("stage edge"), QPen(drop, 2), QBrush(drop, Qt::BDiagPattern)};
        }
        if (m_world->virtualWall)
            entries << LegendEntry{tr("virtual wall"), virtualWallPen()};
        if (m_world->dock) {
            const QColor dock = display::stateColor(display::State::Warning, palette());
            entries << LegendEntry{tr("dock"), QPen(dock.darker(130), 1.5), QBrush(dock)};
        }
    }
    return entries;
}

QPen OdometryMap::wallPen() const
{
    return QPen(palette().color(QPalette::Text), 4, Qt::SolidLine, Qt::SquareCap);
}

QPen OdometryMap::virtualWallPen() const
{
    return QPen(display::stateColor(display::State::Stale, palette()), 3, Qt::DashLine);
}

QStringList OdometryMap::legendLabels() const
{
    QStringList labels;
    for (const LegendEntry &entry : legend())
        labels << entry.text;
    return labels;
}

QList<QRect> OdometryMap::robotRects() const
{
    const double radius = std::max(8.0, kRobotDiameterMm / 2 * m_scale) + 3; // its pen, and a heading line
    const auto around = [&](const oi::Pose &p) {
        const QPointF c = widgetPointFor({p.xMm, p.yMm});
        return QRectF(c.x() - radius, c.y() - radius, 2 * radius, 2 * radius).toAlignedRect();
    };
    QList<QRect> rects;
    if (!m_odometry || m_odometry->isIdentified())
        rects << around(pose());
    for (const TruePose &t : m_truePoses)
        rects << around(t.pose);
    return rects;
}

QRect OdometryMap::legendRect() const
{
    const QList<LegendEntry> entries = legend();
    const QFontMetrics fm(font());
    // Sizes follow the font, so the legend grows with it.
    const int gap = fm.averageCharWidth();
    const int swatch = fm.ascent() * 3 / 2;
    int textWidth = 0;
    for (const LegendEntry &entry : entries)
        textWidth = std::max(textWidth, fm.horizontalAdvance(entry.text));
    const QSize size(3 * gap + swatch + textWidth, int(entries.size()) * (fm.height() + 4) + 4);
    const QRect area = mapRect();
    // Clear of the grid's labels along the top and the pose and scale bar along the bottom.
    const QRect room = area.adjusted(gap, 2 * fm.height(), -gap, -3 * fm.height());
    const QList<QRect> robots = robotRects();
    const QList<QRect> corners = {QRect(QPoint(room.right() - size.width(), room.top()), size),
                                  QRect(room.topLeft() + QPoint(3 * fm.height(), 0), size),
                                  QRect(QPoint(room.right() - size.width(), room.bottom() - size.height()), size),
                                  QRect(QPoint(room.left() + 3 * fm.height(), room.bottom() - size.height()), size)};
    for (const QRect &corner : corners)
        if (std::none_of(robots.begin(), robots.end(), [&](const QRect &r) { return r.intersects(corner); }))
            return corner;
    return corners.first(); // a robot in every corner: a small map, and they move
}

void OdometryMap::paintLegend(QPainter &painter) const
{
    const QList<LegendEntry> entries = legend();
    const QFontMetrics fm(font());
    const int gap = fm.averageCharWidth();
    const int swatch = fm.ascent() * 3 / 2;
    const QRect box = legendRect();
    QColor back = palette().color(QPalette::Base);
    back.setAlpha(220);
    painter.fillRect(box, back);
    int y = box.top() + 2;
    for (const LegendEntry &entry : entries) {
        const QRect sample(box.left() + gap, y + 2, swatch, fm.height() - 4);
        const QRect text(sample.right() + gap, y, box.right() - sample.right() - gap, fm.height());
        if (entry.fill.style() != Qt::NoBrush) {
            painter.setPen(entry.pen);
            painter.setBrush(entry.fill);
            painter.drawRect(sample);
            painter.setBrush(Qt::NoBrush);
        } else {
            painter.setPen(entry.pen);
            painter.drawLine(QPointF(sample.left(), sample.center().y() + 0.5),
                             QPointF(sample.right(), sample.center().y() + 0.5));
        }
        painter.setPen(palette().color(QPalette::Text));
        painter.drawText(text, Qt::AlignLeft | Qt::AlignVCenter, entry.text);
        y += fm.height() + 4;
    }
}

void OdometryMap::paintGrid(QPainter &painter, const QRect &area) const
{
    const double spacing = gridSpacingMm();
    const QPointF c = QRectF(area).center();
    const double xMin = m_centreMm.x() - (c.x() - area.left()) / m_scale;
    const double xMax = m_centreMm.x() + (area.right() - c.x()) / m_scale;
    const double yMin = m_centreMm.y() - (area.bottom() - c.y()) / m_scale;
    const double yMax = m_centreMm.y() + (c.y() - area.top()) / m_scale;

    QColor minor = palette().color(QPalette::Text);
    minor.setAlpha(35);
    QColor axis = palette().color(QPalette::Text);
    axis.setAlpha(110);
    const QFontMetrics fm(font());
    for (double x = std::ceil(xMin / spacing) * spacing; x <= xMax; x += spacing) {
        const double px = widgetPointFor({x, 0}).x();
        painter.setPen(QPen(std::abs(x) < spacing / 2 ? axis : minor, 1));
        painter.drawLine(QPointF(px, area.top()), QPointF(px, area.bottom()));
        painter.setPen(axis);
        // Along the top: the pose text and the scale bar sit at the bottom.
        painter.drawText(QPointF(px + 3, area.top() + fm.ascent() + 2), QString::number(x, 'f', 0));
    }
    for (double y = std::ceil(yMin / spacing) * spacing; y <= yMax; y += spacing) {
        const double py = widgetPointFor({0, y}).y();
        painter.setPen(QPen(std::abs(y) < spacing / 2 ? axis : minor, 1));
        painter.drawLine(QPointF(area.left(), py), QPointF(area.right(), py));
        painter.setPen(axis);
        painter.drawText(QPointF(area.left() + 3, py - 3), QString::number(y, 'f', 0));
    }
}

void OdometryMap::paintWorld(QPainter &painter) const
{
    const sim::World &world = *m_world;
    const QColor drop = display::stateColor(display::State::Alert, palette());
    QColor dropFill = drop;
    dropFill.setAlpha(70);
    for (const sim::Area &a : world.dropOffs) {
        const QRectF r = QRectF(widgetPointFor({a.xMin, a.yMax}), widgetPointFor({a.xMax, a.yMin})).normalized();
        painter.fillRect(r, QBrush(dropFill));
        painter.fillRect(r, QBrush(drop, Qt::BDiagPattern));
        painter.setPen(QPen(drop, 2));
        painter.drawRect(r);
    }
    painter.setPen(wallPen());
    for (const sim::Segment &s : world.walls)
        painter.drawLine(widgetPointFor({s.x1, s.y1}), widgetPointFor({s.x2, s.y2}));
    if (m_editTool->isEditing()) {
        // Every wall's ends can be taken: show where.
        painter.setPen(Qt::NoPen);
        painter.setBrush(palette().color(QPalette::Text));
        for (const sim::Segment &s : world.walls)
            for (const QPointF end : {QPointF(s.x1, s.y1), QPointF(s.x2, s.y2)})
                painter.drawEllipse(widgetPointFor(end), 5, 5);
        painter.setBrush(Qt::NoBrush);
    }

    if (world.virtualWall) {
        const auto &v = *world.virtualWall;
        const QPointF from = widgetPointFor({v.x, v.y});
        const QPointF to = widgetPointFor({v.x + v.rangeMm * std::cos(v.headingRad),
                                           v.y + v.rangeMm * std::sin(v.headingRad)});
        painter.setPen(virtualWallPen());
        painter.drawLine(from, to);
        painter.setBrush(virtualWallPen().color());
        painter.setPen(Qt::NoPen);
        painter.drawEllipse(from, 6, 6);
        painter.setBrush(Qt::NoBrush);
    }
    if (world.dock) {
        const auto &d = *world.dock;
        const QColor dock = display::stateColor(display::State::Warning, palette());
        // A base 300 mm wide behind the contacts, facing out along its heading.
        const double half = 150, depth = 120;
        const double c = std::cos(d.headingRad), s = std::sin(d.headingRad);
        const auto at = [&](double back, double side) {
            return widgetPointFor({d.x - back * c - side * s, d.y - back * s + side * c});
        };
        QPolygonF base{at(0, -half), at(0, half), at(depth, half), at(depth, -half)};
        painter.setPen(QPen(dock.darker(130), 1.5));
        painter.setBrush(dock);
        painter.drawPolygon(base);
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(dock, 2));
        painter.drawLine(at(0, 0), at(-200, 0));
        painter.setPen(palette().color(QPalette::Text));
        painter.drawText(at(depth, half) + QPointF(4, 0), tr("dock"));
    }
}

void OdometryMap::paintTruePoses(QPainter &painter) const
{
    const QFontMetrics fm(font());
    for (qsizetype i = 0; i < m_truePoses.size(); ++i) {
        const TruePose &t = m_truePoses[i];
        const QColor colour = truePoseColour(i);
        const QPointF centre = widgetPointFor({t.pose.xMm, t.pose.yMm});
        const double radius = std::max(8.0, kRobotDiameterMm / 2 * m_scale);
        if (t.lifted) {
            // Held up: its shadow on the floor below and to the right.
            QColor shadow = palette().color(QPalette::Text);
            shadow.setAlpha(60);
            painter.setPen(Qt::NoPen);
            painter.setBrush(shadow);
            painter.drawEllipse(centre + QPointF(radius / 4, radius / 4), radius, radius);
            painter.setBrush(Qt::NoBrush);
        }
        const bool selected = m_selected == t.robot;
        if (selected) {
            painter.setPen(QPen(colour, 1, Qt::DashLine));
            painter.drawLine(centre, widgetPointFor({pose().xMm, pose().yMm}));
            // A halo marks the robot this map's odometry belongs to.
            QColor halo = colour;
            halo.setAlpha(90);
            painter.setPen(QPen(halo, 6));
            painter.drawEllipse(centre, radius + 4, radius + 4);
        }
        paintRobot(painter, t.pose, colour, true);
        if (m_truePoses.size() > 1) {
            const QString number = QString::number(t.robot);
            painter.setPen(palette().color(QPalette::Text));
            painter.drawText(centre + QPointF(radius + 4, -radius), number);
        }
    }
}

void OdometryMap::paintRobot(QPainter &painter, const oi::Pose &pose, const QColor &colour, bool outline) const
{
    const QPointF centre = widgetPointFor({pose.xMm, pose.yMm});
    const double radius = std::max(8.0, kRobotDiameterMm / 2 * m_scale);
    QColor fill = colour;
    fill.setAlpha(outline ? 0 : 70);
    painter.setBrush(fill);
    painter.setPen(QPen(colour, 2, outline ? Qt::DashLine : Qt::SolidLine));
    painter.drawEllipse(centre, radius, radius);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(colour, 2.5));
    painter.drawLine(centre, centre + QPointF(radius * std::cos(pose.thetaRad), -radius * std::sin(pose.thetaRad)));
}

void OdometryMap::paintScaleBar(QPainter &painter, const QRect &area) const
{
    const double spacing = gridSpacingMm();
    const double px = spacing * m_scale;
    const QPointF right(area.right() - 12, area.bottom() - 12);
    const QPointF left = right - QPointF(px, 0);
    painter.setPen(QPen(palette().color(QPalette::Text), 2));
    painter.drawLine(left, right);
    painter.drawLine(left, left - QPointF(0, 5));
    painter.drawLine(right, right - QPointF(0, 5));
    const QString text = spacing >= 1000 ? tr("%1 m").arg(spacing / 1000) : tr("%1 mm").arg(spacing);
    // Centred over the bar, one line high above its ticks.
    const QFontMetricsF fm(font());
    const double w = std::max(px, fm.horizontalAdvance(text));
    painter.drawText(QRectF(right.x() - w, left.y() - 6 - fm.height(), w, fm.height()), Qt::AlignCenter, text);
}

void OdometryMap::wheelEvent(QWheelEvent *event)
{
    const int steps = event->angleDelta().y();
    if (steps == 0)
        return;
    zoomBy(std::pow(kZoomStep, steps / 120.0), event->position());
    event->accept();
}

QPointF OdometryMap::floorPointFor(QPointF widgetPoint) const
{
    const QPointF c = QRectF(mapRect()).center();
    return QPointF(m_centreMm.x() + (widgetPoint.x() - c.x()) / m_scale,
                   m_centreMm.y() - (widgetPoint.y() - c.y()) / m_scale);
}

const OdometryMap::TruePose *OdometryMap::truePoseAt(QPointF widgetPoint) const
{
    const double radius = std::max(8.0, kRobotDiameterMm / 2 * m_scale);
    // The last drawn is on top.
    for (qsizetype i = m_truePoses.size() - 1; i >= 0; --i) {
        const QPointF d = widgetPointFor({m_truePoses[i].pose.xMm, m_truePoses[i].pose.yMm}) - widgetPoint;
        if (std::hypot(d.x(), d.y()) <= radius)
            return &m_truePoses[i];
    }
    return nullptr;
}

void OdometryMap::mousePressEvent(QMouseEvent *event)
{
    if (!mapRect().contains(event->position().toPoint()))
        return;
    if (event->button() == Qt::LeftButton
        && m_editTool->press(floorPointFor(event->position()), gripToleranceMm(),
                             (event->modifiers() & Qt::ShiftModifier) != 0, truePoseAt(event->position()))) {
        setCursor(m_editTool->hoverCursor(floorPointFor(event->position()), gripToleranceMm()));
        return;
    }
    const bool turn = event->button() == Qt::RightButton
                      || (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
    if (event->button() == Qt::LeftButton || turn) {
        if (const TruePose *t = truePoseAt(event->position())) {
            m_hold = Hold{t->robot, t->pose, floorPointFor(event->position()) - QPointF(t->pose.xMm, t->pose.yMm), turn};
            setCursor(turn ? Qt::SizeAllCursor : Qt::ClosedHandCursor);
            return;
        }
    }
    if (event->button() == Qt::LeftButton) {
        m_dragFrom = event->position();
        setCursor(Qt::ClosedHandCursor);
    }
}

void OdometryMap::mouseMoveEvent(QMouseEvent *event)
{
    if (m_editTool->drag(floorPointFor(event->position())))
        return;
    if (m_editTool->isEditing() && !m_hold && !m_dragFrom) {
        const Qt::CursorShape shape = m_editTool->hoverCursor(floorPointFor(event->position()), gripToleranceMm());
        if (shape == Qt::ArrowCursor)
            unsetCursor();
        else
            setCursor(shape);
        return;
    }
    if (m_hold) {
        const QPointF at = floorPointFor(event->position());
        if (m_hold->turning) {
            // It faces the pointer.
            m_hold->pose.thetaRad = std::atan2(at.y() - m_hold->pose.yMm, at.x() - m_hold->pose.xMm);
        } else {
            m_hold->pose.xMm = at.x() - m_hold->grabOffsetMm.x();
            m_hold->pose.yMm = at.y() - m_hold->grabOffsetMm.y();
        }
        emit robotMoveRequested(m_hold->robot, m_hold->pose);
        return;
    }
    if (!m_dragFrom)
        return;
    const QPointF delta = event->position() - *m_dragFrom;
    m_dragFrom = event->position();
    setViewCentreMm(m_centreMm + QPointF(-delta.x() / m_scale, delta.y() / m_scale));
}

void OdometryMap::mouseReleaseEvent(QMouseEvent *)
{
    m_dragFrom.reset();
    m_hold.reset();
    m_editTool->release();
    unsetCursor();
}

void OdometryMap::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return;
    if (const TruePose *t = truePoseAt(event->position()))
        emit robotLiftRequested(t->robot, !t->lifted);
}

// --- Editing the room ---

void OdometryMap::paintEditBanner(QPainter &painter, const QRect &area) const
{
    // A frame round the map says the floor is open to the hand, from the back of the room.
    const QColor frame = palette().color(QPalette::Highlight);
    painter.setPen(QPen(frame, 4));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(QRectF(area).adjusted(2, 2, -2, -2));
    const QString text = m_editTool->bannerText();
    const QFont bold = display::valueFont(font(), 1.15);
    const QFontMetrics fm(bold);
    const int pad = fm.averageCharWidth();
    // At the foot of the map, between the pose and the scale bar, clear of
    // the room's far corners where walls are often taken.
    const int w = fm.horizontalAdvance(text) + 2 * pad, h = fm.height() + pad;
    const int left = std::max(m_poseLabel->geometry().right() + 8, area.center().x() - w / 2);
    const QRect box(std::min(left, std::max(8, area.right() - 8 - w)), area.bottom() - 8 - h, w, h);
    painter.setPen(Qt::NoPen);
    painter.setBrush(frame);
    painter.drawRoundedRect(box, 4, 4);
    painter.setBrush(Qt::NoBrush);
    painter.setFont(bold);
    painter.setPen(palette().color(QPalette::HighlightedText));
    painter.drawText(box, Qt::AlignCenter, text);
    painter.setFont(font());
}

void OdometryMap::keyPressEvent(QKeyEvent *event)
{
    if (!m_editTool->keyPressed(event->key()))
        QWidget::keyPressEvent(event);
}

QMenu *OdometryMap::contextMenuAt(QPoint at)
{
    if (!m_world)
        return nullptr;
    auto *menu = new QMenu(this);
    m_editTool->fillMenu(menu, floorPointFor(at), gripToleranceMm());
    // Whatever the owner of the room added (Undo, Redo).
    if (m_editTool->isEditing() && !actions().isEmpty()) {
        menu->addSeparator();
        menu->addActions(actions());
    }
    return menu;
}

void OdometryMap::contextMenuEvent(QContextMenuEvent *event)
{
    // The right button turning a robot is not a call for the menu.
    if (m_hold || truePoseAt(event->pos()))
        return;
    if (QMenu *menu = contextMenuAt(event->pos())) {
        menu->exec(event->globalPos());
        delete menu;
    }
}

#include "moc_odometry_map.cpp"
