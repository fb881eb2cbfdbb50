# SPDX-License-Identifier: GPL-3.0-or-later
# Run by CTest as `package` (tests/CMakeLists.txt): `cpack -G DEB` of the build into a scratch
# folder, then checks the packages: roomcad holds the command and depends on none of the
# window's libraries (SDL, PulseAudio, ALSA, X11, Wayland), recommending roomcad-view, which
# holds the window and depends on SDL and roomcad.
# Usage: cmake -D BUILD_DIR=<build> -D WORK_DIR=<scratch> -P <this file>
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})

function(run out)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE text ERROR_VARIABLE text)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "`${command}` failed (${status}):\n${text}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

run(ignored cpack -G DEB --config ${BUILD_DIR}/CPackConfig.cmake -B ${WORK_DIR})
file(GLOB command_deb ${WORK_DIR}/roomcad_*.deb)
file(GLOB window_deb ${WORK_DIR}/roomcad-view_*.deb)
if(NOT command_deb OR NOT window_deb)
  message(FATAL_ERROR "cpack made no roomcad and roomcad-view packages in ${WORK_DIR}")
endif()

run(depends dpkg-deb -f ${command_deb} Depends)
run(recommends dpkg-deb -f ${command_deb} Recommends)
run(contents dpkg-deb -c ${command_deb})
set(window_libraries "libsdl2|libpulse|libasound|libx11|libxcb|libwayland|libdecor|libdbus")
if(depends MATCHES "(${window_libraries})")
  message(FATAL_ERROR "roomcad depends on a window library (${CMAKE_MATCH_1}): ${depends}")
endif()
if(NOT recommends MATCHES "roomcad-view")
  message(FATAL_ERROR "roomcad does not recommend roomcad-view: '${recommends}'")
endif()
if(NOT contents MATCHES "/usr/bin/roomcad\n" OR contents MATCHES "roomcad-view")
  message(FATAL_ERROR "roomcad should hold /usr/bin/roomcad and not the window:\n${contents}")
endif()

run(window_depends dpkg-deb -f ${window_deb} Depends)
if(NOT window_depends MATCHES "libsdl2" OR NOT window_depends MATCHES "(^|, )roomcad(,|$| )")
  message(FATAL_ERROR "roomcad-view should depend on SDL and roomcad: ${window_depends}")
endif()
message(STATUS "roomcad depends on ${depends}")
