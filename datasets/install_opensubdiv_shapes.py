#!/usr/bin/env python3
"""Writes OpenSubdiv's hierarchical-edit regression shapes into datasets/opensubdiv/ (git-ignored).

OpenSubdiv's regression shapes (regression/shapes/*.h in its sources) are compiled into the
programs of Debian's `opensubdiv-tools` as string constants; the package ships no shape files.
This reads the five with hierarchical edits, catmark_square_hedit0..4 (the only shapes that
use `t vertexedit`, `t edgeedit` or `t faceedit`), out of /usr/bin/hbr_baseline: each is one
NUL-terminated OBJ text there, and they follow one another in name order.

A shape is recognised by its text, never by its place alone: each must hold the edit tags
its name stands for (below), so a rebuilt package that moved or changed them fails here,
loudly, instead of naming a shape wrongly.

    install_opensubdiv_shapes.py [PROGRAM]      (default /usr/bin/hbr_baseline)
Exit status 0 with the five files written; 1 when the program is missing or the shapes
are not found as described.
"""
import os
import re
import sys

# The tags each shape holds, in order (OpenSubdiv 3.5 regression/shapes/catmark_square_hedit*.h).
EXPECTED = [
    ("catmark_square_hedit0", ["vertexedit", "vertexedit", "vertexedit"]),
    ("catmark_square_hedit1", ["vertexedit", "vertexedit"]),
    ("catmark_square_hedit2", ["vertexedit", "edgeedit"]),
    ("catmark_square_hedit3", ["vertexedit", "edgeedit", "vertexedit"]),
    ("catmark_square_hedit4", ["vertexedit", "faceedit"]),
]
EDIT_TAG = re.compile(rb"^t (vertexedit|edgeedit|faceedit) ", re.M)


def shapes_in(program):
    """The NUL-terminated texts of `program` that are OBJ shapes with hierarchical-edit tags."""
    with open(program, "rb") as f:
        data = f.read()
    for m in re.finditer(rb"[^\x00]{64,}", data):
        text = m.group()
        if EDIT_TAG.search(text) and re.search(rb"^v ", text, re.M) and re.search(rb"^f ", text, re.M):
            yield text


def main():
    program = sys.argv[1] if len(sys.argv) > 1 else "/usr/bin/hbr_baseline"
    if not os.path.exists(program):
        print(f"{program} is missing (Debian package opensubdiv-tools); no OpenSubdiv shapes installed", file=sys.stderr)
        return 1
    found = list(shapes_in(program))
    tags = [[t.decode() for t in EDIT_TAG.findall(s)] for s in found]
    if tags != [t for _, t in EXPECTED]:
        print(f"{program}: expected the five hierarchical-edit shapes with tags {[t for _, t in EXPECTED]}, "
              f"found {tags}", file=sys.stderr)
        return 1
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "opensubdiv")
    os.makedirs(out, exist_ok=True)
    for (name, _), text in zip(EXPECTED, found):
        with open(os.path.join(out, name + ".obj"), "wb") as f:
            f.write(text)
    print(f"OpenSubdiv shapes in {out}: {' '.join(name for name, _ in EXPECTED)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
