# SPDX-License-Identifier: GPL-3.0-or-later
# roomcad_allocator: what the executables (the command, the tests, the benchmarks) link to
# allocate through jemalloc. The exact general path makes many small short-lived vectors per
# plane, from two threads, where glibc's malloc took 12-15% of a real home's build
# (bench/report.md, "the figures behind the build's choices").
# jemalloc_options.cpp keeps the pages it
# frees (see there). The libraries do not link it: a program using them (the Python module
# too) keeps its own allocator. Not with the sanitizers, which bring theirs.
option(ROOMCAD_JEMALLOC "Link the executables with jemalloc (libjemalloc-dev)" ON)
add_library(roomcad_allocator INTERFACE)
if(ROOMCAD_JEMALLOC AND NOT ROOMCAD_SANITIZE)
  pkg_check_modules(JEMALLOC REQUIRED IMPORTED_TARGET GLOBAL jemalloc)
  target_link_libraries(roomcad_allocator INTERFACE PkgConfig::JEMALLOC)
  target_sources(roomcad_allocator INTERFACE ${CMAKE_CURRENT_LIST_DIR}/jemalloc_options.cpp)
endif()
