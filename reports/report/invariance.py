"""The invariance section: each implementation x transformation, how many inputs kept their
surface, and one representative per finding with its minimal input and reproduce line.

An invariance case (crossdiv's `invariance` operation) has one run per implementation and
transformation: `subject` is the implementation, `check` the transformation, and `verdict`
agree (invariant), not-compared, diverge (not invariant, with its measured class) or
ref-nondeterministic.
"""
from collections import Counter, defaultdict

from .model import Link, Section, Table, Text
from .records import fmt, outcome, short_input


def invariance_cases(results):
    """The invariance cases of a results.json, by the kind crossdiv lists for each operation."""
    kinds = {o["name"]: o["kind"] for o in results["operations"]}
    return [c for c in results["cases"] if kinds.get(c.get("operation")) == "invariance"]


def _cell(counter):
    """"40 of 42 (3 not bit for bit); 2 non-manifold-handling": inputs invariant of those compared
    (of which within the tolerance only: invariant in the weak tier, not in the strict), then each
    finding's outcome."""
    invariant = counter.get("agree", 0) + counter.get("agree, not bit for bit", 0)
    compared = sum(n for o, n in counter.items() if o != "not-compared")
    findings = [f"{n} {o}" for o, n in sorted(counter.items()) if o not in ("agree", "agree, not bit for bit", "not-compared")]
    notes = []
    if counter.get("agree, not bit for bit"):
        notes.append(f"{counter['agree, not bit for bit']} not bit for bit")
    if counter.get("not-compared"):
        notes.append(f"+{counter['not-compared']} n/c")
    text = f"{invariant} of {compared}" + (f" ({', '.join(notes)})" if notes else "")
    return text + ("; " + ", ".join(findings) if findings else "")


def invariance_section(cases, view_index=None):
    """`view_index`: each viewed case's place in the 3D viewer (viewer.view_index), to link a
    representative to its view."""
    view_index = view_index or {}
    if not cases:
        return None
    transformations = []
    for c in cases:
        for t in c.get("transformations", []):
            if t not in transformations:
                transformations.append(t)
    table = defaultdict(Counter)  # (scheme, implementation) -> transformation/outcome counts
    failed_inputs = Counter()
    representatives = {}
    for c in cases:
        scheme = c.get("scheme", "-")
        minimal = {i["name"]: i.get("minimal") for i in c.get("implementations", [])}
        for r in c["runs"]:
            impl = r["subject"]
            if r["check"] == "input":
                failed_inputs[(scheme, impl, outcome(c, r))] += 1
                continue
            o = outcome(c, r)
            weak_only = o == "agree" and not r.get("bit_identical", True)
            table[(scheme, impl)][(r["check"], "agree, not bit for bit" if weak_only else o)] += 1
            if r["verdict"] in ("agree", "not-compared"):
                continue
            key = (scheme, impl, r["check"], o)
            m = minimal.get(impl)
            shrunk = m if m and m.get("transformation") == r["check"] else None
            best = representatives.get(key)
            # The representative: one with a minimal input, the smallest one.
            rank = (shrunk is None, shrunk["faces"] if shrunk else c.get("input_faces", 0))
            if best is None or rank < best[0]:
                representatives[key] = (rank, c, r, shrunk, 0)
            representatives[key] = representatives[key][:4] + (representatives[key][4] + 1,)

    rows = []
    for (scheme, impl), counts in sorted(table.items()):
        row = [scheme, impl]
        for t in transformations:
            row.append(_cell(Counter({o: n for (tt, o), n in counts.items() if tt == t})))
        rows.append(row)
    section = Section("Invariance").add(
        Text("Each implementation refines every input and the input written otherwise (corners rotated, faces "
             "reordered, vertices relabelled, orientation reversed, the mesh moved, scaled, mirrored, rotated, the "
             "same run again) and run otherwise (its connected components apart, whose union must be the whole; its "
             "levels one at a time, which must equal the levels in one run); mapped back, the two must be the same "
             "surface: bit for bit where floating point makes the transformation exact, within the tolerance "
             "elsewhere. No reference is needed. Each cell: inputs invariant of those compared (of which not bit for "
             "bit: invariant in the weak tier, not in the strict; n/c: not compared, for vertices at one position, "
             "where only the point sets are compared, or nothing to run otherwise: one component, a tagged mesh, a "
             "rule that counts its levels from the input, a level a face list cannot state), then the "
             "findings by outcome; a reference's finding is classed by what removes it (its isolated vertices, its "
             "non-manifold vertices split), core's is a failure."),
        Table(["scheme", "implementation", *transformations], rows))
    if failed_inputs:
        section.add(Table(["scheme", "implementation", "its run on the input", "inputs"],
                          [k + (n,) for k, n in sorted(failed_inputs.items())]))
    if representatives:
        reps = []
        for (scheme, impl, t, o), (_, c, r, shrunk, n) in sorted(representatives.items()):
            minimal = Link(f"{shrunk['faces']} faces", shrunk["mesh"]) if shrunk else "-"
            shown = short_input(c["input"])
            if c["job"] in view_index:
                shown = Link(shown, "#crossdiv-viewer", f" data-view='{view_index[c['job']]}'")
            reps.append((scheme, impl, t, o, n, shown, fmt(r.get("measured")), minimal,
                         shrunk["reproduce"] if shrunk else "-", r.get("explanation", "")))
        section.add(Text("One representative per finding (implementation, transformation, outcome): the smallest input "
                         "that shows it (a link opens the case's first finding in the 3D viewer: the implementation's "
                         "levels, and as its reference its run on the input written otherwise, mapped back), shrunk "
                         "by delta debugging where it has at most 500 faces, and the command that reproduces it."),
                    Table(["scheme", "implementation", "transformation", "outcome", "inputs", "representative",
                           "max rel", "minimal input", "reproduce", "explanation"], reps))
    return section
