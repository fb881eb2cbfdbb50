# SPDX-License-Identifier: GPL-3.0-or-later
# Run by CTest as `<module>_tests.label_patterns` (tests/CMakeLists.txt): fails when one of the
# gtest filter patterns that label tests `slow` or `window` matches no test of the executable,
# so that a renamed test cannot fall back to `fast` unnoticed.
# Usage: cmake -D TEST_EXE=<gtest executable> -D "PATTERNS=<pattern>;..." -P <this file>
foreach(pattern IN LISTS PATTERNS)
  execute_process(COMMAND ${TEST_EXE} --gtest_list_tests --gtest_filter=${pattern}
                  OUTPUT_VARIABLE listed RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${TEST_EXE} --gtest_list_tests failed (${status})")
  endif()
  # Test names are the indented lines of the listing; suite names are not indented.
  if(NOT listed MATCHES "\n  [^ ]")
    message(FATAL_ERROR "the label pattern '${pattern}' matches no test of ${TEST_EXE}: "
                        "rename it in tests/CMakeLists.txt")
  endif()
  message(STATUS "'${pattern}' matches tests")
endforeach()
