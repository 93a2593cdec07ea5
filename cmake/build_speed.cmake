# SPDX-License-Identifier: GPL-3.0-or-later
# What keeps the build short on a two-core machine: precompiled Qt headers
# (roomba_precompile_qt) and ccache working with them, unity builds of the
# libraries (roomba_unity_build), and lld for the many links.

# ccache leaves compilations that use a precompiled header uncached unless
# told that the header's time stamps and __DATE__ do not matter; it is told
# here, so that a fresh machine's ccache needs no configuration.
if(CMAKE_CXX_COMPILER_LAUNCHER MATCHES "ccache$")
    set(CMAKE_CXX_COMPILER_LAUNCHER
        ${CMAKE_COMMAND} -E env
        "CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime"
        ${CMAKE_CXX_COMPILER_LAUNCHER})
endif()

# GCC collects its garbage as its heap grows from a small floor, and a unit
# that loads a precompiled header starts with a large heap that every
# collection walks. A 1 GiB floor spares most units every collection: a
# tenth less CPU for a widget unit, for 7 % more memory at its peak.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(--param=ggc-min-expand=100 --param=ggc-min-heapsize=1048576)
endif()

option(ROOMBA_PRECOMPILED_HEADERS "Precompile the Qt headers of the Qt-heavy targets" ON)

# The Qt headers most sources of a widget-side target include. Parsing them
# is most of each file's compile time; precompiled, a target parses them once.
set(ROOMBA_QT_CORE_HEADERS
    <QByteArray> <QCoreApplication> <QDateTime> <QDir> <QElapsedTimer> <QFile> <QFileInfo>
    <QHash> <QJsonArray> <QJsonDocument> <QJsonObject> <QList> <QObject> <QPointer> <QSettings>
    <QString> <QStringList> <QTimer> <QVariant>
    <algorithm> <cmath> <functional> <memory> <optional> <span> <string> <vector>)
set(ROOMBA_QT_WIDGETS_HEADERS
    ${ROOMBA_QT_CORE_HEADERS}
    <QAction> <QApplication> <QCheckBox> <QComboBox> <QDockWidget> <QGridLayout> <QGroupBox>
    <QHBoxLayout> <QLabel> <QLineEdit> <QMainWindow> <QMenu> <QMessageBox> <QMouseEvent>
    <QPainter> <QPushButton> <QSlider> <QSpinBox> <QToolButton> <QVBoxLayout> <QWidget>)

# roomba_precompile_qt(target CORE|WIDGETS): the target uses the one
# precompiled header of that set, compiled once for every library by a small
# library of its own (roomba_pch_core, roomba_pch_widgets) with the first
# such library's options (SDL's -D_REENTRANT for the widgets). GCC takes a
# precompiled header in a unit with more definitions than it was made with,
# if the header does not read them: no Qt Core, Gui or Widgets header reads
# the QT_<MODULE>_LIB definitions the other Qt modules bring. So the header
# is made with Qt Core's (or Qt Widgets') own definitions only; every library
# is compiled with the same options (-fPIC from Qt, the warnings).
# -Winvalid-pch says so if a unit does not take it.
function(roomba_precompile_qt target set)
    if(NOT ROOMBA_PRECOMPILED_HEADERS)
        return()
    endif()
    string(TOLOWER "roomba_pch_${set}" donor)
    if(NOT TARGET ${donor})
        add_library(${donor} STATIC ${PROJECT_SOURCE_DIR}/cmake/pch_donor.cpp)
        if(set STREQUAL "WIDGETS")
            target_link_libraries(${donor} PRIVATE Qt6::Widgets)
        else()
            target_link_libraries(${donor} PRIVATE Qt6::Core)
        endif()
        target_compile_options(${donor} PRIVATE $<TARGET_PROPERTY:${target},COMPILE_OPTIONS>)
        set_target_properties(${donor} PROPERTIES AUTOMOC OFF AUTOUIC OFF AUTORCC OFF)
        target_precompile_headers(${donor} PRIVATE ${ROOMBA_QT_${set}_HEADERS})
    endif()
    target_precompile_headers(${target} REUSE_FROM ${donor})
    roomba_moc_unit_without_pch(${target})
endfunction()

# AUTOMOC's one unit per target (mocs_compilation.cpp) is empty where every
# source includes its own moc output, and loading a precompiled header costs
# it a second; it is compiled without one.
function(roomba_moc_unit_without_pch target)
    get_target_property(automoc ${target} AUTOMOC)
    if(automoc)
        get_target_property(binary_dir ${target} BINARY_DIR)
        set_source_files_properties(${binary_dir}/${target}_autogen/mocs_compilation.cpp TARGET_DIRECTORY ${target}
                                    PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
    endif()
endfunction()

# Unity builds: a library's sources compiled a few at a time in one unit, so
# the headers they share are parsed and their inline code compiled once per
# batch, not once per source. Batches of 6 keep both cores busy to the end.
# A source whose file-local names clash with another's is listed in
# `alone` and compiled by itself (SKIP_UNITY_BUILD_INCLUSION).
# A library's moc step waits only for its own sources, not for the libraries
# it links to be built (none of ours generates a header), so the widgets'
# and the window's sources start while the layers below still compile.
set(CMAKE_AUTOGEN_ORIGIN_DEPENDS OFF)

option(ROOMBA_UNITY_BUILD "Compile each library's sources in batches (unity build)" ON)
function(roomba_unity_build target)
    cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "ALONE")
    if(NOT ROOMBA_UNITY_BUILD)
        return()
    endif()
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 6)
    if(arg_ALONE)
        set_source_files_properties(${arg_ALONE} TARGET_DIRECTORY ${target}
                                    PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
endfunction()

# lld links the ~100 test programs and the dashboard in a fraction of the
# time of GNU ld; Debian's lld package (in .ci/install-deps) provides it, and
# without it the default linker is used.
option(ROOMBA_USE_LLD "Link with lld where it is installed" ON)
if(ROOMBA_USE_LLD)
    include(CheckLinkerFlag)
    check_linker_flag(CXX -fuse-ld=lld ROOMBA_HAVE_LLD)
    if(ROOMBA_HAVE_LLD)
        add_link_options(-fuse-ld=lld)
    endif()
endif()
