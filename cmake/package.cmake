# SPDX-License-Identifier: GPL-3.0-or-later
# `cpack -G DEB` in the build folder: roomcad_<version>_<arch>.deb holding what `cmake
# --install` installs under /usr (the command, the Python module in Debian's python3 path, the
# headers, libraries and CMake package). Its Depends come from dpkg-shlibdeps (the runtime
# libraries the command and the Python module link) plus python3 and python3-numpy.
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
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # roomcad_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)    # needs dpkg-shlibdeps (dpkg-dev)
if(ROOMCAD_PYTHON)  # the module is built for one minor version of Python
  math(EXPR next_minor "${Python_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}~), python3 (<< ${Python_VERSION_MAJOR}.${next_minor}), python3-numpy")
endif()
include(CPack)
