#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Draws the 15 test surfaces of lab 4 of the Tomsk manual "Laboratory works in computer
# graphics" with `roomcad surface`.
# Usage: draw_all.sh OUT_DIR [svg|png] [extra roomcad surface options...]
# The roomcad binary is $ROOMCAD, else build/roomcad of this checkout.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="${1:?usage: draw_all.sh OUT_DIR [svg|png] [options...]}"
format="${2:-svg}"
shift $(( $# >= 2 ? 2 : 1 ))
roomcad="${ROOMCAD:-$here/../../build/roomcad}"
[[ "$format" == svg || "$format" == png ]] || { echo "draw_all.sh: format must be svg or png" >&2; exit 2; }
mkdir -p "$out"

# name | x range | z range | y = f(x, z)
surfaces=(
  "01_corner|-5:5|-1:1|abs(x) + abs(z)"
  "02_bird|-2:2|-2:0|abs(x*z)"
  "03_saddle|-2:2|-2:2|x*x - z*z"
  "04_hammock|-2:2|-2:2|x*x + z*z"
  "05_ribbon|-5:5|-2:2|z*z*z + x*z"
  "06_propeller|-2:2|-2:2|x*z*(x + z)*(x - z)"
  "07_peak|-2:2|-2:2|exp(-sqrt(x*x + z*z)) - 0.5"
  "08_wave|-2*pi:2*pi|-2*pi:2*pi|cos(sqrt(x*x + z*z))"
  "09_hump|0:pi|0:pi|sin(x)*sin(z)"
  "10_damped_wave|-2*pi:2*pi|-2*pi:2*pi|cos(sqrt(x*x + z*z))/(sqrt(x*x + z*z) + 1)"
  "11_wavy_hump|0:pi|0:pi|(sin(x) + sin(16*x)/16)*sin(z)"
  "12_damped_bumps_and_pits|-1.5*pi:1.5*pi|-pi/2:pi/2|cos(x)*cos(z)/(abs(x) + 1)"
  "13_funnel|-pi:pi|-pi:pi|-1.5*cos(1.75*(x*x + z*z))*exp(-(x*x + z*z)) + 0.2*sin(x + pi)*cos(z + pi)"
  "14_two_damped_waves|-6*pi:6*pi|-3*pi:3*pi|cos(sqrt((x + 3*pi)^2 + z*z))/(sqrt((x + 3*pi)^2 + z*z) + 1) + cos(sqrt((x - 3*pi)^2 + z*z))/(sqrt((x - 3*pi)^2 + z*z) + 1)"
  "15_bohan|-5:5|-5:5|-ln(abs(x*x*(x*x - z*z)) + 0.15)"
)

for entry in "${surfaces[@]}"; do
  IFS='|' read -r name xr zr expr <<<"$entry"
  # EXPR goes last, after --, since some start with '-'.
  "$roomcad" surface --x="$xr" --z="$zr" "$@" -o "$out/$name.$format" -- "$expr"
done
