#!/usr/bin/env python3
"""The course's generalized-cylinder task in Python, standard library only: every gcyl record
of an SWP file places its profile curve (in the xy-plane) in the local frame of each sample of
its sweep curve, profile point (x, y) at V + x N + y B, and joins consecutive copies with two
triangles per quad. Writes an OBJ with a `vn` per `v`:

    python3 cylinder.py IN.swp OUT.obj [--open-seam]

Curves are bez2/bez3/bsp2/bsp3 (tessellated by ../python-curves/tessellate.py) or circ
(`circ NAME STEPS RADIUS`, in the xy-plane from (r, 0, 0) counterclockwise). The sweep's frames
follow the assignment's recursive update from B = +z (N_i = B_(i-1) x T_i normalized,
B_i = T_i x N_i). A closed sweep's last frame does not meet its first: the twist left between
them (the closure angle) is spread over the sweep by arc length, so that the last ring is the
first and the tube closes. --open-seam leaves it (the assignment's text stops at the recursive
update), keeping the last ring as its own: the tube gets a crack at the seam, which crossdiv
names.

The normal at a sample is the profile's outward normal (its tangent turned right, flipped for a
clockwise closed profile) placed in the frame like the profile, then tilted along T until it is
perpendicular to the step between neighbouring rings: where the recursive frames twist, the
surface moves within the normal plane too.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python-curves"))
import tessellate  # noqa: E402
from tessellate import cross, normalized  # noqa: E402


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def add(a, b, s=1.0):
    return [x + s * y for x, y in zip(a, b)]


def read_records(path):
    """Curves by name as (keyword, words, points), and the (profile, sweep) of every gcyl line."""
    curves, cylinders, current = {}, [], None
    for line in open(path):
        words = line.replace("[", " [ ").replace("]", " ] ").split()
        if not words:
            continue
        if words[0] == "[":
            while words and words[0] == "[":
                end = words.index("]")
                xyz = [float(v) for v in words[1:end]]
                current[2].append(xyz + [0.0] * (3 - len(xyz)))
                words = words[end + 1:]
        elif words[0] == "gcyl":
            cylinders.append((words[2], words[3]))
        elif words[0] != "srev":
            current = (words[0], words, [])
            curves[words[1]] = current
    return curves, cylinders


def samples(record):
    """(position, unit tangent) per sample, and whether the curve is closed."""
    keyword, words, points = record
    if keyword == "circ":
        steps, r = int(words[2]), float(words[3])
        out = []
        for i in range(steps + 1):
            a = 0.0 if i == steps else 2 * math.pi * i / steps
            out.append(([r * math.cos(a), r * math.sin(a), 0.0], [-math.sin(a), math.cos(a), 0.0]))
        return out, True
    out = [(p, normalized(t)) for p, t in tessellate.tessellate(keyword, int(words[2]), points, False)]
    first, last = out[0][0], out[-1][0]
    return out, max(abs(a - b) for a, b in zip(first, last)) <= 1e-9 * (1 + max(map(abs, first)))


def recursive_frames(sweep):
    frames, b = [], [0.0, 0.0, 1.0]
    for _, t in sweep:
        n = normalized(cross(b, t))
        b = cross(t, n)
        frames.append((t, n, b))
    return frames


def close_frames(sweep, frames):
    """Turns every frame about its tangent by its share (arc length) of the closure angle."""
    t0, n0, _ = frames[0]
    last_n = normalized(add(frames[-1][1], t0, -dot(frames[-1][1], t0)))
    angle = math.atan2(dot(cross(last_n, n0), t0), dot(last_n, n0))
    lengths = [0.0]
    for (p, _), (q, _) in zip(sweep, sweep[1:]):
        lengths.append(lengths[-1] + math.dist(p, q))
    closed = []
    for (t, n, b), s in zip(frames, lengths):
        a = angle * s / lengths[-1]
        n = add([math.cos(a) * c for c in n], b, math.sin(a))
        closed.append((t, n, cross(t, n)))
    closed[-1] = closed[0]
    return closed


def profile_normals(profile, closed):
    area = sum(p[0] * q[1] - q[0] * p[1] for (p, _), (q, _) in zip(profile, profile[1:]))
    side = -1.0 if closed and area < 0 else 1.0
    return [normalized([side * t[1], -side * t[0], 0.0]) for _, t in profile]


def cylinder(profile_record, sweep_record, open_seam):
    profile, profile_closed = samples(profile_record)
    sweep, sweep_closed = samples(sweep_record)
    frames = recursive_frames(sweep)
    wrap = sweep_closed and not open_seam
    if wrap:
        frames = close_frames(sweep, frames)[:-1]  # the last ring is the first
    normals2 = profile_normals(profile, profile_closed)
    rings = [[add(add(v, n, p[0]), b, p[1]) for p, _ in profile] for (v, _), (_, n, b) in zip(sweep, frames)]
    count = len(rings)
    normals = []
    for i, (t, n, b) in enumerate(frames):
        before, after = (i - 1) % count if wrap else max(i - 1, 0), (i + 1) % count if wrap else min(i + 1, count - 1)
        for j, n2 in enumerate(normals2):
            m = add([n2[0] * c for c in n], b, n2[1])
            d = add(rings[after][j], rings[before][j], -1.0)
            along = dot(t, d)
            if abs(along) > 1e-3 * math.sqrt(dot(d, d)):
                m = add(m, t, -dot(m, d) / along)
            normals.append(normalized(m))
    quads = [(i, (i + 1) % count) for i in range(count if wrap else count - 1)]
    return [p for ring in rings for p in ring], normals, len(profile), quads


def main():
    src, out = sys.argv[1], sys.argv[2]
    open_seam = "--open-seam" in sys.argv[3:]
    curves, cylinders = read_records(src)
    v_lines, vn_lines, f_lines = [], [], []
    for profile, sweep in cylinders:
        positions, normals, m, quads = cylinder(curves[profile], curves[sweep], open_seam)
        first = len(v_lines) + 1
        v_lines += ["v %r %r %r" % tuple(p) for p in positions]
        vn_lines += ["vn %r %r %r" % tuple(n) for n in normals]
        for i, k in quads:
            for j in range(m - 1):
                a, b, c, d = (first + i * m + j, first + i * m + j + 1, first + k * m + j + 1, first + k * m + j)
                f_lines.append(f"f {a}//{a} {b}//{b} {c}//{c}")
                f_lines.append(f"f {a}//{a} {c}//{c} {d}//{d}")
    with open(out, "w") as f:
        f.write("\n".join(v_lines + vn_lines + f_lines) + "\n")


if __name__ == "__main__":
    main()
