"""The curve editor as a user meets it: `crossdiv editor` writes the page, headless Chromium
opens it from disk, scripted mouse drags, clicks and Alt-clicks edit the control points, and the
exported SWP must hold exactly the points the edits aimed at (the editor snaps to a grid of 1/8,
so an aimed point is reached exactly). Core then reads the export: its uniform tessellation must
be the page's, its de Casteljau levels the page's.

The crossdiv program is CROSSDIV_BIN (set by CTest), else build/verification/crossdiv."""
import json
import os
import re
import subprocess
import sys

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))

import check_viewer  # noqa: E402

CROSSDIV = os.environ.get("CROSSDIV_BIN") or os.path.join(HERE, "..", "..", "build", "verification", "crossdiv")

# The page's spline arithmetic and core's differ only in the order of a few sums (the basis
# conversions), a few ulps of the coordinates: 1e-12 of the curve's size is far above that and
# far below any wrong rule (a wrong weight moves points by 1e-2 of the size and more).
SAMPLE_TOLERANCE_REL = 1e-12

PLANAR = """# two planar curves and one the editor does not edit
bez2 arch 8 4 [0 0] [1 2] [3 2] [4 0]
crc2 ring 6 3 [0 -1] [2 -2] [4 -1]
tcb2 keys 8 4 [0 0] [1 1] [2 0] [3 1]
"""
SPACE = "bsp3 coil 6 5 [0 0 0] [2 0 0.5] [2 2 1] [0 2 1.5] [0 0 2]\n"


def write_editor(folder, swp_text):
    src = os.path.join(folder, "in.swp")
    with open(src, "w") as f:
        f.write(swp_text)
    out = os.path.join(folder, "editor")
    run = subprocess.run([CROSSDIV, "editor", src, "--out", out], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    return out, run


def read_swp_points(text):
    """[(keyword, name, steps, [[x, y(, z)]...])] of an SWP text, numbers as Python floats."""
    records = []
    for line in text.splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        head, *points = re.split(r"\s*\[", line)
        keyword, name, steps, count = head.split()
        pts = [[float(x) for x in p.rstrip("] ").split()] for p in points]
        assert len(pts) == int(count)
        records.append((keyword, name, int(steps), pts))
    return records


def canvas_offset(driver, point):
    """The offset from the canvas centre (Selenium's origin) of a world point on screen."""
    return driver.execute_script("""
        const s = window.crossdivEditor.screenOf(arguments[0]), r = window.crossdivEditor.renderer.domElement.getBoundingClientRect();
        return [s.x - r.left - r.width / 2, s.y - r.top - r.height / 2];""", point)


def drag(driver, canvas, start, end, shift=False):
    (x0, y0), (x1, y1) = canvas_offset(driver, start), canvas_offset(driver, end)
    chain = ActionChains(driver)
    if shift:
        chain.key_down(Keys.SHIFT)
    chain.move_to_element_with_offset(canvas, round(x0), round(y0)).click_and_hold()
    # In steps, as a hand moves: the page follows every mouse move.
    for k in range(1, 5):
        chain.move_to_element_with_offset(canvas, round(x0 + (x1 - x0) * k / 4), round(y0 + (y1 - y0) * k / 4))
    chain.release()
    if shift:
        chain.key_up(Keys.SHIFT)
    chain.perform()


def click(driver, canvas, point, alt=False):
    x, y = canvas_offset(driver, point)
    chain = ActionChains(driver)
    if alt:
        chain.key_down(Keys.ALT)
    chain.move_to_element_with_offset(canvas, round(x), round(y)).click()
    if alt:
        chain.key_up(Keys.ALT)
    chain.perform()


def points(driver, curve):
    return driver.execute_script("return window.crossdivEditor.state.curves[arguments[0]].points", curve)


def open_editor(driver, folder):
    check_viewer.open_page(driver, os.path.join(folder, "editor.html"), "return !!window.crossdivEditor", "the editor")
    return driver.find_element(By.CSS_SELECTOR, "#view canvas")


def core_agrees(folder, swp_text, driver):
    """Core reads the export; its uniform tessellation is the page's, curve by curve."""
    path = os.path.join(folder, "export.swp")
    with open(path, "w") as f:
        f.write(swp_text)
    out = os.path.join(folder, "export.json")
    subprocess.run([CROSSDIV, "tessellate", path, "--mode", "uniform", "-o", out], check=True, capture_output=True, timeout=60)
    with open(out) as f:
        core = json.load(f)["curves"]
    for i, c in enumerate(core):
        page = driver.execute_script("return window.crossdivEditor.tessellate(arguments[0])", i)
        assert len(page["points"]) == len(c["points"]), (i, len(page["points"]), len(c["points"]))
        pts = [p + [0.0] * (3 - len(p)) for p in c["points"]]
        size = max(max(p[k] for p in pts) - min(p[k] for p in pts) for k in range(3))
        worst = max(abs(a - b) for p, q in zip(page["points"], pts) for a, b in zip(p, q))
        assert worst <= SAMPLE_TOLERANCE_REL * size, f"curve {i}: the page's samples part from core's by {worst}"
        assert page["params"] == c["params"], f"curve {i}: the sample parameters differ"
    return len(core)


def test_the_editor_page_is_written_from_disk_and_says_what_it_left_out(tmp_path):
    folder, run = write_editor(str(tmp_path), PLANAR)
    for name in ("editor.html", "editor.js", "spline_math.js", "three.min.js", "OrbitControls.js", "curves.js"):
        assert os.path.getsize(os.path.join(folder, name)) > 100, name
    assert "keys (tcb2, line 4)" in run.stderr
    with open(os.path.join(folder, "editor.html")) as f:
        sources = re.findall(r"""src=['"]([^'"]+)['"]""", f.read())
    assert sources and not [s for s in sources if re.match(r"[a-z]+:|/", s)], sources  # offline, beside the page


def test_an_unreadable_curve_file_is_refused_by_line(tmp_path):
    bad = tmp_path / "bad.swp"
    bad.write_text("bez2 a 8 5 [0 0] [1 1] [2 0] [3 1] [4 4]\n")
    run = subprocess.run([CROSSDIV, "editor", str(bad), "--out", str(tmp_path / "e")], capture_output=True, text=True, timeout=60)
    assert run.returncode == 2 and "bad.swp:1" in run.stderr, run.stderr
    assert not (tmp_path / "e").exists()


def test_drags_clicks_and_removals_make_the_expected_swp(tmp_path, driver):
    folder, _ = write_editor(str(tmp_path), PLANAR)
    canvas = open_editor(driver, folder)
    assert not driver.execute_script("return window.crossdivEditor.state.mode3d")  # planar curves: the 2D view
    lit = check_viewer.differing_pixels(canvas.screenshot_as_png, check_viewer.EDITOR_BACKGROUND)
    assert lit > 1000, f"the editor's canvas is blank ({lit} pixels drawn)"

    # Drag the arch's second point onto (1.5, 2.5): exactly there, the grid's point.
    drag(driver, canvas, [1, 2, 0], [1.5, 2.5, 0])
    assert points(driver, 0) == [[0, 0, 0], [1.5, 2.5, 0], [3, 2, 0], [4, 0, 0]]
    # Click empty space with the last point selected: a point after it. Four points and one
    # more are not 3n + 1: the export is refused and says why.
    drag(driver, canvas, [4, 0, 0], [4, 0, 0])  # a press without a move selects
    click(driver, canvas, [4.75, -0.5, 0])
    assert points(driver, 0)[-1] == [4.75, -0.5, 0]
    problem = driver.find_element(By.ID, "swp-problem").text
    assert "3n + 1" in problem and "it has 5" in problem, problem
    assert driver.find_element(By.ID, "download").get_attribute("disabled")
    click(driver, canvas, [4.5, 1.25, 0])
    click(driver, canvas, [3.75, 0.625, 0])
    # Alt-click removes the ring's first point; the ring keeps three more after two clicks.
    drag(driver, canvas, [4, -1, 0], [4, -1, 0])
    click(driver, canvas, [3, -2.5, 0])
    click(driver, canvas, [1, -2.625, 0])
    click(driver, canvas, [0, -1, 0], alt=True)
    assert driver.find_element(By.ID, "swp-problem").text == ""

    text = driver.find_element(By.ID, "swp").get_attribute("value")
    records = read_swp_points(text)
    assert records == [
        ("bez2", "arch", 8, [[0, 0], [1.5, 2.5], [3, 2], [4, 0], [4.75, -0.5], [4.5, 1.25], [3.75, 0.625]]),
        ("crc2", "ring", 6, [[2, -2], [4, -1], [3, -2.5], [1, -2.625]]),
    ], text
    assert core_agrees(str(tmp_path), text, driver) == 2
    errors = check_viewer.console_errors(driver)
    assert not errors, errors


def test_de_casteljau_levels_are_cores_bit_for_bit(tmp_path, driver):
    folder, _ = write_editor(str(tmp_path), "bez2 one 8 4 [0 0] [1 2] [3 2.5] [4 0.25]\n")
    open_editor(driver, folder)
    for t in (0.0, 0.3, 0.5, 0.77, 1.0):
        out = os.path.join(str(tmp_path), "levels.json")
        subprocess.run([CROSSDIV, "casteljau", os.path.join(str(tmp_path), "in.swp"), "--t", repr(t), "--json", out],
                       check=True, capture_output=True, timeout=60)
        with open(out) as f:
            core = json.load(f)["levels"]
        page = driver.execute_script("return window.crossdivEditor.casteljau(0, arguments[0])", t)
        # The page's t is along the chain; one segment makes it the segment's t.
        assert [[p[:2] for p in level] for level in page] == core, (t, page, core)


def test_three_dimensional_drags_stay_on_their_plane(tmp_path, driver):
    folder, _ = write_editor(str(tmp_path), SPACE)
    canvas = open_editor(driver, folder)
    assert driver.execute_script("return window.crossdivEditor.state.mode3d")
    # On the horizontal plane through the point: x and y move, z stays.
    drag(driver, canvas, [2, 2, 1], [2.5, 1.75, 1])
    assert points(driver, 0)[2] == [2.5, 1.75, 1]
    # With Shift: up the vertical through it, only z moves.
    drag(driver, canvas, [2.5, 1.75, 1], [2.5, 1.75, 1.625], shift=True)
    assert points(driver, 0)[2] == [2.5, 1.75, 1.625]
    # A click adds on the horizontal plane through the selected point.
    click(driver, canvas, [1, 1, 1.625])
    assert points(driver, 0)[3] == [1, 1, 1.625]
    text = driver.find_element(By.ID, "swp").get_attribute("value")
    assert read_swp_points(text) == [
        ("bsp3", "coil", 6, [[0, 0, 0], [2, 0, 0.5], [2.5, 1.75, 1.625], [1, 1, 1.625], [0, 2, 1.5], [0, 0, 2]])], text
    assert core_agrees(str(tmp_path), text, driver) == 1
    errors = check_viewer.console_errors(driver)
    assert not errors, errors
