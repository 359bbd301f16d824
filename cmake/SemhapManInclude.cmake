# SPDX-License-Identifier: MIT
# Writes OUTPUT, a help2man include file with a COMMANDS section: every command that
# `PROGRAM --help` lists, with its summary and its own --help, so the man page documents
# each subcommand from the one place its options are defined.
execute_process(COMMAND "${PROGRAM}" --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} --help failed")
endif()
string(REGEX MATCH "Commands:\n(.*)\n\n" commands "${help}")
string(REGEX MATCHALL "\n  ([a-z]+) " names "\n${CMAKE_MATCH_1}")
# roff: a backslash is "\e", a line starting with "." or "'" needs "\&" before it.
function(roff_escape text out)
    string(REPLACE "\\" "\\e" text "${text}")
    string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
    set(${out} "${text}" PARENT_SCOPE)
endfunction()
set(page "[COMMANDS]\nEach command has options of its own; \\fBsemhap\\fR \\fICOMMAND\\fR \\fB\\-\\-help\\fR prints them.\n")
foreach(entry IN LISTS names)
    string(STRIP "${entry}" name)
    execute_process(COMMAND "${PROGRAM}" ${name} --help OUTPUT_VARIABLE text
        RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "${PROGRAM} ${name} --help failed")
    endif()
    roff_escape("${text}" text)
    string(APPEND page ".SS ${name}\n.nf\n${text}.fi\n")
endforeach()
string(APPEND page "[EXIT STATUS]\n0 success (also when stream lines were rejected and reported), 1 invalid input or a failed write, 2 a usage error.\n")
string(APPEND page "[FILES]\nUser patterns: \\fI~/.local/share/semhap/semhap-studio/patterns/\\fR.\n")
string(APPEND page "[SEE ALSO]\n\\fBsemhap-studio\\fR(1)\n")
file(WRITE "${OUTPUT}" "${page}")
