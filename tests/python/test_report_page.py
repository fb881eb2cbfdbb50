# SPDX-License-Identifier: GPL-3.0-or-later
# The report page of `roomcad report`, opened from disk in a real browser: Debian's Chromium,
# driven by Selenium (scripts/setup.sh --tests installs both). For every bundled plan and Sweet
# Home 3D home, selecting a finding marks exactly its objects `selected` (up to 200 findings,
# spread over a large home); a link to #finding-N opens on it; filtering hides the others; the
# console shows no error. A screenshot of the largest home's page is not blank.
import os

import numpy as np
import pytest
from selenium import webdriver
from selenium.webdriver.chrome.options import Options

from conftest import SOURCE_DIR, read_png_rgb, run_cli

PLANS = sorted((SOURCE_DIR / "examples").glob("*.json")) + sorted(
    (SOURCE_DIR / "examples" / "version2").glob("*.json")) + sorted(
        (SOURCE_DIR / "examples" / "sweethome3d").glob("*.json"))
MOST_SELECTED = 200

# Clicks each finding given (by index) and returns, for each, the data-id of every element
# marked `selected` and the finding's data-objects.
SELECT_EACH = """
const items = Array.from(document.querySelectorAll('li.finding'));
return arguments[0].map(function (i) {
  items[i].click();
  return {objects: items[i].dataset.objects.split(' ').filter(Boolean),
          selected: Array.from(document.querySelectorAll('.selected'))
                         .map(function (e) { return e.getAttribute('data-id'); }),
          current: Array.from(document.querySelectorAll('li.current')).map(e => e.id)};
});
"""


@pytest.fixture(scope="module")
def browser():
    options = Options()
    for argument in ("--headless=new", "--no-sandbox", "--window-size=1400,1000"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(options=options)
    yield driver
    driver.quit()


def write_report(exe, plan, page, *extra):
    done = run_cli(exe, "report", plan, "-o", page, *extra, check=False)
    assert done.returncode in (0, 1), done.stderr.decode()
    assert page.stat().st_size > 0
    return page


def console_errors(browser):
    return [e for e in browser.get_log("browser") if e["level"] == "SEVERE"]


def spread(count, most):
    """Up to `most` indices spread evenly over range(count)."""
    if count <= most:
        return list(range(count))
    return sorted({round(k * (count - 1) / (most - 1)) for k in range(most)})


@pytest.mark.parametrize("plan", PLANS, ids=lambda p: p.name)
def test_selecting_a_finding_marks_exactly_its_objects(browser, roomcad_exe, plan, tmp_path):
    page = write_report(roomcad_exe, plan, tmp_path / "report.html", "--picture", "off")
    browser.get(page.as_uri())
    drawn = set(browser.execute_script(
        "return Array.from(document.querySelectorAll('[data-id]')).map(e => e.getAttribute('data-id'));"))
    count = len(browser.find_elements("css selector", "li.finding"))
    marked = 0
    for k, seen in zip(spread(count, MOST_SELECTED),
                       browser.execute_script(SELECT_EACH, spread(count, MOST_SELECTED))):
        assert seen["current"] == [f"finding-{k + 1}"]
        assert set(seen["selected"]) == set(seen["objects"]) & drawn, seen
        marked += bool(seen["selected"])
    if count:
        assert marked > 0, "no finding marked any object"
        assert browser.execute_script("return location.hash") == f"#finding-{spread(count, MOST_SELECTED)[-1] + 1}"
    assert console_errors(browser) == []


def test_a_link_opens_on_its_finding_and_filters_hide_the_rest(browser, roomcad_exe, tmp_path):
    home = SOURCE_DIR / "examples" / "sweethome3d" / "arif-putra-pertama-1.json"
    page = write_report(roomcad_exe, home, tmp_path / "home.html", "--picture", "off")
    browser.get(page.as_uri() + "#finding-7")
    current = browser.find_elements("css selector", "li.current")
    assert [li.get_attribute("id") for li in current] == ["finding-7"]
    objects = set(current[0].get_attribute("data-objects").split())
    selected = {e.get_attribute("data-id") for e in browser.find_elements("css selector", ".selected")}
    assert selected and selected <= objects
    # Filter by the second code of the list: exactly the findings of that code stay shown.
    code = browser.execute_script(
        "const s = document.querySelector('#filters select[data-key=code]');"
        "s.selectedIndex = 2; s.dispatchEvent(new Event('change')); return s.value;")
    shown = browser.execute_script(
        "return Array.from(document.querySelectorAll('li.finding:not(.hidden)'))"
        ".map(li => li.dataset.code);")
    total = browser.execute_script(
        "return Array.from(document.querySelectorAll('li.finding'))"
        ".filter(li => li.dataset.code === arguments[0]).length;", code)
    assert shown and set(shown) == {code} and len(shown) == total
    assert console_errors(browser) == []


def test_the_page_of_the_largest_home_is_not_blank(browser, roomcad_exe, tmp_path):
    home = SOURCE_DIR / "examples" / "sweethome3d" / "arif-putra-pertama-1.json"
    page = write_report(roomcad_exe, home, tmp_path / "home.html")
    browser.get(page.as_uri() + "#finding-1")
    assert browser.execute_script("return document.querySelector('img.picture').naturalWidth") == 960
    shot = tmp_path / "shot.png"
    assert browser.save_screenshot(str(shot))
    pixels = read_png_rgb(shot)
    assert pixels.shape[0] > 500 and pixels.shape[1] > 500
    colours = np.unique(pixels.reshape(-1, 3), axis=0)
    assert len(colours) > 20, "the screenshot is nearly one colour"
    red = np.all(pixels == [0xd0, 0, 0], axis=-1).sum()
    assert red > 100, "the selected finding's objects are not drawn in red"
    assert console_errors(browser) == []
    assert os.path.getsize(page) < 4 * 1024 * 1024


def test_selecting_a_repair_edit_marks_its_objects(browser, roomcad_exe, tmp_path):
    home = SOURCE_DIR / "examples" / "sweethome3d" / "1-BedroomApartment.json"
    page = write_report(roomcad_exe, home, tmp_path / "repair.html", "--picture", "off", "--repair")
    browser.get(page.as_uri())
    edits = browser.find_elements("css selector", "li.edit")
    assert len(edits) == 3
    for edit in edits:
        edit.click()
        objects = set(edit.get_attribute("data-objects").split())
        selected = {e.get_attribute("data-id") for e in browser.find_elements("css selector", ".selected")}
        assert selected and selected <= objects
        assert browser.execute_script("return location.hash") == "#" + edit.get_attribute("id")
    assert console_errors(browser) == []
