#!/usr/bin/env bash
# Runs every fuzz target of a CROSSDIV_FUZZ build for SECONDS each, from seed corpora written
# fresh by fuzz_corpus (the bundled and course data), and fails when a target finds a crash,
# a sanitizer report, an uncaught exception, a timeout or an out-of-memory input.
#   fuzz/run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]
# CROSSDIV_FUZZ_PARALLEL=N runs N targets at a time (default 1; one per core is the most
# that keeps SECONDS of fuzzing each).
# Findings are kept in BUILD_DIR/fuzz-findings/ (reproduce: BUILD_DIR/fuzz/fuzz_T FILE).
set -euo pipefail
build="$1"; seconds="$2"; shift 2
targets="${*:-obj off ply swp bzc bez volume manifest merge}"
parallel="${CROSSDIV_FUZZ_PARALLEL:-1}"
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
corpus="$build/fuzz-corpus"; work="$build/fuzz-work"; findings="$build/fuzz-findings"
rm -rf "$corpus" "$work"
mkdir -p "$work" "$findings"
"$build/fuzz/fuzz_corpus" "$corpus" "$source_dir"
# The merge target's seed: a small suite's own results.json, written by this build's crossdiv.
printf 'suite seed\ncase bundled:tetrahedron loop levels=1 against=opensubdiv\ncase bundled:quad-cube catmull-clark levels=1 against=opensubdiv\n' \
  > "$work/seed.suite"
if "$build/verification/crossdiv" suite "$work/seed.suite" --out "$work/seed-out" --jobs 1 > "$work/seed.log" 2>&1; then
  mkdir -p "$corpus/merge" && cp "$work/seed-out/results.json" "$corpus/merge/"
fi

# One target: its verdict line in $work/T.verdict, exit 1 when it found something.
fuzz_one() {
  local t="$1" log="$build/fuzz-$1.log"
  mkdir -p "$work/$t"
  # -timeout: one input may take 10 s (a hang is a finding); -rss_limit_mb: 4 GB (an input
  # that makes the readers or refinement allocate without bound is a finding).
  if "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=16384 \
       -print_final_stats=1 -artifact_prefix="$findings/$t-" "$work/$t" "$corpus/$t" > "$log" 2>&1; then
    echo "fuzz_$t: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$log" | tail -1), nothing found" > "$work/$t.verdict"
  else
    { echo "fuzz_$t: FOUND something (log: $log, inputs: $findings/$t-*)"
      grep -E "ERROR|runtime error|uncaught|deadly signal|timeout|out-of-memory" "$log" | head -5 || true
    } > "$work/$t.verdict"
    return 1
  fi
}

failed=""
running=()
finish() {  # waits for the oldest running target and reports it
  local t="${running[0]}" pid="${pids[0]}"
  running=("${running[@]:1}"); pids=("${pids[@]:1}")
  wait "$pid" || failed="$failed $t"
  cat "$work/$t.verdict"
}
pids=()
for t in $targets; do
  [ "${#running[@]}" -ge "$parallel" ] && finish
  fuzz_one "$t" &
  running+=("$t"); pids+=("$!")
done
while [ "${#running[@]}" -gt 0 ]; do finish; done
if [ -n "$failed" ]; then echo "fuzzing found inputs that break:$failed" >&2; exit 1; fi
