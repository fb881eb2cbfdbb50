# SPDX-License-Identifier: GPL-3.0-or-later
# Run by CTest as `<target>_link_closure` (tests/CMakeLists.txt: validation, roomcad): fails
# when the libraries TARGET links, directly or through the modules it links, include one of
# FORBIDDEN. The closure is written at configure time (tests/CMakeLists.txt walks
# LINK_LIBRARIES and INTERFACE_LINK_LIBRARIES) to CLOSURE, one name per line.
# Usage: cmake -D CLOSURE=<file> -D TARGET=<name> -D FORBIDDEN=a,b -P <this file>
cmake_minimum_required(VERSION 3.20)
string(REPLACE "," ";" FORBIDDEN "${FORBIDDEN}")
file(STRINGS "${CLOSURE}" closure)
set(found "")
foreach(library IN LISTS FORBIDDEN)
  if(library IN_LIST closure)
    list(APPEND found ${library})
  endif()
endforeach()
if(found)
  message(FATAL_ERROR "${TARGET} links ${found} (its closure: ${closure})")
endif()
list(JOIN closure ", " names)
message(STATUS "${TARGET} links ${names}: none of ${FORBIDDEN}")
