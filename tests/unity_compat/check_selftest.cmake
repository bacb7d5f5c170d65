# tests/unity_compat/check_selftest.cmake - run selftest.c and compare its
# output, line by line, and its exit status with what Unity 2.6 prints for the
# same tests.   cmake -DSELFTEST=<path to executable> -P check_selftest.cmake
#
# Result lines are compared without their "<file>:<line>:" prefix (the path
# depends on the build); the prefix itself is checked by a regex.
cmake_minimum_required(VERSION 3.20)

if(NOT SELFTEST)
  message(FATAL_ERROR "usage: cmake -DSELFTEST=<executable> -P ${CMAKE_CURRENT_LIST_FILE}")
endif()

set(expected_results
  "test_pass_every_macro:PASS"
  "test_pass_early:PASS"
  "test_pass_with_message:INFO: hello"
  "test_pass_with_message:PASS"
  "test_fail_equal_int:FAIL: Expected 5 Was 6"
  "test_pass_failure_aborted_test:PASS"
  "test_fail_equal_message:FAIL: Expected 1 Was 2. pixel (3, 4)"
  "test_fail_assert:FAIL: Expression Evaluated To FALSE"
  "test_fail_assert_true:FAIL: Expected TRUE Was FALSE"
  "test_fail_assert_false:FAIL: Expected FALSE Was TRUE"
  "test_fail_assert_message:FAIL: custom text"
  "test_fail_uint8:FAIL: Expected 255 Was 0"
  "test_fail_uint:FAIL: Expected 1 Was 4000000000"
  "test_fail_hex16:FAIL: Expected 0xBEEF Was 0xBEEE"
  "test_fail_hex32_message:FAIL: Expected 0xDEADBEEF Was 0x00000ABC. word 7"
  "test_fail_int64:FAIL: Expected -9223372036854775808 Was 9223372036854775807"
  "test_fail_not_equal:FAIL: Expected Not-Equal"
  "test_fail_null:FAIL: Expected NULL"
  "test_fail_not_null:FAIL: Expected Non-NULL"
  "test_fail_int_within:FAIL: Values Not Within Delta 2 Expected 10 Was 13"
  "test_fail_uint32_within:FAIL: Values Not Within Delta 1 Expected 0 Was 4294967295"
  "test_fail_double_within:FAIL: Expected 1.5 Was 1.75"
  "test_fail_double_within_nan:FAIL: Expected 0 Was nan. nan"
  "test_fail_less_or_equal:FAIL: Expected 7 to be less than or equal to 5"
  "test_fail_less_or_equal_double:FAIL: Expected 0.5 to be less than or equal to 0.25"
  "test_fail_greater_or_equal:FAIL: Expected 4 to be greater than or equal to 5"
  "test_fail_less_than:FAIL: Expected 5 to be less than 5"
  "test_fail_greater_than:FAIL: Expected -2 to be greater than -1"
  "test_fail_memory:FAIL: Memory Mismatch. Byte 2 Expected 0x03 Was 0x33"
  "test_fail_memory_null:FAIL: Actual pointer was NULL"
  "test_fail_string:FAIL: Expected 'abc' Was 'ab\\n'"
  "test_fail_string_null:FAIL: Expected NULL Was 'x'"
  "test_fail_plain:FAIL"
  "test_fail_with_message:FAIL: boom"
  "test_ignore_plain:IGNORE"
  "test_ignore_with_message:IGNORE: later"
  "test_pass_counts_so_far:PASS"
)
set(expected_summary
  ""
  "-----------------------"
  "36 Tests 29 Failures 2 Ignored "
  "FAIL"
)
set(expected_status 29)

execute_process(COMMAND "${SELFTEST}"
                OUTPUT_VARIABLE output
                ERROR_VARIABLE errors
                RESULT_VARIABLE status)
message("${output}")
if(errors)
  message("stderr:\n${errors}")
endif()

set(problems "")
if(NOT status STREQUAL expected_status)
  string(APPEND problems "exit status ${status}, expected ${expected_status}\n")
endif()

# One list element per line; the output has no ';' to confuse list splitting.
string(REGEX REPLACE "\n$" "" output "${output}")
string(REPLACE "\n" ";" lines "${output}")
list(LENGTH expected_results n_results)
list(LENGTH lines n_lines)
math(EXPR n_expected "${n_results} + 4")
if(NOT n_lines EQUAL n_expected)
  string(APPEND problems "${n_lines} output lines, expected ${n_expected}\n")
endif()

set(i 0)
foreach(want IN LISTS expected_results)
  if(i LESS n_lines)
    list(GET lines ${i} line)
    if(line MATCHES "^[^:]*selftest\\.c:[1-9][0-9]*:(.*)$")
      set(got "${CMAKE_MATCH_1}")
    else()
      set(got "<no file:line: prefix> ${line}")
    endif()
    if(NOT got STREQUAL want)
      string(APPEND problems "line ${i}: got  '${got}'\n         want '${want}'\n")
    endif()
  endif()
  math(EXPR i "${i} + 1")
endforeach()
foreach(want IN LISTS expected_summary)
  if(i LESS n_lines)
    list(GET lines ${i} line)
    if(NOT line STREQUAL want)
      string(APPEND problems "line ${i}: got  '${line}'\n         want '${want}'\n")
    endif()
  endif()
  math(EXPR i "${i} + 1")
endforeach()

if(problems)
  message(FATAL_ERROR "unity_compat output differs from Unity 2.6:\n${problems}")
endif()
message(STATUS "unity_compat output and exit status match Unity 2.6 (${n_results} result lines)")
