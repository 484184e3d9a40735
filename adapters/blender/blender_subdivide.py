"""Blender as a crossdiv reference: one run of the Subdivision Surface modifier.

    blender --background --factory-startup --python blender_subdivide.py -- \\
        SCHEME LEVELS BOUNDARY UV IN.obj OUT.ply
    blender --background --factory-startup --python blender_subdivide.py -- --check
    blender --background --factory-startup --python blender_subdivide.py -- --serve
        (each run's SCHEME LEVELS BOUNDARY UV IN.obj OUT.ply as a request, adapters/common/serve.py)

Blender 3.4 (Debian `blender`) refines through its own build of OpenSubdiv; this script, run by
Blender's Python, builds the mesh from IN.obj (every vertex kept, in order: `from_pydata`, not
Blender's importer, which may merge or reorder), adds the modifier, evaluates the object and
writes the evaluated mesh as binary PLY. Blender holds coordinates in float32, so its results
are held to the float tier; the PLY carries them as doubles, every bit kept.

The modifier's options, as crossdiv's rules name them:
  SCHEME    catmull-clark -> subdivision_type CATMULL_CLARK; bilinear -> SIMPLE
  LEVELS    levels and render_levels (the evaluated depsgraph in background mode is the viewport's)
  BOUNDARY  edge-only -> boundary_smooth ALL (corners smoothed); edge-and-corner ->
            PRESERVE_CORNERS (a vertex of one face kept as a corner); linear (bilinear) -> ALL
  UV        the face-varying rule -> uv_smooth: none -> SMOOTH_ALL, corners-only ->
            PRESERVE_CORNERS, corners-plus1 -> PRESERVE_CORNERS_AND_JUNCTIONS, corners-plus2 ->
            PRESERVE_CORNERS_JUNCTIONS_AND_CONCAVE, boundaries -> PRESERVE_BOUNDARIES, all -> NONE
  use_limit_surface False (the refined level's own points, not their limit), use_creases True
  (OBJ `t crease` tags become edge crease weights: sharpness s as s / 10, Blender's scale),
  use_custom_normals False, show_only_control_edges irrelevant here.

With --serve, Blender starts once (about 1.5 s) and every run of a suite worker is a request to
it; each run starts from an empty file (every object and mesh of the run before removed).

Exit status: 0 with OUT written; 2 for a bad command line or an unreadable input; 3 when run
outside Blender (--check, run by plain python3, exits 1 when `blender` is not on PATH); 4 when
the modifier has no rule for the input (a tag with no counterpart on a Blender mesh, or an input
Mesh.validate would change), the reason on stderr: a refusal (`rejects=4` in a manifest).
"""
import struct
import sys


class NoCounterpart(Exception):
    """The input has what Blender's mesh or modifier cannot hold: a refusal, exit status 4."""

SCHEMES = {"catmull-clark": "CATMULL_CLARK", "bilinear": "SIMPLE"}
BOUNDARIES = {"edge-only": "ALL", "edge-and-corner": "PRESERVE_CORNERS", "linear": "ALL"}
# Rule tags whose value arrives as an argument (BOUNDARY, UV).
PASSED_AS_ARGUMENTS = ("interpolateboundary", "facevaryinginterpolateboundary", "facevaryingpropagatecorners")
UV_RULES = {"none": "SMOOTH_ALL", "corners-only": "PRESERVE_CORNERS", "corners-plus1": "PRESERVE_CORNERS_AND_JUNCTIONS",
            "corners-plus2": "PRESERVE_CORNERS_JUNCTIONS_AND_CONCAVE", "boundaries": "PRESERVE_BOUNDARIES", "all": "NONE"}


def read_obj(path):
    """Vertices, faces (0-based) and crease tags (a, b, sharpness) of an OBJ file."""
    vertices, faces, creases = [], [], []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                vertices.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "f":
                faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
            elif words[0] == "t" and len(words) > 1 and words[1] in PASSED_AS_ARGUMENTS:
                continue
            elif words[0] == "t" and len(words) > 1 and words[1] != "crease":
                # Holes, corners, Chaikin's crease decay, smooth triangles: no counterpart on a
                # Blender mesh or its modifier.
                raise NoCounterpart(f"{path}:{number}: tag '{words[1]}' has no counterpart in Blender's modifier")
            elif words[0] == "t" and len(words) > 1 and words[1] == "crease":
                # t crease 2/1/0 a b sharpness
                counts = [int(c) for c in words[2].split("/")]
                ints, floats = words[3:3 + counts[0]], words[3 + counts[0]:3 + counts[0] + counts[1]]
                creases.append((int(ints[0]), int(ints[1]), float(floats[0])))
    if not vertices:
        # Another format (an OFF file read as OBJ) would otherwise refine to nothing, exit 0.
        # Vertices without a face are a mesh (a point cloud among real models): Blender holds
        # them as loose vertices, and what its modifier makes of them is compared.
        raise ValueError(f"{len(vertices)} vertices and {len(faces)} faces: not an OBJ mesh")
    for f, face in enumerate(faces):
        for v in face:
            if not 0 <= v < len(vertices):
                raise ValueError(f"{path}: face {f} names vertex {v + 1} of {len(vertices)}")
    return vertices, faces, creases


def write_ply(path, vertices, faces):
    with open(path, "wb") as out:
        out.write(("ply\nformat binary_little_endian 1.0\n"
                   f"element vertex {len(vertices)}\nproperty double x\nproperty double y\nproperty double z\n"
                   f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n").encode("ascii"))
        for v in vertices:
            out.write(struct.pack("<3d", *v))
        for face in faces:
            out.write(struct.pack("<B", len(face)) + struct.pack(f"<{len(face)}i", *face))


def subdivide(scheme, levels, boundary, uv, mesh_in, mesh_out):
    import bpy
    vertices, faces, creases = read_obj(mesh_in)
    # Nothing of another run stays (a served Blender refines one mesh after another).
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    for old in list(bpy.data.meshes):
        bpy.data.meshes.remove(old)
    mesh = bpy.data.meshes.new("input")
    mesh.from_pydata(vertices, [], faces)
    if mesh.validate(verbose=False):
        # validate() changed the mesh (a face naming a vertex twice, a duplicate face, ...):
        # Blender would refine another mesh than the one asked about.
        print("Blender's Mesh.validate changed the input (repeated or degenerate elements)", file=sys.stderr)
        return 4
    if creases:
        ends = {}
        for e in mesh.edges:
            a, b = e.vertices
            ends[(min(a, b), max(a, b))] = e.index
        layer = mesh.edges  # Blender 3.4: the crease is an attribute of each edge
        for a, b, s in creases:
            e = ends.get((min(a, b), max(a, b)))
            if e is not None:
                layer[e].crease = min(s / 10.0, 1.0)
    obj = bpy.data.objects.new("input", mesh)
    bpy.context.scene.collection.objects.link(obj)
    mod = obj.modifiers.new("subdivision", "SUBSURF")
    mod.subdivision_type = SCHEMES[scheme]
    mod.levels = levels
    mod.render_levels = levels
    mod.boundary_smooth = BOUNDARIES[boundary]
    mod.uv_smooth = UV_RULES[uv]
    mod.use_limit_surface = False
    mod.use_creases = True
    mod.use_custom_normals = False
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(depsgraph)
    result = evaluated.to_mesh()
    write_ply(mesh_out, [tuple(v.co) for v in result.vertices], [list(p.vertices) for p in result.polygons])
    evaluated.to_mesh_clear()
    return 0


def main(argv):
    args = argv[argv.index("--") + 1:] if "--" in argv else argv[1:]
    try:
        import bpy  # noqa: F401
    except ImportError:
        if args == ["--check"]:
            import shutil
            if shutil.which("blender") is None:
                print("blender is not on PATH (Debian package blender)", file=sys.stderr)
                return 1
            return 0
        print("run this script with: blender --background --factory-startup --python blender_subdivide.py -- ...",
              file=sys.stderr)
        return 3
    if args == ["--serve"]:
        import os
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
        from serve import serve
        return serve(run)
    return run(args)


def run(args):
    """One run: SCHEME LEVELS BOUNDARY UV IN.obj OUT.ply; its exit status."""
    if len(args) != 6:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    scheme, levels, boundary, uv, mesh_in, mesh_out = args
    if scheme not in SCHEMES or boundary not in BOUNDARIES or uv not in UV_RULES or not levels.isdigit():
        print(f"unknown scheme, boundary, uv rule or levels: {args}", file=sys.stderr)
        return 2
    try:
        return subdivide(scheme, int(levels), boundary, uv, mesh_in, mesh_out)
    except NoCounterpart as e:
        print(e, file=sys.stderr)
        return 4
    except (OSError, ValueError, IndexError) as e:
        print(f"cannot read {mesh_in}: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    status = main(sys.argv)
    # Blender's own exit: sys.exit inside --python would be reported as a Python error. os._exit
    # skips Blender's clean-up too, which would remove its session folder (blender_XXXX in the
    # temporary folder): removed here, or every run would leave one behind.
    import os
    try:
        import bpy
        import shutil
        if bpy.app.tempdir:
            shutil.rmtree(bpy.app.tempdir, ignore_errors=True)
    except ImportError:
        pass
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)
