#!/usr/bin/env bash
# Installs Debian's libcgal-demo (if missing) and unpacks a selection of its real meshes into
# datasets/cgal/ (git-ignored). The conformance tests use them when present.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
archive=/usr/share/doc/libcgal-demo/data.tar.gz
if [ ! -f "$archive" ]; then
  if [ "$(id -u)" -ne 0 ]; then echo "libcgal-demo is not installed; run as root to install it" >&2; exit 1; fi
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libcgal-demo >/dev/null
fi
# Closed and bordered, smooth and sharp, 1k to 13k faces: enough variety, fast enough for 3 levels.
meshes="elephant cow fandisk mesh_with_border elephant-with-holes knot1 mushroom cube-meshed oblong"
mkdir -p "$here/cgal"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
tar -xzf "$archive" -C "$tmp" $(for m in $meshes; do echo "data/meshes/$m.off"; done)
for m in $meshes; do cp "$tmp/data/meshes/$m.off" "$here/cgal/$m.off"; done
echo "CGAL meshes in $here/cgal: $meshes"
