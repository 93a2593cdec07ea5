// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-dashboard: the desktop dashboard.
#include "command_line.h"
#include "language_switcher.h"
#include "live_server_actions.h"
#include "main_window.h"
#include "screen_fit.h"
#include "settings_file.h"
#include "termination_signals.h"
#include "x11_images.h"

#include <QApplication>
#include <QIcon>
#include <QSettings>
#include <QTranslator>
#include <QStyleFactory>

#include <cstdio>

int main(int argc, char **argv)
{
    // Read the arguments before a window system is needed, so --help and a
    // bad argument work anywhere.
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    QCoreApplication::setOrganizationName("RoombaDashboard");
    QCoreApplication::setApplicationName("roomba-dashboard");
    // Errors and --help in the language the window would speak.
    QString language = QSettings().value("language").toString();
    const qsizetype lang = arguments.indexOf("--lang");
    if (lang > 0 && lang + 1 < arguments.size() && isUiLanguage(arguments[lang + 1]))
        language = arguments[lang + 1];
    if (!isUiLanguage(language))
        language = systemUiLanguage();
    QTranslator commandLineTranslator;
    if (language != QLatin1String("en") && loadUiTranslation(commandLineTranslator, language))
        DashboardCommandLine::setTranslator(&commandLineTranslator);
    const DashboardCommandLine line = DashboardCommandLine::parse(arguments);
    if (!line.error.isEmpty()) {
        std::fprintf(stderr, "roomba-dashboard: %s\n", qPrintable(line.error));
        return 2;
    }
    if (line.showHelp || line.showVersion) {
        std::printf("%s", qPrintable(line.showHelp ? DashboardCommandLine::usage()
                                                   : QString("roomba-dashboard %1\n").arg(ROOMBA_VERSION)));
        return 0;
    }
    // From here the application's translator speaks, and follows the View menu.
    DashboardCommandLine::setTranslator(nullptr);

    sendX11ImagesThroughTheSocket();
    QApplication app(argc, argv);
    SettingsFile::checkAtStart(); // a damaged or foreign settings file is kept aside, not read
    QApplication::setApplicationVersion(ROOMBA_VERSION);
    // Fusion draws the same everywhere and takes the system's light or dark palette.
    QApplication::setStyle(QStyleFactory::create("Fusion"));

    // Wayland matches the window to its menu entry and icon by this name.
    QGuiApplication::setDesktopFileName("io.github.roombadashboard.RoombaDashboard");
    // Installed, the icon theme has it (share/icons/hicolor); from a build tree
    // the window simply has none.
    QApplication::setWindowIcon(QIcon::fromTheme("io.github.roombadashboard.RoombaDashboard"));

    MainWindow window;
    // Killed or hung up: stop every robot and leave it in Passive, as closing
    // the window does, then end.
    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app, [&window](int signal) {
        window.close();
        QCoreApplication::exit(TerminationSignals::exitStatusFor(signal));
    });
    if (!line.language.isEmpty())
        window.setLanguage(line.language, false);
    // First start: a laptop's size, or the whole of a smaller screen.
    const QRect room = screenfit::available(&window);
    const QSize wanted(1600, 1000);
    window.resize(screenfit::fitted(wanted, room.size()));
    if (room.width() < wanted.width() || room.height() < wanted.height())
        window.showMaximized();
    else
        window.show();
    window.setVirtualPacks(line.batteryFadePercent, line.batteryResistanceMohm);
    window.start(line.connection, line.robotCount);
    if (!line.recordPath.isEmpty())
        window.startRecording(line.recordPath);
    if (line.liveServer)
        window.liveServer()->start(*line.liveServer); // a port in use is said, and the window goes on
    return app.exec();
}
