"""The class roster: results.json's "roster" (one row per subject and scheme, made by crossdiv's
roster_table) as a section of the report and as roster.html, a page of its own whose table
sorts by any column and whose rows open the subject's cases."""
import html
import json

from .model import STYLE, Link, Section, Table, Text

# Sorting and opening, inline: the page is one file that works from the disk, offline.
SCRIPT = """
function sortBy(th) {
  const table = th.closest('table'), col = th.cellIndex, body = table.tBodies[0];
  const dir = th.dataset.dir === 'asc' ? 'desc' : 'asc';
  th.dataset.dir = dir;
  const rows = [...body.querySelectorAll('tr.subject')];
  const key = r => { const t = r.cells[col].dataset.key ?? r.cells[col].textContent; const n = Number(t);
                     return t !== '' && !isNaN(n) ? n : t.toLowerCase(); };
  rows.sort((a, b) => (key(a) < key(b) ? -1 : key(a) > key(b) ? 1 : 0) * (dir === 'asc' ? 1 : -1));
  for (const r of rows) { body.appendChild(r); body.appendChild(document.getElementById(r.dataset.details)); }
}
function toggle(row) {
  const d = document.getElementById(row.dataset.details);
  d.hidden = !d.hidden;
}
window.addEventListener('load', () => {
  const id = decodeURIComponent(location.hash.slice(1));
  const row = [...document.querySelectorAll('tr.subject')].find(r => r.dataset.subject === id);
  if (row) { toggle(row); row.scrollIntoView(); }
});
"""

VERDICT_ORDER = {"fail": 0, "other-rule": 1, "pass": 2}


def subject_cases(results):
    """Each subject's cases, by subject name: (case id, status or match, rule, unfit classes, message)."""
    out = {}
    for c in results["cases"]:
        s = c.get("subject")
        if not isinstance(s, dict):
            continue
        rules = s.get("rules") or {}
        unfit = [f"{k['class']}{' ' + str(k['valence']) if k['valence'] else ''}"
                 for k in rules.get("classes", []) if not any(f["fits"] for f in k["fits"])]
        run = s["status"] if s["status"] != "ok" else (s.get("match") or {}).get("method", "-")
        out.setdefault(s["name"], []).append(
            (c["id"], run, rules.get("rule") or ("no named rule" if rules else "-"), ", ".join(unfit) or "-",
             s.get("status_message") or s.get("unmatched") or ""))
    return out


def failures_text(row):
    return " ".join(f"{how}={n}" for how, n in sorted(row["failures"].items())) or "-"


def minimal_text(row):
    """Its first failing case shrunk by the suite: "2 faces: <symptom>", or why it was not."""
    m = row.get("minimal") or {}
    return f"{m['faces']} faces: {m['symptom']}" if m.get("mesh") else (m.get("note") or "-")


def rule_text(row):
    """The rule it follows where it follows one: the one another than asked, when there is one."""
    return row["rule"] or "-"


def write_page(results, path):
    """roster.html: the sortable class table, each row opening that subject's cases."""
    cases = subject_cases(results)
    header = ["subject", "roster", "scheme", "verdict", "cases", "ran", "rule", "failures", "diagnosis", "minimal failing input"]
    out = [f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>class roster: suite "
           f"{html.escape(str(results.get('suite')))}</title><style>{STYLE}"
           "tr.subject{cursor:pointer}tr.details td{background:#f6f6f6}th{cursor:pointer}"
           ".fail{color:#b00}.pass{color:#070}.other-rule{color:#a60}</style>"
           f"<script>{SCRIPT}</script></head><body>",
           f"<h1>Class roster: suite {html.escape(str(results.get('suite')))}</h1>",
           "<p>One row per subject and scheme; click a column to sort, a row to open its cases "
           "(the run or how its vertices were matched, the named rule that fits every vertex, the vertex "
           "classes no named rule fits, the message). The last column is its first failing case shrunk to a "
           "minimal input, an OBJ to run it on. <a href='index.html'>The report</a>.</p>",
           "<table><thead><tr>" + "".join(f"<th onclick='sortBy(this)'>{h}</th>" for h in header) +
           "</tr></thead><tbody>"]
    for k, row in enumerate(results["roster"]):
        cells = [(row["subject"], None), (row["roster"], None), (row["scheme"], None),
                 (row["verdict"], VERDICT_ORDER.get(row["verdict"], 0)), (row["cases"], None), (row["ran"], None),
                 (rule_text(row), None), (failures_text(row), None), (row["diagnosis"], None)]
        tds = "".join(f"<td{'' if key is None else f' data-key={key}'}"
                      f"{' class=' + html.escape(row['verdict']) if i == 3 else ''}>{html.escape(str(v))}</td>"
                      for i, (v, key) in enumerate(cells))
        m = row.get("minimal") or {}
        # The minimal input opens as a file, without opening the row.
        tds += (f"<td data-key={m['faces']}><a href='{html.escape(m['mesh'])}' onclick='event.stopPropagation()'>"
                f"{html.escape(m['mesh'])}</a> ({m['faces']} faces: {html.escape(m['symptom'])})</td>" if m.get("mesh")
                else f"<td data-key=99999>{html.escape(minimal_text(row))}</td>")
        out.append(f"<tr class='subject' data-details='d{k}' data-subject='{html.escape(row['subject'])}' "
                   f"onclick='toggle(this)'>{tds}</tr>")
        detail = "".join("<tr>" + "".join(f"<td>{html.escape(str(v))}</td>" for v in c) + "</tr>"
                         for c in cases.get(row["subject"], []))
        out.append(f"<tr class='details' id='d{k}' hidden><td colspan='{len(header)}'><table><tr><th>case</th>"
                   f"<th>run / match</th><th>rule</th><th>classes no rule fits</th><th>message</th></tr>{detail}"
                   "</table></td></tr>")
    out.append("</tbody></table>")
    out.append(f"<script type='application/json' id='roster-data'>{html.escape(json.dumps(results['roster']))}</script>")
    out.append("</body></html>\n")
    with open(path, "w") as f:
        f.write("\n".join(out))


def roster_section(results, folder):
    """The class table in the report, each subject linking to its row of roster.html (written
    here); None when the suite had no subject."""
    rows = results.get("roster")
    if not rows:
        return None
    write_page(results, f"{folder}/roster.html")
    counts = {v: sum(r["verdict"] == v for r in rows) for v in ("pass", "other-rule", "fail")}
    return Section("Class roster").add(
        Text(f"{len(rows)} subjects: {counts['pass']} pass (the rule each case names), {counts['other-rule']} follow "
             f"another named rule, {counts['fail']} fail (a run failed, or no named rule fits). roster.html sorts "
             "the table and opens each subject's cases; roster.csv holds the same rows."),
        Table(["subject", "roster", "scheme", "verdict", "rule", "failures", "diagnosis", "minimal failing input"],
              [(Link(r["subject"], f"roster.html#{r['subject']}"), r["roster"], r["scheme"], r["verdict"], rule_text(r),
                failures_text(r), r["diagnosis"],
                Link(minimal_text(r), r["minimal"]["mesh"]) if (r.get("minimal") or {}).get("mesh") else minimal_text(r))
               for r in rows]))
