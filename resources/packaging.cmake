# SPDX-License-Identifier: GPL-3.0-or-later
# CPack: `cpack -G DEB` in the build directory makes two packages from the
# install rules, as Debian splits a program: roomba-bridge_<version>_<arch>.deb
# (roomba-bridge, roomba-ctl, roomba-sim, roomba-classroom, the systemd unit
# and the MQTT samples; no GUI library, for a robot's Pi) and
# roomba-dashboard_<version>_<arch>.deb (the window, which depends on the
# first for its command-line tools). A bridge-only build
# (-DROOMBA_BRIDGE_ONLY=ON) makes the first alone. Included from the
# top-level CMakeLists.txt, after every install rule.
set(CPACK_PACKAGE_NAME roomba-dashboard)
set(CPACK_PACKAGE_VENDOR "Roomba Dashboard developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "A Qt 6 dashboard for iRobot robots that speak the Open Interface (Roomba 500, \
Roomba 600 / Create 2, original Create), over a serial port or a TCP bridge: \
live sensors, gauges and plots, driving from a drive pad, keyboard or gamepad, \
and editors for songs, LEDs, schedule and Create scripts. Includes roomba-sim, \
a virtual robot on a pseudo-terminal or TCP, and the roomba-ctl command-line tool.")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Whatever the build type, users get the binaries without debug info.
set(CPACK_STRIP_FILES ON)

set(ROOMBA_PACKAGE_MAINTAINER "Roomba Dashboard developers <roomba-dashboard@users.noreply.github.com>"
    CACHE STRING "Maintainer field of the .deb (Name <email>)")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${ROOMBA_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
# dpkg-shlibdeps works out the Qt, QCustomPlot, SDL and libsmf libraries
# (Debian's libqt6gui6 carries the xcb platform plugin). Qt's Wayland plugin is
# loaded at run time and named by no linked library; without it the window
# runs under XWayland, so recommend it rather than depend on it.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-wayland")

set(CPACK_DEB_COMPONENT_INSTALL ON)
if(ROOMBA_BRIDGE_ONLY)
    set(CPACK_COMPONENTS_ALL bridge)
else()
    set(CPACK_COMPONENTS_ALL dashboard bridge python)
endif()
set(CPACK_DEBIAN_DASHBOARD_PACKAGE_NAME roomba-dashboard)
set(CPACK_DEBIAN_DASHBOARD_PACKAGE_DEPENDS "roomba-bridge (= ${PROJECT_VERSION})")
set(CPACK_COMPONENT_DASHBOARD_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION}")
set(CPACK_DEBIAN_BRIDGE_PACKAGE_NAME roomba-bridge)
set(CPACK_DEBIAN_BRIDGE_PACKAGE_RECOMMENDS "")
set(CPACK_DEBIAN_BRIDGE_PACKAGE_SUGGESTS "mosquitto, openssl")
# (CPack 3.25 heads every package's description with the project's summary.)
set(CPACK_COMPONENT_BRIDGE_DESCRIPTION
    "The network classroom's part, without a desktop. roomba-bridge puts one iRobot Open Interface robot (Roomba 500, Roomba 600 / \
Create 2, original Create) on an MQTT broker with every safety rule, for a \
Raspberry Pi beside the robot; roomba-classroom init sets up a classroom's \
TLS broker in one command; roomba-ctl and roomba-sim are the command-line \
tool and the virtual robot. Needs no GUI library.")

# The Python library for students' programs: pure Python, any architecture.
set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-roomba)
set(CPACK_DEBIAN_PYTHON_PACKAGE_ARCHITECTURE all)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SHLIBDEPS OFF)
set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "python3 (>= 3.11), python3-paho-mqtt")
# At home, python3 -m roomba.practice runs a broker and a practice robot.
set(CPACK_DEBIAN_PYTHON_PACKAGE_RECOMMENDS "roomba-bridge, mosquitto")
set(CPACK_COMPONENT_PYTHON_DESCRIPTION
    "Students' programs drive classroom robots: the roomba Python library speaks to a robot's \
roomba-bridge over MQTT, with moves that wait until done (straight, turn, arc in millimetres and \
degrees, closed on the robot's own odometry by the bridge), sensors, and every stop the bridge \
makes (Stop all, a cliff, a lost connection) as an exception. python3 -m roomba.practice starts a \
broker and a practice robot at home.")

include(CPack)
