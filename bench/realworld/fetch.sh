#!/usr/bin/env bash
# Gets the real-world corpus of bench/realworld/run.sh: the files bench/realworld/manifest.txt
# lists, from public repositories at the commits it pins and from CGAL's data meshes in
# Debian's libcgal-demo. None of it is part of this repository.
#
# Each git source is cloned into DIR/NAME without a work tree, and the manifest's files of
# that source are checked out at the pinned commit (`git checkout SHA -- PATH...`): only
# the listed files are written, and against GitHub the clone is partial
# (--filter=blob:none), so only their contents are downloaded, not every blob of every
# commit. Each file's blob is compared with the manifest's, so a different file under the
# same name is an error rather than a silent change of the benchmark.
# CGAL's meshes are extracted from /usr/share/doc/libcgal-dev/data.tar.gz (apt-get
# install libcgal-demo) into DIR/cgal/data/meshes/.
#
# A file that cannot be had (a mirror that lacks it: snapshots may leave out files over
# 4 MiB; another libcgal-demo version) is skipped with a message; run.sh skips it too.
#
# usage: bench/realworld/fetch.sh [DIR]
#   DIR        where the corpus goes (default build/realworld in the repository)
#   TETREC_CORPUS_MIRROR=path
#              clone from local git mirrors instead of GitHub: path/OWNER+NAME/repo (a bare
#              or normal repository that has the pinned commit), e.g. for a machine
#              without internet access; the same commits and files
#   CGAL_DATA=path   CGAL's data.tar.gz (default /usr/share/doc/libcgal-dev/data.tar.gz)
#   SOURCES="a b"    only these sources of the manifest (default all)
# Prints one line per source (files taken, skipped) and the skipped files; exit 1 when a
# source could not be had at all or a file differs from the manifest.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
MANIFEST=$ROOT/bench/realworld/manifest.txt
if [ -n "${1:-}" ]; then
  DIR=$1
  case $DIR in /*) ;; *) DIR=$PWD/$DIR ;; esac
else
  DIR=$ROOT/build/realworld
fi
MIRROR=${TETREC_CORPUS_MIRROR:-}
CGAL_DATA=${CGAL_DATA:-/usr/share/doc/libcgal-dev/data.tar.gz}
SOURCES=${SOURCES:-$(awk '$1 == "source" { print $2 }' "$MANIFEST")}
command -v git >/dev/null || { echo "needs git" >&2; exit 1; }
mkdir -p "$DIR"

status=0
total=0
total_skipped=0
# paths SOURCE: the manifest's "PATH BLOB" lines of SOURCE
paths() { awk -v s="$1" '$1 == "file" && $2 == s { print $3, $4 }' "$MANIFEST"; }

# git_source NAME URL SHA: clone (or reuse DIR/NAME), check out the listed files at SHA
git_source() {
  local name=$1 url=$2 sha=$3 repo=$DIR/$1 from owner_name path blob got n=0 skipped=()
  local -a want=()
  if [ -n "$MIRROR" ]; then
    # github.com/OWNER/NAME -> MIRROR/OWNER+NAME/repo
    owner_name=${url#https://github.com/}
    from=$MIRROR/${owner_name/\//+}/repo
  else
    from=$url
  fi
  if [ ! -d "$repo/.git" ]; then
    rm -rf "$repo"
    local -a filter=()
    # a partial clone needs a server that serves missing blobs on demand; a local path
    # has them all (or, a snapshot, lacks some for good), so it is cloned whole
    [ -n "$MIRROR" ] || filter=(--filter=blob:none)
    if ! git clone -q --no-checkout "${filter[@]}" "$from" "$repo"; then
      echo "$name: cannot clone $from: skipped" >&2
      rm -rf "$repo"
      status=1
      return
    fi
  fi
  if ! git -C "$repo" cat-file -e "$sha^{commit}" 2>/dev/null; then
    # an older clone in DIR, or a mirror made before the pin moved
    git -C "$repo" fetch -q origin "$sha" 2>/dev/null || true
  fi
  if ! git -C "$repo" cat-file -e "$sha^{commit}" 2>/dev/null; then
    echo "$name: commit $sha is not in $from: skipped" >&2
    status=1
    return
  fi
  while read -r path blob; do
    [ -n "$path" ] || continue
    got=$(git -C "$repo" rev-parse -q --verify "$sha:$path" 2>/dev/null || true)
    if [ -z "$got" ]; then
      echo "$name: $path is not in commit $sha" >&2
      status=1
    elif [ "$got" != "$blob" ]; then
      echo "$name: $path at $sha is blob $got, the manifest says $blob" >&2
      status=1
    else
      want+=("$path")
    fi
  done < <(paths "$name")
  # all at once (one download from GitHub); when that fails, one by one, to name the
  # files the clone lacks (a snapshot without its big files)
  if [ ${#want[@]} -gt 0 ] &&
      ! git -C "$repo" checkout -q "$sha" -- "${want[@]}" 2>/dev/null; then
    for path in "${want[@]}"; do
      git -C "$repo" checkout -q "$sha" -- "$path" 2>/dev/null || skipped+=("$path")
    done
  fi
  for path in "${want[@]}"; do [ -f "$repo/$path" ] && n=$((n + 1)); done
  echo "$name: $n files at $sha from $from${skipped[*]:+, ${#skipped[@]} skipped (not in the clone)}"
  for path in "${skipped[@]}"; do echo "  skipped: $name $path" ; done
  total=$((total + n))
  total_skipped=$((total_skipped + ${#skipped[@]}))
}

# cgal_source NAME VERSION: the listed files of CGAL's data archive
cgal_source() {
  local name=$1 version=$2 path blob got n=0 skipped=() have
  if [ ! -f "$CGAL_DATA" ]; then
    echo "$name: $CGAL_DATA not found (apt-get install libcgal-demo): skipped" >&2
    status=1
    return
  fi
  have=$(dpkg-query -W -f='${Version}' libcgal-demo 2>/dev/null || echo unknown)
  [ "$have" = "$version" ] ||
    echo "$name: libcgal-demo $have here, the manifest was made from $version: files may differ" >&2
  mkdir -p "$DIR/$name"
  local -a want=()
  while read -r path blob; do want+=("$path"); done < <(paths "$name")
  # tar names the members it lacks and fails: extract what is there, then look
  tar xzf "$CGAL_DATA" -C "$DIR/$name" "${want[@]}" 2>/dev/null || true
  while read -r path blob; do
    if [ ! -f "$DIR/$name/$path" ]; then
      skipped+=("$path")
      continue
    fi
    got=$(git hash-object "$DIR/$name/$path")
    # kept: a newer CGAL may have fixed a model, and run.sh names the file it measured
    [ "$got" = "$blob" ] || echo "$name: $path differs from the manifest's (blob $got)" >&2
    n=$((n + 1))
  done < <(paths "$name")
  echo "$name: $n files from $CGAL_DATA (libcgal-demo $have)${skipped[*]:+, ${#skipped[@]} skipped (not in the archive)}"
  for path in "${skipped[@]}"; do echo "  skipped: $name $path"; done
  total=$((total + n))
  total_skipped=$((total_skipped + ${#skipped[@]}))
}

for name in $SOURCES; do
  read -r _ _ origin pin < <(awk -v s="$name" '$1 == "source" && $2 == s' "$MANIFEST") || {
    echo "$name: no such source in $MANIFEST" >&2; status=1; continue; }
  case $origin in
    https://*) git_source "$name" "$origin" "$pin" ;;
    debian:*) cgal_source "$name" "$pin" ;;
    *) echo "$name: unknown origin $origin" >&2; status=1 ;;
  esac
done
echo "corpus in $DIR: $total files, $total_skipped skipped"
exit $status
