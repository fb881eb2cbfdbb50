#!/usr/bin/env bash
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
  >/dev/null
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

section_validate() {
  # validate_bench: | grid | walls | openings | wall ms | cpu ms | critical | no rooms wall | cpu | errors |
  build/bench/validate_bench $quick |
    awk -F'|' 'NR == 1 { print "walls,openings,wall_ms,cpu_ms,no_rooms_ms"; next } NR > 2 {
        for (i = 2; i <= 9; i++) gsub(/ /, "", $i); print $3 "," $4 "," $5 "," $6 "," $8 }' \
    >"$out/validate_scaling.csv"
  plot "$out/validate_scaling.csv" "$out/validate_scaling.png" "validate: time against walls" \
    walls ms xy 3:"wall-clock ms" 5:"no room warnings ms"
}

# The face count an OFF file declares ("OFF v f e" on one line, or "OFF" then "v f e").
off_face_count() {
  awk 'NR == 1 && NF >= 3 { print $3; exit } NR == 2 { print $2; exit }' "$1"
}

section_build() {
  local max_n=20 cgal_max_n=5
  [[ $quick == --quick ]] && max_n=10 && cgal_max_n=2
  # build_bench: | grid | walls | openings | fast ms | faces | triangles | OFF bytes | CGAL ms |
  #              CGAL triangles | CGAL / fast | valid |
  build/bench/build_bench --max-n "$max_n" --cgal-max-n "$cgal_max_n" --runs 3 |
    awk -F'|' 'NR == 1 { print "walls,fast_ms,fast_triangles,fast_off_bytes,cgal_ms,cgal_triangles,valid"; next }
      NR > 2 { for (i = 2; i <= 12; i++) gsub(/ /, "", $i); c = $9 == "-" ? "" : $9; t = $10 == "-" ? "" : $10
               print $3 "," $5 "," $7 "," $8 "," c "," t "," $12 }' >"$out/build_paths.csv"
  # OpenSCAD on the small grids only (its CGAL Nef union grows fast): time, triangles, bytes.
  local tmp
  tmp=$(mktemp -d)
  echo "walls,openscad_ms,openscad_faces,openscad_off_bytes" >"$tmp/openscad.csv"
  if command -v openscad >/dev/null; then
    for n in 1 2; do
      build/bench/build_bench --scad "$n" "$tmp/grid.scad"
      local t0 t1
      t0=$(date +%s%N)
      if timeout 120 openscad -o "$tmp/out.off" "$tmp/grid.scad" >/dev/null 2>&1; then
        t1=$(date +%s%N)
        echo "$((2 * n * (n + 1))),$(((t1 - t0) / 1000000)),$(off_face_count "$tmp/out.off"),$(stat -c %s "$tmp/out.off")" \
          >>"$tmp/openscad.csv"
      fi
    done
  fi
  awk -F, 'FNR == NR { if (FNR > 1) o[$1] = $2 "," $3 "," $4; next }
           FNR == 1 { print $0 ",openscad_ms,openscad_faces,openscad_off_bytes"; next }
           { print $0 "," ($1 in o ? o[$1] : ",,") }' "$tmp/openscad.csv" "$out/build_paths.csv" \
    >"$tmp/joined.csv"
  mv "$tmp/joined.csv" "$out/build_paths.csv"
  rm -rf "$tmp"
  plot "$out/build_paths.csv" "$out/build_paths.png" "build: fast path, CGAL path and OpenSCAD against walls" \
    walls ms xy 2:"fast path ms" 5:"CGAL path ms" 8:"OpenSCAD ms"
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
set terminal pngcairo size 800,500 noenhanced
set output '$out/kernels.png'
set datafile separator ','
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set logscale y
set format y '%g'
set yrange [0.1:*]
set grid ytics
set key top left
set title 'orientation predicate: ns per test (bars) and % wrong signs on nearly collinear points'
set ylabel 'ns per test / % wrong'
plot '$out/kernels_by_kernel.csv' using 2:xtic(1) title 'ns, random at 1e6 m', \
     '' using 3 title 'ns, nearly collinear', '' using 4 title '% wrong, nearly collinear'
GNUPLOT
}

section_validate
section_build
section_render
section_antialiasing
section_depth
section_kernels
seconds=$((SECONDS - start))

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
  echo "## Build: fast path against CGAL path"
  echo "The same grids built and written as OFF: the per-wall exact fast path, and CGAL's Nef"
  echo "polyhedra (\`--boolean cgal\`); \`valid\`: both solids closed, manifold, without self-intersection,"
  echo "with the analytic volume to 1e-9 (so the volume error of both is below 1e-9 relative)."
  echo "Growth exponent of the fast path: k = $(fit_exponent "$out/build_paths.csv" 1 2); of the CGAL path: k = $(fit_exponent "$out/build_paths.csv" 1 5)."
  echo "OpenSCAD (Debian's, on the same grids written as .scad, openings a hair wider than the wall as"
  echo "OpenSCAD models are written) runs on the two smallest grids only (faces: the polygons of its OFF)."
  echo
  csv_to_markdown "$out/build_paths.csv"
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
  echo "## Not measured yet"
  echo "Culling on/off (back-face, frustum,"
  echo "visibility) and OpenSCAD's volume error are not in this report yet; the per-wall fast path on/off is the"
  echo "fast path against CGAL path table above."
} >bench/report.md
echo "bench/report.sh: wrote bench/report.md and bench/report/ in ${seconds} s"
