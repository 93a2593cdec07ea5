// SPDX-License-Identifier: GPL-3.0-or-later
// A process that records a link to the virtual robot until it is killed:
// tst_recording_killed starts it, kills it with SIGKILL and replays what it
// left. Prints "frames N" after every stream frame it has been handed.
//
//   record_until_killed FILE
#include "robot_link_thread.h"
#include "transport_factory.h"

#include <QCoreApplication>

#include <cstdio>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    if (argc != 2) {
        std::fprintf(stderr, "usage: record_until_killed FILE\n");
        return 2;
    }
    oilink::registerLinkMetaTypes();
    oilink::RobotLinkThread link;
    link.setTransportFactory(transports::transportFactory());
    long long frames = 0;
    QObject::connect(&link, &oilink::RobotLinkThread::snapshot, &app, [&] {
        std::printf("frames %lld\n", ++frames);
        std::fflush(stdout);
    });
    QObject::connect(&link, &oilink::RobotLinkThread::recordingStatus, &app,
                     [](const oilink::RecordingStatus &status) {
                         if (!status.error.isEmpty()) {
                             std::fprintf(stderr, "record_until_killed: %s\n", qPrintable(status.error));
                             QCoreApplication::exit(1);
                         }
                     });
    link.open(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
    link.startRecording(QString::fromLocal8Bit(argv[1]));
    return QCoreApplication::exec();
}
