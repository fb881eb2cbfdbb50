# SPDX-License-Identifier: GPL-3.0-or-later
# Run by CTest as `layers` (tests/CMakeLists.txt). The build already refuses a header of a
# module that is not linked (cmake/module.cmake; tests/layers/ shows it); this test states the
# layers themselves and what the compiler cannot see. It fails when
#   - a module's file includes a header of a module that is not below it (or beside it, for
#     validation and render);
#   - a file includes another module's detail/ header;
#   - a public header (a module's top-level .h) includes a detail/ header, even its own: what
#     a public header includes is public too;
#   - an include climbs out of its folder ("../"), which would reach past the include roots.
# The layers, bottom up (docs/architecture.md draws them):
#   core < exact < plan < geometry < mesh < solid < validation, render < repair, daylight < io
#   < import < view < cli
# except that plan uses no exact (its decimals are its own) and mesh no geometry or exact;
# validation and render stand side by side, neither on the solid kernel for validation, nor on
# the exact numbers for render; repair stands on validation (what to clear) and the solid
# kernel (the analytic volume that checks its claims), not on render; daylight (the sun, and the
# sunlight a plan's windows get) stands on validation (rooms, rule sets) and the solid kernel
# (the built model its rays test), beside repair. python/ sits beside view. testing/ (plans shared by tests and
# benchmarks) sits on plan; tests/, bench/ and fuzz/ may include anything.
# Usage: cmake -D SOURCE_DIR=<repository> -P <this file>
cmake_minimum_required(VERSION 3.20)
set(allowed_core "core")
set(allowed_exact "core;exact")
set(allowed_plan "core;plan")
set(allowed_geometry "core;exact;plan;geometry")
set(allowed_mesh "core;plan;mesh")
set(allowed_solid "core;exact;plan;geometry;mesh;solid")
set(allowed_validation "core;exact;plan;geometry;validation")
set(allowed_render "core;plan;geometry;mesh;render")
set(allowed_repair "core;exact;plan;geometry;mesh;solid;validation;repair")
set(allowed_daylight "core;exact;plan;geometry;mesh;solid;validation;daylight")
set(allowed_io "core;exact;plan;geometry;mesh;solid;validation;render;repair;daylight;io")
set(allowed_import "${allowed_io};import")
set(allowed_view "${allowed_import};view")
set(allowed_cli "${allowed_view};cli")
set(allowed_python "${allowed_import};python")
set(allowed_testing "core;plan;testing")
set(modules core exact plan geometry mesh solid validation render repair daylight io import view cli python testing)

set(problems "")
set(checked 0)
foreach(module IN LISTS modules)
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${module}/*.h" "${SOURCE_DIR}/${module}/*.cpp")
  file(GLOB public_headers "${SOURCE_DIR}/${module}/*.h")
  foreach(source IN LISTS sources)
    math(EXPR checked "${checked} + 1")
    file(STRINGS "${source}" includes REGEX "^#include \"")
    file(RELATIVE_PATH where "${SOURCE_DIR}" "${source}")
    foreach(line IN LISTS includes)
      if(line MATCHES "\\.\\./")
        string(APPEND problems "\n  ${where}: ${line} (climbs out of its folder)")
        continue()
      endif()
      if(NOT line MATCHES "^#include \"([a-z_]+)/([^\"]*)\"")
        continue()  # a header beside the file (a library's own layout), not a module's
      endif()
      set(target "${CMAKE_MATCH_1}")
      set(path "${CMAKE_MATCH_2}")
      if(NOT target IN_LIST modules)
        continue()  # a library's header (CGAL/..., OpenMesh/..., glm/...)
      endif()
      if(NOT target IN_LIST allowed_${module})
        string(APPEND problems "\n  ${where}: ${line} (${module} may not use ${target})")
      elseif(NOT target STREQUAL module AND path MATCHES "^detail/")
        string(APPEND problems "\n  ${where}: ${line} (${target}/detail is private to ${target})")
      elseif(source IN_LIST public_headers AND path MATCHES "^detail/")
        string(APPEND problems "\n  ${where}: ${line} (a public header exposes a detail/ one)")
      endif()
    endforeach()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "includes that reach across the layers:${problems}")
endif()
list(JOIN modules ", " names)
message(STATUS "${checked} files of ${names}: every include is of the module itself or below")
