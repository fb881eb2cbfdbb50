#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs, from Debian's packages, whatever roomcad needs that this machine lacks (toolchain
# included); with --tests also Chromium, its driver and Selenium (the report page's tests),
# Dask's python3-distributed (roomcad.batch), and the independent readers of the export tests
# (python3-ezdxf, Node.js, and tests/readers' npm packages web-ifc and gltf-validator at the
# versions of its package-lock.json), which the demo does not need. Idempotent and
# non-interactive: packages already installed are left alone, and nothing is fetched when
# nothing is missing. Run as root, or as a user with sudo (npm runs as the caller).
# Usage: scripts/setup.sh [--tests] [EXTRA_PACKAGE...]   (e.g. the sanitized build's clang)
set -euo pipefail
tests=false
if [[ "${1:-}" == --tests ]]; then tests=true; shift; fi

packages=(
  # toolchain
  g++ make cmake pkg-config
  # geometry, meshes, maths
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libopenmesh-dev libglm-dev libeigen3-dev
  # formats, command line, threads, allocation, images, windows, archives
  nlohmann-json3-dev libsimdjson-dev libcli11-dev libfmt-dev libpng-dev libtbb-dev libjemalloc-dev libsdl2-dev
  libzip-dev libpugixml-dev
  # the sun's position (ERFA: the IAU's SOFA astronomy routines)
  liberfa-dev
  # the Python module (python/) and its tests; dpkg-dev and file: `cpack -G DEB` reads Depends
  # with dpkg-shlibdeps, on the files that `file` says are executables and libraries
  python3-dev python3-pybind11 python3-numpy python3-pytest dpkg-dev file
  # tests and benchmarks (Xvfb: a screen for the window tests of `roomcad view`; gnuplot draws
  # bench/report.sh's plots; admesh: an independent STL reader for the export tests; strace:
  # the durable-save tests watch the flushes and renames and inject their failures)
  libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth gnuplot-nox admesh strace
  # the `format` test checks the tree against .clang-format with Debian 12's clang-format
  clang-format-14
  "$@"
)
if $tests; then
  # the independent readers of the IFC, glTF and DXF export tests: ezdxf reads the DXF,
  # Node.js runs web-ifc and the Khronos glTF validator (tests/readers); Node.js from Debian
  # unless a node and npm are already on the PATH (a newer one, e.g. nvm's)
  packages+=(python3-ezdxf)
  # the report page's tests open it in a real browser: Chromium driven by Selenium
  packages+=(chromium chromium-driver python3-selenium)
  # the sun tests' independent reader of sun positions
  packages+=(python3-ephem)
  # roomcad.batch's engine (docs/batch.md) and its tests: Dask's distributed scheduler
  packages+=(python3-distributed)
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then packages+=(nodejs npm); fi
fi

# The npm readers (with --tests), when tests/readers/node_modules does not hold its lock
# file's versions.
install_readers() {
  $tests || return 0
  local readers
  readers="$(dirname "$0")/../tests/readers"
  if ! cmp -s <(sed -n '/"node_modules\//,$p' "$readers/package-lock.json") \
              <(sed -n '/"node_modules\//,$p' "$readers/node_modules/.package-lock.json" 2>/dev/null); then
    echo "setup: installing the test readers (npm ci in tests/readers)"
    npm ci --prefix "$readers" --no-audit --no-fund --loglevel=error
  fi
}

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  install_readers
  exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 2; }
  sudo=(sudo)
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_readers
