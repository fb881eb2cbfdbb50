#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The report page (`roomcad report`): the wall time to write it (median of RUNS whole
# processes) and to open it in Chromium (headless, through Selenium: from navigation to the
# load event, then selecting the first finding), on the largest bundled home and on a plan
# with 2,000 findings (bench/many_findings_plan.py).
# Usage: bench/report_page_bench.sh [BUILD_DIR] [RUNS]   (default build, 11)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-11}
roomcad=$build/roomcad
[[ -x $roomcad ]] || { echo "report_page_bench: no $roomcad (bash scripts/build.sh roomcad)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 bench/many_findings_plan.py 2000 "$work/findings-2000.json"

source bench/median_ms.sh

echo "| plan | findings | write ms (median of $runs) | page bytes | open ms (median of $runs) |"
echo "| --- | --- | --- | --- | --- |"
for plan in examples/sweethome3d/arif-putra-pertama-1.json "$work/findings-2000.json"; do
  page=$work/$(basename "$plan" .json).html
  write=$(median_ms "$roomcad" report "$plan" -o "$page")
  findings=$(grep -c '<li class="finding' "$page" || true)
  open=$(/usr/bin/python3 - "$page" "$runs" <<'PY'
import sys, time
from selenium import webdriver
from selenium.webdriver.chrome.options import Options
options = Options()
for argument in ("--headless=new", "--no-sandbox", "--window-size=1400,1000"):
    options.add_argument(argument)
driver = webdriver.Chrome(options=options)
times = []
for _ in range(int(sys.argv[2])):
    start = time.perf_counter()
    driver.get("file://" + sys.argv[1])
    driver.execute_script("document.querySelector('li.finding').click()")
    times.append((time.perf_counter() - start) * 1000)
    driver.get("about:blank")
driver.quit()
print(f"{sorted(times)[len(times) // 2]:.1f}")
PY
)
  echo "| $(basename "$plan") | $findings | $write | $(stat -c %s "$page") | $open |"
done
