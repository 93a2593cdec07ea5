// SPDX-License-Identifier: GPL-3.0-or-later
#include "marker_actions.h"

#include "lesson_runner.h"
#include "marker_list.h"
#include "marker_note_editor.h"
#include "replay_bar.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "sensor_plots.h"

#include <QAction>
#include <QFileInfo>
#include <QToolBar>

MarkerActions::MarkerActions(RobotFleet &fleet, SensorPlots *plots, ReplayBar *replayBar, QToolBar *toolBar,
                             QWidget *parent)
    : QObject(parent), m_fleet(fleet), m_plots(plots), m_replayBar(replayBar)
{
    m_drop = new QAction(this);
    m_drop->setObjectName("dropMarkerAction");
    m_drop->setShortcut(QKeySequence(Qt::Key_M));
    connect(m_drop, &QAction::triggered, this, &MarkerActions::drop);
    m_previous = new QAction(this);
    m_previous->setObjectName("previousMarkerAction");
    m_previous->setShortcut(QKeySequence(Qt::Key_Comma));
    connect(m_previous, &QAction::triggered, this, [this] { jumpBy(-1); });
    m_next = new QAction(this);
    m_next->setObjectName("nextMarkerAction");
    m_next->setShortcut(QKeySequence(Qt::Key_Period));
    connect(m_next, &QAction::triggered, this, [this] { jumpBy(1); });

    m_list = new MarkerList(parent);
    m_list->setObjectName("markerList");
    m_noteEditor = new MarkerNoteEditor(toolBar);
    m_noteEditor->setObjectName("markerNoteEditor");
    toolBar->addAction(m_drop);
    m_noteEditorAction = toolBar->addWidget(m_noteEditor);
    m_noteEditorAction->setVisible(false);
    connect(m_noteEditor, &MarkerNoteEditor::visibilityWanted, m_noteEditorAction, &QAction::setVisible);
    connect(m_noteEditor, &MarkerNoteEditor::noteEntered, this, [this](int id, const QString &note) {
        QString error;
        if (m_noteRobot && !m_noteRobot->markers().rename(id, note, &error))
            emit message(error);
    });

    const auto onSelected = [this](const auto &change) {
        RobotSession *robot = m_fleet.selected();
        if (!robot)
            return;
        QString error;
        if (!change(robot->markers(), &error))
            emit message(error);
    };
    connect(m_list, &MarkerList::renameRequested, this, [onSelected](int id, const QString &note) {
        onSelected([&](RobotMarkers &markers, QString *error) { return markers.rename(id, note, error); });
    });
    connect(m_list, &MarkerList::deleteRequested, this, [onSelected](int id) {
        onSelected([&](RobotMarkers &markers, QString *error) { return markers.remove(id, error); });
    });
    connect(m_list, &MarkerList::jumpRequested, this, &MarkerActions::jumpTo);
    connect(m_replayBar, &ReplayBar::previousMarkerRequested, this, [this] { jumpBy(-1); });
    connect(m_replayBar, &ReplayBar::nextMarkerRequested, this, [this] { jumpBy(1); });
    // The first robot added is selected without a selection change.
    connect(&m_fleet, &RobotFleet::selectionChanged, this, [this](RobotSession *robot) { follow(robot); });
    connect(&m_fleet, &RobotFleet::robotAdded, this, [this](RobotSession *robot) {
        if (robot == m_fleet.selected())
            follow(robot);
    });
    follow(m_fleet.selected());
}

void MarkerActions::retranslate()
{
    m_drop->setText(tr("Mark &this moment"));
    m_drop->setIconText(tr("Mark"));
    m_drop->setToolTip(tr("Drop a marker on the recording here, with an optional note (M)"));
    m_previous->setText(tr("Previo&us marker"));
    m_next->setText(tr("&Next marker"));
    show();
}

void MarkerActions::follow(RobotSession *robot)
{
    for (const QMetaObject::Connection &c : std::as_const(m_followed))
        disconnect(c);
    m_followed.clear();
    if (robot) {
        m_followed << connect(&robot->markers(), &RobotMarkers::changed, this, &MarkerActions::show)
                   << connect(robot, &RobotSession::recordingStatus, this, &MarkerActions::show)
                   << connect(robot, &RobotSession::stateChanged, this, &MarkerActions::show);
    }
    show();
}

void MarkerActions::show()
{
    const RobotSession *robot = m_fleet.selected();
    const bool replay = robot && robot->isReplay();
    QList<PlotMarker> own;
    if (robot)
        for (const oilink::RecordingMarker &m : robot->markers().list())
            own << PlotMarker{robot->markers().seconds(m), m.label()};
    m_plots->setMarkers(own);
    m_replayBar->setMarkers(replay ? own : QList<PlotMarker>());
    m_list->setMarkers(robot ? robot->markers().list() : QList<oilink::RecordingMarker>());
    const bool editable = robot && robot->markers().canChange();
    m_list->setEditable(editable, tr("Markers are kept in a recording: start one (File → Record) or open one. "
                                     "Then M marks the moment."));
    m_list->setJumpable(replay);
    m_previous->setEnabled(replay && !own.isEmpty());
    m_next->setEnabled(replay && !own.isEmpty());
    // Said once for each file that holds more markers than are read.
    if (robot && robot->markers().leftOut() > 0 && robot->markers().path() != m_leftOutSaidFor) {
        m_leftOutSaidFor = robot->markers().path();
        emit message(QStringLiteral("%1: %2").arg(QFileInfo(m_leftOutSaidFor).fileName(),
                                                  oilink::markersLeftOutNotice(robot->markers().leftOut())));
    }
}

int MarkerActions::drop()
{
    RobotSession *robot = m_fleet.selected();
    if (!robot)
        return 0;
    QString error;
    const int id = robot->dropMarker(QString(), &error);
    if (!id) {
        emit message(error);
        return 0;
    }
    const std::optional<oilink::RecordingMarker> marker = robot->markers().find(id);
    m_noteRobot = robot;
    m_list->select(id);
    m_noteEditor->edit(id, tr("Marker %1 at %2:").arg(marker->label(), ReplayBar::clock(marker->timeUs)));
    return id;
}

void MarkerActions::markStepsOf(const LessonRunner &runner)
{
    connect(&runner, &LessonRunner::stepDone, this, [this](int step) {
        RobotSession *robot = m_fleet.selected();
        if (robot && robot->recording().active)
            robot->dropMarker(tr("Lesson step %1 done").arg(step + 1));
    });
}

void MarkerActions::jumpTo(int id)
{
    RobotSession *robot = m_fleet.selected();
    if (!robot || !robot->isReplay())
        return;
    if (const std::optional<oilink::RecordingMarker> m = robot->markers().find(id))
        robot->controlReplay(oilink::ReplayCommand::seek(m->timeUs));
}

void MarkerActions::jumpBy(int direction)
{
    RobotSession *robot = m_fleet.selected();
    if (!robot || !robot->isReplay())
        return;
    const double now = static_cast<double>(robot->replay().positionUs) / 1e6;
    const RobotMarkers &markers = robot->markers();
    if (const auto m = direction > 0 ? markers.next(now) : markers.previous(now)) {
        m_list->select(m->id);
        robot->controlReplay(oilink::ReplayCommand::seek(m->timeUs));
    }
}

#include "moc_marker_actions.cpp"
