#!/usr/bin/env python3
"""Open3D as a crossdiv reference: one subdivision run of Open3D's TriangleMesh.

    open3d_subdivide.py SCHEME LEVELS IN.off OUT.ply
    open3d_subdivide.py --check
    open3d_subdivide.py --serve     (each run's SCHEME LEVELS IN.off OUT.ply as a request, adapters/common/serve.py)

Open3D 0.16 (Debian `python3-open3d`) subdivides through its Python module:
  loop   TriangleMesh.subdivide_loop(number_of_iterations=LEVELS): Loop's weights (beta of
         Loop's thesis), the 1-6-1 boundary vertex and the midpoint boundary edge (crossdiv's
         edge-only), no corner rule; positions in double precision.
  midpoint  TriangleMesh.subdivide_midpoint(number_of_iterations=LEVELS): each triangle into four
         at its edge midpoints, the old vertices kept (crossdiv's midpoint scheme).

The mesh goes in and out without Open3D's file readers, which may drop or merge vertices: the
OFF file the harness writes is parsed here into numpy arrays (every vertex kept, in order), and
the result is written as binary little-endian PLY with double coordinates, so every bit
Open3D computes reads back.

With --serve, Open3D is imported once (about a second) and every run of a suite worker is a
request to this one process (the harness's `serve=` key).

Exit status: 0 with OUT written; 2 for a bad command line or input file; 3 when Open3D cannot
be imported (--check prints why and exits 1: the manifest's setup command, so that a machine
without it records ref-unavailable).
"""
import sys


# crossdiv's scheme name -> Open3D's TriangleMesh method.
SUBDIVIDE = {"loop": "subdivide_loop", "midpoint": "subdivide_midpoint"}


def read_off(path):
    """Vertices (n x 3 float64) and triangles (m x 3 int32) of an OFF file of triangles."""
    import numpy as np
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#", 1)[0].split()]
    if not tokens or tokens[0] != "OFF":
        raise ValueError(f"{path}: not an OFF file")
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    vertices = np.array(tokens[at:at + 3 * nv], dtype=np.float64).reshape(nv, 3)
    at += 3 * nv
    faces = []
    for f in range(nf):
        n = int(tokens[at])
        if n != 3:
            raise ValueError(f"{path}: face {f} has {n} corners; Open3D's TriangleMesh holds triangles only")
        faces.append([int(t) for t in tokens[at + 1:at + 4]])
        at += 1 + n
    return vertices, np.array(faces, dtype=np.int32).reshape(len(faces), 3)


def write_ply(path, vertices, triangles):
    import numpy as np
    header = ("ply\nformat binary_little_endian 1.0\n"
              f"element vertex {len(vertices)}\nproperty double x\nproperty double y\nproperty double z\n"
              f"element face {len(triangles)}\nproperty list uchar int vertex_indices\nend_header\n")
    faces = np.zeros(len(triangles), dtype=[("n", "u1"), ("v", "<i4", (3,))])
    faces["n"] = 3
    faces["v"] = triangles
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(np.ascontiguousarray(vertices, dtype="<f8").tobytes())
        f.write(faces.tobytes())


def main(argv):
    try:
        import numpy as np
        import open3d as o3d
    except Exception as e:  # ImportError, or a library it links failing to load
        print(f"Open3D cannot be imported: {e} (Debian package python3-open3d)", file=sys.stderr)
        return 1 if argv[1:] == ["--check"] else 3
    if argv[1:] == ["--check"]:
        return 0
    if len(argv) != 5:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    scheme, levels, mesh_in, mesh_out = argv[1:]
    if scheme not in SUBDIVIDE:
        print(f"open3d has no {scheme} here (it has: {', '.join(SUBDIVIDE)})", file=sys.stderr)
        return 2
    if not levels.isdigit() or int(levels) < 1:
        print(f"levels must be a positive integer, got '{levels}'", file=sys.stderr)
        return 2
    try:
        vertices, triangles = read_off(mesh_in)
    except (OSError, ValueError, IndexError) as e:
        print(f"cannot read {mesh_in}: {e}", file=sys.stderr)
        return 2
    mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(vertices), o3d.utility.Vector3iVector(triangles))
    result = getattr(mesh, SUBDIVIDE[scheme])(number_of_iterations=int(levels))
    write_ply(mesh_out, np.asarray(result.vertices), np.asarray(result.triangles))
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--serve"]:
        import os
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
        from serve import serve
        sys.exit(serve(lambda args: main([sys.argv[0]] + args)))
    sys.exit(main(sys.argv))
