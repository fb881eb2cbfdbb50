# SPDX-License-Identifier: GPL-3.0-or-later
# Sourced by scripts/test-sanitized.sh and scripts/fuzz.sh: how the sanitizers of build-san/
# report. Any report fails the run (the build has -fno-sanitize-recover=all; abort_on_error
# makes ASan's exit visible to CTest and libFuzzer alike); leaks are reported at exit.
# Third-party noise is left out in scripts/ubsan-ignorelist.txt (at compile time) and
# suppressed in scripts/lsan.supp, each entry with the reason.
roomcad_scripts=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$roomcad_scripts/lsan.supp
# SDL (roomcad view) would draw its window surface through OpenGL, i.e. Mesa's swrast_dri.so,
# which libGLX dlopens and dlcloses with the window. Memory the driver keeps from its globals
# is then unreachable, and LeakSanitizer reports it from an unloaded, so unnamed and
# unsuppressable, module (measured: 240 bytes in 3 blocks per window; with the driver
# preloaded, so never unloaded, nothing leaks). SDL's plain X11 framebuffer avoids the driver;
# roomcad's own code runs the same either way.
export SDL_FRAMEBUFFER_ACCELERATION=0
