#!/usr/bin/env bash
# The documentation, checked as a reader meets it:
#   1. the site builds in strict mode (mkdocs.yml: a link to a missing page or a missing image
#      fails the build), its command-line and Python reference pages generated from this
#      build's program and module, the C++ API reference by Doxygen from the headers;
#   2. every relative link of README.md names a file of the tree;
#   3. every example marked `<!-- example: exit N -->` in README.md or docs/*.md runs (in a
#      folder of its own): the
#      `$ crossdiv ...` command of the code block after it (with its `\` continuation lines)
#      exits with N, and the first line the block shows after the command is in its output,
#      its parts around "..." in order, spaces aside;
#   4. every other code block that shows a command (crossdiv, crossdiv-cluster, ./run.sh,
#      python3) is marked `<!-- synopsis: WHY -->` (why it is not run: placeholders, a long job,
#      code of a language), and each of its crossdiv lines names a subcommand the program has
#      and only options that subcommand's --help lists; each ./run.sh line a job run.sh has.
# Usage: docs_site_test.sh path/to/crossdiv [ROOT]   (ROOT: the tree to check, default this one)
set -u
crossdiv="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"  # absolute: the examples run elsewhere
root="${2:-$(cd "$(dirname "$0")/../.." && pwd)}"
cd "$root" || exit 2
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failed=0
# The reference pages are generated from this build's program and module (mkdocs_hooks.py).
export CROSSDIV="$crossdiv" CROSSDIV_PYTHONPATH="$(cd "$(dirname "$crossdiv")/../python" 2>/dev/null && pwd)"
if ! out="$(mkdocs build --strict --quiet --config-file mkdocs.yml --site-dir "$tmp/site" 2>&1)"; then
  echo "FAIL mkdocs build --strict:"; echo "$out"; failed=1
elif [ ! -f "$tmp/site/index.html" ] || [ ! -f "$tmp/site/search/search_index.json" ]; then
  echo "FAIL the site has no index.html or no search index"; failed=1
else
  echo "ok site: $(find "$tmp/site" -name '*.html' | wc -l) pages, with a search index"
  # The generated pages hold what the program and the module say now.
  if ! grep -q -- '--max-faces' "$tmp/site/cli-reference.html" || ! grep -q 'subdivide' "$tmp/site/python-reference.html"; then
    echo "FAIL the generated reference pages lack the program's options or the module's functions"; failed=1
  fi
  if ! grep -q 'catmull_clark_levels' "$tmp/site/api/catmull__clark_8h.html" 2>/dev/null; then
    echo "FAIL the C++ API reference (Doxygen, site api/) lacks catmull_clark.h's functions"; failed=1
  fi
fi
# README's relative links (not a URL, not an anchor).
while IFS= read -r target; do
  if [ ! -e "$root/${target%%#*}" ]; then echo "FAIL README.md links to $target, which does not exist"; failed=1; fi
done < <(grep -oE '\]\([^)#][^)]*\)' README.md | sed -E 's/^\]\((.*)\)$/\1/' | grep -vE '^[a-z]+://')
# The marked examples, run in a folder of their own (what they write stays out of the tree) that
# sees the tree's examples/ as a reader's checkout would.
mkdir "$tmp/work" && ln -s "$root/examples" "$tmp/work/examples"
python3 - "$crossdiv" "$tmp/work" README.md docs/*.md <<'PY' || failed=1
import re, shlex, subprocess, sys
crossdiv, work, files = sys.argv[1], sys.argv[2], sys.argv[3:]
bad = ran = 0
for path in files:
    lines = open(path).read().split("\n")
    for i, line in enumerate(lines):
        m = re.match(r"<!-- example: exit (\d+) -->", line.strip())
        if not m:
            continue
        want = int(m.group(1))
        j = i + 1
        while j < len(lines) and not lines[j].startswith("```"):
            j += 1
        block = []
        j += 1
        while j < len(lines) and not lines[j].startswith("```"):
            block.append(lines[j])
            j += 1
        if not block or not block[0].startswith("$ crossdiv "):
            print(f"FAIL {path}:{i + 1}: the marked block does not start with '$ crossdiv '")
            bad += 1
            continue
        command, k = block[0][2:], 1
        while command.endswith("\\") and k < len(block):
            command = command[:-1] + " " + block[k].strip()
            k += 1
        shown = block[k] if k < len(block) else ""
        argv = shlex.split(command)
        argv[0] = crossdiv
        r = subprocess.run(argv, capture_output=True, text=True, timeout=600, cwd=work)
        ran += 1
        output = " ".join((r.stdout + r.stderr).split())
        at, ok = 0, bool(shown.strip())
        for part in (" ".join(p.split()) for p in shown.split("...")):
            if not part:
                continue
            found = output.find(part, at)
            if found < 0:
                ok = False
                break
            at = found + len(part)
        if r.returncode != want or not ok:
            print(f"FAIL {path}:{i + 1}: {command}\n  exit {r.returncode} (want {want}); "
                  f"{'output has' if ok else 'output lacks'}: {shown.strip()}")
            bad += 1
        else:
            print(f"ok example {path}:{i + 1}: {command[:80]}")
if ran == 0:
    print("FAIL no marked example found")
    bad += 1

# Every other block that shows a command: marked as a synopsis, and its crossdiv lines spelled as
# the program spells its subcommands and options now.
command_line = re.compile(r"^\s*(\$ )?(crossdiv|crossdiv-cluster|\./run\.sh|python3)\b")
helps = {}
def options_of(sub):
    if sub not in helps:
        r = subprocess.run([crossdiv, sub, "--help"], capture_output=True, text=True, timeout=60)
        helps[sub] = None if r.returncode != 0 else set(re.findall(r"(--[a-z][a-z0-9-]*)", r.stdout))
    return helps[sub]
jobs = set(re.findall(r"^  ([a-z]+)\)", open("run.sh").read(), re.M))
synopses = 0
for path in files:
    lines = open(path).read().split("\n")
    i = 0
    while i < len(lines):
        if not lines[i].startswith("```"):
            i += 1
            continue
        j = i + 1
        while j < len(lines) and not lines[j].startswith("```"):
            j += 1
        body = lines[i + 1:j]
        prev = next((lines[k].strip() for k in range(i - 1, -1, -1) if lines[k].strip()), "")
        shown = [l for l in body if command_line.match(l)]
        if shown and not prev.startswith("<!-- example:"):
            if not re.match(r"<!-- synopsis: \S.* -->$", prev):
                print(f"FAIL {path}:{i + 1}: a block of commands ({shown[0].strip()[:60]}) neither run as an example "
                      f"nor marked '<!-- synopsis: why -->'")
                bad += 1
            synopses += 1
            for l in shown:
                text = l.strip().removeprefix("$ ").split("#")[0]
                words = text.split()
                if words[0] == "./run.sh" and (len(words) < 2 or words[1] not in jobs):
                    print(f"FAIL {path}:{i + 1}: '{l.strip()}': run.sh has no such job (it has {sorted(jobs)})")
                    bad += 1
                if words[0] != "crossdiv" or len(words) < 2 or words[1].startswith("-"):
                    continue
                known = options_of(words[1])
                unknown = [] if known is None else [o for o in re.findall(r"--[a-z][a-z0-9-]*", text) if o not in known]
                if known is None or unknown:
                    print(f"FAIL {path}:{i + 1}: '{l.strip()[:80]}': " +
                          (f"crossdiv has no subcommand {words[1]}" if known is None else f"{words[1]} has no {unknown}"))
                    bad += 1
        i = j + 1
print(f"ok {synopses} synopsis block(s) checked against the program's subcommands and options")
sys.exit(1 if bad else 0)
PY
[ "$failed" -eq 0 ] && echo "docs: every check passed"
exit "$failed"
