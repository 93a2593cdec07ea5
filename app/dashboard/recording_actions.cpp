// SPDX-License-Identifier: GPL-3.0-or-later
#include "recording_actions.h"

#include "recording_file.h"
#include "recording_mcap.h"
#include "replay_bar.h"
#include "robot_fleet.h"
#include "robot_session.h"

#include <QAction>
#include <QApplication>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTextStream>
#include <QToolBar>

RecordingActions::RecordingActions(RobotFleet &fleet, QWidget *dialogParent)
    : QObject(dialogParent), m_fleet(fleet), m_dialogParent(dialogParent)
{
    m_record = new QAction(this);
    m_record->setObjectName("recordAction");
    m_record->setCheckable(true);
    m_record->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    connect(m_record, &QAction::triggered, this, &RecordingActions::chooseRecordingFile);
    m_open = new QAction(this);
    m_open->setObjectName("openRecordingAction");
    m_open->setShortcut(QKeySequence::Open);
    connect(m_open, &QAction::triggered, this, &RecordingActions::chooseRecordingToOpen);
    m_exportCsv = new QAction(this);
    m_exportCsv->setObjectName("exportCsvAction");
    connect(m_exportCsv, &QAction::triggered, this, [this] { exportCsv(Source::OnScreen); });
    m_exportMcap = new QAction(this);
    m_exportMcap->setObjectName("exportMcapAction");
    connect(m_exportMcap, &QAction::triggered, this, [this] { exportMcap(Source::OnScreen); });
    m_exportOtherCsv = new QAction(this);
    m_exportOtherCsv->setObjectName("exportOtherCsvAction");
    connect(m_exportOtherCsv, &QAction::triggered, this, [this] { exportCsv(Source::ChooseAnother); });
    m_exportOtherMcap = new QAction(this);
    m_exportOtherMcap->setObjectName("exportOtherMcapAction");
    connect(m_exportOtherMcap, &QAction::triggered, this, [this] { exportMcap(Source::ChooseAnother); });

    m_toolBar = new QToolBar(dialogParent);
    m_toolBar->setObjectName("recordingToolBar");
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->addAction(m_record);
    m_toolBar->addAction(m_open);
    // A row of its own, shown only in a replay: beside the recording and
    // marker tools a narrow window would push it into the overflow menu.
    m_replayToolBar = new QToolBar(dialogParent);
    m_replayToolBar->setObjectName("replayToolBar");
    m_replayBar = new ReplayBar(m_replayToolBar);
    m_replayBar->setObjectName("replayBar");
    m_replayToolBar->addWidget(m_replayBar);
    m_replayToolBar->hide();
    const auto control = [this](const oilink::ReplayCommand &command) {
        if (RobotSession *robot = m_fleet.selected())
            robot->controlReplay(command);
    };
    connect(m_replayBar, &ReplayBar::playRequested, this, [control] { control(oilink::ReplayCommand::play()); });
    connect(m_replayBar, &ReplayBar::pauseRequested, this, [control] { control(oilink::ReplayCommand::pause()); });
    connect(m_replayBar, &ReplayBar::stepRequested, this,
            [control](int frames) { control(oilink::ReplayCommand::step(frames)); });
    connect(m_replayBar, &ReplayBar::speedChosen, this,
            [control](double speed) { control(oilink::ReplayCommand::setSpeed(speed)); });
    connect(m_replayBar, &ReplayBar::seekRequested, this,
            [control](qint64 us) { control(oilink::ReplayCommand::seek(us)); });
}

void RecordingActions::retranslate()
{
    m_record->setText(tr("&Record"));
    m_record->setToolTip(tr("Record every byte to and from the selected robot into a file"));
    m_open->setText(tr("&Open recording…"));
    m_open->setToolTip(tr("Replay a recording as a robot of its own"));
    m_exportCsv->setText(tr("&Export recording as CSV…"));
    m_exportMcap->setText(tr("Export recording as &MCAP…"));
    m_exportMcap->setToolTip(tr("For Foxglove, Lichtblick and PlotJuggler"));
    m_exportOtherCsv->setText(tr("Export another recording as CSV…"));
    m_exportOtherMcap->setText(tr("Export another recording as MCAP…"));
    m_exportCsv->setToolTip(tr("The recording on screen: a replay, or the last recording of the selected robot"));
    m_exportOtherCsv->setToolTip(tr("Choose a recording file first, then where to write the CSV"));
    m_exportOtherMcap->setToolTip(tr("Choose a recording file first, then where to write the MCAP file"));
    m_toolBar->setWindowTitle(tr("Recording and replay"));
    m_replayToolBar->setWindowTitle(tr("Replay"));
}

void RecordingActions::showSelectedRobot()
{
    const RobotSession *robot = m_fleet.selected();
    m_record->setEnabled(robot && !robot->isReplay());
    m_record->setChecked(robot && robot->recording().active);
    const bool replay = robot && robot->isReplay();
    m_replayToolBar->setVisible(replay);
    if (replay)
        showReplay(robot->replay());
}

void RecordingActions::showReplay(const oilink::ReplayStatus &status)
{
    ReplayBar::Position p;
    p.positionUs = status.positionUs;
    p.durationUs = status.durationUs;
    p.frame = status.frame;
    p.frameCount = status.frameCount;
    p.playing = status.playing;
    p.finished = status.finished;
    p.speed = status.speed;
    p.fileName = QFileInfo(status.path).fileName();
    p.damage = status.damage;
    m_replayBar->setPosition(p);
}

bool RecordingActions::openRecording(const QString &path, QString *error)
{
    QString why;
    // The stream's description only: the replay reads the whole file once, on the link's thread.
    const std::optional<oilink::Recording::StreamInfo> stream = oilink::Recording::readStream(path, &why);
    if (!stream) {
        if (error)
            *error = why;
        return false;
    }
    RobotSession *robot = m_fleet.addRobot(
        oilink::LinkSettings::replayOf(path, stream->profile->id, stream->baud, stream->packets),
        QFileInfo(path).completeBaseName());
    m_fleet.select(robot);
    return true;
}

QString RecordingActions::exportRecordingCsv(const QString &recordingPath, const QString &csvPath)
{
    QString why;
    const std::optional<oilink::Recording> recording = oilink::Recording::load(recordingPath, &why);
    if (!recording)
        return why;
    QSaveFile file(csvPath);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return QStringLiteral("%1: %2").arg(csvPath, file.errorString());
    QTextStream out(&file);
    recording->writeCsv(out);
    out.flush();
    if (!file.commit())
        return QStringLiteral("%1: %2").arg(csvPath, file.errorString());
    return QString();
}

void RecordingActions::chooseRecordingFile(bool start)
{
    RobotSession *robot = m_fleet.selected();
    if (!robot)
        return;
    if (!start) {
        robot->stopRecording();
        return;
    }
    m_record->setChecked(false); // until the link says it records
    const QString suggested = QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
                                  .filePath(QStringLiteral("%1-%2.%3")
                                                .arg(robot->name().simplified().replace(' ', '-'),
                                                     QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss"),
                                                     oilink::recording::kFileSuffix));
    const QString path = QFileDialog::getSaveFileName(m_dialogParent, tr("Record %1 to").arg(robot->name()), suggested,
                                                      tr("Roomba Dashboard recordings (*.oirec)"));
    // The selection may have changed while the dialog was open.
    if (!path.isEmpty() && m_fleet.indexOf(robot) >= 0)
        robot->startRecording(path);
}

void RecordingActions::chooseRecordingToOpen()
{
    const QString path = QFileDialog::getOpenFileName(m_dialogParent, tr("Open recording"), QString(),
                                                      tr("Roomba Dashboard recordings (*.oirec);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!openRecording(path, &error))
        QMessageBox::warning(m_dialogParent, tr("Open recording"), tr("This file cannot be replayed.\n\n%1").arg(error));
}

QString RecordingActions::recordingOnScreen() const
{
    const RobotSession *robot = m_fleet.selected();
    if (!robot)
        return {};
    if (robot->isReplay())
        return robot->settings().replayPath;
    if (!robot->recording().active)
        return robot->recording().path;
    return {};
}

std::pair<QString, QString> RecordingActions::chooseExportFiles(Source source, const QString &format,
                                                               const QString &suffix, const QString &filters,
                                                               QString *selectedFilter)
{
    QString from = source == Source::OnScreen ? recordingOnScreen() : QString();
    if (from.isEmpty())
        from = QFileDialog::getOpenFileName(m_dialogParent, tr("Choose the recording to export as %1").arg(format),
                                            QString(), tr("Roomba Dashboard recordings (*.oirec);;All files (*)"));
    if (from.isEmpty())
        return {};
    const QString to = QFileDialog::getSaveFileName(
        m_dialogParent, tr("Export %1 as %2").arg(QFileInfo(from).fileName(), format),
        QFileInfo(from).path() + '/' + QFileInfo(from).completeBaseName() + suffix, filters, selectedFilter);
    if (to.isEmpty())
        return {};
    return {from, to};
}

void RecordingActions::exportCsv(Source source)
{
    const auto [from, to] = chooseExportFiles(source, QStringLiteral("CSV"), ".csv", tr("CSV files (*.csv)"));
    if (to.isEmpty())
        return;
    const QString error = exportRecordingCsv(from, to);
    if (!error.isEmpty())
        QMessageBox::warning(m_dialogParent, tr("Export recording as CSV"), tr("Nothing was written.\n\n%1").arg(error));
    else
        emit message(tr("Wrote %1").arg(QDir::toNativeSeparators(to)));
}

QString RecordingActions::exportRecordingMcap(const QString &recordingPath, const QString &mcapPath,
                                              mcap::Compression compression, QString *damage)
{
    std::optional<oilink::RecordingDamage> found;
    const QString error = oilink::exportRecordingMcap(recordingPath, mcapPath, {compression}, &found);
    if (damage)
        *damage = found && error.isEmpty() ? found->describe() : QString();
    return error;
}

void RecordingActions::exportMcap(Source source)
{
    const QString zstd = tr("MCAP, zstd compression (*.mcap)");
    const QString lz4 = tr("MCAP, lz4 compression: quicker to open (*.mcap)");
    QString filter = zstd;
    const auto [from, to] = chooseExportFiles(source, QStringLiteral("MCAP"), ".mcap", zstd + ";;" + lz4, &filter);
    if (to.isEmpty())
        return;
    QString damage;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const QString error =
        exportRecordingMcap(from, to, filter == lz4 ? mcap::Compression::Lz4 : mcap::Compression::Zstd, &damage);
    QApplication::restoreOverrideCursor();
    if (!error.isEmpty())
        QMessageBox::warning(m_dialogParent, tr("Export recording as MCAP"), tr("Nothing was written.\n\n%1").arg(error));
    else if (!damage.isEmpty())
        QMessageBox::warning(m_dialogParent, tr("Export recording as MCAP"),
                             tr("The recording is damaged; %1 holds everything up to the damage.\n\n%2")
                                 .arg(QDir::toNativeSeparators(to), damage));
    else
        emit message(tr("Wrote %1").arg(QDir::toNativeSeparators(to)));
}

#include "moc_recording_actions.cpp"
