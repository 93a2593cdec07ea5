// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "odometry.h"
#include "robot_odometry.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"
#include "world.h" // the floor as plain values; no robot
#include "world_edit.h"

#include <QColor>
#include <QList>
#include <QPen>
#include <QVector>
#include <QPointF>
#include <QPolygonF>
#include <QWidget>

#include <optional>

class QDoubleSpinBox;
class RoomEditTool;
class QLabel;
class QMenu;
class QPushButton;

// Where the robot thinks it is: its model's odometry, drawn as a trail on a
// millimetre grid. With virtual robots, their room and true poses can be
// drawn too (several robots, each in its colour, the selected one
// highlighted), so a class can watch odometry drift from the truth. Wheel
// base and wheel diameter can be measured and set on the robot's odometry;
// they change the integration from then on. Zoom with the wheel or the
// buttons, pan by dragging. Repaints from a display timer when something
// moved, not once per frame.
//
// A virtual robot can be touched: drag it to carry it elsewhere, drag it
// with Shift (or the right button) to turn it, double-click it to lift it
// or put it down. The map only asks (robotMoveRequested, robotLiftRequested);
// whoever owns the room moves the robot, and the map shows it when the
// true poses come back.
//
// The room itself can be edited (the Edit room button or the context menu)
// with its RoomEditTool, which asks for every change (worldEditRequested);
// the map draws the floor it is given.
class OdometryMap : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMaxTrailPoints = RobotOdometry::kMaxTrailPoints;
    static constexpr double kDefaultWheelDiameterMm = oi::kWheelDiameterMm;
    static constexpr double kMinScale = 0.005; // pixels per mm
    static constexpr double kMaxScale = 5.0;

    explicit OdometryMap(QWidget *parent = nullptr);

    // The robot's profile: the Create 1 has no encoders to measure.
    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &robotProfile() const { return *m_profile; }

    // The odometry shown, owned by the robot's model; nullptr shows none.
    void setOdometry(RobotOdometry *odometry);
    oi::Pose pose() const { return m_odometry ? m_odometry->pose() : oi::Pose{}; }
    // Positions in mm, oldest first, at most kMaxTrailPoints; starts with the start pose.
    QList<QPointF> trail() const { return m_odometry ? m_odometry->trail() : QList<QPointF>{}; }

    // The colour of the robot this odometry belongs to, as the robot list
    // shows it: its path and pose are drawn in it (solid, filled), its true
    // pose in the same colour, dashed. Invalid: the palette's highlight.
    void setOdometryColour(const QColor &colour);
    QColor odometryColour() const;

    // Where a virtual robot really is.
    struct TruePose {
        int robot = 0;      // the room's robot id
        oi::Pose pose;
        QColor colour;      // invalid: robotColour() of its place in the list
        bool lifted = false;
    };
    // Every robot in the room; repaints on the display timer when they moved.
    void setTruePoses(const QList<TruePose> &poses);
    const QList<TruePose> &truePoses() const { return m_truePoses; }
    // The robot this map's odometry belongs to: highlighted, and the drift
    // is measured from it. nullopt: none of them.
    void setSelectedRobot(std::optional<int> robot);
    std::optional<int> selectedRobot() const { return m_selected; }
    // The true pose of the selected robot, if it is in the list.
    std::optional<oi::Pose> selectedTruePose() const;
    // Distinct colours for robots on the map, by index.
    static QColor robotColour(int index);

    // Another run's path (a recording opened for comparison), in mm on the
    // same floor, drawn in a style of its own and named in the legend by
    // `label`; an empty path clears it.
    void setComparisonPath(const QVector<QPointF> &pointsMm, const QString &label);
    const QVector<QPointF> &comparisonPath() const { return m_comparisonPath; }
    // What the legend names, top to bottom.
    QStringList legendLabels() const;
    // Where the legend is drawn: the first corner of the map (top right, top
    // left, bottom right, bottom left) where it hides no robot.
    QRect legendRect() const;
    // Where each robot is drawn (its odometry, then each true pose).
    QList<QRect> robotRects() const;

    void setWorld(std::optional<sim::World> world);
    const std::optional<sim::World> &world() const { return m_world; }

    // Edit mode, offered while a room is shown.
    void setEditing(bool editing);
    bool isEditing() const;
    // The thing on the floor selected for editing.
    std::optional<sim::WorldItem> selectedItem() const;
    void setSelectedItem(std::optional<sim::WorldItem> item);
    RoomEditTool *editTool() const { return m_editTool; }
    // The context menu as it would pop up at widget point `at`; the caller
    // owns it. nullptr when there is nothing to offer (no room shown).
    QMenu *contextMenuAt(QPoint at);

    void setWheelBaseMm(double mm);
    void setWheelDiameterMm(double mm);
    double wheelBaseMm() const;
    double wheelDiameterMm() const;

    // Pixels per millimetre.
    double scale() const { return m_scale; }
    void setScale(double pixelsPerMm);
    // The floor point shown at the centre of the map, in mm.
    QPointF viewCentreMm() const { return m_centreMm; }
    void setViewCentreMm(QPointF mm);
    // Where a floor point (mm) is drawn, in this widget's coordinates.
    QPointF widgetPointFor(QPointF mm) const;
    QPolygonF widgetPolygon(const QList<QPointF> &pointsMm) const;
    QRect mapRect() const;

    // "x 120 mm  y -35 mm  θ 12.5°", and the distance from the true pose if
    // known; while the robot is not identified (RobotOdometry::isIdentified),
    // says so instead, and the map draws no path.
    QString poseText() const;
    // The pose in words for a screen reader; the map's accessible description.
    QString spokenPose() const;

signals:
    // Put robot `robot` down at `pose` (carried or turned by hand).
    void robotMoveRequested(int robot, const oi::Pose &pose);
    // Hold robot `robot` up (its wheels drop) or put it back down.
    void robotLiftRequested(int robot, bool lifted);
    // Change the floor: move, add or remove a wall, a stage edge, the dock
    // or the virtual wall. Every step of a drag asks again, with one
    // `gesture` number for the whole drag.
    void worldEditRequested(const sim::WorldEdit &edit);
    void editingChanged(bool editing);

public slots:
    void zoomIn();
    void zoomOut();
    void centreOnRobot();
    // Clears the robot's trail and starts its odometry again from its start.
    void reset();

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    // Checks for changes on each display tick while on screen.
    void followDisplay();
    void retranslateUi();
    QString notIdentifiedText() const;
    // The label's short pose or the screen reader's sentence: one reading, two wordings.
    enum class Wording { Shown, Spoken };
    QString poseWords(Wording wording) const;
    void updateGeometryTips();
    void zoomBy(double factor, QPointF anchorWidget);
    void applyGeometry();
    void refresh();
    void paintGrid(QPainter &painter, const QRect &area) const;
    void paintWorld(QPainter &painter) const;
    void paintEditBanner(QPainter &painter, const QRect &area) const;
    double gripToleranceMm() const;
    void paintTruePoses(QPainter &painter) const;
    QColor truePoseColour(qsizetype index) const;
    void paintRobot(QPainter &painter, const oi::Pose &pose, const QColor &colour, bool outline) const;
    void paintScaleBar(QPainter &painter, const QRect &area) const;
    double gridSpacingMm() const;
    QPointF floorPointFor(QPointF widgetPoint) const;
    // One line of the legend: how the thing is drawn, and its name.
    struct LegendEntry {
        QString text;
        QPen pen;                 // a stroke of it
        QBrush fill = Qt::NoBrush; // or a patch of it, where it is an area
    };
    QList<LegendEntry> legend() const;
    void paintLegend(QPainter &painter) const;
    QPen comparisonPen() const;
    QPen wallPen() const;
    QPen virtualWallPen() const;
    // The true pose under a widget point, if a robot is drawn there.
    const TruePose *truePoseAt(QPointF widgetPoint) const;

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    RobotOdometry *m_odometry = nullptr;
    quint64 m_shownRevision = ~0ull;
    QList<TruePose> m_truePoses;
    std::optional<int> m_selected;
    std::optional<sim::World> m_world;
    QColor m_odometryColour;
    QVector<QPointF> m_comparisonPath;
    QString m_comparisonLabel;

    double m_scale = 0.1;
    QPointF m_centreMm{1000, 0};
    std::optional<QPointF> m_dragFrom;
    // A robot held by the pointer: carried, or turned about its centre.
    struct Hold {
        int robot = 0;
        oi::Pose pose;
        QPointF grabOffsetMm; // from the robot's centre to where it was grabbed
        bool turning = false;
    };
    std::optional<Hold> m_hold;
    RoomEditTool *m_editTool = nullptr;
    bool m_dirty = false;

    QWidget *m_controls = nullptr;
    QDoubleSpinBox *m_wheelBase = nullptr;
    QDoubleSpinBox *m_wheelDiameter = nullptr;
    QLabel *m_wheelBaseTitle = nullptr;
    QLabel *m_wheelDiameterTitle = nullptr;
    QPushButton *m_zoomIn = nullptr;
    QPushButton *m_zoomOut = nullptr;
    QPushButton *m_centre = nullptr;
    QPushButton *m_reset = nullptr;
    QPushButton *m_edit = nullptr;
    QLabel *m_poseLabel = nullptr;
};

Q_DECLARE_METATYPE(sim::WorldEdit)
