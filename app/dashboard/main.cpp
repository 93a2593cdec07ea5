// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-dashboard: the desktop dashboard.
#include "main_window.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QStyleFactory>

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName("RoombaDashboard");
    QApplication::setApplicationName("roomba-dashboard");
    QApplication::setApplicationVersion(ROOMBA_VERSION);
    // Fusion draws the same everywhere and takes the system's light or dark palette.
    QApplication::setStyle(QStyleFactory::create("Fusion"));

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate(
        "main", "Dashboard and teleoperation for iRobot robots that speak the Open Interface."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption sim("sim", QApplication::translate("main", "Connect to the built-in virtual robot, "
                                                                         "whatever was used last time."));
    parser.addOption(sim);
    parser.process(app);

    MainWindow window;
    window.resize(1280, 860);
    window.show();
    std::optional<oilink::LinkSettings> settings;
    if (parser.isSet(sim))
        settings = MainWindow::linkSettingsFor(ConnectionRequest{});
    window.start(settings);
    return app.exec();
}
