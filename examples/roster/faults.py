"""The class of the roster example: each submission is a course-style Loop or Catmull-Clark
(examples/subjects) with one fault planted, named in its folder's subdivide.py. A submission
runs as

    python3 submissions/NAME/subdivide.py IN.obj LEVELS OUT.obj

Faults: none; warren (the assignment's Loop weights: another named rule); corners-kept
(one-face corners stay: the edge-and-corner rule); weights (a vertex weight no one names);
boundary (boundary vertices left in place); corners (one-face corners moved to the average of
their boundary neighbours); crash (SIGSEGV); hang; nan (one coordinate NaN); shuffle (a
correct result in a random numbering); wrong-count (the last face dropped).
"""
import os
import random
import signal
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "subjects", "python-loop"))
sys.path.insert(0, os.path.join(HERE, "..", "subjects", "python-schemes"))
import catmull_clark  # noqa: E402
import loop  # noqa: E402
import polymesh  # noqa: E402


def loop_beta(n):
    """Loop's 1987 weight of each neighbour of an interior vertex of valence n."""
    import math
    return (5.0 / 8.0 - (3.0 / 8.0 + math.cos(2.0 * math.pi / n) / 4.0) ** 2) / n


def one_face_corners(verts, faces):
    """The vertices of exactly one face that lie on the boundary, each with its two boundary neighbours."""
    t = polymesh.Tables(verts, faces)
    return {v: t.boundary_neighbours[v] for v in range(len(verts)) if t.face_count[v] == 1 and len(t.boundary_neighbours[v]) == 2}


def boundary_vertices(verts, faces):
    t = polymesh.Tables(verts, faces)
    return [v for v in range(len(verts)) if t.on_boundary(v)]


def submission(scheme, fault):
    src, levels, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    if fault == "crash":
        os.kill(os.getpid(), signal.SIGSEGV)
    if fault == "hang":
        time.sleep(3600)
    if scheme == "loop":
        loop.even_beta = loop_beta if fault != "warren" else loop.even_beta
        if fault == "weights":
            loop.even_beta = lambda n: 1.0 / (2.0 * n)
        refine = loop.subdivide
    else:
        if fault == "weights":
            catmull_clark.vertex_point = lambda F, R, P, n: polymesh.scale(
                polymesh.add(polymesh.add(F, R, 1.0), P, n - 2.0), 1.0 / n)
        refine = catmull_clark.subdivide
    verts, faces = polymesh.read_obj(src)
    for _ in range(levels):
        # Old vertices keep their indices in both programs: a fault on them reads the old level.
        corners = one_face_corners(verts, faces)
        boundary = boundary_vertices(verts, faces)
        old = [list(p) for p in verts]
        verts, faces = refine(verts, faces)
        if fault == "boundary":
            for v in boundary:
                verts[v] = old[v]
        if fault == "corners-kept":
            for v in corners:
                verts[v] = old[v]
        if fault == "corners":
            for v, (a, b) in corners.items():
                verts[v] = polymesh.scale(polymesh.add(old[a], old[b]), 0.5)
    if fault == "nan":
        verts[len(verts) // 2][1] = float("nan")
    if fault == "wrong-count":
        faces.pop()
    if fault == "shuffle":
        rng = random.Random(7)
        order = list(range(len(verts)))
        rng.shuffle(order)
        new_of = {old: new for new, old in enumerate(order)}
        verts = [verts[old] for old in order]
        faces = [[new_of[v] for v in f] for f in faces]
        rng.shuffle(faces)
    polymesh.write_obj(out, verts, faces)
