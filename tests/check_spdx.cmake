# SPDX-License-Identifier: GPL-3.0-or-later
# Run by CTest as `spdx_headers` (tests/CMakeLists.txt): fails when a file of roomcad's own
# code does not start with its SPDX licence line (CONTRIBUTING.md, "Licence and SPDX
# headers": the first line, or the second after a script's `#!` line).
# Usage: cmake -D SOURCE_DIR=<repository> -P <this file>
cmake_minimum_required(VERSION 3.20)
set(folders bench cli core examples exact fuzz geometry import io mesh plan python render repair scripts
            testing tests validation view)
set(patterns *.h *.cpp *.sh *.py *.cmake CMakeLists.txt)
set(sources "${SOURCE_DIR}/CMakeLists.txt" "${SOURCE_DIR}/.ci/run" "${SOURCE_DIR}/.clang-format"
            "${SOURCE_DIR}/.clang-tidy")
foreach(folder IN LISTS folders)
  foreach(pattern IN LISTS patterns)
    file(GLOB_RECURSE found "${SOURCE_DIR}/${folder}/${pattern}")
    list(APPEND sources ${found})
  endforeach()
endforeach()

# The independent readers' npm packages (tests/readers/node_modules) are other people's code.
list(FILTER sources EXCLUDE REGEX "/node_modules/")

set(problems "")
list(LENGTH sources checked)
foreach(source IN LISTS sources)
  file(STRINGS "${source}" head LIMIT_COUNT 2)
  list(GET head 0 first)
  if(first MATCHES "^#!")
    list(GET head 1 first)
  endif()
  if(NOT first MATCHES "^(//|#) SPDX-License-Identifier: ")
    file(RELATIVE_PATH where "${SOURCE_DIR}" "${source}")
    string(APPEND problems "\n  ${where}")
  endif()
endforeach()
if(problems)
  message(FATAL_ERROR "files without their SPDX line (CONTRIBUTING.md):${problems}")
endif()
message(STATUS "${checked} files start with their SPDX line")
