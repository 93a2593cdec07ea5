// SPDX-License-Identifier: GPL-3.0-or-later
#include "run_comparison.h"

#include "comparison_bar.h"
#include "odometry_map.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "sensor_plots.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QToolBar>

#include <cmath>

RunComparison::RunComparison(RobotFleet &fleet, SensorPlots *plots, OdometryMap *map, QWidget *dialogParent)
    : QObject(dialogParent), m_fleet(fleet), m_plots(plots), m_map(map), m_dialogParent(dialogParent)
{
    m_compare = new QAction(this);
    m_compare->setObjectName("compareAction");
    connect(m_compare, &QAction::triggered, this, &RunComparison::chooseFile);
    m_close = new QAction(this);
    m_close->setObjectName("closeComparisonAction");
    m_close->setEnabled(false);
    connect(m_close, &QAction::triggered, this, &RunComparison::close);
    m_toolBar = new QToolBar(dialogParent);
    m_toolBar->setObjectName("comparisonToolBar");
    m_bar = new ComparisonBar(m_toolBar);
    m_bar->setObjectName("comparisonBar");
    m_toolBar->addWidget(m_bar);
    m_toolBar->hide();
    connect(m_bar, &ComparisonBar::alignRequested, this, &RunComparison::alignAt);
    connect(m_bar, &ComparisonBar::closeRequested, this, &RunComparison::close);
    // Another robot selected, or its markers changed: line the run up with it again.
    const auto follow = [this](RobotSession *robot) {
        for (const QMetaObject::Connection &c : std::as_const(m_followed))
            disconnect(c);
        m_followed.clear();
        if (robot)
            m_followed << connect(&robot->markers(), &RobotMarkers::changed, this, &RunComparison::apply);
        apply();
    };
    connect(&m_fleet, &RobotFleet::selectionChanged, this, follow);
    connect(&m_fleet, &RobotFleet::robotAdded, this, [this, follow](RobotSession *robot) {
        if (robot == m_fleet.selected()) // the first robot is selected without a selection change
            follow(robot);
    });
    follow(m_fleet.selected());
}

void RunComparison::retranslate()
{
    m_compare->setText(tr("&Compare with recording…"));
    m_compare->setToolTip(tr("Show a second recording beside this run: plots and map, in a style of its own"));
    m_close->setText(tr("C&lose comparison"));
    m_toolBar->setWindowTitle(tr("Comparison"));
}

void RunComparison::chooseFile()
{
    const QString path = QFileDialog::getOpenFileName(m_dialogParent, tr("Compare with recording"), QString(),
                                                      tr("Roomba Dashboard recordings (*.oirec);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!open(path, &error))
        QMessageBox::warning(m_dialogParent, tr("Compare with recording"),
                             tr("This file cannot be compared.\n\n%1").arg(error));
}

bool RunComparison::open(const QString &path, QString *error)
{
    std::optional<RecordedRun> run = RecordedRun::load(path, error);
    if (!run)
        return false;
    m_run = std::move(run);
    m_alignedAt.clear();
    apply();
    return true;
}

void RunComparison::close()
{
    if (!m_run)
        return;
    m_run.reset();
    m_alignedAt.clear();
    apply();
}

void RunComparison::alignAt(const QString &marker)
{
    m_alignedAt = sharedMarkers().contains(marker) ? marker : QString();
    apply();
}

double RunComparison::startOf(const RobotSession &robot)
{
    // A replay or a recording: its own time 0. Live and not recording: now,
    // so that the compared run plays out beside what comes next.
    if (robot.isReplay() || !robot.markers().path().isEmpty())
        return robot.markers().originSeconds();
    return robot.history().newestTime();
}

QStringList RunComparison::sharedMarkers() const
{
    QStringList shared;
    const RobotSession *robot = m_fleet.selected();
    if (!m_run || !robot)
        return shared;
    QStringList own;
    for (const oilink::RecordingMarker &m : robot->markers().list())
        own << m.label();
    for (const oilink::RecordingMarker &m : m_run->markers())
        if (own.contains(m.label()) && !shared.contains(m.label()))
            shared << m.label();
    return shared;
}

double RunComparison::alignedShift() const
{
    const RobotSession *robot = m_fleet.selected();
    if (!m_run || !robot)
        return 0;
    const auto firstLabelled = [&](const QList<oilink::RecordingMarker> &markers) -> std::optional<oilink::RecordingMarker> {
        for (const oilink::RecordingMarker &m : markers)
            if (m.label() == m_alignedAt)
                return m;
        return std::nullopt;
    };
    const auto own = firstLabelled(robot->markers().list());
    const auto other = firstLabelled(m_run->markers());
    if (m_alignedAt.isEmpty() || !own || !other)
        return startOf(*robot);
    return robot->markers().seconds(*own) - static_cast<double>(other->timeUs) / 1e6;
}

void RunComparison::apply()
{
    const RobotSession *robot = m_fleet.selected();
    if (m_run && robot) {
        if (!sharedMarkers().contains(m_alignedAt))
            m_alignedAt.clear();
        m_shift = alignedShift();
        // The legend names each file; a live robot by its name.
        const QString own = robot->isReplay() ? QFileInfo(robot->replay().path).fileName() : robot->name();
        m_plots->setComparison(&m_run->history(), m_shift, m_run->name(), own);
        // The compared path starts where the robot's own odometry started, facing its way.
        const oi::Pose &start = robot->odometry().start();
        const double c = std::cos(start.thetaRad), s = std::sin(start.thetaRad);
        QVector<QPointF> path;
        path.reserve(m_run->pathMm().size());
        for (const QPointF &p : m_run->pathMm())
            path << QPointF(start.xMm + c * p.x() - s * p.y(), start.yMm + s * p.x() + c * p.y());
        m_map->setComparisonPath(path, m_run->name());
        m_bar->showRun(m_run->name(), sharedMarkers(), m_alignedAt);
    } else {
        m_plots->setComparison(nullptr, 0, QString(), QString());
        m_map->setComparisonPath({}, QString());
    }
    m_toolBar->setVisible(m_run.has_value());
    m_close->setEnabled(m_run.has_value());
}

#include "moc_run_comparison.cpp"
