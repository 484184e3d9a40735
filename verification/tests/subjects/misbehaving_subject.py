#!/usr/bin/env python3
"""A subject that fails in one named way, for the tests of the harness's program runs:

    misbehaving_subject.py MODE IN.obj LEVELS OUT.obj [SCHEME]
    misbehaving_subject.py --serve      (each run's MODE IN.obj LEVELS OUT.obj [SCHEME] as a request)

SCHEME (loop when not given) is any scheme of examples/subjects/python-schemes; the modes that
write a mesh start from that scheme's course-style example.

MODE: crash (SIGSEGV), hang, exit (status 3 with a message on stderr), nothing (exit 0, no
file), nan, garbage (an unreadable line), wrong-count (one face dropped), quads (two
triangles written as one quad), shuffle (Loop's own weights, or the scheme's example, with
vertices, faces and each face's corners in a random order: a correct result in another numbering), float (Loop's own
weights, every coordinate rounded to float32 and written as binary PLY, as MeshLab writes: a
correct result of a float implementation; OUT names the .ply), float-shuffle (the two at once:
a float implementation that numbers its vertices otherwise), keep-boundary (Loop's own
weights, but every boundary vertex left where it is: a rule no one names), closed-only (exits
with a traceback on any input with a boundary edge, as a program that assumes two faces per
edge does), midpoint (Loop's connectivity, but old vertices kept and every edge point its
edge's midpoint: a midpoint subdivision handed in as Loop), reversed (every face's winding
reversed), scrambled (the faces replaced by as many random triangles over the same vertices),
duplicate-face (the last face replaced by a copy of the first): the right positions with faces
that are not the scheme's.

Modes of a program that tries to outlive or overrun its run (PIDFILE after SCHEME): escape
(Loop's own result, but first a child that leaves the process group by setsid, writes its id
to PIDFILE and sleeps for an hour), hang-pid (writes its own id to PIDFILE, then hangs), hog
(asks for 8 GiB at once before writing Loop's own result).
"""
import math
import os
import random
import signal
import struct
import sys
import time

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "subjects")
sys.path.insert(0, os.path.join(EXAMPLES, "python-loop"))
sys.path.insert(0, os.path.join(EXAMPLES, "python-schemes"))
import importlib  # noqa: E402

import loop  # noqa: E402

# The course-style example of each scheme other than Loop, by the name crossdiv gives it.
SCHEME_MODULES = {"catmull-clark": "catmull_clark", "doo-sabin": "doo_sabin", "sqrt3": "sqrt3", "butterfly": "butterfly",
                  "modified-butterfly": "modified_butterfly", "bilinear": "bilinear",
                  "midpoint": "midpoint"}


def loop_beta(n):
    """Loop's 1987 weight: (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n."""
    return (5.0 / 8.0 - (3.0 / 8.0 + math.cos(2.0 * math.pi / n) / 4.0) ** 2) / n


def write_pid(path, pid):
    # A part file of this process's own: two runs of a suite's jobs may write one PIDFILE at once,
    # and a shared part file would be replaced by one of them under the other.
    part = "%s.%d.part" % (path, os.getpid())
    with open(part, "w") as f:
        f.write("%d\n" % pid)
    os.replace(part, path)  # whole or absent for whoever polls it


def escape(pidfile):
    """A child in a session of its own, out of the process group crossdiv kills."""
    if os.fork() == 0:
        os.setsid()
        write_pid(pidfile, os.getpid())
        time.sleep(3600)
        os._exit(0)
    while not os.path.exists(pidfile):
        time.sleep(0.01)


def main(argv):
    mode, src, levels, out = argv[1], argv[2], int(argv[3]), argv[4]
    if mode == "crash":
        os.kill(os.getpid(), signal.SIGSEGV)
    if mode == "hang":
        time.sleep(3600)
    if mode == "hang-pid":
        write_pid(argv[6], os.getpid())
        time.sleep(3600)
    if mode == "escape":
        escape(argv[6])
    if mode == "hog":
        hog = bytearray(8 << 30)  # noqa: F841 (held until the result is written)
    if mode == "exit":
        sys.stderr.write("cannot subdivide: half-edge table overflow\n")
        sys.exit(3)
    if mode == "nothing":
        return
    scheme = argv[5] if len(argv) > 5 else "loop"
    if mode == "midpoint":
        butterfly = importlib.import_module("butterfly")
        butterfly.four_point = midpoint = lambda t, vs, a, b: loop.scale(loop.add(vs[a], vs[b]), 0.5)  # boundary edges too
        verts, faces = loop.read_obj(src)
        for _ in range(levels):
            verts, faces = butterfly.subdivide(verts, faces, midpoint)
        loop.write_obj(out, verts, faces)
        return
    loop.even_beta = loop_beta
    verts, faces = loop.read_obj(src)
    if scheme != "loop":
        module = importlib.import_module(SCHEME_MODULES[scheme])
        for _ in range(levels):
            verts, faces = module.subdivide(verts, faces)
    for _ in range(levels if scheme == "loop" else 0):
        edges = {}
        for t in faces:
            for k in range(3):
                edge = (min(t[k], t[(k + 1) % 3]), max(t[k], t[(k + 1) % 3]))
                edges[edge] = edges.get(edge, 0) + 1
        if mode == "closed-only":
            assert all(n == 2 for n in edges.values()), "an edge without its second face"
        boundary = {v for edge, n in edges.items() if n == 1 for v in edge} if mode == "keep-boundary" else set()
        kept = {v: list(verts[v]) for v in boundary}
        verts, faces = loop.subdivide(verts, faces)
        for v, p in kept.items():
            verts[v] = p
    if mode == "nan":
        verts[len(verts) // 2][1] = float("nan")
    if mode == "wrong-count":
        faces.pop()
    if mode == "reversed":
        faces = [list(reversed(t)) for t in faces]
    if mode == "scrambled":
        rng = random.Random(5)
        faces = [rng.sample(range(len(verts)), 3) for _ in faces]
    if mode == "duplicate-face":
        faces[-1] = list(faces[0])
    if mode == "garbage":
        with open(out, "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n")
        return
    if mode == "quads":
        with open(out, "w") as f:
            for v in verts:
                f.write("v %r %r %r\n" % tuple(v))
            a, b = faces[0], faces[1]
            f.write("f %d %d %d %d\n" % (a[0] + 1, a[1] + 1, a[2] + 1, b[0] + 1))
            for t in faces[2:]:
                f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))
        return
    if mode in ("shuffle", "float-shuffle"):
        rng = random.Random(17)
        order = list(range(len(verts)))
        rng.shuffle(order)  # order[new] = old
        new_of = [0] * len(verts)
        for new, old in enumerate(order):
            new_of[old] = new
        verts = [verts[old] for old in order]
        faces = [[new_of[v] for v in t] for t in faces]
        rng.shuffle(faces)
        faces = [t[k:] + t[:k] for t, k in ((t, rng.randrange(len(t))) for t in faces)]
    if mode in ("float", "float-shuffle"):
        with open(out, "wb") as f:
            f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                     "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                     % (len(verts), len(faces))).encode())
            for v in verts:
                f.write(struct.pack("<3f", *v))
            for t in faces:
                f.write(struct.pack("<B3i", 3, *t))
        return
    with open(out, "w") as f:
        for v in verts:
            f.write("v %r %r %r\n" % tuple(v))
        for t in faces:
            f.write("f " + " ".join(str(i + 1) for i in t) + "\n")


if __name__ == "__main__":
    if sys.argv[1:] == ["--serve"]:
        # The same modes, each run a request to this one process (adapters/common/serve.py): a
        # crash or a hang ends the server with the run.
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "adapters", "common"))
        from serve import serve
        sys.exit(serve(lambda args: main([sys.argv[0]] + args)))
    main(sys.argv)
