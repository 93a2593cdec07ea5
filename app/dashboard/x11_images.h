// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Call before QApplication. On X11 the window's pixels go to the X server
// through its socket, not through shared memory (MIT-SHM). With shared
// memory, Qt waits for a round trip to the X server before it paints any
// area it has just sent, and the dashboard repaints the same small areas
// (the plots' newest columns, the gauges) many times a second: those waits
// were a tenth of the GUI thread's time with one robot. Through the socket,
// a small area is a short copy; a whole 1920x1080 window, a few milliseconds.
// QT_XCB_NO_MITSHM set by the user is left as it is.
void sendX11ImagesThroughTheSocket();
