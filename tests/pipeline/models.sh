#!/bin/sh
# usage: models.sh TEST_MODELS_BINARY EXTRACT_DIR MAXTRIS BUDGET
# Extracts CGAL's sample meshes (libcgal-dev) and runs the end-to-end model test.
tarball=/usr/share/doc/libcgal-dev/data.tar.gz
[ -f "$tarball" ] || { echo "no $tarball: skipped"; exit 77; }
mkdir -p "$2" || exit 1
if [ ! -d "$2/data/meshes" ]; then
  tar xzf "$tarball" -C "$2" --wildcards 'data/meshes/*.off' || exit 1
fi
exec "$1" "$2/data/meshes" "$3" "$4"
