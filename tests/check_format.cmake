# SPDX-License-Identifier: GPL-3.0-or-later
# Run by CTest as `format` (tests/CMakeLists.txt): fails when a C++ file of the tree is not as
# clang-format (the .clang-format at the root) would write it, listing the files. Format a file
# with `clang-format -i FILE`.
# Usage: cmake -D SOURCE_DIR=<repository> -D CLANG_FORMAT=<clang-format> -P <this file>
cmake_minimum_required(VERSION 3.20)
set(folders core exact plan geometry mesh solid validation render io import view cli python
            testing tests bench fuzz examples/cpp cmake)
set(files "")
foreach(folder IN LISTS folders)
  file(GLOB_RECURSE found "${SOURCE_DIR}/${folder}/*.h" "${SOURCE_DIR}/${folder}/*.cpp")
  list(FILTER found EXCLUDE REGEX "/node_modules/")
  list(APPEND files ${found})
endforeach()
list(LENGTH files count)
if(count LESS 100)
  message(FATAL_ERROR "found only ${count} C++ files under ${SOURCE_DIR}: wrong SOURCE_DIR?")
endif()
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror --style=file ${files}
                WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE failed ERROR_VARIABLE diagnostics)
if(failed)
  string(REGEX MATCHALL "[^\n]*: error: code should be clang-formatted" lines "${diagnostics}")
  set(unformatted "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE ":[0-9]+:[0-9]+: error: code should be clang-formatted" "" file "${line}")
    list(APPEND unformatted "${file}")
  endforeach()
  list(REMOVE_DUPLICATES unformatted)
  list(JOIN unformatted "\n  " names)
  message(FATAL_ERROR "not formatted as .clang-format says (clang-format -i FILE):\n  ${names}")
endif()
message(STATUS "${count} C++ files formatted as .clang-format says")
