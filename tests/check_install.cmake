# SPDX-License-Identifier: GPL-3.0-or-later
# Run by CTest as `install` (tests/CMakeLists.txt): installs the build into a fresh prefix,
# checks what is there (the command, public headers and no detail/ header, the libraries, the
# package config), then configures and builds examples/cpp against that prefix alone and runs
# it on an example plan: what a user of `find_package(roomcad)` does.
# Usage: cmake -D BUILD_DIR=<build> -D SOURCE_DIR=<repository> -D WORK_DIR=<scratch>
#              [-D LAUNCHER=ccache] -P <this file>
cmake_minimum_required(VERSION 3.25)
set(prefix ${WORK_DIR}/prefix)
set(example_build ${WORK_DIR}/example)
file(REMOVE_RECURSE ${WORK_DIR})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "`${command}` failed (${status}):\n${out}")
  endif()
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

foreach(file bin/roomcad include/roomcad/plan/plan.h include/roomcad/core/error.h
             include/roomcad/io/plan_json.h include/roomcad/validation/validate.h
             lib/cmake/roomcad/roomcadConfig.cmake lib/cmake/roomcad/roomcadConfigVersion.cmake
             lib/cmake/roomcad/roomcadTargets.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()
foreach(module core exact plan geometry mesh solid validation render io import view)
  file(GLOB library ${prefix}/lib*/roomcad/lib${module}.a)
  if(NOT library)
    message(FATAL_ERROR "library ${module} not installed in ${prefix}/lib/roomcad")
  endif()
endforeach()
file(GLOB_RECURSE private_headers ${prefix}/include/*/detail/*)
if(private_headers)
  message(FATAL_ERROR "detail/ headers installed: ${private_headers}")
endif()
# Every installed header names only installed headers of the project.
file(GLOB_RECURSE headers RELATIVE ${prefix}/include/roomcad ${prefix}/include/roomcad/*.h)
foreach(header IN LISTS headers)
  file(STRINGS ${prefix}/include/roomcad/${header} includes REGEX "^#include \"[a-z_]+/")
  foreach(line IN LISTS includes)
    string(REGEX MATCH "^#include \"([^\"]*)\"" _ "${line}")
    if(NOT EXISTS ${prefix}/include/roomcad/${CMAKE_MATCH_1})
      message(FATAL_ERROR "${header} includes ${CMAKE_MATCH_1}, which is not installed")
    endif()
  endforeach()
endforeach()

set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/cpp -B ${example_build} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix} ${launcher})
run(${CMAKE_COMMAND} --build ${example_build})
run(${example_build}/plan_to_obj ${SOURCE_DIR}/examples/house.json ${WORK_DIR}/house.obj)
file(SIZE ${WORK_DIR}/house.obj size)
file(STRINGS ${WORK_DIR}/house.obj faces REGEX "^f ")
list(LENGTH faces face_count)
if(face_count LESS 100)
  message(FATAL_ERROR "house.obj has ${face_count} faces (${size} bytes): not the house")
endif()
# A plan with errors: exit status 1, like `roomcad build`.
file(WRITE ${WORK_DIR}/bad.json "{\"version\": 1, \"walls\": [{\"id\": \"w\", \"from\": [0, 0], \"to\": [0, 0], \"thickness\": -1, \"height\": 2.5}]}")
execute_process(COMMAND ${example_build}/plan_to_obj ${WORK_DIR}/bad.json ${WORK_DIR}/bad.obj
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
if(NOT status EQUAL 1 OR EXISTS ${WORK_DIR}/bad.obj)
  message(FATAL_ERROR "plan_to_obj on a plan with errors: exit ${status} (want 1, no file)")
endif()
message(STATUS "installed into ${prefix}; examples/cpp built against it wrote ${face_count} faces")
file(REMOVE_RECURSE ${WORK_DIR})
