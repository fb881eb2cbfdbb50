# SPDX-License-Identifier: GPL-3.0-or-later
# `cmake --install build --prefix P`: the `roomcad` command in P/bin, the public headers in
# P/include/roomcad/<module>/ (the include lines of the tree, e.g. "plan/plan.h", work
# against -I P/include/roomcad), the static module libraries in P/lib/roomcad (their names,
# libcore.a, libio.a, ..., are the project's own, not for the shared lib folder), a CMake package
# (P/lib/cmake/roomcad) exporting roomcad::<module> per module and roomcad::roomcad for all.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(roomcad_modules core exact plan geometry mesh solid validation repair daylight render io import
                    view)

# Everything at once: `target_link_libraries(app PRIVATE roomcad::roomcad)`. The executable
# owns the name `roomcad` in this build, hence another target name exported as `roomcad`.
add_library(roomcad_all INTERFACE)
target_link_libraries(roomcad_all INTERFACE ${roomcad_modules})
set_target_properties(roomcad_all PROPERTIES EXPORT_NAME roomcad)

install(TARGETS roomcad RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
# The window of `roomcad view`, with its libraries (SDL, audio, X11, Wayland): its own package.
install(TARGETS roomcad-view RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT window)
install(TARGETS ${roomcad_modules} roomcad_all EXPORT roomcadTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}/roomcad COMPONENT development
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/roomcad)

# Public headers only: never detail/, nor validation/rules/ (each rule's implementation, as
# private as detail/). exact/exact_predicates.h and geometry/exact_wall_lines.h are left out
# too: they are the in-tree templates the judging modules share (over CGAL's intervals and
# exact/radical.h), not an interface for programs outside.
foreach(module IN LISTS roomcad_modules)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${module}/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/roomcad/${module} COMPONENT development
          FILES_MATCHING PATTERN "*.h"
          PATTERN "detail" EXCLUDE
          PATTERN "rules" EXCLUDE
          PATTERN "exact_wall_lines.h" EXCLUDE
          PATTERN "exact_predicates.h" EXCLUDE)
endforeach()

set(roomcad_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/roomcad)
install(EXPORT roomcadTargets NAMESPACE roomcad:: DESTINATION ${roomcad_cmake_dir}
        COMPONENT development)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/roomcadConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/roomcadConfig.cmake
                              INSTALL_DESTINATION ${roomcad_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/roomcadConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/roomcadConfig.cmake
              ${PROJECT_BINARY_DIR}/roomcadConfigVersion.cmake
        DESTINATION ${roomcad_cmake_dir} COMPONENT development)
