// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_card.h"

#include <QList>
#include <QWidget>

class QButtonGroup;
class QHBoxLayout;
class QLineEdit;
class QMenu;
class QScrollArea;
class QToolButton;

// The strip of robots above the docks: a card per robot (name, colour,
// profile, mode, battery, link), the selected one checked, and buttons to add,
// rename and remove robots. It shows the values it is given and asks for
// changes by signal; the robots themselves live elsewhere.
class RobotList : public QWidget {
    Q_OBJECT
public:
    enum class AddKind { VirtualRobot, Connection, Recording };

    explicit RobotList(QWidget *parent = nullptr);

    // One card per robot, in order; only what changed is repainted.
    void setCards(const QList<RobotCardValues> &cards);
    int count() const { return int(m_cards.size()); }
    RobotCard *card(int index) const { return m_cards.value(index); }
    void setSelected(int index);
    int selected() const;

    // Edits the name of robot `index` in place; Enter (or leaving the field)
    // asks for it with renameRequested().
    void beginRename(int index);
    QLineEdit *renameEditor() const { return m_renameEditor; }
    QToolButton *addButton() const { return m_add; }
    QMenu *addMenu() const { return m_addMenu; }
    QToolButton *removeButton() const { return m_remove; }

signals:
    void selectRequested(int index);
    void addRequested(RobotList::AddKind kind);
    void renameRequested(int index, const QString &name);
    void removeRequested(int index);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void finishRename();

    QScrollArea *m_scroll = nullptr;
    QHBoxLayout *m_cardLayout = nullptr;
    QButtonGroup *m_group = nullptr;
    QList<RobotCard *> m_cards;
    QToolButton *m_add = nullptr;
    QMenu *m_addMenu = nullptr;
    QAction *m_addVirtual = nullptr;
    QAction *m_addConnection = nullptr;
    QAction *m_addRecording = nullptr;
    QToolButton *m_rename = nullptr;
    QToolButton *m_remove = nullptr;
    QLineEdit *m_renameEditor = nullptr;
    int m_renaming = -1;
};
