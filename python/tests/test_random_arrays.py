"""The Python module's array inputs fuzzed: random V and F of every shape, dtype and value class
(NaN, infinities, 1e308, negative and out-of-range indices, fractions, bools, strings, objects,
ragged lists) handed to subdivide, write_mesh and compare. Each call must either refuse with
crossdiv.InputError, ValueError or TypeError, or answer with a finite mesh whose faces index its
vertices; a crash ends the interpreter and so the test.

A fixed seed and 1500 cases by default; CROSSDIV_PYTHON_FUZZ_SECONDS=N runs random seeds for N
seconds instead (fuzz/README.md: the long run)."""
import os
import time

import numpy as np

import crossdiv

SCHEMES = ["loop", "catmull-clark", "doo-sabin", "sqrt3", "butterfly", "modified-butterfly", "bilinear", "midpoint"]
REFUSALS = (crossdiv.InputError, ValueError, TypeError)


def random_values(rng, shape):
    """Coordinates of one value class: ordinary, huge, tiny, with NaN or infinity."""
    kind = rng.integers(6)
    x = rng.normal(size=shape)
    if kind == 0 and x.ndim == 2 and len(x) >= 3:  # a few shared positions, as welded meshes have
        x[len(x) // 2] = x[0]
    if kind == 1:
        x *= 1e308
    elif kind == 2:
        x *= 1e-300
    elif kind == 3 and x.size:
        x.flat[rng.integers(x.size)] = np.nan
    elif kind == 4 and x.size:
        x.flat[rng.integers(x.size)] = np.inf
    return x


def random_V(rng):
    n = int(rng.integers(0, 12))
    shape = [(n, 3)] * 6 + [(n, 2), (n, 4), (n,), (n, 3, 1)]
    shape = shape[rng.integers(len(shape))]
    V = random_values(rng, shape)
    dtype = [np.float64] * 5 + [np.float32, np.int64, np.bool_, object, np.complex128, str]
    dtype = dtype[rng.integers(len(dtype))]
    try:
        return V.astype(dtype)
    except (ValueError, OverflowError):
        return V


def random_index(rng, n):
    kind = rng.integers(10)
    if kind < 6:
        return int(rng.integers(0, max(n, 1)))
    return [-1, n, 2**40, 1.5, float("nan"), True, "1", None][rng.integers(8)] if kind < 9 else 2**31


def random_F(rng, n):
    m = int(rng.integers(0, 10))
    corners = [3, 3, 3, 4, 4, 2, 5, 1][rng.integers(8)]
    if rng.integers(3) == 0:  # a list, ragged or with entries of any type
        return [[random_index(rng, n) for _ in range(int(rng.integers(1, 6)))] for _ in range(m)]
    F = rng.integers(-1 if rng.integers(4) == 0 else 0, max(n, 1) + (rng.integers(4) == 0), size=(m, corners))
    dtype = [np.int32, np.int64, np.uint8, np.int8, np.float64, np.bool_, object, str][rng.integers(8)]
    F = F.astype(dtype)
    if dtype == np.float64 and F.size and rng.integers(2):
        F.flat[rng.integers(F.size)] += 0.5
    return F if rng.integers(6) else F.reshape(-1)


def check_mesh(V, F):
    """An answer: finite n x 3 float64 positions and faces that index them."""
    V = np.asarray(V)
    assert V.dtype == np.float64 and V.ndim == 2 and V.shape[1] == 3
    assert np.isfinite(V).all()
    faces = [np.asarray(F)] if isinstance(F, np.ndarray) else [np.asarray(f) for f in F]
    for f in faces:
        if f.size:
            assert f.min() >= 0 and f.max() < len(V)


def one_case(rng, tmp_path, with_compare):
    V = random_V(rng)
    F = random_F(rng, len(V) if hasattr(V, "__len__") else 0)
    scheme = SCHEMES[rng.integers(len(SCHEMES))]
    # Complex or bool positions are no coordinates: cast, they would be answered wrongly.
    not_real = isinstance(V, np.ndarray) and V.dtype.kind in "cb"
    try:
        check_mesh(*crossdiv.subdivide(V, F, scheme=scheme, levels=int(rng.integers(0, 3))))
        assert not not_real, f"V of dtype {V.dtype} was taken as coordinates"
    except REFUSALS:
        pass
    path = str(tmp_path / ["m.obj", "m.off", "m.ply"][rng.integers(3)])
    try:
        crossdiv.write_mesh(path, V, F)
    except REFUSALS:
        pass
    else:
        W, G = crossdiv.read_mesh(path)
        check_mesh(W, G)
    if with_compare:
        try:
            record = crossdiv.compare(V, F, levels=1, scheme=scheme, references=["opensubdiv"], timeout=30)
            assert isinstance(record, dict) and "runs" in record
        except REFUSALS:
            pass


def test_random_arrays_are_refused_or_answered(tmp_path):
    seconds = float(os.environ.get("CROSSDIV_PYTHON_FUZZ_SECONDS", "0"))
    if seconds > 0:
        seed, cases, end = int(time.time()), 0, time.monotonic() + seconds
        while time.monotonic() < end:
            rng = np.random.default_rng(seed + cases)
            one_case(rng, tmp_path, with_compare=cases % 20 == 0)
            cases += 1
        print(f"{cases} random cases from seed {seed}, nothing found")
        return
    rng = np.random.default_rng(43)
    for k in range(1500):
        one_case(rng, tmp_path, with_compare=k % 25 == 0)
