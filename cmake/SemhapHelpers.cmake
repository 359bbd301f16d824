# SPDX-License-Identifier: MIT
# Compiler settings shared by every semhap target, and the one-line test helper.

set(SEMHAP_SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/..")

# Strict Qt: no implicit string conversions, no foreach, nothing deprecated before 6.4.
# qcustomplot.h uses foreach, so the studio opts out of QT_NO_FOREACH (see STYLE.md).
# Tests may build QStrings from literals (ALLOW_ASCII): their rows read better that way.
function(semhap_strict_target target)
    cmake_parse_arguments(arg "ALLOW_FOREACH;ALLOW_ASCII" "" "" ${ARGN})
    target_compile_definitions(${target} PRIVATE
        QT_NO_CAST_TO_ASCII QT_NO_CAST_FROM_BYTEARRAY
        QT_NO_URL_CAST_FROM_STRING QT_USE_QSTRINGBUILDER
        QT_DISABLE_DEPRECATED_BEFORE=0x060400)
    if(NOT arg_ALLOW_ASCII)
        target_compile_definitions(${target} PRIVATE QT_NO_CAST_FROM_ASCII)
    endif()
    if(NOT arg_ALLOW_FOREACH)
        target_compile_definitions(${target} PRIVATE QT_NO_FOREACH)
    endif()
    target_compile_options(${target} PRIVATE
        -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast
        -Wcast-align -Woverloaded-virtual -Wconversion -Wno-sign-conversion)
    if(SEMHAP_SANITIZE)
        target_compile_options(${target} PRIVATE
            -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    endif()
    if(SEMHAP_FUZZ)
        # Coverage feedback from the libraries too, not only from the fuzz targets' own code.
        target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
    endif()
endfunction()

# semhap_add_test(name LIBS lib... [LABELS label...] [SOURCES extra...] [ALLOW_FOREACH])
# ALLOW_FOREACH: for tests that include <qcustomplot.h> (see STYLE.md).
# Builds tests/<name>/tst_<name>.cpp into tst_<name> and registers it with CTest.
# Tests read their golden files from SEMHAP_TEST_DATA (the test's own folder).
function(semhap_add_test name)
    cmake_parse_arguments(arg "ALLOW_FOREACH" "" "LIBS;LABELS;SOURCES" ${ARGN})
    # The sanitizer build runs only the tests labelled "sanitize": build only those.
    if(SEMHAP_SANITIZE AND NOT "sanitize" IN_LIST arg_LABELS)
        return()
    endif()
    set(target tst_${name})
    add_executable(${target} ${CMAKE_CURRENT_SOURCE_DIR}/${name}/tst_${name}.cpp ${arg_SOURCES})
    target_link_libraries(${target} PRIVATE Qt6::Test ${arg_LIBS})
    target_compile_definitions(${target} PRIVATE
        SEMHAP_TEST_DATA="${CMAKE_CURRENT_SOURCE_DIR}/${name}"
        SEMHAP_RESOURCES="${SEMHAP_SOURCE_DIR}/resources"
        SEMHAP_VECTORS="${SEMHAP_SOURCE_DIR}/tests/vectors")
    if(arg_ALLOW_FOREACH)
        semhap_strict_target(${target} ALLOW_ASCII ALLOW_FOREACH)
    else()
        semhap_strict_target(${target} ALLOW_ASCII)
    endif()
    add_test(NAME ${name} COMMAND ${target})
    set_tests_properties(${name} PROPERTIES
        LABELS "${arg_LABELS}" TIMEOUT 300
        ENVIRONMENT "QT_QPA_PLATFORM=offscreen;ASAN_OPTIONS=detect_leaks=1")
endfunction()
