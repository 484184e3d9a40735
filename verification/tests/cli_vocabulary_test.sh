#!/usr/bin/env bash
# The command line speaks one vocabulary: every command's options, read from its own --help,
# checked against the shared names. -o/--output is a file, --out a folder; --levels is always
# range-checked; a tolerance is --tolerance, a list of valences --valences; no command keeps a
# retired spelling. Usage: cli_vocabulary_test.sh path/to/crossdiv
set -u
crossdiv="$1"
failed=0 checked=0
fail() { echo "FAIL $1"; failed=$((failed + 1)); }

commands="$("$crossdiv" --help | awk '/^Subcommands:/ { f = 1; next } f && NF { print $1 }')"
[ "$(wc -w <<<"$commands")" -ge 20 ] || fail "crossdiv --help lists $(wc -w <<<"$commands") commands"
for c in $commands; do
  help="$("$crossdiv" "$c" --help)" || { fail "$c --help exits nonzero"; continue; }
  # One option per line: its names, then its description joined from the continuation lines.
  options="$(awk '/^  -/ { if (o) print o; o = $0; next } /^ {10,}/ && o { o = o " " $0; next } { if (o) print o; o = "" } END { if (o) print o }' <<<"$help" | tr -s ' ')"
  checked=$((checked + 1))
  while IFS= read -r line; do
    names="$(awk '{ print $1 }' <<<"$line")"
    case "$names" in
      -o,--output) grep -qiE 'folder' <<<"$line" && fail "$c: -o,--output names a folder: $line" ;;
      --out) grep -qiE 'folder' <<<"$line" || fail "$c: --out is not a folder: $line" ;;
      *--out|-o*) fail "$c: '$names': a file is -o,--output and a folder --out" ;;
      --levels) grep -qE 'INT in \[[0-9]+ - [0-9]+\]' <<<"$line" || fail "$c: --levels without its range: $line" ;;
      --tol|--angle-tol|--valence|--level|--outdir|--output-dir) fail "$c: retired or stray spelling $names" ;;
    esac
  done <<<"$options"
done
# The shared names mean one thing wherever they appear.
for pair in "subdivide --levels" "compare --levels" "invariance --levels" "limit --levels" "suite --out" "diff --out" \
            "tessellate --tolerance" "sweep --tolerance" "spectrum --valences" "bench --valences" "subdivide --output"; do
  set -- $pair
  "$crossdiv" "$1" --help | grep -qE -- "^  (-[a-z],)?$2 " || fail "$1 has no $2"
done
echo "$checked commands checked, $failed failed"
[ "$failed" -eq 0 ] && [ "$checked" -ge 20 ]
