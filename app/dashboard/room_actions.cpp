// SPDX-License-Identifier: GPL-3.0-or-later
#include "room_actions.h"

#include "room_file.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QUndoCommand>
#include <QUndoStack>

namespace {

const QString kSettingsKey = QStringLiteral("room/file");

// The rooms embedded from resources/rooms, with their titles for the menu.
struct ShippedRoom {
    const char *file;
    const char *title;
};
constexpr ShippedRoom kShippedRooms[] = {
    {"classroom.json", QT_TRANSLATE_NOOP("RoomActions", "Classroom")},
    {"empty_floor.json", QT_TRANSLATE_NOOP("RoomActions", "Empty floor")},
    {"table_top.json", QT_TRANSLATE_NOOP("RoomActions", "Table top")},
    {"corridor.json", QT_TRANSLATE_NOOP("RoomActions", "Corridor")},
    {"dock_corner.json", QT_TRANSLATE_NOOP("RoomActions", "Dock corner")},
};

// One change of the floor: the floor before and after. The steps of one
// drag share a gesture and merge into one.
class FloorChange : public QUndoCommand {
public:
    FloorChange(std::shared_ptr<sim::Room> room, sim::World before, sim::World after, std::uint64_t gesture)
        : m_room(std::move(room)), m_before(std::move(before)), m_after(std::move(after)), m_gesture(gesture)
    {
    }
    void undo() override { m_room->setWorld(m_before); }
    void redo() override { m_room->setWorld(m_after); }
    int id() const override { return 1; }
    bool mergeWith(const QUndoCommand *other) override
    {
        const auto *next = static_cast<const FloorChange *>(other);
        if (m_gesture == 0 || next->m_gesture != m_gesture)
            return false;
        m_after = next->m_after;
        return true;
    }

private:
    std::shared_ptr<sim::Room> m_room;
    sim::World m_before, m_after;
    std::uint64_t m_gesture;
};

} // namespace

RoomActions::RoomActions(std::shared_ptr<sim::Room> room, QWidget *dialogParent)
    : QObject(dialogParent), m_room(std::move(room)), m_dialogParent(dialogParent)
{
    m_undoStack = new QUndoStack(this);
    m_open = new QAction(this);
    m_open->setObjectName("openRoomAction");
    connect(m_open, &QAction::triggered, this, &RoomActions::chooseRoomToOpen);
    m_saveAs = new QAction(this);
    m_saveAs->setObjectName("saveRoomAsAction");
    connect(m_saveAs, &QAction::triggered, this, &RoomActions::chooseFileToSave);
    m_undo = m_undoStack->createUndoAction(this);
    m_undo->setObjectName("undoRoomEditAction");
    m_undo->setShortcut(QKeySequence::Undo);
    m_redo = m_undoStack->createRedoAction(this);
    m_redo->setObjectName("redoRoomEditAction");
    m_redo->setShortcut(QKeySequence::Redo);

    m_shipped = new QMenu(dialogParent);
    m_shipped->setObjectName("shippedRoomsMenu");
    for (const ShippedRoom &r : kShippedRooms) {
        QAction *a = m_shipped->addAction(QString());
        a->setObjectName(QStringLiteral("room_%1").arg(QFileInfo(r.file).completeBaseName()));
        a->setData(QStringLiteral(":/rooms/%1").arg(r.file));
        connect(a, &QAction::triggered, this, [this, a] { openOrSay(a->data().toString()); });
    }
}

void RoomActions::retranslate()
{
    m_open->setText(tr("O&pen room…"));
    m_open->setToolTip(tr("Put the virtual robots in a room from a file"));
    m_saveAs->setText(tr("Sa&ve room as…"));
    m_saveAs->setToolTip(tr("Write the virtual robots' room, as edited on the map, to a file"));
    m_shipped->setTitle(tr("E&xample rooms"));
    const QList<QAction *> actions = m_shipped->actions();
    for (qsizetype i = 0; i < actions.size(); ++i)
        actions[i]->setText(tr(kShippedRooms[i].title));
    m_undo->setText(tr("&Undo room edit"));
    m_redo->setText(tr("Re&do room edit"));
}

bool RoomActions::openRoom(const QString &path, QString *error)
{
    std::optional<sim::World> world = sim::loadRoomFile(path, error);
    if (!world)
        return false;
    m_room->setWorldAndPlaceRobots(std::move(*world));
    // A new room is a new document: the old one's steps do not apply to it.
    m_undoStack->clear();
    QSettings().setValue(kSettingsKey, path);
    return true;
}

bool RoomActions::saveRoom(const QString &path, QString *error)
{
    if (!sim::saveRoomFile(path, m_room->world(), error))
        return false;
    m_undoStack->setClean();
    QSettings().setValue(kSettingsKey, path);
    return true;
}

void RoomActions::restoreLastRoom()
{
    const QString path = QSettings().value(kSettingsKey).toString();
    if (path.isEmpty())
        return;
    QString why;
    if (!openRoom(path, &why)) {
        QSettings().remove(kSettingsKey);
        emit message(tr("The room of last time could not be opened: %1").arg(why));
    }
}

void RoomActions::edit(const sim::WorldEdit &edit)
{
    const sim::World before = m_room->world();
    sim::World after = before;
    if (!sim::applyEdit(after, edit) || after == before)
        return;
    m_undoStack->push(new FloorChange(m_room, before, std::move(after), edit.gesture));
}

void RoomActions::openOrSay(const QString &path)
{
    QString why;
    if (openRoom(path, &why))
        emit message(tr("Room opened: %1").arg(QString::fromStdString(m_room->world().name)));
    else
        QMessageBox::warning(m_dialogParent, tr("Open room"), tr("This room could not be opened; the room stays as it was.\n\n%1").arg(why));
}

void RoomActions::chooseRoomToOpen()
{
    const QString path = QFileDialog::getOpenFileName(m_dialogParent, tr("Open room"),
                                                      QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation),
                                                      tr("Rooms (*.json);;All files (*)"));
    if (!path.isEmpty())
        openOrSay(path);
}

void RoomActions::chooseFileToSave()
{
    const QString name = QString::fromStdString(m_room->world().name).toLower().replace(' ', '_');
    const QString suggested = QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
                                  .filePath((name.isEmpty() ? QStringLiteral("room") : name) + ".json");
    const QString path = QFileDialog::getSaveFileName(m_dialogParent, tr("Save room as"), suggested,
                                                      tr("Rooms (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    QString why;
    if (saveRoom(path, &why))
        emit message(tr("Room saved to %1").arg(QDir::toNativeSeparators(path)));
    else
        QMessageBox::warning(m_dialogParent, tr("Save room as"), tr("The room could not be saved.\n\n%1").arg(why));
}

#include "moc_room_actions.cpp"
