# SPDX-License-Identifier: GPL-3.0-or-later
# One precompiled header for many tests: Qt Test and the Qt headers most tests
# include, compiled once per family and reused by every test of it. GCC
# refuses a precompiled header made with other predefined macros than a unit
# has, if the header reads them (-Winvalid-pch says so). Of the QT_<MODULE>_LIB
# definitions the Qt libraries bring, Qt Test's headers read only those of
# Gui, Widgets and Network, and glibc's read _REENTRANT (from SDL); no header
# in it reads the others. So a family is the tests that bring the same of
# those, and its header is compiled by a small program linking only the Qt
# modules they name: a test may bring more definitions than its header was
# made with, never fewer.

set(ROOMBA_TEST_PCH_CORE <QTest> <QSignalSpy> <QTemporaryDir> ${ROOMBA_QT_CORE_HEADERS})
set(ROOMBA_TEST_PCH_WIDGETS <QTest> <QSignalSpy> <QTemporaryDir> ${ROOMBA_QT_WIDGETS_HEADERS})

# What the libraries `target` links bring to its compile line, directly or
# through other libraries, that the precompiled header reads: their interface
# definitions and options but the QT_<MODULE>_LIB ones it does not read, as a
# list in `out`.
function(roomba_test_family target out)
    set(seen "")
    set(queue ${target})
    set(brought "")
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
    set(all ${brought})
    list(FILTER brought EXCLUDE REGEX "^QT_[A-Z0-9_]+_LIB$")
    foreach(module IN ITEMS GUI WIDGETS NETWORK)
        if("QT_${module}_LIB" IN_LIST all)
            list(APPEND brought QT_${module}_LIB)
        endif()
    endforeach()
    list(REMOVE_DUPLICATES brought)
    list(SORT brought)
    set(${out} "${brought}" PARENT_SCOPE)
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
        roomba_test_family(${test} family)
        string(MD5 key "${family}")
        list(FIND keys ${key} index)
        if(index LESS 0)
            list(LENGTH keys index)
            list(APPEND keys ${key})
            set(donor roomba_test_pch_${index})
            add_executable(${donor} EXCLUDE_FROM_ALL ${PROJECT_SOURCE_DIR}/tests/common/pch_donor.cpp)
            set(modules Qt6::Test)
            foreach(module IN ITEMS Network Gui Widgets)
                string(TOUPPER ${module} upper)
                if("QT_${upper}_LIB" IN_LIST family)
                    list(APPEND modules Qt6::${module})
                endif()
            endforeach()
            target_link_libraries(${donor} PRIVATE ${modules})
            # What else the family brings (SDL's -D_REENTRANT), as it came.
            set(rest ${family})
            list(FILTER rest EXCLUDE REGEX "QT_")
            foreach(item IN LISTS rest)
                if(item MATCHES "^-")
                    target_compile_options(${donor} PRIVATE ${item})
                else()
                    target_compile_definitions(${donor} PRIVATE ${item})
                endif()
            endforeach()
            target_compile_options(${donor} PRIVATE ${ROOMBA_TEST_COMPILE_OPTIONS} -UQT_TESTCASE_SOURCEDIR
                                                    -UQT_TESTCASE_BUILDDIR)
            set_target_properties(${donor} PROPERTIES AUTOMOC OFF AUTOUIC OFF AUTORCC OFF)
            if("QT_WIDGETS_LIB" IN_LIST family)
                target_precompile_headers(${donor} PRIVATE ${ROOMBA_TEST_PCH_WIDGETS})
            else()
                target_precompile_headers(${donor} PRIVATE ${ROOMBA_TEST_PCH_CORE})
            endif()
        endif()
        target_precompile_headers(${test} REUSE_FROM roomba_test_pch_${index})
        roomba_moc_unit_without_pch(${test})
    endforeach()
endfunction()
