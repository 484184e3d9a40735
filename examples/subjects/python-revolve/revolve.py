#!/usr/bin/env python3
"""The course's surface-of-revolution task in Python, standard library only: every srev record
of an SWP file rotates its profile curve (tessellated by ../python-curves/tessellate.py, in the
xy-plane) about the y-axis in STEPS slices, each sample (x, y) at angle a becoming
(x cos a, y, -x sin a) with the profile's normal rotated alike, and each quad of the grid two
triangles. Writes an OBJ with a `vn` per `v`:

    python3 revolve.py IN.swp OUT.obj [--left-normals]

The profile's normal is its tangent turned right, (t_y, -t_x), outward for a profile drawn
downward on the x < 0 side as the course's are; --left-normals takes the curve task's planar
normal N = +z x T instead, which points inward here: the slip crossdiv names ("reversed").
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python-curves"))
import tessellate  # noqa: E402


def records(path):
    """Curve records by name, and the (steps, profile name) of every srev line."""
    revolutions = [(int(w[2]), w[3]) for w in (line.split() for line in open(path)) if w and w[0] == "srev"]
    named = [w[1] for w in (line.split() for line in open(path))
             if w and not w[0].startswith("[") and w[0] not in ("srev", "gcyl")]
    return dict(zip(named, tessellate.read_swp(path))), revolutions


def main():
    src, out = sys.argv[1], sys.argv[2]
    left = "--left-normals" in sys.argv[3:]
    curves, revolutions = records(src)
    v_lines, vn_lines, f_lines = [], [], []
    for steps, name in revolutions:
        keyword, curve_steps, points = curves[name]
        samples = tessellate.tessellate(keyword, curve_steps, points, False)
        first = len(v_lines)
        for i in range(steps):
            a = 2 * math.pi * i / steps
            c, s = math.cos(a), math.sin(a)
            for pos, tan in samples:
                t = tessellate.normalized(tan)
                n = [-t[1], t[0]] if left else [t[1], -t[0]]
                v_lines.append("v %r %r %r" % (pos[0] * c, pos[1], -pos[0] * s))
                vn_lines.append("vn %r %r %r" % (n[0] * c, n[1], -n[0] * s))
        m = len(samples)
        for i in range(steps):
            for j in range(m - 1):
                a, b = first + i * m + j + 1, first + ((i + 1) % steps) * m + j + 1
                f_lines.append(f"f {a}//{a} {b + 1}//{b + 1} {b}//{b}")
                f_lines.append(f"f {a}//{a} {a + 1}//{a + 1} {b + 1}//{b + 1}")
    with open(out, "w") as f:
        f.write("\n".join(v_lines + vn_lines + f_lines) + "\n")


if __name__ == "__main__":
    main()
