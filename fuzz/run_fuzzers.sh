#!/usr/bin/env bash
# Runs every fuzz target of a CROSSDIV_FUZZ build for SECONDS each, from seed corpora written
# fresh by fuzz_corpus (the bundled and course data), and fails when a target finds a crash,
# a sanitizer report, an uncaught exception, a timeout or an out-of-memory input.
#   fuzz/run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]
# Findings are kept in BUILD_DIR/fuzz-findings/ (reproduce: BUILD_DIR/fuzz/fuzz_T FILE).
set -euo pipefail
build="$1"; seconds="$2"; shift 2
targets="${*:-obj off ply swp bzc bez manifest}"
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
corpus="$build/fuzz-corpus"; work="$build/fuzz-work"; findings="$build/fuzz-findings"
rm -rf "$corpus" "$work"
mkdir -p "$work" "$findings"
"$build/fuzz/fuzz_corpus" "$corpus" "$source_dir"
failed=""
for t in $targets; do
  mkdir -p "$work/$t"
  log="$build/fuzz-$t.log"
  # -timeout: one input may take 10 s (a hang is a finding); -rss_limit_mb: 4 GB (an input
  # that makes the readers or refinement allocate without bound is a finding).
  if "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=16384 \
       -print_final_stats=1 -artifact_prefix="$findings/$t-" "$work/$t" "$corpus/$t" > "$log" 2>&1; then
    echo "fuzz_$t: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$log" | tail -1), nothing found"
  else
    echo "fuzz_$t: FOUND something (log: $log, inputs: $findings/$t-*)"
    grep -E "ERROR|runtime error|uncaught|deadly signal|timeout|out-of-memory" "$log" | head -5 || true
    failed="$failed $t"
  fi
done
if [ -n "$failed" ]; then echo "fuzzing found inputs that break:$failed" >&2; exit 1; fi
