// SPDX-License-Identifier: GPL-3.0-or-later
#include "x11_images.h"

#include <QtGlobal>

void sendX11ImagesThroughTheSocket()
{
    // Qt's X11 plugin reads this once, when it connects to the X server.
    if (!qEnvironmentVariableIsSet("QT_XCB_NO_MITSHM"))
        qputenv("QT_XCB_NO_MITSHM", "1");
}
