# SPDX-License-Identifier: GPL-3.0-or-later
# `cpack -G DEB` in the build folder: one package per install component of what `cmake
# --install` puts under /usr, so that the command needs none of the window's libraries:
#   roomcad          the command (runtime), recommending roomcad-view;
#   roomcad-view     the window `roomcad view` runs (window): SDL, audio, X11, Wayland;
#   roomcad-dev      the headers, libraries and CMake package (development);
#   python3-roomcad  the Python module in Debian's python3 path (python).
# Each package's Depends come from dpkg-shlibdeps (the libraries its files link), plus
# python3 and python3-numpy for the module, and roomcad for the window.
set(CPACK_PACKAGE_NAME roomcad)
set(CPACK_PACKAGE_VENDOR "roomcad")
set(CPACK_PACKAGE_CONTACT "roomcad maintainers <roomcad@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Room plans validated exactly, built as exact solids, rendered and drawn")
set(CPACK_PACKAGE_DESCRIPTION "roomcad validates room plans (JSON) with exact geometry, \
builds their 3D solids, exports meshes, renders on the CPU, draws SVG plans and edits plans; \
from the command line, from C++ (find_package(roomcad)) and from Python (import roomcad).")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <package>_0.1.0_amd64.deb
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME roomcad)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS roomcad-view)
set(CPACK_DEBIAN_WINDOW_PACKAGE_NAME roomcad-view)
set(CPACK_DEBIAN_WINDOW_PACKAGE_DEPENDS roomcad)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME roomcad-dev)
set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-roomcad)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)    # needs dpkg-shlibdeps (dpkg-dev)
if(ROOMCAD_PYTHON)  # the module is built for one minor version of Python
  math(EXPR next_minor "${Python_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
      "python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}~), python3 (<< ${Python_VERSION_MAJOR}.${next_minor}), python3-numpy")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_RECOMMENDS python3-distributed)  # roomcad.batch's engine
endif()
include(CPack)
