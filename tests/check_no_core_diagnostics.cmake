# SPDX-License-Identifier: GPL-3.0-or-later
# Run by CTest as `no_core_diagnostics` (tests/CMakeLists.txt): fails when one of the given
# executables holds CGAL CORE's diagnostics writer, which appends to `Core_Diagnostics` in
# whatever directory the program runs in (its file name is a string in the binary).
# Usage: cmake -D "FILES=<executable>;..." -P <this file>
foreach(file IN LISTS FILES)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${file} does not exist: build it first")
  endif()
  file(STRINGS "${file}" hits REGEX "Core_Diagnostics" LIMIT_COUNT 1)
  if(hits)
    message(FATAL_ERROR "${file} links CGAL's CORE diagnostics (core_error): it would write "
                        "Core_Diagnostics into the current directory on a CORE warning. Use "
                        "exact/radical.h for exact square roots instead of CORE::Expr.")
  endif()
endforeach()
list(LENGTH FILES count)
message(STATUS "none of the ${count} executables links CORE's Core_Diagnostics writer")
