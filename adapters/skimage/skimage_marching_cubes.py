#!/usr/bin/env python3
"""scikit-image's marching cubes as a crossdiv reference: one extraction of an isosurface.

    skimage_marching_cubes.py VOLUME.mhd LEVEL below|above lewiner|lorensen OUT.obj

VOLUME.mhd is a MetaImage header naming raw little-endian doubles, x fastest, as crossdiv's
write_metaimage writes it (ObjectType, NDims, BinaryData, BinaryDataByteOrderMSB, DimSize,
ElementSpacing, Offset, ElementType MET_DOUBLE, ElementDataFile). The samples go to
skimage.measure.marching_cubes (Debian python3-skimage) as an array indexed [x, y, z], so its
vertex coordinates are x, y, z; they are scaled by the spacing there and moved by the offset
here. `below`: the solid is where the value is below the level; `above`: above it. The surface
faces away from the solid by the right-hand rule, as OBJ and crossdiv orient faces; skimage
states its gradient_direction by the left-hand rule ('ascent': exterior greater, faces outward
by the left hand), so the other direction is passed: 'descent' for below, 'ascent' for above.
method 'lewiner' is Lewiner et al.'s MC33 table, 'lorensen' the 1987 table; degenerate triangles are kept (allow_degenerate), as
crossdiv's marching cubes keeps them.

skimage converts the samples to float32: its vertices differ from a double computation by
float32 rounding. Writes OUT.obj with 9 significant digits (enough for a float32). Exit status 0
on success, 3 when scikit-image is not installed, 2 for an unreadable header.
"""
import sys


def read_header(path):
    fields = {}
    with open(path) as header:
        for line in header:
            if "=" in line:
                key, value = line.split("=", 1)
                fields[key.strip()] = value.strip()
    try:
        size = [int(v) for v in fields["DimSize"].split()]
        spacing = [float(v) for v in fields.get("ElementSpacing", "1 1 1").split()]
        offset = [float(v) for v in fields.get("Offset", "0 0 0").split()]
        if fields.get("ElementType") != "MET_DOUBLE" or fields.get("BinaryDataByteOrderMSB", "False") != "False":
            raise ValueError("only little-endian MET_DOUBLE samples are read")
        data = fields["ElementDataFile"]
    except (KeyError, ValueError) as e:
        sys.exit(f"{path}: not a header this script reads: {e}")
    import os
    return size, spacing, offset, os.path.join(os.path.dirname(path), data)


def main(argv):
    if len(argv) != 6 or argv[3] not in ("below", "above") or argv[4] not in ("lewiner", "lorensen"):
        print(__doc__, file=sys.stderr)
        return 2
    try:
        import numpy as np
        from skimage import measure
    except ImportError as e:
        print(f"scikit-image is not installed (Debian: python3-skimage): {e}", file=sys.stderr)
        return 3
    size, spacing, offset, data = read_header(argv[1])
    volume = np.fromfile(data, dtype="<f8")
    if volume.size != size[0] * size[1] * size[2]:
        sys.exit(f"{data}: {volume.size} samples, the header says {size[0] * size[1] * size[2]}")
    volume = volume.reshape(size[2], size[1], size[0]).transpose(2, 1, 0)  # [x, y, z]
    verts, faces, _, _ = measure.marching_cubes(
        volume, float(argv[2]), spacing=tuple(spacing),
        gradient_direction="descent" if argv[3] == "below" else "ascent",
        allow_degenerate=True, method=argv[4])
    with open(argv[5], "w") as out:
        for v in verts:
            out.write("v %.9g %.9g %.9g\n" % (v[0] + offset[0], v[1] + offset[1], v[2] + offset[2]))
        for f in faces:
            out.write("f %d %d %d\n" % (f[0] + 1, f[1] + 1, f[2] + 1))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
