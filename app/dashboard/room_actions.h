// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "room.h"
#include "world_edit.h"

#include <QObject>
#include <QString>

#include <memory>

class QAction;
class QMenu;
class QUndoStack;
class QWidget;

// The room the virtual robots share, as a document: File → Open room…,
// Save room as…, the shipped rooms, and the map's edits with Undo and Redo.
// Every change goes to the room at once, so every robot in it senses the
// new floor at its next step. The last room opened or saved is remembered
// (QSettings "room/file") and opened again at the next start.
class RoomActions : public QObject {
    Q_OBJECT
public:
    RoomActions(std::shared_ptr<sim::Room> room, QWidget *dialogParent);

    QAction *openAction() const { return m_open; }
    QAction *saveAsAction() const { return m_saveAs; }
    QAction *undoAction() const { return m_undo; }
    QAction *redoAction() const { return m_redo; }
    // The rooms that come with the program, one action each.
    QMenu *shippedMenu() const { return m_shipped; }
    QUndoStack *undoStack() const { return m_undoStack; }

    // Replaces the floor with the room in `path` (a file or a shipped
    // ":/rooms/…" one) and puts the robots down at its start. False, with the
    // reason in `error`, for a file that is not a room: the room is left
    // as it was.
    bool openRoom(const QString &path, QString *error = nullptr);
    // Writes the floor to `path` through QSaveFile. False, with the reason in `error`.
    bool saveRoom(const QString &path, QString *error = nullptr);
    // Opens the room remembered from last time, if any. A file that has gone
    // or gone bad is said so and forgotten; the room stays as it is.
    void restoreLastRoom();
    // Applies one edit from the map, as a step that Undo takes back (the
    // steps of one drag are one).
    void edit(const sim::WorldEdit &edit);

    void retranslate();

signals:
    void message(const QString &text);

private:
    void chooseRoomToOpen();
    void chooseFileToSave();
    void openOrSay(const QString &path);

    std::shared_ptr<sim::Room> m_room;
    QWidget *m_dialogParent;
    QUndoStack *m_undoStack = nullptr;
    QAction *m_open = nullptr;
    QAction *m_saveAs = nullptr;
    QAction *m_undo = nullptr;
    QAction *m_redo = nullptr;
    QMenu *m_shipped = nullptr;
};
