// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "display_palette.h"
#include "sensor_snapshot.h"

#include <QPointF>
#include <QRectF>
#include <QTransform>
#include <QWidget>

#include <optional>

#include <utility>

class QPainter;

// A top-down drawing of the robot, front at the top, seen from above: the
// robot's right is on the right of the widget. It shows the bumper halves,
// wheel drops, cliff sensors with their signals, the light bumpers (Roomba
// 500 / 600), the wall and virtual wall, the IR characters, buttons, stasis
// and overcurrents, in shapes and colours meant to be read from across a
// room. The drawing keeps its aspect and scales with the widget.
class RobotDiagram : public QWidget {
    Q_OBJECT
public:
    explicit RobotDiagram(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &profile() const { return *m_profile; }
    // Stores the values and schedules a repaint; call it from a display timer.
    void setSnapshot(const oi::SensorSnapshot &snapshot);
    // Stale data is drawn in grey under a STALE banner.
    void setStale(bool stale, bool replayEnded = false);
    bool isStale() const { return m_stale; }
    // No text drawn smaller than this many pixels (a projector: 14).
    void setLeastTextPixels(qreal pixels);
    // How high the chips' captions ("IR omni") are drawn, in pixels.
    qreal captionPixels() const;
    // Rings drawn round these parts, to point a class at them: "bump_left",
    // "bump_right", "wheel_left", "wheel_right", "caster", "cliff_left",
    // "cliff_front_left", "cliff_front_right", "cliff_right", "wall",
    // "light_bump_left" .. "light_bump_right", "ir_receiver". Unknown names
    // and parts this profile lacks are left out.
    void setHighlightedParts(const QStringList &parts);
    QStringList highlightedParts() const { return m_highlighted; }
    // Where a highlighted part's ring is drawn, in widget coordinates.
    std::optional<QPointF> partCentre(const QString &part) const;

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

    // Where things are drawn, in widget coordinates, for tests and tooltips.
    // Each point lies inside a filled shape and clear of any text.
    QPointF cliffSensorCentre(oi::CliffSensor sensor) const;
    QRectF cliffSignalRect(oi::CliffSensor sensor) const;
    QPointF bumperCentre(bool left) const;
    QRectF bumperRect(bool left) const;
    QPointF lightBumperCentre(oi::LightBumper bumper) const;
    // A point on the light bumper's signal bar, `level` (0..1) of the way out.
    QPointF lightBumpSignalPoint(oi::LightBumper bumper, qreal level) const;
    QPointF wheelCentre(bool left) const;
    QPointF casterCentre() const; // Create 1 only
    QPointF wallCentre() const;
    QRectF robotRect() const;

    // What the status chips say, e.g. "Omni: Forward", for tests.
    QStringList statusTexts() const;
    // Whether the chips put each caption beside its value, as where they
    // are too short for the two lines (a 1280×720 window).
    bool chipCaptionsBesideValues() const;

protected:
    bool event(QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct Chip {
        QString caption;
        QString value;
        display::State state = display::State::Idle;
        QString shortValue; // drawn when the value would be too small to read
    };

    void retranslateUi();
    // What the drawing shows, in words, for screen readers.
    QString stateSummary() const;
    void updateDescription();

    // Scene units (about 1.47 per mm of robot) to widget pixels.
    QTransform sceneToWidget() const;
    qreal sceneScale() const;
    qreal sceneTop() const;
    qreal topOffset() const; // pixels
    QList<QList<Chip>> chipRows() const;
    qreal chipRowHeight() const;
    QList<std::pair<QRectF, Chip>> placedChips() const; // in scene units
    // A chip's text area: the chip less its margins (scene units).
    static QRectF chipTextArea(const QRectF &chip) { return chip.adjusted(14, 4, -14, -4); }

    QColor fill(display::State state) const;
    QColor textColour(display::State state) const;
    QColor inkColour() const;
    QFont sceneFont(qreal pixelSize, bool bold = true) const;
    // A bold scene font of about `pixelSize`, smaller where `text` is wider than `width`.
    QFont fittingFont(qreal pixelSize, const QString &text, qreal width) const;

    void paintBody(QPainter &p) const;
    void paintBumper(QPainter &p) const;
    void paintLightBumpers(QPainter &p) const;
    void paintWheels(QPainter &p) const;
    void paintCliffs(QPainter &p) const;
    void paintWall(QPainter &p) const;
    void paintChips(QPainter &p) const;
    void paintStale(QPainter &p) const;
    void paintHighlights(QPainter &p) const;
    std::optional<QPointF> scenePartCentre(const QString &part) const;

    const oi::Capabilities &caps() const { return m_profile->caps; }

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    oi::SensorSnapshot m_snapshot;
    bool m_stale = false;
    qreal m_leastTextPixels = 0; // 0: as the drawing's proportions give
    qreal captionSize() const; // scene units
    bool m_replayEnded = false;
    QStringList m_highlighted;
};
