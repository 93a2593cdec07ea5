// SPDX-License-Identifier: GPL-3.0-or-later
// A process that records a link to the virtual robot until it is killed:
// tst_recording_killed starts it, kills it with SIGKILL and replays what it
// left. Prints "frames N" after every stream frame it has been handed.
//
//   record_until_killed FILE
#include "local_robot_port.h"
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
    oilink::LocalRobotPort link;
    link.setTransportFactory(transports::transportFactory());
    long long frames = 0;
    oilink::connectEvent<oilink::event::Frame>(&link, &app, [&] {
        std::printf("frames %lld\n", ++frames);
        std::fflush(stdout);
    });
    oilink::connectEvent<oilink::event::Recording>(&link, &app,
                     [](const oilink::RecordingStatus &status) {
                         if (!status.error.isEmpty()) {
                             std::fprintf(stderr, "record_until_killed: %s\n", qPrintable(status.error));
                             QCoreApplication::exit(1);
                         }
                     });
    link.post(oilink::request::Open{oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
    link.post(oilink::request::StartRecording{QString::fromLocal8Bit(argv[1])});
    return QCoreApplication::exec();
}
