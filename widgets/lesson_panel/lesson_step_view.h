// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lesson.h"
#include "sensor_snapshot.h"

#include <QHash>
#include <QWidget>

class LessonRunner;
class QGridLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class RobotDiagram;
class SensorHistory;
class SensorPlots;
class ValueGauge;

// One lesson step as the class sees it: "Step 2 of 5", the step's text in
// large type, its goal and how far it has got, the robot diagram with the
// parts that matter ringed, a plot of the step's channels and a readout of
// its values. The lesson panel shows it at desk size, the projector view
// larger; without a step it shows the robot alone (the diagram, and the
// readouts it is given).
class LessonStepView : public QWidget {
    Q_OBJECT
public:
    explicit LessonStepView(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &profile() const { return *m_profile; }
    // Not owned; the session keeps it alive while it is set.
    void setHistory(const SensorHistory *history);
    // Shows step `index` of `count`; nullptr shows the robot alone with `readouts`.
    void setStep(const LessonStep *step, int index, int count, const QStringList &readouts = {});
    // Text size, 1 at a desk; the projector view makes it larger.
    void setScale(qreal scale);
    // No text smaller than this many pixels, whatever the scale (a projector: 14).
    void setLeastTextPixels(int pixels);
    // From the display timer: the robot's latest values, and the runner for
    // the goal's progress and the pose readouts (nullptr: none).
    void refresh(const oi::SensorSnapshot &latest, bool stale, const LessonRunner *runner);
    // Why the goal cannot be met in the robot's state now and what to do
    // (RobotMode::outOfReach()), shown under the goal; empty hides it.
    void setOutOfReach(const QString &why);

    // What is shown, for tests and the projector.
    QString headingText() const;
    QString stepText() const;
    QString goalText() const;
    int progressPercent() const;
    QString progressText() const;
    QString outOfReachText() const;
    // The step's hand on the virtual robot ("On the virtual robot: Hold it
    // further over the edge"), shown while the robot is one in the room.
    QPushButton *placementButton() const { return m_placement; }
    QStringList readoutKeys() const { return m_readoutKeys; }
    QString readoutText(const QString &key) const;
    RobotDiagram *diagram() const { return m_diagram; }
    SensorPlots *plots() const { return m_plots; }

    // A goal in words: "Bump Left on", "Cliff Front Left Signal below 500 for 0.5 s".
    static QString describeGoal(const LessonGoal &goal, const oi::RobotProfile &profile);

signals:
    // The placement button: carry, hold or lift the virtual robot as the step says.
    void placementRequested(const LessonPlacement &placement);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void applyScale();
    void rebuildReadouts();
    void showStep();
    void showPlacement();

    const oi::RobotProfile *m_profile;
    const LessonStep *m_step = nullptr;
    int m_index = 0;
    int m_count = 0;
    qreal m_scale = 1;
    int m_leastTextPixels = 0;
    QStringList m_readoutKeys;
    QLabel *m_heading;
    QLabel *m_text;
    QLabel *m_goal;
    QProgressBar *m_progress;
    QLabel *m_outOfReach;
    QPushButton *m_placement;
    bool m_virtualRobotHere = false; // the runner knows the robot's true pose
    RobotDiagram *m_diagram;
    SensorPlots *m_plots;
    QGridLayout *m_readoutGrid;
    QHash<QString, ValueGauge *> m_readouts;
};
