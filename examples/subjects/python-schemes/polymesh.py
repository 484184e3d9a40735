"""The mesh tables the course's subdivision exercises are written against: a polygon mesh as a
list of vertex positions and a list of faces (vertex indices, counter-clockwise), with the
edge table, each edge's faces and each vertex's boundary neighbours. Standard library only.

An OBJ file is read for its 'v' and 'f' lines; everything else ('vt', 'vn', groups, tags) is
ignored, as a course program does.
"""


import sys


def main(subdivide):
    """The command line every exercise shares: IN.obj LEVELS OUT.obj, `subdivide` applied
    LEVELS times to (verts, faces)."""
    src, levels, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    verts, faces = read_obj(src)
    for _ in range(levels):
        verts, faces = subdivide(verts, faces)
    write_obj(out, verts, faces)


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
        for face in faces:
            f.write("f " + " ".join(str(i + 1) for i in face) + "\n")


def add(a, b, s=1.0):
    return [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]]


def scale(a, s):
    return [a[0] * s, a[1] * s, a[2] * s]


def combine(verts, terms):
    """The affine combination sum w * verts[i] of (i, w) terms."""
    p = [0.0, 0.0, 0.0]
    for i, w in terms:
        p = add(p, verts[i], w)
    return p


def with_edge_midpoints(verts, t):
    """The old vertices, then one midpoint per edge of the Tables `t` (in its edge order), and
    each edge's index among them: the first half of every linear subdivision."""
    new_verts = [list(p) for p in verts]
    edge_index = {}
    for a, b in t.edges:
        edge_index[(a, b)] = len(new_verts)
        new_verts.append(scale(add(verts[a], verts[b]), 0.5))
    return new_verts, edge_index


def centroid(verts, face):
    return combine(verts, [(i, 1.0 / len(face)) for i in face])


def key(a, b):
    return (min(a, b), max(a, b))


class Tables:
    """Connectivity of one level: each half-edge (a, b) maps to its face and its position in
    it; each edge to its faces; each vertex to its boundary neighbours."""

    def __init__(self, verts, faces):
        self.faces = faces
        self.half_edge = {}   # (a, b) -> (face, corner of a)
        self.edge_faces = {}  # key(a, b) -> [faces]
        self.edges = []       # each edge once, in the order the faces meet them
        for fi, face in enumerate(faces):
            n = len(face)
            for k in range(n):
                a, b = face[k], face[(k + 1) % n]
                self.half_edge[(a, b)] = (fi, k)
                e = key(a, b)
                if e not in self.edge_faces:
                    self.edge_faces[e] = []
                    self.edges.append(e)
                self.edge_faces[e].append(fi)
        self.neighbours = [[] for _ in verts]
        self.boundary_neighbours = [[] for _ in verts]
        self.face_count = [0] * len(verts)
        for a, b in self.edges:
            self.neighbours[a].append(b)
            self.neighbours[b].append(a)
            if len(self.edge_faces[(a, b)]) == 1:
                self.boundary_neighbours[a].append(b)
                self.boundary_neighbours[b].append(a)
        for face in faces:
            for v in face:
                self.face_count[v] += 1

    def is_boundary_edge(self, a, b):
        return len(self.edge_faces[key(a, b)]) == 1

    def on_boundary(self, v):
        return len(self.boundary_neighbours[v]) > 0

    def third_vertex(self, a, b):
        """The vertex after b in the triangle that has half-edge a -> b, or None."""
        hit = self.half_edge.get((a, b))
        if hit is None:
            return None
        face, k = hit
        return self.faces[face][(k + 2) % len(self.faces[face])]

    def boundary_before(self, v):
        """The boundary vertex before v along its boundary (the tail of the boundary edge into v)."""
        for u in self.boundary_neighbours[v]:
            if (u, v) in self.half_edge:
                return u
        return v

    def boundary_after(self, v):
        """The boundary vertex after v (the head of the boundary edge out of v)."""
        for u in self.boundary_neighbours[v]:
            if (v, u) in self.half_edge:
                return u
        return v

    def ring(self, v, first):
        """v's neighbours in order around v, starting at `first` (an interior vertex)."""
        ring, u = [first], first
        while True:
            u = self.third_vertex(v, u)  # the face with half-edge v -> u, its vertex after u
            if u is None or u == first:
                return ring
            ring.append(u)
