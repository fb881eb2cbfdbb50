# SPDX-License-Identifier: GPL-3.0-or-later
# roomcad_module(name): the static library of the top-level folder <name>, from every .cpp under
# it, with the include roots that make the layers a property of the build.
#
# Every module includes headers as "<module>/<header>.h". A module sees:
#   - its own folder whole, detail/ included (a private include root: <build>/include-private/
#     <name>/<name> links to the folder);
#   - of every module it links, only the top-level headers (a public include root:
#     <build>/include/<name>/<name>/ holds a link per top-level header, never detail/).
# So a header of a module that is not linked, or another module's detail/ header, is "No such
# file or directory" at compile time (tests/layers/ shows it). The project root is on no
# module's include path.
#
# Cost: one symbolic link per public header, made at configure time.

# roomcad_include_roots(target folder): gives `target` the public root of `folder` (PUBLIC, so
# whoever links target sees it) and its private root.
function(roomcad_include_roots target folder)
  set(public_root ${PROJECT_BINARY_DIR}/include/${folder})
  set(private_root ${PROJECT_BINARY_DIR}/include-private/${folder})
  # Only the public root is cleared (a header may have been removed): it holds links to files.
  # The private root's one link points at a source folder, which must never be recursed into.
  file(REMOVE_RECURSE ${public_root})
  file(MAKE_DIRECTORY ${public_root}/${folder} ${private_root})
  file(GLOB headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.h)
  foreach(header IN LISTS headers)
    get_filename_component(name ${header} NAME)
    file(CREATE_LINK ${header} ${public_root}/${folder}/${name} SYMBOLIC)
  endforeach()
  if(NOT IS_SYMLINK ${private_root}/${folder})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${private_root}/${folder} SYMBOLIC)
  endif()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    target_include_directories(${target} INTERFACE $<BUILD_INTERFACE:${public_root}>
                                                   $<INSTALL_INTERFACE:include/roomcad>)
  else()
    target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${public_root}>
                                                $<INSTALL_INTERFACE:include/roomcad>
                                         PRIVATE ${private_root})
  endif()
endfunction()

# roomcad_module(name [EXCLUDE file...]): add_library(name STATIC <every .cpp under name/ but
# the EXCLUDE files, relative to name/>) with its include roots.
function(roomcad_module name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "EXCLUDE")
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${name}/*.cpp)
  foreach(file IN LISTS arg_EXCLUDE)
    list(REMOVE_ITEM sources ${PROJECT_SOURCE_DIR}/${name}/${file})
  endforeach()
  add_library(${name} STATIC ${sources})
  roomcad_include_roots(${name} ${name})
endfunction()
