# SPDX-License-Identifier: GPL-3.0-or-later
# One precompiled header for many tests: Qt Test and the Qt headers most tests
# include, compiled once per family and reused by every test of it. GCC
# refuses a precompiled header made with other predefined macros (and
# -Winvalid-pch says so), and Qt Test's headers read QT_WIDGETS_LIB and the
# like, so a family is the tests whose linked libraries bring the same
# definitions and options; its header is compiled by a small program linking
# those same libraries.

set(ROOMBA_TEST_PCH_CORE <QTest> <QSignalSpy> <QTemporaryDir> ${ROOMBA_QT_CORE_HEADERS})
set(ROOMBA_TEST_PCH_WIDGETS <QTest> <QSignalSpy> <QTemporaryDir> ${ROOMBA_QT_WIDGETS_HEADERS})

# What the libraries `target` links bring to its compile line, directly or
# through other libraries: their interface definitions and options, as one
# string; `widgets` tells whether Qt Widgets is among them.
function(roomba_test_family target out widgets)
    set(seen "")
    set(queue ${target})
    set(brought "")
    set(${widgets} OFF PARENT_SCOPE)
    while(queue)
        list(POP_FRONT queue item)
        if(item MATCHES "^\\$<LINK_ONLY:(.+)>$")
            set(item "${CMAKE_MATCH_1}")
        endif()
        if(NOT TARGET "${item}")
            continue()
        endif()
        get_target_property(aliased ${item} ALIASED_TARGET)
        if(aliased)
            set(item ${aliased})
        endif()
        if(item IN_LIST seen)
            continue()
        endif()
        list(APPEND seen ${item})
        if(item STREQUAL "Qt6::Widgets")
            set(${widgets} ON PARENT_SCOPE)
        endif()
        foreach(property IN ITEMS INTERFACE_COMPILE_DEFINITIONS INTERFACE_COMPILE_OPTIONS)
            get_target_property(values ${item} ${property})
            if(values)
                list(APPEND brought "${values}")
            endif()
        endforeach()
        get_target_property(imported ${item} IMPORTED)
        get_target_property(type ${item} TYPE)
        set(direct "")
        if(NOT imported AND NOT type STREQUAL "INTERFACE_LIBRARY")
            get_target_property(direct ${item} LINK_LIBRARIES)
        endif()
        get_target_property(interface ${item} INTERFACE_LINK_LIBRARIES)
        foreach(library IN LISTS direct interface)
            if(library AND NOT library MATCHES "-NOTFOUND$")
                list(APPEND queue "${library}")
            endif()
        endforeach()
    endwhile()
    list(REMOVE_DUPLICATES brought)
    list(SORT brought)
    string(MD5 key "${brought}")
    set(${out} ${key} PARENT_SCOPE)
endfunction()

# Gives every test in `tests` the precompiled header of its family; the first
# test of a family makes the program that compiles it.
function(roomba_share_test_pch tests)
    if(NOT ROOMBA_PRECOMPILED_HEADERS)
        return()
    endif()
    set(keys "")
    foreach(test IN LISTS tests)
        # The tests' own source and build folders differ from test to test and
        # are tested by Qt Test's headers; no test looks for data by them
        # (QFINDTESTDATA), so they are left undefined.
        target_compile_options(${test} PRIVATE -UQT_TESTCASE_SOURCEDIR -UQT_TESTCASE_BUILDDIR)
        roomba_test_family(${test} key widgets)
        list(FIND keys ${key} index)
        if(index LESS 0)
            list(LENGTH keys index)
            list(APPEND keys ${key})
            set(donor roomba_test_pch_${index})
            add_executable(${donor} EXCLUDE_FROM_ALL ${PROJECT_SOURCE_DIR}/tests/common/pch_donor.cpp)
            get_target_property(libraries ${test} LINK_LIBRARIES)
            target_link_libraries(${donor} PRIVATE ${libraries})
            target_compile_options(${donor} PRIVATE ${ROOMBA_TEST_COMPILE_OPTIONS} -UQT_TESTCASE_SOURCEDIR
                                                    -UQT_TESTCASE_BUILDDIR)
            set_target_properties(${donor} PROPERTIES AUTOMOC OFF AUTOUIC OFF AUTORCC OFF)
            if(widgets)
                target_precompile_headers(${donor} PRIVATE ${ROOMBA_TEST_PCH_WIDGETS})
            else()
                target_precompile_headers(${donor} PRIVATE ${ROOMBA_TEST_PCH_CORE})
            endif()
        endif()
        target_precompile_headers(${test} REUSE_FROM roomba_test_pch_${index})
        roomba_moc_unit_without_pch(${test})
    endforeach()
endfunction()
