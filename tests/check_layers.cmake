# SPDX-License-Identifier: GPL-3.0-or-later
# Run by CTest as `layers` (tests/CMakeLists.txt): fails when a module's source includes a
# header of a module above it, or another module's detail/ header. The layers, bottom up (the
# README's "Layout" says what each holds):
#   core < modeling < validation, render < io < import < view < cli
# python/ (the Python module) sits beside view, on import and below.
# validation and render are side by side: neither includes the other. testing/ (plans shared
# by tests and benchmarks) sits on modeling; tests/, bench/ and fuzz/ may include anything.
# Usage: cmake -D SOURCE_DIR=<repository> -P <this file>
cmake_minimum_required(VERSION 3.20)
set(allowed_core "core")
set(allowed_modeling "core;modeling")
set(allowed_validation "core;modeling;validation")
set(allowed_render "core;modeling;render")
set(allowed_io "core;modeling;validation;render;io")
set(allowed_import "core;modeling;validation;render;io;import")
set(allowed_view "core;modeling;validation;render;io;import;view")
set(allowed_cli "core;modeling;validation;render;io;import;view;cli")
set(allowed_python "core;modeling;validation;render;io;import;python")
set(allowed_testing "core;modeling;testing")
set(modules core modeling validation render io import view cli python testing)

set(problems "")
set(checked 0)
foreach(module IN LISTS modules)
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${module}/*.h" "${SOURCE_DIR}/${module}/*.cpp")
  foreach(source IN LISTS sources)
    math(EXPR checked "${checked} + 1")
    file(STRINGS "${source}" includes REGEX "^#include \"[a-z_]+/")
    file(RELATIVE_PATH where "${SOURCE_DIR}" "${source}")
    foreach(line IN LISTS includes)
      string(REGEX MATCH "^#include \"([a-z_]+)/([^\"]*)\"" _ "${line}")
      set(target "${CMAKE_MATCH_1}")
      set(path "${CMAKE_MATCH_2}")
      if(NOT target IN_LIST modules)
        continue()  # a library's header (CGAL/..., OpenMesh/..., glm/...)
      endif()
      if(NOT target IN_LIST allowed_${module})
        string(APPEND problems "\n  ${where}: ${line} (${module} is below ${target})")
      elseif(NOT target STREQUAL module AND path MATCHES "^detail/")
        string(APPEND problems "\n  ${where}: ${line} (${target}/detail is private to ${target})")
      endif()
    endforeach()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "includes that reach across the layers:${problems}")
endif()
list(JOIN modules ", " names)
message(STATUS "${checked} files of ${names}: every include is of the module itself or below")
