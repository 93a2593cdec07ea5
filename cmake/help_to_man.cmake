# Writes a man page (section 1) from a program's own --help, so the page
# says what the program says. Run with -DPROGRAM= -DNAME= -DSUMMARY=
# -DVERSION= -DOUT=.
execute_process(COMMAND ${PROGRAM} --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR help STREQUAL "")
    message(FATAL_ERROR "${NAME} --help failed (${status})")
endif()
# The usage line names the program, not the build path it ran from.
string(REPLACE "${PROGRAM}" "${NAME}" help "${help}")
# roff: a backslash and a leading dot or quote are special.
string(REPLACE "\\" "\\e" help "${help}")
string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
file(WRITE ${OUT} ".TH ${NAME} 1 \"\" \"Roomba Dashboard ${VERSION}\" \"User Commands\"
.SH NAME
${NAME} \\- ${SUMMARY}
.SH DESCRIPTION
The text below is what
.B ${NAME} --help
prints.
.PP
.nf
${help}.fi
.SH SEE ALSO
.BR roomba-dashboard (1),
.BR roomba-ctl (1),
.BR roomba-sim (1),
.BR roomba-bridge (1),
.BR roomba-classroom (1).
The manual is in the docs/ folder of the source.
")
