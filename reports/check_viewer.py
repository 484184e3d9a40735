#!/usr/bin/python3
"""Opens a report's index.html in headless Chromium, as a reader would, and checks its 3D view.

Usage: check_viewer.py DIR [--screenshots] [--case TEXT]
Then the pages the suite's pages study wrote (curves/editor.html, levels/levels.html), when
there: no console error, every canvas (every level of every levels entry) drawn.
Fails (exit 1, naming what) on any console error of the page, when the viewer's canvas is
blank (no pixel differs from the background) or when a click on the surface does not show the
picked vertex with every implementation's position. With --screenshots the page, the viewer
after the pick and the viewer with its panel are saved as DIR/screenshots/*.png; --case shows
the first case whose label contains TEXT (a divergence class, an input) instead of the first.
Needs Debian's chromium, chromium-driver and python3-selenium; a report without views (the
suite made no divergence small enough) is reported and passes.
"""
import argparse
import contextlib
import io
import os
import sys
import time

import numpy
from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By

BACKGROUND = (0xf4, 0xf4, 0xf4)  # the viewer's clear colour (viewer.js)
TIMEOUT_SECONDS = 60


def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for arg in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1400,1000",
                # WebGL without a GPU: Chromium's software rasterizer.
                "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--allow-file-access-from-files"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def reset(driver):
    """Makes a browser from browser() as new for the next check: the window at its first size,
    a blank page, the console's earlier messages read and dropped. Starting Chromium and loading
    the viewer's scripts the first time take about 4 s; a check run in a reset browser skips both."""
    driver.set_window_size(1400, 1000)
    driver.get("about:blank")
    driver.get_log("browser")


@contextlib.contextmanager
def session(driver=None):
    """`driver` reset for a check, or a browser of the check's own, quit when it ends."""
    if driver is not None:
        reset(driver)
        yield driver
        return
    own = browser()
    try:
        yield own
    finally:
        own.quit()


def console_errors(driver):
    """The page's console errors since the last call (uncaught exceptions among them)."""
    return [e["message"] for e in driver.get_log("browser") if e["level"] == "SEVERE"]


def wait_for(driver, script, what):
    """Polls `script` until it is true; fails at once on a console error, else after the timeout."""
    end = time.time() + TIMEOUT_SECONDS
    while time.time() < end:
        errors = console_errors(driver)
        if errors:
            raise AssertionError(f"console error while waiting for {what}: {errors}")
        if driver.execute_script(script):
            return
        time.sleep(0.2)
    raise AssertionError(f"timed out after {TIMEOUT_SECONDS} s waiting for {what}")


# In the page: the canvas point (x, y, width, height) of the visible triangle centre nearest the
# marked vertex on screen, or null.
VISIBLE_POINT = """
const v = window.crossdivViewer, canvas = arguments[0], rect = canvas.getBoundingClientRect();
const L = v.state.view.levels[v.state.level], P = L.positions, T = L.triangles;
const target = v.screenOf(v.state.vertex);
const order = [];
for (let t = 0; t < T.length / 3; ++t) {
  const c = new THREE.Vector3();
  for (let k = 0; k < 3; ++k) c.add(new THREE.Vector3(P[3 * T[3 * t + k]], P[3 * T[3 * t + k] + 1], P[3 * T[3 * t + k] + 2]));
  c.multiplyScalar(1 / 3);
  const s = c.clone().project(v.camera);
  const x = (s.x + 1) / 2 * rect.width, y = (1 - s.y) / 2 * rect.height;
  if (x < 2 || y < 2 || x > rect.width - 2 || y > rect.height - 2) continue;
  order.push([Math.hypot(rect.left + x - target.x, rect.top + y - target.y), t, x, y, s]);
}
order.sort((a, b) => a[0] - b[0]);
const ray = new THREE.Raycaster();
for (const [, t, x, y, s] of order.slice(0, 2000)) {
  ray.setFromCamera(new THREE.Vector2(s.x, s.y), v.camera);
  const hit = ray.intersectObject(v.mesh)[0];
  if (hit && hit.faceIndex === t) return [x, y, rect.width, rect.height];
}
return null;
"""


def pixels(png):
    """A PNG's pixels as a height x width x 3 array of signed integers (room for differences)."""
    return numpy.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=numpy.int16)


def count_differing(rgb, background=BACKGROUND):
    """How many pixels of an array from pixels() differ from a page's background by more than
    antialiasing (8 of 255 in some channel). Counted by numpy: a screenshot has a million pixels,
    which a loop in Python takes a second to visit."""
    return int(numpy.count_nonzero(numpy.abs(rgb - numpy.array(background, dtype=numpy.int16)).max(axis=2) > 8))


def differing_pixels(png, background=BACKGROUND):
    """How many pixels of a PNG differ from a page's background by more than antialiasing."""
    return count_differing(pixels(png), background)


EDITOR_BACKGROUND = (0x1e, 0x22, 0x26)  # editor.js
LEVELS_BACKGROUND = (0xf4, 0xf4, 0xf4)  # levels.js


def open_page(driver, path, ready, what):
    """Loads a page from disk and waits until `ready` (a script) is true."""
    driver.get("file://" + os.path.abspath(path))
    wait_for(driver, "return document.readyState === 'complete'", f"{what} to load")
    wait_for(driver, ready, what)


def check_pages(folder, screenshots=False, driver=None):
    """The pages study's pages, when the report has them: the bundled curves in the editor (a
    curve with core's runs shown, its frames drawn) and the subdivision levels (every entry's
    views drawn). Fails on a console error or a blank canvas. Returns lines of what was seen.
    Runs in `driver` (reset first) when given, else in a browser of its own."""
    seen, shots = [], os.path.join(folder, "screenshots")
    editor, levels = os.path.join(folder, "curves", "editor.html"), os.path.join(folder, "levels", "levels.html")
    if not os.path.exists(editor) and not os.path.exists(levels):
        return [f"{folder}: no interactive pages (the suite ran no pages study)"]
    if screenshots:
        os.makedirs(shots, exist_ok=True)
    with session(driver) as driver:
        if os.path.exists(editor):
            open_page(driver, editor, "return !!window.crossdivEditor", "the curve editor page")
            curves = driver.execute_script("return window.crossdivEditor.state.curves.length")
            # A 3D curve with core's runs: its closest-tolerance distance run and its
            # rotation-minimizing frames drawn over the editor's own view.
            index = driver.execute_script("""
                const cs = window.crossdivEditor.state.curves;
                const i = cs.findIndex((c) => c.keyword.endsWith('3') && c.core);
                return i >= 0 ? i : cs.findIndex((c) => c.core);""")
            assert index >= 0, "no curve on the curves page carries core's tessellations"
            driver.execute_script("""
                const list = document.getElementById('curve-list');
                list.value = String(arguments[0]); list.dispatchEvent(new Event('change'));
                document.getElementById('core-run').value = '2'; document.getElementById('core-frames').value = 'rmf';
                window.crossdivEditor.redraw();""", index)
            rows = len(driver.find_elements(By.CSS_SELECTOR, "#core-table tr")) - 1
            assert rows >= 6, f"core's table lists {rows} runs"
            canvas = driver.find_element(By.CSS_SELECTOR, "#view canvas")
            lit = differing_pixels(canvas.screenshot_as_png, EDITOR_BACKGROUND)
            assert lit > 1000, f"the curves page's canvas is blank: {lit} pixels drawn"
            seen.append(f"curves page: {curves} curves, {rows} core runs of curve {index}, {lit} pixels drawn")
            if screenshots:
                driver.save_screenshot(os.path.join(shots, "curves.png"))
            errors = console_errors(driver)
            assert not errors, f"console errors on the curves page: {errors}"
        if os.path.exists(levels):
            open_page(driver, levels, "return !!window.crossdivLevels", "the subdivision levels page")
            entries = driver.execute_script("return window.crossdivLevels.entries.length")
            canvas = driver.find_element(By.CSS_SELECTOR, "#view canvas")
            for i in range(entries):
                driver.execute_script("window.crossdivLevels.select(arguments[0])", i)
                img = pixels(canvas.screenshot_as_png)
                n = driver.execute_script("return window.crossdivLevels.state.scenes.length")
                cell = img.shape[1] // n
                for level in range(n):
                    lit = count_differing(img[:, level * cell:(level + 1) * cell], LEVELS_BACKGROUND)
                    assert lit > 500, f"levels page, entry {i}, level {level}: blank ({lit} pixels drawn)"
            seen.append(f"levels page: {entries} entries, every level drawn")
            if screenshots:
                driver.execute_script("window.crossdivLevels.select(0);"
                                      "document.getElementById('show-wire').checked = true; window.crossdivLevels.build();")
                driver.save_screenshot(os.path.join(shots, "levels.png"))
            errors = console_errors(driver)
            assert not errors, f"console errors on the levels page: {errors}"
        seen.append("no console error on the pages")
    return seen


def check(folder, screenshots=False, case=None, driver=None):
    """The checks; returns a list of lines describing what was seen. Raises AssertionError.
    Runs in `driver` (reset first) when given, else in a browser of its own."""
    page = os.path.abspath(os.path.join(folder, "index.html"))
    if not os.path.exists(page):
        raise AssertionError(f"{page}: no report")
    shots = os.path.join(folder, "screenshots")
    seen = []
    with session(driver) as driver:
        driver.get("file://" + page)
        wait_for(driver, "return document.readyState === 'complete'", "the page to load")
        if not driver.execute_script("return !!document.getElementById('crossdiv-viewer')"):
            errors = console_errors(driver)
            assert not errors, f"console errors: {errors}"
            return [f"{page}: no 3D views in this report (no divergence small enough); no console error"]
        if screenshots:
            os.makedirs(shots, exist_ok=True)
            driver.save_screenshot(os.path.join(shots, "overview.png"))
        wait_for(driver, "return window.crossdivViewer && window.crossdivViewer.ready === true", "the first 3D view")
        if case:
            index = driver.execute_script("return window.CROSSDIV_VIEWS.findIndex((e) => e.label.includes(arguments[0]))", case)
            assert index >= 0, f"no 3D view's label contains {case!r}"
            driver.execute_script("window.crossdivViewer.ready = false;"
                                  "window.crossdivViewer.show(arguments[0]).then(() => { window.crossdivViewer.ready = true; })", index)
            wait_for(driver, "return window.crossdivViewer.ready === true", f"the 3D view of case {index}")
        canvas = driver.find_element(By.CSS_SELECTOR, "#crossdiv-viewer canvas")
        driver.execute_script("arguments[0].scrollIntoView()", canvas)
        lit = differing_pixels(canvas.screenshot_as_png)
        assert lit > 1000, f"the 3D canvas is blank: {lit} pixels differ from the background"
        seen.append(f"canvas: {lit} pixels drawn")
        # A real click on the surface where it is drawn nearest the marked vertex: the centre of
        # the nearest triangle that a ray through it hits first (the vertex itself may sit on a
        # silhouette or a pinch, where a ray misses). The page picks by ray casting.
        worst = driver.execute_script("return window.crossdivViewer.state.vertex;")
        where = driver.execute_script(VISIBLE_POINT, canvas)
        assert where, f"no triangle of the shown mesh is visible on the canvas (marked vertex v{worst})"
        x, y, w, h = where
        driver.execute_script("window.crossdivViewer.state.vertex = -2;")  # forget it: only a pick sets it again
        ActionChains(driver).move_to_element_with_offset(canvas, int(x - w / 2), int(y - h / 2)).click().perform()
        wait_for(driver, "return window.crossdivViewer.state.vertex >= 0", "the click to pick a vertex")
        info = driver.execute_script("return window.crossdivViewer.pickedInfo")
        text = driver.find_element(By.CSS_SELECTOR, "#crossdiv-viewer .cv-picked").text
        refs = driver.execute_script("return Object.keys(window.crossdivViewer.state.view.references)")
        assert f"v{info['vertex']}" in text and "valence" in text, f"the picked vertex is not shown: {text!r}"
        for name in refs:
            assert name in text, f"the picked vertex's panel does not name {name}: {text!r}"
        assert len(info["rows"]) == 1 + len(refs), info
        seen.append(f"picked v{info['vertex']} at level {info['level']} ({info['cls']}); {len(refs)} reference(s) shown")
        if driver.execute_script("return !!window.crossdivViewer.state.view.levels[window.crossdivViewer.state.level].uv"):
            # Texture coordinates: the clicked side's corner, with every implementation's value.
            assert info["corner"] >= 0 and "texture coordinates" in text, f"the picked corner's values are not shown: {text!r}"
            uv_refs = driver.execute_script("return Object.keys(window.crossdivViewer.state.view.referenceUvs)")
            assert len(info["uvRows"]) == 1 + len(uv_refs), info["uvRows"]
            seen.append(f"picked corner {info['corner']} of face {info['face']}: {len(info['uvRows'])} texture-coordinate rows")
        if screenshots:
            canvas.screenshot(os.path.join(shots, "viewer.png"))
            driver.find_element(By.ID, "crossdiv-viewer").screenshot(os.path.join(shots, "viewer-panel.png"))
        errors = console_errors(driver)
        assert not errors, f"console errors: {errors}"
        seen.append("no console error")
    return seen


def main(argv):
    parser = argparse.ArgumentParser(description="Check a report's 3D viewer in headless Chromium.")
    parser.add_argument("folder")
    parser.add_argument("--screenshots", action="store_true")
    parser.add_argument("--case", help="show the first case whose label contains this text")
    args = parser.parse_args(argv[1:])
    try:
        for line in check(args.folder, args.screenshots, args.case) + check_pages(args.folder, args.screenshots):
            print(line)
    except AssertionError as e:
        sys.exit(f"{args.folder}/index.html: {e}")


if __name__ == "__main__":
    main(sys.argv)
