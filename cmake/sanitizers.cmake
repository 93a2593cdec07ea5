# SPDX-License-Identifier: GPL-3.0-or-later
# ROOMBA_SANITIZE: build every target with sanitizers, e.g.
#   cmake -S . -B build-asan -G Ninja -DROOMBA_SANITIZE=address,undefined
#   cmake -S . -B build-tsan -G Ninja -DROOMBA_SANITIZE=thread
# Run the result with ASAN_OPTIONS / UBSAN_OPTIONS / TSAN_OPTIONS as .ci/run
# and tests/tsan.sh do, so that any report fails the run.
set(ROOMBA_SANITIZE "" CACHE STRING
    "Sanitizers for every target: empty, address, undefined, address,undefined or thread")
set_property(CACHE ROOMBA_SANITIZE PROPERTY STRINGS "" address undefined address,undefined thread)

if(ROOMBA_SANITIZE)
    string(REPLACE "," ";" roomba_sanitizers "${ROOMBA_SANITIZE}")
    foreach(s IN LISTS roomba_sanitizers)
        if(NOT s MATCHES "^(address|undefined|thread)$")
            message(FATAL_ERROR "ROOMBA_SANITIZE: unknown sanitizer '${s}' (address, undefined, thread)")
        endif()
    endforeach()
    if("thread" IN_LIST roomba_sanitizers AND "address" IN_LIST roomba_sanitizers)
        message(FATAL_ERROR "ROOMBA_SANITIZE: thread cannot be combined with address")
    endif()
    # Frame pointers give whole stacks in the reports at little cost.
    add_compile_options(-fsanitize=${ROOMBA_SANITIZE} -fno-omit-frame-pointer)
    add_link_options(-fsanitize=${ROOMBA_SANITIZE})
    message(STATUS "Sanitizers: ${ROOMBA_SANITIZE}")
endif()
