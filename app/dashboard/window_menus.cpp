// SPDX-License-Identifier: GPL-3.0-or-later
#include "window_menus.h"

#include "broker_actions.h"
#include "calibration_wizard.h"
#include "dock_layout.h"
#include "firmware_reading.h"
#include "language_menu.h"
#include "live_server_actions.h"
#include "marker_actions.h"
#include "projector_mode.h"
#include "recording_actions.h"
#include "robot_bar.h"
#include "room_actions.h"
#include "run_comparison.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenuBar>
#include <QMessageBox>
#include <QToolBar>

WindowMenus::WindowMenus(QMainWindow *window, const WindowActions &a)
    : QObject(window), m_window(window), m_actions(a)
{
    m_quit = new QAction(this);
    m_quit->setShortcut(QKeySequence::Quit);
    connect(m_quit, &QAction::triggered, window, &QWidget::close);
    window->addAction(a.broker->fleetViewAction());
    m_about = new QAction(this);
    connect(m_about, &QAction::triggered, window, [window] {
        QMessageBox::about(window, QCoreApplication::translate("MainWindow", "About Roomba Dashboard"),
                           QCoreApplication::translate("MainWindow",
                                                       "Roomba Dashboard %1\nA dashboard for iRobot robots that "
                                                       "speak the Open Interface.\nGPL-3.0-or-later.")
                               .arg(QApplication::applicationVersion()));
    });

    window->addToolBar(a.recording->toolBar());
    // Rows of their own, each shown only when in use: side by side they
    // would squeeze the replay slider.
    window->addToolBarBreak();
    window->addToolBar(a.recording->replayToolBar());
    window->addToolBarBreak();
    window->addToolBar(a.comparison->toolBar());

    QMenuBar *bar = window->menuBar();
    m_file = bar->addMenu(QString());
    m_file->addActions({a.recording->recordAction(), a.recording->openAction(), a.recording->exportCsvAction(),
                        a.recording->exportMcapAction(), a.recording->exportOtherCsvAction(),
                        a.recording->exportOtherMcapAction(), a.comparison->compareAction(),
                        a.comparison->closeAction()});
    m_file->addSeparator();
    m_file->addActions({a.markers->dropAction(), a.markers->previousAction(), a.markers->nextAction()});
    m_file->addSeparator();
    m_file->addAction(a.room->openAction());
    m_file->addMenu(a.room->shippedMenu());
    m_file->addAction(a.room->saveAsAction());
    m_file->addSeparator();
    m_file->addActions({a.broker->connectAction(), a.broker->disconnectAction()});
    m_file->addSeparator();
    m_file->addAction(a.robots->stopAllAction());
    m_file->addSeparator();
    m_file->addAction(m_quit);

    m_robot = bar->addMenu(QString());
    m_robot->setObjectName("robotMenu");
    m_robot->addActions({a.firmware->action(), a.calibration->action()});

    m_view = bar->addMenu(QString());
    for (QDockWidget *dock : a.docks->docks())
        m_view->addAction(a.docks->viewAction(dock));
    m_view->addActions({a.recording->toolBar()->toggleViewAction(), a.broker->fleetViewAction(), a.live->action()});
    m_view->addSeparator();
    m_view->addActions({a.projector->action(), a.docks->nextAction(), a.docks->previousAction()});
    m_view->addMenu(a.languages->menu());
    m_view->addAction(a.docks->resetAction());

    m_help = bar->addMenu(QString());
    m_help->addAction(m_about);
}

// The menus' words are MainWindow's, where they were first marked.
void WindowMenus::retranslate()
{
    const WindowActions &a = m_actions;
    m_file->setTitle(QCoreApplication::translate("MainWindow", "&File"));
    a.recording->retranslate();
    a.markers->retranslate();
    a.comparison->retranslate();
    a.room->retranslate();
    a.broker->retranslate();
    m_quit->setText(QCoreApplication::translate("MainWindow", "&Quit"));
    m_robot->setTitle(QCoreApplication::translate("MainWindow", "&Robot"));
    a.firmware->retranslate();
    a.calibration->retranslate();
    a.live->retranslate();
    m_view->setTitle(QCoreApplication::translate("MainWindow", "&View"));
    a.languages->retranslate();
    a.docks->retranslate();
    a.projector->retranslate();
    m_help->setTitle(QCoreApplication::translate("MainWindow", "&Help"));
    m_about->setText(QCoreApplication::translate("MainWindow", "&About"));
}
