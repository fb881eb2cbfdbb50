#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# One command for the evidence report: builds the benchmark drivers, runs them side by side in
# one run (so their ratios hold on a noisy machine) and writes bench/report.md, with its CSV
# files and gnuplot PNG plots in bench/report/. Prints and records its own run time.
# Usage: bench/report.sh [--quick]   (--quick: smaller scenes, for a smoke run)
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
quick=${1:-}
bash scripts/setup.sh >/dev/null
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target validate_bench build_bench render_bench depth_format_bench kernel_bench \
  skipping_bench homes_bench >/dev/null
out=bench/report
mkdir -p "$out"

# Least-squares slope of log(y) against log(x) over the CSV rows (columns x_col, y_col; header
# skipped; rows with x or y <= 0 left out): the growth exponent, time ~ size^k.
fit_exponent() {
  awk -F, -v xc="$2" -v yc="$3" 'NR > 1 && $xc > 0 && $yc > 0 {
      x = log($xc); y = log($yc); n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
    END { if (n < 2) print "n/a"; else printf "%.2f\n", (n * sxy - sx * sy) / (n * sxx - sx * sx) }' "$1"
}

# A markdown table row per CSV row (header included).
csv_to_markdown() {
  awk -F, 'NR == 1 { row = "|"; sep = "|"; for (i = 1; i <= NF; i++) { row = row " " $i " |"; sep = sep " --- |" }
                     print row; print sep; next }
           { row = "|"; for (i = 1; i <= NF; i++) row = row " " $i " |"; print row }' "$1"
}

# plot CSV PNG TITLE XLABEL YLABEL LOGSCALE(xy|x|"") then "col:title" pairs (x is column 1).
plot() {
  local csv=$1 png=$2 title=$3 xlabel=$4 ylabel=$5 logscale=$6
  shift 6
  local series=()
  for s in "$@"; do series+=("'$csv' using 1:${s%%:*} with linespoints lw 2 title '${s#*:}'"); done
  local joined
  joined=$(IFS=,; echo "${series[*]}")
  gnuplot <<GNUPLOT
set terminal pngcairo size 800,500 noenhanced
set output '$png'
set datafile separator ','
set key autotitle columnhead
set key top left
set grid
set title '$title'
set xlabel '$xlabel'
set ylabel '$ylabel'
${logscale:+set logscale $logscale}
set format y '%g'
set format x '%g'
plot $joined
GNUPLOT
}

# The gnuplot lines every clustered bar chart starts with: bar_plot_preamble PNG WIDTH.
bar_plot_preamble() {
  cat <<GNUPLOT
set terminal pngcairo size $2,500 noenhanced
set output '$1'
set datafile separator ','
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set grid ytics
set key top left
GNUPLOT
}

section_validate() {
  # validate_bench: | grid | walls | openings | wall ms | cpu ms | critical | no rooms wall | cpu | errors |
  # (then the rules' tables, of other columns): the rows of that first table, the last run of
  # each size, by walls.
  build/bench/validate_bench $quick |
    awk -F'|' '$2 ~ /^ [0-9]+ x [0-9]+ $/ && NF == 11 {
        for (i = 2; i <= 10; i++) gsub(/ /, "", $i); row[$3] = $3 "," $4 "," $5 "," $6 "," $8 }
      END { print "walls,openings,wall_ms,cpu_ms,no_rooms_ms"; for (w in row) print row[w] | "sort -t, -k1,1n" }' \
    >"$out/validate_scaling.csv"
  plot "$out/validate_scaling.csv" "$out/validate_scaling.png" "validate: time against walls" \
    walls ms xy 3:"wall-clock ms" 5:"no room warnings ms"
}

section_homes() {
  # homes_bench: the bundled Sweet Home 3D homes and the generated tower on every path in one
  # run (its --csv columns: walls, slabs, the share of walls per path, the five times, the
  # volume difference against the analytic volume and, for the walls alone, against Nef).
  build/bench/homes_bench --csv "$out/homes.csv" >/dev/null 2>&1
}

section_build() {
  # The per-wall fast path on and off: roomcad's fast path against its CGAL path, plain Nef and
  # OpenSCAD on small grids (bench/modeling_report.sh's CSV and table; volume errors included).
  bash bench/modeling_report.sh build "$out/build_paths" --max-n 10 --cgal-max-n 5 --openscad-max-n 5 \
    >/dev/null 2>&1
  # Column 2 is walls: the x axis.
  cut -d, -f2- "$out/build_paths.csv" >"$out/build_paths_by_walls.csv"
  plot "$out/build_paths_by_walls.csv" "$out/build_paths.png" \
    "build: fast path, CGAL path, plain Nef and OpenSCAD against walls" walls ms xy \
    3:"fast path ms" 4:"CGAL path ms" 5:"plain Nef ms" 6:"OpenSCAD ms"
}

section_render() {
  local filter='BM_Frame1080p/(2|10|25|50)/[01]/2/'
  [[ $quick == --quick ]] && filter='BM_Frame1080p/(2|10)/[01]/2/'
  # Separate runs: Google Benchmark's CSV header names the first benchmark's counters only.
  build/bench/render_bench --benchmark_filter="$filter" --benchmark_format=csv 2>/dev/null \
    >"$out/render_frames_raw.csv"
  build/bench/render_bench --benchmark_filter=BM_ShadowResolutionError --benchmark_format=csv \
    2>/dev/null >"$out/shadow_resolution_raw.csv"
  # Columns by name: the counters come after Google Benchmark's own.
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { gsub(/"/, "", $i); c[$i] = i }
                     print "triangles,no_shadows_ms,pcf_ms"; next }
           { split($1, a, "/"); t[a[2]] = $c["triangles"]; ms[a[2], a[3]] = $c["real_time"]; n[a[2]] = 1 }
           END { for (k in n) print t[k] "," ms[k, 0] "," ms[k, 1] }' "$out/render_frames_raw.csv" |
    sort -t, -k1,1n >"$out/render_scaling.csv"
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { gsub(/"/, "", $i); c[$i] = i }
                     print "resolution,hard_error_pct,pcf_error_pct,texel_cm,hard_shadow_ms,pcf_shadow_ms"; next }
           { split($1, a, "/"); r[a[2]] = 1; e[a[2], a[3]] = $c["error_pct"]; t[a[2], a[3]] = $c["shadow_ms"]
             texel[a[2]] = $c["texel_cm"] }
           END { for (k in r) print k "," e[k, 0] "," e[k, 1] "," texel[k] "," t[k, 0] "," t[k, 1] }' \
    "$out/shadow_resolution_raw.csv" | sort -t, -k1,1n >"$out/shadow_resolution.csv"
  plot "$out/render_scaling.csv" "$out/render_scaling.png" "render at 1920x1080, 2 threads: frame time against triangles" \
    triangles ms xy 2:"no shadows" 3:"PCF shadows"
  plot "$out/shadow_resolution.csv" "$out/shadow_resolution.png" "shadows: floor pixels wrong vs ray-traced, against map resolution" \
    "texels per side" "% of floor pixels wrong / shadow pass ms" xy 2:"hard: error %" 3:"PCF: error %" \
    5:"hard: shadow ms" 6:"PCF: shadow ms"
}

section_depth() {
  build/bench/depth_format_bench >"$out/depth_formats.csv"
  # Pivoted for the plot: a row per distance, a column per format.
  awk -F, 'NR > 1 { if (!($1 in seen)) { seen[$1] = 1; names[++n] = $1 }
                    if (!($2 in dseen)) { dseen[$2] = 1; ds[++m] = $2 } step[$1, $2] = $3 }
           END { row = "distance_m"; for (i = 1; i <= n; i++) row = row "," names[i]; print row
                 for (j = 1; j <= m; j++) { row = ds[j]; for (i = 1; i <= n; i++) row = row "," step[names[i], ds[j]]; print row } }' \
    "$out/depth_formats.csv" >"$out/depth_formats_by_distance.csv"
  plot "$out/depth_formats_by_distance.csv" "$out/depth_formats.png" \
    "depth step (error) against distance, near plane 0.05 m, infinite far" "distance (m)" "depth step (m)" xy \
    2:"float32 reversed-Z (roomcad)" 3:"float32 standard Z" 4:"fixed 24-bit standard Z" 5:"fixed 16-bit standard Z" 6:"float32 linear distance"
}

section_antialiasing() {
  build/bench/render_bench --benchmark_filter=BM_AntiAliasingError --benchmark_format=csv \
    2>/dev/null >"$out/antialiasing_raw.csv"
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { gsub(/"/, "", $i); c[$i] = i }
                     print "ssaa,mean_error_levels,pixels_off_pct,frame_ms"; next }
           { split($1, a, "/"); print a[2] "," $c["mean_error_levels"] "," $c["pixels_off_pct"] "," $c["frame_ms"] }' \
    "$out/antialiasing_raw.csv" >"$out/antialiasing.csv"
  plot "$out/antialiasing.csv" "$out/antialiasing.png" \
    "anti-aliasing: error against a 64-sample reference, and frame time (400 x 300)" \
    "samples per pixel side (ssaa)" "error / ms" xy 2:"mean error (0-255 levels)" 3:"% pixels off by > 8 levels" 4:"frame ms"
}

section_kernels() {
  build/bench/kernel_bench >"$out/kernels.csv"
  # Pivoted: a row per kernel, time on both sets and wrong signs on the hard one.
  awk -F, 'NR > 1 { if (!($1 in seen)) { seen[$1] = 1; k[++n] = $1 }
                    if ($2 ~ /random/) easy[$1] = $4; else { hard[$1] = $4; wrong[$1] = $5 } }
           END { print "kernel,random_ns,nearly_collinear_ns,nearly_collinear_wrong_pct"
                 for (i = 1; i <= n; i++) print k[i] "," easy[k[i]] "," hard[k[i]] "," wrong[k[i]] }' \
    "$out/kernels.csv" >"$out/kernels_by_kernel.csv"
  gnuplot <<GNUPLOT
$(bar_plot_preamble "$out/kernels.png" 800)
set logscale y
set format y '%g'
set yrange [0.1:*]
set title 'orientation predicate: ns per test (bars) and % wrong signs on nearly collinear points'
set ylabel 'ns per test / % wrong'
plot '$out/kernels_by_kernel.csv' using 2:xtic(1) title 'ns, random at 1e6 m', \
     '' using 3 title 'ns, nearly collinear', '' using 4 title '% wrong, nearly collinear'
GNUPLOT
}

section_skipping() {
  build/bench/skipping_bench --benchmark_format=csv 2>/dev/null >"$out/skipping_raw.csv"
  # A row per view and switch setting (name BM_Skipping/view/cull/frustum, label the view).
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { gsub(/"/, "", $i); c[$i] = i }
                     print "view,cull,frustum_cull,frame_ms,triangles,screen_triangles,prepass_skipped,cells_visited,drawn_triangles"; next }
           /BM_Skipping/ { split($1, a, "/"); gsub(/"/, "", $c["label"])
             printf "%s,%s,%s,%.2f,%d,%d,%d,%d,%d\n", $c["label"], (a[3] == 0 ? "none" : a[3] == 1 ? "back" : a[3] == 2 ? "portals" : "visibility"),
                    (a[4] == 1 ? "on" : "off"), $c["real_time"], $c["triangles"], $c["screen_triangles"], $c["prepass_skipped"],
                    $c["cells_visited"], $c["drawn_triangles"] }' \
    "$out/skipping_raw.csv" >"$out/skipping.csv"
  # The same eye inside models of every size (name BM_Inside/view/cull/shadows).
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { gsub(/"/, "", $i); c[$i] = i }
                     print "view,cull,shadows,frame_ms,triangles,screen_triangles,cells_visited,drawn_triangles"; next }
           /BM_Inside/ { split($1, a, "/"); gsub(/"/, "", $c["label"])
             printf "%s,%s,%s,%.2f,%d,%d,%d,%d\n", $c["label"], (a[3] == 1 ? "back" : a[3] == 2 ? "portals" : "visibility"),
                    (a[4] == 1 ? "pcf (kept)" : "off"), $c["real_time"], $c["triangles"], $c["screen_triangles"],
                    $c["cells_visited"], $c["drawn_triangles"] }' \
    "$out/skipping_raw.csv" >"$out/inside.csv"
  # Pivoted for the bars: a row per view, a column per setting.
  awk -F, 'NR > 1 { if (!($1 in seen)) { seen[$1] = 1; v[++n] = $1 } ms[$1, $2 "/" $3] = $4 }
           END { split("none/off none/on back/off back/on portals/off portals/on visibility/off visibility/on", k, " ")
                 row = "view"; for (j = 1; j <= 8; j++) { split(k[j], f, "/"); row = row ",faces " f[1] " + frustum " f[2] }; print row
                 for (i = 1; i <= n; i++) { row = v[i]; for (j = 1; j <= 8; j++) row = row "," ms[v[i], k[j]]; print row } }' \
    "$out/skipping.csv" >"$out/skipping_by_view.csv"
  gnuplot <<GNUPLOT
$(bar_plot_preamble "$out/skipping.png" 1000)
set key outside below maxrows 2
set logscale y
set format y '%g'
set yrange [5:*]
set title 'what skipping saves: frame ms at 1920x1080, 2 threads, no shadows, per culling setting'
set ylabel 'frame ms (log scale)'
plot for [i=2:9] '$out/skipping_by_view.csv' using i:xtic(1) title columnhead(i)
GNUPLOT
}

section_validate
section_homes
section_build
section_render
section_antialiasing
section_depth
section_kernels
section_skipping
seconds=$((SECONDS - start))

# The hand-written sections (measurements of single changes, CI times) from the marker on.
marker='<!-- Hand-written sections: bench/report.sh keeps everything from this line on. -->'
kept=$(awk -v m="$marker" 'found || $0 == m { found = 1; print }' bench/report.md 2>/dev/null || true)
[[ -n "$kept" ]] || kept=$marker
{
  echo "# roomcad evidence report: run time against size and error"
  echo
  echo "Written by \`bench/report.sh${quick:+ $quick}\` on $(date -u +%Y-%m-%d) ($(nproc) cores, $(uname -m));"
  echo "the whole run took ${seconds} s. Every table is a CSV beside its plot in \`bench/report/\`."
  echo "Times are wall-clock milliseconds on a machine shared with other work: compare within a table."
  echo
  echo "## Validation against scene size"
  echo "Grids of rooms (a door in every inner wall, three windows in every outer one)."
  echo "Fitted growth exponent (least squares on log-log, time ~ walls^k): k = $(fit_exponent "$out/validate_scaling.csv" 1 3) with room warnings,"
  echo "k = $(fit_exponent "$out/validate_scaling.csv" 1 5) without."
  echo
  csv_to_markdown "$out/validate_scaling.csv"
  echo
  echo "![validate scaling](report/validate_scaling.png)"
  echo
  echo "## Real homes: every path against Nef"
  echo "The Sweet Home 3D homes of examples/sweethome3d/ (imported as version 2 plans, built as"
  echo "\`--force\` builds them) and a generated 504-wall tower of six storeys on their floors"
  echo "(testing/tower_plan.h), the solid of walls and slabs at 2 threads (\`build/bench/homes_bench\`):"
  echo "the share of walls each path took in the automatic build (fast, general, Nef; an arc wall"
  echo "counts as its chords), its time (\`auto_ms\`), the same with every plane of the general path"
  echo "through its 2D boolean (\`boolean_ms\`: none on the grid of its lines), every wall on the"
  echo "general path and on CGAL Nef, \`before_ms\` the fast path with Nef for the rest (the automatic"
  echo "build before the general path); Nef builds the walls alone and refuses sloped tops and shaped"
  echo "openings (nan). The automatic solid's volume against the analytic one, and its walls' against"
  echo "Nef's (-1: refused), relative."
  echo
  csv_to_markdown "$out/homes.csv"
  echo
  echo "## Build: fast path against CGAL path and OpenSCAD"
  echo "The per-wall fast path on and off: N x N grids of rooms built and written as OFF by the fast"
  echo "path and, with it off, by the CGAL path (\`--boolean cgal\`); beside them plain CGAL Nef and"
  echo "Debian's OpenSCAD (grids up to 5 x 5), with each solid's volume error against the analytic"
  echo "volume and the fast path's OFF size (\`bench/modeling_report.sh\`, columns described there)."
  echo "Growth exponent of the fast path: k = $(fit_exponent "$out/build_paths.csv" 2 4); of the CGAL path: k = $(fit_exponent "$out/build_paths.csv" 2 5)."
  echo
  cat "$out/build_paths.md"
  echo
  echo "![build paths](report/build_paths.png)"
  echo
  echo "## Render against scene size"
  echo "1920 x 1080, 2 threads, grids of rooms as meshes. Growth exponent against triangles:"
  echo "k = $(fit_exponent "$out/render_scaling.csv" 1 2) without shadows, k = $(fit_exponent "$out/render_scaling.csv" 1 3) with PCF shadows."
  echo
  csv_to_markdown "$out/render_scaling.csv"
  echo
  echo "![render scaling](report/render_scaling.png)"
  echo
  echo "## Shadow-map resolution and PCF against shadow error"
  echo "Hard and PCF shadows on the floor of 3 x 3 rooms seen from above (800 x 800) against ray-traced"
  echo "shadows (CGAL AABB tree): share of floor pixels classified differently (shadowed: darker than"
  echo "half the floor colour), and the shadow pass time."
  echo
  csv_to_markdown "$out/shadow_resolution.csv"
  echo
  echo "![shadow resolution](report/shadow_resolution.png)"
  echo
  echo "## Anti-aliasing level against edge error and time"
  echo "3 x 3 rooms from the default camera, 400 x 300, Phong with PCF shadows, at ssaa 1, 2 and 4,"
  echo "against the same frame rendered at 1600 x 1200 with ssaa 4 and box-filtered (64 samples a pixel)."
  echo
  csv_to_markdown "$out/antialiasing.csv"
  echo
  echo "![anti-aliasing](report/antialiasing.png)"
  echo
  echo "## Depth formats against depth error"
  echo "The step between neighbouring stored depths at 1 m, 100 m and 1 km (metres) for the perspective"
  echo "camera's near plane (0.05 m) and infinite far plane: surfaces closer than a step can tie or swap."
  echo "Computed from the formats' encodings (bench/depth_format_bench.cpp), not timed: roomcad stores"
  echo "reversed-Z float (tests/render/depth_test.cpp checks 1 mm apart at 1 km in real frames)."
  echo
  csv_to_markdown "$out/depth_formats.csv"
  echo
  echo "![depth formats](report/depth_formats.png)"
  echo
  echo "## Exact against filtered kernels"
  echo "The orientation predicate behind validation's verdicts (touching, crossing, inside), on random"
  echo "triples 1e6 m away and on nearly collinear ones (Kettner et al.'s classroom example: a point a"
  echo "few ulps off (0.5, 0.5), and (12, 12), (24, 24)): plain doubles, CGAL's filtered exact"
  echo "predicates (Epick, what roomcad uses) and unfiltered exact rationals; wrong signs against exact."
  echo "A wrong sign is what turns touching into overlapping. (A 0 % bar is not drawn on the log axis.)"
  echo
  csv_to_markdown "$out/kernels.csv"
  echo
  echo "![kernels](report/kernels.png)"
  echo
  echo "## What skipping saves"
  echo "Each culling switch on and off (\`roomcad render --cull none|back|portals|visibility --frustum-cull on|off\`),"
  echo "1920 x 1080, 2 threads, shadows off (the switches touch only the colour pass): the 10 x 10 grid"
  echo "of rooms and examples/house.json, from outside (grid: default iso view; house: its first camera)"
  echo "and from inside a room at eye height. The pictures are byte-identical whatever the switches"
  echo "(tests/cli/cull_test.cpp). \`screen_triangles\`: triangles left after culling and clipping"
  echo "(frustum culling only skips work clipping would discard, so it changes the time, not this count);"
  echo "\`prepass_skipped\`: triangles the visibility pre-pass found hidden; \`cells_visited\` and"
  echo "\`drawn_triangles\`: the cells the portal walk reached and the triangles it submitted (tests:"
  echo "tests/render/portal_walk_test.cpp)."
  echo
  csv_to_markdown "$out/skipping.csv"
  echo
  echo "![what skipping saves](report/skipping.png)"
  echo
  echo "### The same eye inside models of every size"
  echo "One eye inside a room (the grids: \`--eye 2,2,1.6 --target 3.5,3,1.5\`; the others: the largest"
  echo "room the walk can start from, looking east), 1920 x 1080, 2 threads, shadows off and on (the"
  echo "maps kept between frames, as the window keeps them): the 10 x 10 and 70 x 70 grids,"
  echo "examples/house.json (one storey), the six-storey tower and arif-putra-pertama-1."
  echo
  csv_to_markdown "$out/inside.csv"
  echo
  echo "The per-wall fast path on and off is the fast path against the CGAL path in the build section."
  echo
  printf '%s\n' "$kept"
} >bench/report.md.new
mv bench/report.md.new bench/report.md
echo "bench/report.sh: wrote bench/report.md and bench/report/ in ${seconds} s"
