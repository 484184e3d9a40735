"""The Python module crossdiv: hand values on a tetrahedron, the references through it, the
subdivision matrix against subdivision, the comparison record against `crossdiv compare
--json`, and a Python function as the implementation under test (examples/python/loop_numpy.py).

Run by CTest with PYTHONPATH=build/python, CROSSDIV_BIN and CROSSDIV_SOURCE set."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest
import scipy.sparse
from scipy.spatial import cKDTree

import crossdiv

SOURCE = os.environ.get("CROSSDIV_SOURCE", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "examples", "python"))
from loop_numpy import loop_once  # noqa: E402

# A regular tetrahedron's corners, outward oriented.
TETRA_V = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float)
TETRA_F = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]], dtype=np.int32)


def largest_distance_to_nearest(A, B):
    """max over rows of A of the distance to the nearest row of B (A, B: n x 3)."""
    return cKDTree(B).query(A)[0].max()


def test_one_loop_level_of_a_tetrahedron_by_hand():
    V, F = crossdiv.subdivide(TETRA_V, TETRA_F, levels=1)
    assert V.shape == (10, 3) and F.shape == (16, 3) and F.dtype == np.int32
    # Valence 3: beta = 3/16, so a vertex point is 7/16 v + 3/16 (sum of the other three) =
    # 7/16 v - 3/16 v (the four corners sum to 0) = v / 4.
    np.testing.assert_array_equal(V[:4], TETRA_V / 4)
    # An edge point: 3/8 of its ends and 1/8 of the two other corners = (a + b) / 4.
    edge_points = {tuple(p) for p in V[4:]}
    for a in range(4):
        for b in range(a + 1, 4):
            assert tuple((TETRA_V[a] + TETRA_V[b]) / 4) in edge_points


def test_threads_give_the_bits_of_one_thread():
    # The tetrahedron at 7 levels: the last level's input has 24,576 edges, past the 8,192 below
    # which a pass stays on one thread.
    V1, F1 = crossdiv.subdivide(TETRA_V, TETRA_F, levels=7)
    V2, F2 = crossdiv.subdivide(TETRA_V, TETRA_F, levels=7, threads=2)
    assert F1.shape == (4 * 4**7, 3)
    np.testing.assert_array_equal(F1, F2)
    np.testing.assert_array_equal(V1, V2)  # bit for bit, not within a tolerance
    with pytest.raises(crossdiv.InputError, match="threads must be >= 1"):
        crossdiv.subdivide(TETRA_V, TETRA_F, threads=0)
    # Catmull-Clark likewise: the tetrahedron's 12 corners are 12 x 4**5 quads at 6 levels.
    C1, Q1 = crossdiv.subdivide(TETRA_V, TETRA_F, scheme="catmull-clark", levels=6)
    C2, Q2 = crossdiv.subdivide(TETRA_V, TETRA_F, scheme="catmull-clark", levels=6, threads=2)
    assert len(Q1) == 12 * 4**5
    np.testing.assert_array_equal(Q1, Q2)
    np.testing.assert_array_equal(C1, C2)


def test_arrays_out_are_the_meshs_own_memory():
    V, F = crossdiv.subdivide(TETRA_V, TETRA_F, levels=2)
    # Not copied: each array is a view on a buffer the module handed over.
    assert not V.flags.owndata and not F.flags.owndata and V.base is not None
    assert V.flags.c_contiguous and V.dtype == np.float64


def test_each_reference_refines_as_core_does():
    core, _ = crossdiv.subdivide(TETRA_V, TETRA_F, levels=2)
    for impl in ("opensubdiv", "openmesh", "cgal"):
        V, F = crossdiv.subdivide(TETRA_V, TETRA_F, levels=2, impl=impl)
        assert V.shape == core.shape and F.shape == (64, 3), impl
        # The same vertex set to rounding (each library numbers and sums in its own order).
        assert largest_distance_to_nearest(V, core) < 1e-15 and largest_distance_to_nearest(core, V) < 1e-15, impl


def test_the_subdivision_matrix_is_subdivision():
    S = crossdiv.subdivision_matrix(TETRA_V, TETRA_F)
    assert isinstance(S, scipy.sparse.csr_matrix) and S.shape == (10, 4)
    np.testing.assert_allclose(np.asarray(S.sum(axis=1)).ravel(), 1, rtol=0, atol=1e-15)
    V, _ = crossdiv.subdivide(TETRA_V, TETRA_F, levels=1)
    np.testing.assert_array_equal(S @ TETRA_V, V)
    assert S[0, 0] == 7 / 16 and S[0, 1] == 3 / 16


def test_meshes_and_curves_round_trip_through_files(tmp_path):
    path = str(tmp_path / "t.off")
    crossdiv.write_mesh(path, TETRA_V, TETRA_F)
    V, F = crossdiv.read_mesh(path)
    np.testing.assert_array_equal(V, TETRA_V)
    np.testing.assert_array_equal(F, TETRA_F)
    quads = str(tmp_path / "mixed.obj")
    crossdiv.write_mesh(quads, TETRA_V, [[0, 1, 2, 3], [0, 2, 3]])
    _, mixed = crossdiv.read_mesh(quads)
    assert [list(f) for f in mixed] == [[0, 1, 2, 3], [0, 2, 3]]
    curves = [{"name": "arc", "keyword": "bez2", "steps": 8, "control": np.array([[0, 0], [0.5, 1], [1.5, 1], [2, 0.1]])},
              {"name": "", "keyword": "bsp3", "steps": 4, "control": np.array([[0, 0, 0], [1, 0, 1], [1, 1, 2], [0, 1, 3]])},
              {"name": "loop", "keyword": "kpc2", "steps": 6, "control": np.array([[0, 0], [2, 0], [2, 1], [0, 1.5]])}]
    swp = str(tmp_path / "c.swp")
    crossdiv.write_curves(swp, curves)
    back = crossdiv.read_curves(swp)
    assert [(c["name"], c["keyword"], c["dim"], c["steps"]) for c in back] == [
        ("arc", "bez2", 2, 8), ("", "bsp3", 3, 4), ("loop", "kpc2", 2, 6)]
    with pytest.raises(crossdiv.InputError, match="keyword 'circ' is not a spline record"):
        crossdiv.write_curves(swp, [{"keyword": "circ", "control": np.zeros((4, 2))}])
    np.testing.assert_array_equal(back[0]["control"][:, :2], curves[0]["control"])
    np.testing.assert_array_equal(back[1]["control"], curves[1]["control"])


def test_bad_input_names_the_element():
    with pytest.raises(crossdiv.InputError, match="F face 1 corner 2: vertex 9 is not in V"):
        crossdiv.subdivide(TETRA_V, [[0, 1, 2], [0, 2, 9]])
    # An index past 32 bits is named as given, not as it would wrap.
    with pytest.raises(crossdiv.InputError, match="F face 0 corner 1: vertex 1099511627776 is not in V"):
        crossdiv.subdivide(TETRA_V, np.array([[0, 2**40, 2]], dtype=np.int64))
    # Indices are whole numbers: a fraction would be truncated, a bool or a string is no index.
    with pytest.raises(crossdiv.InputError, match="F face 0 corner 1: 1.999999999 is not a whole number"):
        crossdiv.subdivide(TETRA_V, np.array([[0, 1.999999999, 2]]))
    with pytest.raises(crossdiv.InputError, match="F face 1 corner 0: nan is not a whole number"):
        crossdiv.subdivide(TETRA_V, [[0, 1, 2], [math.nan, 1, 3]])
    with pytest.raises(crossdiv.InputError, match="F face 0 corner 0: a bool is not a vertex index"):
        crossdiv.subdivide(TETRA_V, np.array([[True, False, True]]))
    with pytest.raises(crossdiv.InputError, match="F face 0 corner 2: a str is not a vertex index"):
        crossdiv.subdivide(TETRA_V, [[0, 1, "2"]])
    with pytest.raises(crossdiv.InputError, match="F face 0 corner 0: a str_ is not a vertex index"):
        crossdiv.subdivide(TETRA_V, np.array([["0", "1", "2"]]))
    # Whole floats and every integer type are indices.
    whole = crossdiv.subdivide(TETRA_V, np.asarray(TETRA_F, dtype=np.float64))
    same = crossdiv.subdivide(TETRA_V, [[np.uint16(a), np.int8(b), int(c)] for a, b, c in TETRA_F])
    assert np.array_equal(whole[0], same[0])
    # Positions are real numbers: complex ones would lose their imaginary parts, bools are no coordinates.
    with pytest.raises(crossdiv.InputError, match="V is complex"):
        crossdiv.subdivide(TETRA_V + 1j, TETRA_F)
    with pytest.raises(crossdiv.InputError, match="V holds bools"):
        crossdiv.subdivide(TETRA_V > 0, TETRA_F)
    with pytest.raises(crossdiv.InputError, match=r"V must be an n x 3 array of positions \(got shape \(4, 2\)\)"):
        crossdiv.subdivide(TETRA_V[:, :2], TETRA_F)
    with pytest.raises(ValueError, match="V row 3 is not finite"):
        crossdiv.subdivide(np.vstack([TETRA_V[:3], [math.nan, 0, 0]]), TETRA_F)
    with pytest.raises(ValueError, match="unknown scheme"):
        crossdiv.subdivide(TETRA_V, TETRA_F, scheme="loopy")
    with pytest.raises(ValueError, match="cannot open|No such|not found|t.obj"):
        crossdiv.read_mesh("/nonexistent/t.obj")


def test_write_mesh_on_a_full_disk_raises_naming_the_file(tmp_path):
    # /dev/full fails every write with ENOSPC, as a full disk does.
    full = tmp_path / "full.obj"
    full.symlink_to("/dev/full")
    with pytest.raises(crossdiv.InputError, match="full.obj: cannot write: No space left on device"):
        crossdiv.write_mesh(str(full), TETRA_V, TETRA_F)


def test_compare_is_the_record_of_crossdiv_compare_json(tmp_path):
    mesh = str(tmp_path / "octa.off")
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    crossdiv.write_mesh(mesh, V, F)
    record = crossdiv.compare(V, F, levels=2, weights="warren", references=["opensubdiv", "openmesh"])
    out = str(tmp_path / "cli.json")
    subprocess.run([os.environ.get("CROSSDIV_BIN", os.path.join(SOURCE, "build", "verification", "crossdiv")),
                    "compare", mesh, "--levels", "2", "--weights", "warren", "--against", "opensubdiv,openmesh",
                    "--json", out], check=False, capture_output=True, timeout=300)
    with open(out) as f:
        cli = json.load(f)
    cli_record = cli["comparisons"][0] if "comparisons" in cli else cli
    key = lambda r: (r["reference"], r["verdict"], r.get("divergence_class"), r["positions"]["max_rel"])  # noqa: E731
    assert [key(r) for r in record["runs"]] == [key(r) for r in cli_record["runs"]]
    assert {r["divergence_class"] for r in record["runs"]} == {"weight-family"}


def test_compare_takes_every_scheme():
    # A 2 x 2 grid of quads: OpenMesh's Catmull-Clark applies its midpoint-average boundary rule,
    # OpenSubdiv's agrees; bilinear agrees with OpenSubdiv; a triangle scheme refuses the quads.
    V = np.array([[x, y, 0.1 * ((x + 2 * y) % 3)] for y in range(3) for x in range(3)], dtype=float)
    F = np.array([[3 * y + x, 3 * y + x + 1, 3 * y + x + 4, 3 * y + x + 3] for y in range(2) for x in range(2)])
    cc = crossdiv.compare(V, F, scheme="catmull-clark", levels=2, references=["opensubdiv", "openmesh"])
    assert cc["scheme"] == "catmull-clark" and cc["rule"] == "edge-only"
    outcome = {r["reference"]: (r["verdict"], r["divergence_class"]) for r in cc["runs"]}
    assert outcome == {"opensubdiv": ("agree", ""), "openmesh": ("diverge", "boundary-rule")}, outcome
    bilinear = crossdiv.compare(V, F, scheme="bilinear", levels=2)
    assert [(r["reference"], r["verdict"]) for r in bilinear["runs"]] == [("opensubdiv", "agree"), ("hbr", "agree")]
    assert len(bilinear["runs"][0]["positions"]["level_max_rel"]) == 2  # every level matched through provenance
    with pytest.raises(ValueError, match="weights name a Loop weight family"):
        crossdiv.compare(V, F, scheme="catmull-clark", weights="warren")
    with pytest.raises(ValueError, match="has 4 corners"):
        crossdiv.compare(V, F, scheme="sqrt3")


def test_a_python_loop_is_identified_by_its_rule():
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    loop = crossdiv.compare(V, F, levels=2, references=["opensubdiv"], subject=loop_once)
    assert loop["subject"]["status"] == "ok"
    assert loop["subject"]["rules"]["rule"] == "weights=loop boundary=edge-only"
    assert loop["runs"][0]["verdict"] == "agree"
    warren = crossdiv.compare(V, F, levels=2, references=["opensubdiv"], subject=lambda V, F: loop_once(V, F, "warren"))
    assert warren["subject"]["rules"]["rule"] == "weights=warren boundary=edge-only"
    assert warren["runs"][0]["divergence_class"] == "weight-family"


def test_a_python_subject_of_every_scheme_is_named():
    # The course-style programs of examples/subjects/python-schemes, called one level at a time
    # on numpy arrays, each named by the rule it follows on a patch with a boundary.
    sys.path.insert(0, os.path.join(SOURCE, "examples", "subjects", "python-schemes"))
    import bilinear
    import butterfly
    import catmull_clark
    import doo_sabin
    import midpoint
    import modified_butterfly
    import sqrt3
    V = np.array([[x, y, 0.1 * ((x * x + 2 * y) % 3)] for y in range(4) for x in range(4)], dtype=float)
    F = np.array([t for y in range(3) for x in range(3)
                  for t in ([4 * y + x, 4 * y + x + 1, 4 * y + x + 5], [4 * y + x, 4 * y + x + 5, 4 * y + x + 4])])
    expected = {"catmull-clark": (catmull_clark, "edge-only"), "doo-sabin": (doo_sabin, "drop-border-faces"),
                "sqrt3": (sqrt3, "restart-each-level"), "butterfly": (butterfly, "reflected-wings"),
                "modified-butterfly": (modified_butterfly, "reflected-wings"), "bilinear": (bilinear, "linear"),
                "midpoint": (midpoint, "linear")}
    def as_lists(subdivide):  # the programs take Python lists, as the course's tables are
        return lambda V, F: subdivide(np.asarray(V, dtype=float).tolist(), [[int(i) for i in f] for f in F])
    for scheme, (module, rule) in expected.items():
        record = crossdiv.compare(V, F, scheme=scheme, levels=2, subject=as_lists(module.subdivide), subject_name=scheme)
        assert record["subject"]["status"] == "ok", (scheme, record["subject"]["status_message"])
        assert record["subject"]["rules"]["rule"] == rule, (scheme, record["subject"]["rules"])
    # One that drops a face is held to the counts of the scheme it is given as.
    record = crossdiv.compare(V, F, scheme="doo-sabin", levels=1,
                              subject=lambda V, F: (lambda m: (m[0], m[1][1:]))(as_lists(doo_sabin.subdivide)(V, F)))
    assert record["subject"]["status"] == "wrong-count", record["subject"]


def test_a_subject_that_raises_or_lies_is_recorded_not_raised():
    def broken(V, F):
        raise RuntimeError("my bug")
    record = crossdiv.compare(TETRA_V, TETRA_F, levels=1, references=["opensubdiv"], subject=broken)
    assert record["subject"]["status"] != "ok" and "my bug" in record["subject"]["status_message"]
    assert record["runs"] == []

    def non_finite(V, F):
        V1, F1 = loop_once(V, F)
        V1[0, 0] = math.nan
        return V1, F1
    record = crossdiv.compare(TETRA_V, TETRA_F, levels=1, references=["opensubdiv"], subject=non_finite)
    assert record["subject"]["status"] != "ok"

    def fractional_faces(V, F):
        V1, F1 = loop_once(V, F)
        return V1, np.asarray(F1) + 0.3
    record = crossdiv.compare(TETRA_V, TETRA_F, levels=1, references=["opensubdiv"], subject=fractional_faces)
    assert record["subject"]["status"] != "ok" and "is not a whole number" in record["subject"]["status_message"]


def test_a_python_subject_is_not_starved_by_busy_threads():
    # The forked child must own the interpreter's lock even when another thread held or wanted it
    # at the fork; before, 16 of 20 runs with three busy threads were recorded as timeouts.
    import threading
    stop = threading.Event()

    def busy():
        x = 0
        while not stop.is_set():
            x += 1
    threads = [threading.Thread(target=busy) for _ in range(3)]
    for t in threads:
        t.start()
    try:
        statuses = [crossdiv.compare(TETRA_V, TETRA_F, levels=1, references=["opensubdiv"], subject=loop_once,
                                     timeout=30)["subject"]["status"] for _ in range(10)]
    finally:
        stop.set()
        for t in threads:
            t.join()
    assert statuses == ["ok"] * 10


# A tetrahedron and one vertex no face uses: CGAL's Loop dereferences the isolated vertex's
# missing halfedge (SIGSEGV in Debian 12's CGAL 5.5).
ISOLATED_V = np.vstack([TETRA_V, [5, 5, 5]])


def test_a_library_that_crashes_raises_an_error_naming_it():
    with pytest.raises(crossdiv.InputError, match="cgal failed on the mesh: crashed"):
        crossdiv.subdivide(ISOLATED_V, TETRA_F, impl="cgal")
    # The interpreter lives on, and core takes the same mesh.
    V, F = crossdiv.subdivide(ISOLATED_V, TETRA_F)
    assert V.shape == (11, 3) and F.shape == (16, 3)


def test_subdivide_refuses_a_result_past_its_face_bound():
    # Two tetrahedra, 12 levels: 8 * 4^12 = 134M faces > 64 Mi (before: 14 GB, then MemoryError), refused
    # before any work, as crossdiv subdivide --max-faces does.
    with pytest.raises(crossdiv.InputError, match="12 levels would produce 134217728 faces, over the limit of 67108864 "
                                                  r"\(max_faces\)"):
        crossdiv.subdivide(np.vstack([TETRA_V, TETRA_V + 3]), np.vstack([TETRA_F, TETRA_F + 4]), levels=12)
    with pytest.raises(crossdiv.InputError, match="max_faces"):
        crossdiv.subdivide(TETRA_V, TETRA_F, levels=3, max_faces=255)
    assert crossdiv.subdivide(TETRA_V, TETRA_F, levels=3, max_faces=256)[1].shape == (256, 3)


def test_the_example_script_names_warrens_rule_and_draws(tmp_path):
    mesh, png = str(tmp_path / "tetra.off"), str(tmp_path / "plot.png")
    crossdiv.write_mesh(mesh, TETRA_V * 0.5, TETRA_F)
    # Valence 3 everywhere: Warren's weights equal Loop's there, so the two agree.
    done = subprocess.run(["/usr/bin/python3", os.path.join(SOURCE, "examples", "python", "compare_with_opensubdiv.py"), mesh,
                           "--weights", "warren", "-o", png], capture_output=True, text=True, timeout=300,
                          env=dict(os.environ))
    assert done.returncode == 0, done.stderr
    assert "numpy Loop vs opensubdiv: agree" in done.stdout, done.stdout
    assert os.path.getsize(png) > 5000


def test_texture_coordinates_refine_under_each_rule_and_compare_per_corner():
    # Two quads with a seam on their shared edge (1, 4): the left quad's values there are
    # (1, 0) and (1, 1), the right quad's (3, 0) and (3, 3).
    V = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]], dtype=float)
    F = np.array([[0, 1, 4, 3], [1, 2, 5, 4]])
    UV = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [3, 0], [4, 0], [4, 1], [3, 3]], dtype=float)
    FUV = np.array([[0, 1, 2, 3], [4, 5, 6, 7]])
    V1, F1, UV1, FUV1 = crossdiv.subdivide(V, F, scheme="catmull-clark", levels=1, UV=UV, FUV=FUV, fvar="none")
    assert FUV1.shape == F1.shape == (8, 4)
    # Vertex 4 keeps its index; in the left quad's children (quads 0..3) its value is the
    # crease 3/4 (1,1) + 1/8 (1,0) + 1/8 (0,1), in the right one's 3/4 (3,3) + 1/8 (4,1) + 1/8 (3,0).
    left = [UV1[FUV1[q][k]] for q in range(4) for k in range(4) if F1[q][k] == 4]
    right = [UV1[FUV1[q][k]] for q in range(4, 8) for k in range(4) if F1[q][k] == 4]
    assert all(np.array_equal(x, [0.875, 0.875]) for x in left) and left
    assert all(np.array_equal(x, [3.125, 2.375]) for x in right) and right
    # The same through OpenSubdiv, in its numbering: the same values at vertex 4's corners.
    Vo, Fo, UVo, FUVo = crossdiv.subdivide(V, F, scheme="catmull-clark", levels=1, UV=UV, FUV=FUV, fvar="none",
                                           impl="opensubdiv")
    at4 = sorted(tuple(UVo[FUVo[q][k]]) for q in range(len(Fo)) for k in range(4) if Fo[q][k] == 4)
    assert at4 == [(0.875, 0.875), (3.125, 2.375)]
    # compare: a per-corner verdict beside the positions'.
    record = crossdiv.compare(V, F, scheme="catmull-clark", levels=2, references=["opensubdiv"], UV=UV, FUV=FUV,
                              fvar="corners-only")
    assert record["face_varying"] == "corners-only"
    assert record["runs"][0]["uv"]["verdict"] == "agree"
    # Bad channels are refused by name.
    with pytest.raises(crossdiv.InputError, match="FUV face 1 corner 2: texture coordinate 9 is not in UV"):
        crossdiv.subdivide(V, F, scheme="catmull-clark", UV=UV, FUV=np.array([[0, 1, 2, 3], [4, 5, 9, 7]]))
    with pytest.raises(crossdiv.InputError, match="FUV face 1 has 3 corners where F face 1 has 4"):
        crossdiv.subdivide(V, F, scheme="catmull-clark", UV=UV, FUV=[[0, 1, 2, 3], [4, 5, 6]])
    with pytest.raises(crossdiv.InputError, match="UV and FUV go together"):
        crossdiv.subdivide(V, F, scheme="catmull-clark", UV=UV)
    with pytest.raises(crossdiv.InputError, match="unknown face-varying rule 'smooth'"):
        crossdiv.subdivide(V, F, scheme="catmull-clark", UV=UV, FUV=FUV, fvar="smooth")


def test_invariance_finds_a_python_loop_that_reads_how_the_input_is_written():
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    # Loop itself: the same surface however the octahedron is written.
    rows = crossdiv.invariance(V, F, levels=1, impls=["core"])
    assert len(rows) == 15, rows
    # One component and one level: nothing to refine apart, nor level by level.
    assert {r["transformation"] for r in rows if r["result"] == "not-compared"} == {"components", "level-by-level"}, rows
    assert {r["result"] for r in rows} == {"invariant", "not-compared"}, rows
    assert {r["transformation"] for r in rows if r["bit_identical"]} >= {"scale", "swap-axes", "mirror", "repeat"}

    def shifted(V, F):  # right, except that its first new point moves with the first face's first corner
        V2, F2 = loop_once(V, F)
        V2 = np.array(V2, dtype=float)
        V2[len(V)] += 1e-3 * int(F[0][0])
        return V2, F2
    rows = crossdiv.invariance(V, F, levels=1, subject=shifted, subject_name="shifted",
                               transforms=["rotate-corners", "scale"])
    by = {r["transformation"]: r for r in rows}
    assert by["rotate-corners"]["result"] == "not-invariant", by["rotate-corners"]
    assert by["rotate-corners"]["implementation"] == "shifted"
    assert by["rotate-corners"]["cause"]["class"] == "unexplained"
    assert by["scale"]["result"] == "invariant"
    with pytest.raises(ValueError, match="unknown transformation"):
        crossdiv.invariance(V, F, transforms=["spin"])
