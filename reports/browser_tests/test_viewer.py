"""The report as a reader meets it: a small suite run by crossdiv, its index.html opened in
headless Chromium (Debian's chromium, chromium-driver, python3-selenium). Fails on a console
error, a blank 3D canvas, a click that picks nothing, or a page that reaches for the network.

The crossdiv program is CROSSDIV_BIN (set by CTest), else build/verification/crossdiv."""
import json
import os
import re
import subprocess
import sys

import numpy
import pytest
from selenium.webdriver.common.by import By

HERE = os.path.dirname(os.path.abspath(__file__))
REPORTS = os.path.join(HERE, "..")
sys.path.insert(0, REPORTS)

import check_viewer  # noqa: E402

CROSSDIV = os.path.abspath(os.environ.get("CROSSDIV_BIN") or os.path.join(REPORTS, "..", "build", "verification", "crossdiv"))

# Two divergences with a known cause: OpenMesh and CGAL lack Loop's corner rule (open-patch),
# and no reference has Warren's weights (octahedron); a case where all agree; the pages
# study's curve editor and subdivision-levels pages; and a polygon scheme's divergence:
# OpenMesh's Catmull-Clark boundary rule on the quad grid; and texture coordinates that diverge
# where the positions agree: OpenSubdiv splits one of the UV bowtie's values by face order.
MANIFEST = """suite viewer-test
case bundled:open-patch  loop weights=loop boundary=edge-and-corner levels=2 tier=weak tolerance=1e-12 against=opensubdiv,openmesh
case bundled:octahedron  loop weights=warren boundary=edge-only levels=2 tier=weak tolerance=1e-12 against=opensubdiv
case bundled:tetrahedron loop weights=loop boundary=edge-only levels=1 tier=weak tolerance=1e-12 against=opensubdiv
case catalog pages
case bundled:quad-grid   catmull-clark levels=2 tier=weak tolerance=1e-12 against=opensubdiv,openmesh
case edgecase:uv-bowtie  catmull-clark fvar=none levels=2 tier=weak tolerance=1e-12 against=opensubdiv
"""


def run_suite(folder, manifest):
    path = os.path.join(folder, "viewer.suite")
    with open(path, "w") as f:
        f.write(manifest)
    out = os.path.join(folder, "out")
    subprocess.run([CROSSDIV, "suite", path, "--out", out, "--no-report"], check=True, capture_output=True, timeout=300)
    subprocess.run(["/usr/bin/python3", os.path.join(REPORTS, "make_report.py"), out], check=True, timeout=300)
    return out


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    assert os.path.exists(CROSSDIV), f"{CROSSDIV}: build crossdiv first (or set CROSSDIV_BIN)"
    return run_suite(str(tmp_path_factory.mktemp("viewer")), MANIFEST)


def show_case(driver, text):
    """Shows the first case of the viewer whose id contains `text`, and waits for it."""
    index = driver.execute_script("return window.CROSSDIV_VIEWS.findIndex((e) => e.id.includes(arguments[0]))", text)
    assert index >= 0, f"no view of a case with {text}"
    driver.execute_script("window.crossdivViewer.ready = false;"
                          "window.crossdivViewer.show(arguments[0]).then(() => { window.crossdivViewer.ready = true; })", index)
    check_viewer.wait_for(driver, "return window.crossdivViewer.ready === true", f"the view of {text}")


def open_report(driver, report):
    """Opens the report's index.html and waits for its viewer."""
    driver.get("file://" + os.path.abspath(os.path.join(report, "index.html")))
    check_viewer.wait_for(driver, "return window.crossdivViewer && window.crossdivViewer.ready === true", "the viewer")


def test_every_divergence_has_a_view_and_the_page_needs_no_network(report):
    views = sorted(os.listdir(os.path.join(report, "views")))
    # The agreeing tetrahedron has none; every divergence was shrunk to a minimal input.
    assert views == ["job0-minimal.obj", "job0.js", "job1-minimal.obj", "job1.js", "job4-minimal.obj", "job4.js",
                     "job5-minimal.obj", "job5.js"]
    for name in ("three.min.js", "OrbitControls.js", "viewer.js"):
        assert os.path.getsize(os.path.join(report, "viewer", name)) > 1000
    with open(os.path.join(report, "index.html")) as f:
        page = f.read()
    # Every script and image is a relative path beside the page: it opens from disk, offline.
    sources = re.findall(r"""src=['"]([^'"]+)['"]""", page)
    assert sources and not [s for s in sources if re.match(r"[a-z]+:|/", s)], sources
    assert "views/job0.js" in page and "data-view=" in page
    # The meshes are in the side files, not the page.
    assert os.path.getsize(os.path.join(report, "index.html")) < 200_000


def test_the_viewer_draws_picks_and_logs_no_error(report, driver):
    seen = check_viewer.check(report, screenshots=True, driver=driver)
    assert seen[0].startswith("canvas: ") and seen[-1] == "no console error", seen
    for shot in ("overview.png", "viewer.png", "viewer-panel.png"):
        assert os.path.getsize(os.path.join(report, "screenshots", shot)) > 5000


def test_the_warren_case_names_every_reference_at_the_picked_vertex(report, driver):
    seen = check_viewer.check(report, case="weight-family", driver=driver)
    assert any(line.startswith("picked v") and "1 reference(s)" in line for line in seen), seen


def test_the_first_screen_reads_on_a_laptop(report, driver):
    # 1366 x 768: the overview table within the first screen, its counts coloured by the
    # report's own stylesheet, nothing wider than the window; the screenshot kept.
    driver.set_window_size(1366, 768)
    open_report(driver, report)
    driver.execute_script("window.scrollTo(0, 0)")
    table = driver.find_element(By.CSS_SELECTOR, "h2 + p + table")
    assert driver.execute_script("return arguments[0].getBoundingClientRect().bottom", table) < \
        driver.execute_script("return window.innerHeight")
    agree = table.find_element(By.CSS_SELECTOR, "span.agree")
    assert agree.value_of_css_property("color") in ("rgba(26, 127, 55, 1)", "rgb(26, 127, 55)")
    assert not table.find_elements(By.CSS_SELECTOR, "span.failure.nonzero")  # the suite has no failure
    assert driver.execute_script("return document.documentElement.scrollWidth <= window.innerWidth + 1")
    os.makedirs(os.path.join(report, "screenshots"), exist_ok=True)
    shot = os.path.join(report, "screenshots", "first-screen.png")
    driver.save_screenshot(shot)
    assert os.path.getsize(shot) > 20000
    assert not check_viewer.console_errors(driver)


def test_a_broken_view_file_is_a_console_error(report, tmp_path, driver):
    # The check must fail when the page does: a view whose script throws.
    broken = tmp_path / "broken"
    subprocess.run(["cp", "-r", report, str(broken)], check=True)
    with open(broken / "views" / "job0.js", "w") as f:
        f.write("crossdivView({\"job\": 0, \"levels\": 17});\n")
    with pytest.raises(AssertionError, match="console error"):
        check_viewer.check(str(broken), driver=driver)


def test_a_representative_link_opens_its_case_in_the_viewer(report, driver):
    open_report(driver, report)
    links = [a for a in driver.find_elements(By.CSS_SELECTOR, "a[data-view]") if "octahedron" in a.text]
    assert links, "no link to the octahedron's view"
    links[0].click()
    check_viewer.wait_for(driver, "return window.crossdivViewer.state.entry && "
                                  "window.crossdivViewer.state.entry.id.includes('octahedron')", "the linked case")
    assert "bundled:octahedron" in driver.find_element(By.CSS_SELECTOR, "#crossdiv-viewer .cv-info").text
    assert not check_viewer.console_errors(driver)


def test_the_curve_and_levels_pages_draw_and_are_linked(report, driver):
    seen = check_viewer.check_pages(report, screenshots=True, driver=driver)
    assert seen[0].startswith("curves page: ") and seen[1].startswith("levels page: 9 entries"), seen
    assert seen[-1] == "no console error on the pages", seen
    with open(os.path.join(report, "index.html")) as f:
        page = f.read()
    assert "href='curves/editor.html'" in page and "href='levels/levels.html'" in page
    for shot in ("curves.png", "levels.png"):
        assert os.path.getsize(os.path.join(report, "screenshots", shot)) > 5000


def test_a_polygon_scheme_case_is_drawn_with_its_polygons_and_its_minimal_input(report, driver):
    # OpenMesh's midpoint-average boundary on the quad grid: the view of every level, the
    # wireframe of the quads' own edges (no fan diagonal), each reference's last level, the
    # divergence shrunk to one quad whose reproduce line shows it again.
    seen = check_viewer.check(report, case="quad-grid", driver=driver)
    assert any(line.startswith("picked v") and "2 reference(s)" in line for line in seen), seen
    assert seen[-1] == "no console error", seen
    with open(os.path.join(report, "results.json")) as f:
        [case] = [c for c in json.load(f)["cases"] if c["input"] == "bundled:quad-grid"]
    assert case["view"] == "views/job4.js" and case["minimal"]["faces"] == 1, case
    assert "boundary-rule" in case["minimal"]["symptom"]
    open_report(driver, report)
    show_case(driver, "quad-grid")
    # Every level's wireframe has the quads' edges: E = 2 n (n + 1) on an n x n grid.
    edges = driver.execute_script("return window.crossdivViewer.state.view.levels.map((l) => l.edges.length / 2)")
    faces = driver.execute_script("return window.crossdivViewer.state.view.levels.map((l) => l.sizes.length)")
    sides = [round(f ** 0.5) for f in faces]
    assert edges == [2 * n * (n + 1) for n in sides], (edges, faces)
    panel = driver.find_element(By.CSS_SELECTOR, "#crossdiv-viewer .cv-info").text
    assert f"{faces[-1]} faces" in panel, panel
    # Provenance of a polygon scheme: level 1's first face point descends from the four
    # corners of face 0, its first edge point from the two ends of an edge.
    nv = driver.execute_script("return window.crossdivViewer.state.view.levels[0].positions.length / 3")
    picked = []
    for vertex in (nv, nv + faces[0]):
        picked.append(driver.execute_script(
            "const v = window.crossdivViewer; v.state.level = 1; v.state.vertex = arguments[0]; v.rebuild(false);"
            "return v.pickedInfo", vertex))
    assert picked[0]["cls"].startswith("face point of face 0 (v") and len(picked[0]["ancestors"]) == 4, picked[0]
    assert picked[1]["cls"].startswith("edge point of edge (v") and len(picked[1]["ancestors"]) == 2, picked[1]
    assert not check_viewer.console_errors(driver)
    run = subprocess.run([CROSSDIV, "compare", case["minimal"]["mesh"], "--scheme", "catmull-clark", "--boundary", "edge-only",
                          "--levels", "2", "--against", "openmesh"], cwd=report, capture_output=True, text=True, timeout=120)
    assert run.returncode == 1 and "boundary-rule" in run.stdout, run.stdout + run.stderr


def test_a_blank_levels_view_fails_the_check(report, tmp_path, driver):
    # The check must fail when a level draws nothing: a level whose triangles are gone.
    broken = tmp_path / "blank"
    subprocess.run(["cp", "-r", report, str(broken)], check=True)
    with open(broken / "levels" / "levels.js") as f:
        script = f.read()
    with open(broken / "levels" / "levels.js", "w") as f:
        f.write(script.replace("scene.add(surface(level, flat));", "if (level !== e.levels[2]) scene.add(surface(level, flat));")
                      .replace("if (document.getElementById(\"show-net\").checked)", "if (false)"))
    with pytest.raises(AssertionError, match="level 2: blank"):
        check_viewer.check_pages(str(broken), driver=driver)


def test_a_shrunk_case_shows_its_minimal_input_which_reproduces_it(report, driver):
    # The open patch (OpenMesh and CGAL lack the corner rule) shrinks to one triangle.
    with open(os.path.join(report, "results.json")) as f:
        cases = json.load(f)["cases"]
    # Both divergent cases shrink: the open patch to one triangle, the octahedron (Warren's
    # weights, a valence-4 vertex) to that vertex's fan.
    shrunk = {c["input"]: c["minimal"] for c in cases if "minimal" in c and c["operation"] == "loop"}
    assert sorted(shrunk) == ["bundled:octahedron", "bundled:open-patch"], shrunk
    assert shrunk["bundled:octahedron"]["faces"] == 4 and "weight-family" in shrunk["bundled:octahedron"]["symptom"]
    minimal = shrunk["bundled:open-patch"]
    assert minimal["faces"] == 1 and "corner-rule" in minimal["symptom"], minimal
    # The reproduce line, run in the report's folder, shows the same divergence.
    run = subprocess.run([CROSSDIV, "compare", minimal["mesh"], "--weights", "loop", "--boundary", "edge-and-corner",
                          "--levels", "2", "--against", minimal["reference"]], cwd=report, capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 1 and "corner-rule" in run.stdout, run.stdout + run.stderr
    open_report(driver, report)
    show_case(driver, "open-patch")
    box = driver.find_element(By.CSS_SELECTOR, "#crossdiv-viewer .cv-minimal")
    assert "1 face(s) still show that" in box.text and minimal["mesh"] in box.text, box.text
    lit = check_viewer.differing_pixels(box.find_element(By.TAG_NAME, "canvas").screenshot_as_png, (255, 255, 255))
    assert lit > 500, f"the minimal input's canvas is blank ({lit} pixels drawn)"
    # The next case shows its own.
    show_case(driver, "octahedron")
    assert "4 face(s) still show that" in box.text and "weight-family" in box.text, box.text
    assert not check_viewer.console_errors(driver)


def dark_pixels(png):
    """Pixels darker than any shade the untextured viewer gives a surface whose references agree."""
    return int(numpy.count_nonzero(check_viewer.pixels(png).sum(axis=2) < 3 * 110))


def test_texture_coordinates_are_drawn_as_a_checkerboard_with_their_layout_and_each_value_at_a_corner(report, driver):
    # The UV bowtie under `none`: the positions agree, OpenSubdiv's texture coordinates do not
    # (face-order-dependence). The case has a view for them alone, and its shrunk input keeps them.
    with open(os.path.join(report, "results.json")) as f:
        [case] = [c for c in json.load(f)["cases"] if c["input"] == "edgecase:uv-bowtie"]
    assert case["view"] == "views/job5.js" and case["minimal"]["faces"] == 4, case
    with open(os.path.join(report, case["minimal"]["mesh"])) as f:
        assert sum(line.startswith("vt ") for line in f) > 4
    seen = check_viewer.check(report, case="uv-bowtie", driver=driver)
    assert any(line.startswith("picked corner ") and "2 texture-coordinate rows" in line for line in seen), seen
    open_report(driver, report)
    show_case(driver, "uv-bowtie")
    viewer = "window.crossdivViewer"
    # Opened at the corner where the texture coordinates part most; each implementation's
    # value there, OpenSubdiv's away from core's.
    info = driver.execute_script(f"return {viewer}.pickedInfo")
    worst = driver.execute_script(f"return {viewer}.state.view.uvWorstCorner")
    assert worst >= 0 and info["corner"] == worst, (worst, info)
    assert [r[0] for r in info["uvRows"]] == ["core", "opensubdiv"], info["uvRows"]
    assert float(info["uvRows"][1][2]) > 1e-3, info["uvRows"]
    panel = driver.find_element(By.CSS_SELECTOR, "#crossdiv-viewer .cv-picked").text
    assert "texture coordinates" in panel and "face-order-dependence" in panel, panel
    # The checkerboard: dark squares on the surface with the texture, none without it.
    canvas = driver.find_element(By.CSS_SELECTOR, "#crossdiv-viewer canvas")
    driver.execute_script("arguments[0].scrollIntoView()", canvas)
    textured = dark_pixels(canvas.screenshot_as_png)
    driver.execute_script(f"document.querySelector('.cv-texture').checked = false; {viewer}.rebuild(false)")
    plain = dark_pixels(canvas.screenshot_as_png)
    assert textured > 5000 and plain < textured / 20, (textured, plain)
    driver.execute_script(f"document.querySelector('.cv-texture').checked = true; {viewer}.rebuild(false)")
    # The UV layout: drawn, with the seams of the bowtie's regions.
    layout = driver.find_element(By.CSS_SELECTOR, "#crossdiv-viewer .cv-uv")
    assert check_viewer.differing_pixels(layout.screenshot_as_png, (255, 255, 255)) > 2000
    seams = driver.execute_script(f"return {viewer}.uvSeams")
    text = driver.find_element(By.CSS_SELECTOR, "#crossdiv-viewer .cv-uv-text").text
    assert seams > 0 and f"{seams} on a seam" in text, text
    os.makedirs(os.path.join(report, "screenshots"), exist_ok=True)
    assert driver.find_element(By.ID, "crossdiv-viewer").screenshot(os.path.join(report, "screenshots", "viewer-uv.png"))
    assert not check_viewer.console_errors(driver)
