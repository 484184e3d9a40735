#!/usr/bin/env python3
"""Loop subdivision as a course student writes it from the assignment text (CS-C3100 A2):
index-connectivity tables, odd vertices 3/8, 3/8, 1/8, 1/8, even vertices with
B = 3/(8n) for n > 3 and B = 3/16 for n = 3, and the boundary rules from Zorin's course
notes (boundary edge: midpoint; boundary vertex: 1/8, 3/4, 1/8). Standard library only.

    python3 loop.py IN.obj LEVELS OUT.obj
"""
import sys


def read_obj(path):
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                verts.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                faces.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    return verts, faces


def write_obj(path, verts, faces):
    with open(path, "w") as f:
        for v in verts:
            f.write("v %r %r %r\n" % (v[0], v[1], v[2]))
        for t in faces:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def add(a, b, s=1.0):
    return [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]]


def scale(a, s):
    return [a[0] * s, a[1] * s, a[2] * s]


def even_beta(n):
    """The weight of each neighbour of an old interior vertex of valence n."""
    return 3.0 / 16.0 if n == 3 else 3.0 / (8.0 * n)


def subdivide(verts, faces):
    # Connectivity: the faces around each edge, the neighbours of each vertex.
    edge_faces = {}
    for fi, t in enumerate(faces):
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            edge_faces.setdefault((min(a, b), max(a, b)), []).append(fi)
    neighbours = [set() for _ in verts]
    boundary_neighbours = [[] for _ in verts]
    for (a, b), fs in edge_faces.items():
        neighbours[a].add(b)
        neighbours[b].add(a)
        if len(fs) == 1:
            boundary_neighbours[a].append(b)
            boundary_neighbours[b].append(a)

    # Odd vertices, one per edge, numbered after the old ones in the order the faces meet them.
    new_verts = [None] * len(verts)
    edge_index = {}
    for t in faces:
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            key = (min(a, b), max(a, b))
            if key in edge_index:
                continue
            fs = edge_faces[key]
            if len(fs) == 2:
                opposite = [sum(faces[f]) - a - b for f in fs]
                p = add(scale(add(verts[a], verts[b]), 3.0 / 8.0), scale(add(verts[opposite[0]], verts[opposite[1]]), 1.0 / 8.0))
            else:
                p = scale(add(verts[a], verts[b]), 0.5)
            edge_index[key] = len(new_verts)
            new_verts.append(p)

    # Even vertices.
    for v in range(len(verts)):
        n = len(neighbours[v])
        if boundary_neighbours[v]:
            b0, b1 = boundary_neighbours[v][0], boundary_neighbours[v][-1]
            new_verts[v] = add(scale(verts[v], 3.0 / 4.0), scale(add(verts[b0], verts[b1]), 1.0 / 8.0))
        elif n == 0:
            new_verts[v] = list(verts[v])
        else:
            beta = even_beta(n)
            s = [0.0, 0.0, 0.0]
            for w in neighbours[v]:
                s = add(s, verts[w])
            new_verts[v] = add(scale(verts[v], 1.0 - n * beta), scale(s, beta))

    new_faces = []
    for t in faces:
        a, b, c = t
        ab = edge_index[(min(a, b), max(a, b))]
        bc = edge_index[(min(b, c), max(b, c))]
        ca = edge_index[(min(c, a), max(c, a))]
        new_faces += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
    return new_verts, new_faces


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: loop.py IN.obj LEVELS OUT.obj")
    verts, faces = read_obj(sys.argv[1])
    for _ in range(int(sys.argv[2])):
        verts, faces = subdivide(verts, faces)
    write_obj(sys.argv[3], verts, faces)


if __name__ == "__main__":
    main()
