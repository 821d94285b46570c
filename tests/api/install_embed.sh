#!/usr/bin/env bash
# The installed library as an embedding program sees it: `meson install --destdir`, then
# examples/embed.c compiled with nothing but `pkg-config --cflags --libs tetrec` against
# that tree, run on a surface, and its accessor arrays compared with the .mesh file the
# CLI writes for the same surface.
# Usage: install_embed.sh SOURCE_ROOT BUILD_DIR CC SANITIZE TETREC WORK SURFACE...
set -euo pipefail
src=$1 build=$2 cc=$3 sanitize=$4 tetrec=$5 work=$6
shift 6
rm -rf "$work"
mkdir -p "$work"
dest="$work/destdir"
meson install -C "$build" --no-rebuild --quiet --destdir "$dest" >/dev/null
pc=$(find "$dest" -name tetrec.pc | head -n 1)
[ -n "$pc" ] || { echo "FAIL: no tetrec.pc installed"; exit 1; }
libdir=$(dirname "$(dirname "$pc")")
# The .pc file names the final prefix; the sysroot maps its -I and -L into the destdir.
export PKG_CONFIG_PATH="$(dirname "$pc")" PKG_CONFIG_SYSROOT_DIR="$dest"
flags=$(pkg-config --cflags --libs tetrec)
echo "pkg-config --cflags --libs tetrec: $flags"
extra=()
# A sanitized library needs its runtime in the program too.
[ "$sanitize" = none ] || extra=(-fsanitize="$sanitize")
# shellcheck disable=SC2086 # pkg-config output is a list of words
"$cc" -std=c11 -Wall -Wextra -Werror "${extra[@]}" "$src/examples/embed.c" -o "$work/embed" $flags
for surface in "$@"; do
  name=$(basename "$surface")
  "$tetrec" mesh -q "$surface" -o "$work/$name.mesh"
  LD_LIBRARY_PATH="$libdir" "$work/embed" "$surface" "$work/$name.mesh" >"$work/$name.txt" || {
    cat "$work/$name.txt"; echo "FAIL: $name"; exit 1; }
  grep -q "same as the accessors" "$work/$name.txt"
  tail -n 1 "$work/$name.txt"
done
# The program really ran against the installed copy.
LD_LIBRARY_PATH="$libdir" ldd "$work/embed" >"$work/ldd.txt"
grep -q "$libdir/libtetrec.so" "$work/ldd.txt" || {
  echo "FAIL: embed does not load $libdir/libtetrec.so"; exit 1; }
echo "installed library: embed agrees with the CLI on $# surfaces"
