// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>

class QAction;
class QWidget;
class RobotFleet;

// File → Record, Open recording… and Export recording as CSV…: the dialogs,
// and what each does to the robots. Recording acts on the selected robot; a
// recording opens as a robot of its own in the list.
class RecordingActions : public QObject {
    Q_OBJECT
public:
    RecordingActions(RobotFleet &fleet, QWidget *dialogParent);

    QAction *recordAction() const { return m_record; }
    QAction *openAction() const { return m_open; }
    QAction *exportCsvAction() const { return m_exportCsv; }

    // A new robot replaying `path`, selected. False, with the reason in
    // `error`, for a file that cannot be replayed; nothing changes then.
    bool openRecording(const QString &path, QString *error = nullptr);
    // Writes one CSV row per frame of a recording; returns an error or "".
    static QString exportRecordingCsv(const QString &recordingPath, const QString &csvPath);

    // Record follows the selected robot: checked while it records, off for a replay.
    void showSelectedRobot();
    void retranslate();

signals:
    void message(const QString &text);

private:
    void chooseRecordingFile(bool start);
    void chooseRecordingToOpen();
    void chooseRecordingToExport();

    RobotFleet &m_fleet;
    QWidget *m_dialogParent;
    QAction *m_record = nullptr;
    QAction *m_open = nullptr;
    QAction *m_exportCsv = nullptr;
};
