#!/usr/bin/env bash
# The man page generated from the binary (help2man over --help-all and --version), rendered by
# man (troff's line-adjustment warnings on long option lists aside): it names crossdiv's
# version, every command the binary lists, and their options.
# Usage: man_page_test.sh path/to/crossdiv.1 path/to/crossdiv
set -u
page="$1" crossdiv="$2"
text="$(MANWIDTH=100 man -P cat -l "$page" 2>/dev/null)" || { echo "FAIL man cannot render $page"; echo "$text" | tail -5; exit 1; }
failed=0
has() { grep -qE -- "$1" <<<"$text" || { echo "FAIL the man page lacks /$1/"; failed=$((failed + 1)); }; }
version="$("$crossdiv" --version | head -1 | awk '{ print $2 }')"
has "crossdiv $version"
has '^NAME'
has 'spline and subdivision algorithms verified'
commands="$("$crossdiv" --help | awk '/^Subcommands:/ { f = 1; next } f && NF { print $1 }')"
# help2man sets the first command on the "Subcommands:" line, each other on its own.
for c in $commands; do has "^ *(Subcommands: )?$c( |$)"; done
for option in --levels --against --subject --out --output --timeout --tolerance --valences --isovalue; do has -- "$option"; done
echo "$(wc -w <<<"$commands") commands, $failed missing"
[ "$failed" -eq 0 ]
