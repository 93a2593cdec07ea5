# SPDX-License-Identifier: GPL-3.0-or-later
# What keeps the build short on a two-core machine: precompiled Qt headers
# (roomba_precompile_qt) and ccache working with them.

# ccache leaves compilations that use a precompiled header uncached unless
# told that the header's time stamps and __DATE__ do not matter; it is told
# here, so that a fresh machine's ccache needs no configuration.
if(CMAKE_CXX_COMPILER_LAUNCHER MATCHES "ccache$")
    set(CMAKE_CXX_COMPILER_LAUNCHER
        ${CMAKE_COMMAND} -E env
        "CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime"
        ${CMAKE_CXX_COMPILER_LAUNCHER})
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

# roomba_precompile_qt(target CORE|WIDGETS): the target precompiles that set.
function(roomba_precompile_qt target set)
    if(ROOMBA_PRECOMPILED_HEADERS)
        target_precompile_headers(${target} PRIVATE ${ROOMBA_QT_${set}_HEADERS})
    endif()
endfunction()
