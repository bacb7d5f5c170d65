# readme_example.cmake - the README's API example, as a user would take it:
# its ```c block under "## Using it" compiled with -std=c99 -Wall -Wextra
# -Wpedantic -Werror, a 64x64 texture made by fixel-sim and converted by
# fixel-texconv (the README says the texture comes from it), linked against
# libfixel and run (tests/readme/main.c includes it, draws a quad through it
# and checks the pixels). Run by CTest:
#   cmake -DREADME=... -DCC=... -DLIB=... -DINC=... -DSIM=... -DTEXCONV=...
#         -DMAIN=... -DWORK=... [-DEXTRA=flags] -P readme_example.cmake
file(READ "${README}" text)
string(FIND "${text}" "## Using it" at)
if(at LESS 0)
  message(FATAL_ERROR "README: no '## Using it' section")
endif()
string(SUBSTRING "${text}" ${at} -1 text)
string(FIND "${text}" "```c\n" open)
if(open LESS 0)
  message(FATAL_ERROR "README: no ```c block under '## Using it'")
endif()
math(EXPR open "${open} + 5")
string(SUBSTRING "${text}" ${open} -1 text)
string(FIND "${text}" "```" close)
string(SUBSTRING "${text}" 0 ${close} example)
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/example.c" "${example}")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}${err}")
  endif()
endfunction()

run("${SIM}" --scene cube --size 64x64 -o "${WORK}/brick.png")
run("${TEXCONV}" "${WORK}/brick.png" -o "${WORK}/brick.c" --name brick)
set(flags -std=c99 -Wall -Wextra -Wpedantic -Werror "-I${INC}" ${EXTRA})
run("${CC}" ${flags} -c "${WORK}/example.c" -o "${WORK}/example.o")
run("${CC}" ${flags} -c "${WORK}/brick.c" -o "${WORK}/brick.o")
run("${CC}" ${flags} "-I${WORK}" -c "${MAIN}" -o "${WORK}/main.o")
run("${CC}" ${EXTRA} "${WORK}/main.o" "${WORK}/brick.o" "${LIB}" -o "${WORK}/readme_example")
run("${WORK}/readme_example")
message(STATUS "README example: compiled warning-free, linked with fixel-texconv output, ran")
