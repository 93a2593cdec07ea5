// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-dashboard: the desktop dashboard.
#include "main_window.h"

#include <QApplication>
#include <QStyleFactory>

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName("RoombaDashboard");
    QApplication::setApplicationName("roomba-dashboard");
    QApplication::setApplicationVersion(ROOMBA_VERSION);
    // Fusion draws the same everywhere and takes the system's light or dark palette.
    QApplication::setStyle(QStyleFactory::create("Fusion"));

    MainWindow window;
    window.resize(1280, 860);
    window.show();
    window.start();
    return app.exec();
}
