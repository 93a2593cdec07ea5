// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "mcap_writer.h"
#include "replay_transport.h"

#include <QObject>
#include <QString>

#include <utility>

class QAction;
class QToolBar;
class QWidget;
class ReplayBar;
class RobotFleet;

// File → Record, Open recording…, Export recording as CSV… and as MCAP…: the dialogs,
// and what each does to the robots. Recording acts on the selected robot; a
// recording opens as a robot of its own in the list. The Recording and
// replay toolbar holds Record, Open and, while a replay is selected, the
// replay bar, whose buttons play, pause, step and seek that replay.
class RecordingActions : public QObject {
    Q_OBJECT
public:
    RecordingActions(RobotFleet &fleet, QWidget *dialogParent);

    QAction *recordAction() const { return m_record; }
    QAction *openAction() const { return m_open; }
    QAction *exportCsvAction() const { return m_exportCsv; }
    QAction *exportMcapAction() const { return m_exportMcap; }
    // The same exports for a recording chosen first in an Open dialog.
    QAction *exportOtherCsvAction() const { return m_exportOtherCsv; }
    QAction *exportOtherMcapAction() const { return m_exportOtherMcap; }
    // The recording the selected robot shows: a replay's file, or the last
    // recording of a live robot once it is saved; "" when there is none.
    QString recordingOnScreen() const;
    QToolBar *toolBar() const { return m_toolBar; }
    // The replay bar's own row, shown while the selected robot replays.
    QToolBar *replayToolBar() const { return m_replayToolBar; }
    ReplayBar *replayBar() const { return m_replayBar; }

    // A new robot replaying `path`, selected. False, with the reason in
    // `error`, for a file that cannot be replayed; nothing changes then.
    bool openRecording(const QString &path, QString *error = nullptr);
    // Writes one CSV row per frame of a recording; returns an error or "".
    static QString exportRecordingCsv(const QString &recordingPath, const QString &csvPath);
    // Writes the recording as MCAP; returns an error or "". A damaged
    // recording is written up to the damage, which `damage` then names.
    static QString exportRecordingMcap(const QString &recordingPath, const QString &mcapPath,
                                       mcap::Compression compression, QString *damage);

    // Record follows the selected robot: checked while it records, off for a
    // replay; the replay bar shows while a replay is selected.
    void showSelectedRobot();
    void showReplay(const oilink::ReplayStatus &status);
    void retranslate();

signals:
    void message(const QString &text);

private:
    void chooseRecordingFile(bool start);
    void chooseRecordingToOpen();
    enum class Source { OnScreen, ChooseAnother };
    void exportCsv(Source source);
    void exportMcap(Source source);
    // The recording to export and where to write it; empty when cancelled.
    // The recording on screen unless another is asked for (or none is shown).
    std::pair<QString, QString> chooseExportFiles(Source source, const QString &format, const QString &suffix,
                                                  const QString &filters, QString *selectedFilter = nullptr);
    RobotFleet &m_fleet;
    QWidget *m_dialogParent;
    QAction *m_record = nullptr;
    QAction *m_open = nullptr;
    QAction *m_exportCsv = nullptr;
    QAction *m_exportMcap = nullptr;
    QAction *m_exportOtherCsv = nullptr;
    QAction *m_exportOtherMcap = nullptr;
    QToolBar *m_toolBar = nullptr;
    ReplayBar *m_replayBar = nullptr;
    QToolBar *m_replayToolBar = nullptr;
};
