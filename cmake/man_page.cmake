# roomba_man_page(TARGET SUMMARY COMPONENT): the program's man page, made at
# build time from its own --help and installed with its package.
function(roomba_man_page target summary component)
    set(page ${CMAKE_CURRENT_BINARY_DIR}/man/${target}.1)
    add_custom_command(OUTPUT ${page}
        COMMAND ${CMAKE_COMMAND} -E env LC_ALL=C LANGUAGE=en QT_QPA_PLATFORM=offscreen
                ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${target}> -DNAME=${target} -DSUMMARY=${summary}
                -DVERSION=${PROJECT_VERSION} -DOUT=${page} -P ${PROJECT_SOURCE_DIR}/cmake/help_to_man.cmake
        DEPENDS ${target} ${PROJECT_SOURCE_DIR}/cmake/help_to_man.cmake
        COMMENT "Man page of ${target}"
        VERBATIM)
    add_custom_target(${target}-man ALL DEPENDS ${page})
    install(FILES ${page} DESTINATION share/man/man1 COMPONENT ${component})
endfunction()
