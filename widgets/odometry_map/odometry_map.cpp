// SPDX-License-Identifier: GPL-3.0-or-later
// The odometry map: its controls, its view of the floor and its pose in words.
#include "odometry_map.h"
#include "odometry_map_measures.h"

#include "display_palette.h"
#include "display_tick.h"
#include "on_screen.h"
#include "room_edit_tool.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace {

// A value that rounds to nothing is 0, never "-0": a place, not a sign.
double shown(double value, int decimals)
{
    const double scale = std::pow(10.0, decimals);
    const double rounded = std::round(value * scale) / scale;
    return rounded == 0 ? 0.0 : rounded;
}

constexpr double kPi = 3.14159265358979323846;
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
    // Without encoders (the Create 1) the robot reports distance and angle itself.
    if (m_profile->caps.encoders == oi::WheelEncoders::None) {
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
    const bool encoders = profile.caps.encoders != oi::WheelEncoders::None;
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

void OdometryMap::zoomIn() { zoomBy(map_measures::kZoomStep, QRectF(mapRect()).center()); }
void OdometryMap::zoomOut() { zoomBy(1 / map_measures::kZoomStep, QRectF(mapRect()).center()); }

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
    return poseWords(Wording::Shown);
}

QString OdometryMap::spokenPose() const
{
    return poseWords(Wording::Spoken);
}

QString OdometryMap::poseWords(Wording wording) const
{
    if (m_odometry && !m_odometry->isIdentified())
        return notIdentifiedText();
    const bool spoken = wording == Wording::Spoken;
    const oi::Pose &p = pose();
    const int headingDecimals = spoken ? 0 : 1;
    QString text = (spoken ? tr("Robot at x %1 mm, y %2 mm, heading %3 degrees") : tr("x %1 mm   y %2 mm   θ %3°"))
                       .arg(shown(p.xMm, 0), 0, 'f', 0)
                       .arg(shown(p.yMm, 0), 0, 'f', 0)
                       .arg(shown(p.thetaRad * 180 / kPi, headingDecimals), 0, 'f', headingDecimals);
    if (const auto truth = selectedTruePose()) {
        const double driftMm = std::hypot(p.xMm - truth->xMm, p.yMm - truth->yMm);
        text += (spoken ? tr("; %1 mm from the true pose") : tr("   drift %1 mm")).arg(driftMm, 0, 'f', 0);
    }
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

#include "moc_odometry_map.cpp"
