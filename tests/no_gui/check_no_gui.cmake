# SPDX-License-Identifier: GPL-3.0-or-later
# cmake -DPROGRAMS="a;b" -P check_no_gui.cmake: fails if any program needs a
# GUI library (Qt Gui, Widgets, Charts, OpenGL, PrintSupport, Multimedia,
# QCustomPlot, SDL, X11, Wayland) or no Qt Core at all (a wrong reading).
find_program(READELF readelf REQUIRED)
foreach(program IN LISTS PROGRAMS)
    execute_process(COMMAND ${READELF} -d ${program} OUTPUT_VARIABLE dynamic RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "readelf -d ${program} failed (${rc}): build it first")
    endif()
    string(REGEX MATCHALL "\\(NEEDED\\)[^\n]*\\[([^]\n]+)\\]" lines "${dynamic}")
    set(needed "")
    foreach(line IN LISTS lines)
        string(REGEX REPLACE ".*\\[([^]]+)\\].*" "\\1" lib "${line}")
        list(APPEND needed ${lib})
    endforeach()
    if(NOT needed MATCHES "libQt6Core")
        message(FATAL_ERROR "${program}: no libQt6Core among its NEEDED libraries (${needed}): not a Qt program?")
    endif()
    foreach(lib IN LISTS needed)
        if(lib MATCHES "Qt6(Gui|Widgets|Charts|OpenGL|PrintSupport|Multimedia)|qcustomplot|SDL|libX11|xcb|wayland|libGL")
            message(FATAL_ERROR "${program} needs ${lib}, a GUI library: a robot's Pi installs none. "
                                "Find what pulls it in (a Qt Gui type in protocol/ or robot/ core code) and keep it "
                                "in the dashboard's libraries.")
        endif()
    endforeach()
    message(STATUS "${program}: ${needed}")
endforeach()
