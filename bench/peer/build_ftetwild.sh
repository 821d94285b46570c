#!/usr/bin/env bash
# Builds fTetWild (Hu et al. 2020, "Fast Tetrahedral Meshing in the Wild";
# github.com/wildmeshing/fTetWild, MPL-2.0) for the peer benchmarks: bench/realworld/run.sh
# and bench/quality/run.sh take the executable as FTETWILD=OUT. Neither fTetWild nor its
# dependencies are part of this repository; this script gets them into DIR and builds there.
#
# usage: bench/peer/build_ftetwild.sh DIR OUT
#   DIR   work folder: the sources go to DIR/src/NAME, the CMake build to DIR/build
#         (both reused when the script runs again)
#   OUT   where the executable (FloatTetwild_bin) is copied
#   TETREC_PEER_MIRROR=path
#         clone from local git mirrors instead of GitHub: path/OWNER+NAME/repo (bare or not),
#         the layout of bench/realworld/fetch.sh's TETREC_CORPUS_MIRROR, e.g. for a machine
#         without internet access; the same commits
#   JOBS  ninja's parallel jobs (default 1: about 6 min of CPU, 16 min of wall clock at
#         nice 10 on a loaded two-core machine)
#
# Sources, pinned by commit (fTetWild's cmake/FloatTetwildDependencies.cmake names the tags
# it downloads; the two exceptions are said below):
#   wildmeshing/fTetWild        d7d99bb4387a07895b9adce058dc7305f6b6e5ab  (master, 2025-11)
#   libigl/libigl               40e7900ccbd767f1f360e0eb10f0f1a6432e0993  v2.6.0
#   libigl/libigl-predicates    decb7bc1260e689cbe008109e3cc5d3a5a433aea
#   BrunoLevy/geogram           fc3eb9bf44d2ee29686592e3ef5f5f4daeda27f8  v1.9.6, with the
#     submodules it needs without graphics, at the commits geogram records:
#     ddemidov/amgcl            ab57038d68ee372ed5df280631051b91f17ed2d1
#     LoicMarechal/libMeshb     952a157c9d516b28cc6c69cd1550c3e48d4792f9
#     diegonehab/rply           4296cc91b5c8c26d4e7d7aac0cee2b194ffc5800
#   CLIUtils/CLI11              4160d259d961cd393fd8d67590a8c7d210207348  v2.5.0
#   jdumas/json                 0901d33bf6e7dfe6f70fd9d142c8f5c6695c6c5b
#   gabime/spdlog               7c02e204c92545f869e2f04edaab1f19fe8b19fd  v1.13.0
#     (fTetWild asks for v1.15.3; 1.13 is the newest the mirrors this was made with had,
#     and it builds)
#   fmtlib/fmt                  e69e5f977d458f2650bb346dadf2ad30c5320281  10.2.1
#     (fTetWild asks for 11.2.0, which spdlog 1.13 does not compile with; 10.2.1 is the fmt
#     spdlog 1.13 bundles)
# With internet access the script clones them itself; by hand that is, per line above,
#   git clone https://github.com/OWNER/NAME DIR/src/NAME && git -C DIR/src/NAME checkout SHA
# (the submodules into DIR/src/geogram/src/lib/geogram/third_party/{amgcl,libMeshb,rply}).
# Eigen and TBB come from Debian (fTetWild's CMake would download them). Needs, from Debian 12:
#   apt-get install git cmake ninja-build g++ libeigen3-dev libgmp-dev libtbb-dev
# (not in scripts/setup.sh: only this peer needs them).
#
# The CMake line, offline (FETCHCONTENT_FULLY_DISCONNECTED: every FetchContent source is
# one of the folders above):
#   cmake -S DIR/src/fTetWild -B DIR/build -G Ninja -DCMAKE_BUILD_TYPE=Release
#     -DFETCHCONTENT_FULLY_DISCONNECTED=ON
#     -DFETCHCONTENT_SOURCE_DIR_{LIBIGL,PREDICATES,GEOGRAM,CLI11,JSON,SPDLOG,FMT}=DIR/src/...
#     -DFETCHCONTENT_SOURCE_DIR_EIGEN=/usr/include/eigen3
#     -DCMAKE_PROJECT_FloatTetwild_INCLUDE=DIR/system_tbb.cmake
# where DIR/system_tbb.cmake (written by this script) holds `find_package(TBB REQUIRED)`:
# run right after fTetWild's project(), it defines TBB::tbb from Debian's libtbb-dev, so
# fTetWild does not fetch oneTBB. TBB cannot be left out: with FLOAT_TETWILD_ENABLE_TBB=OFF
# its sources still include oneapi/tbb.h. The benchmarks run it with --max-threads 1.
# The one edit to fTetWild's tree: its unit tests are not configured (they download
# Catch2), by commenting out `add_subdirectory(tests)` in its CMakeLists.txt.
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 DIR OUT" >&2; exit 1; }
DIR=$1
OUT=$2
case $DIR in /*) ;; *) DIR=$PWD/$DIR ;; esac
case $OUT in /*) ;; *) OUT=$PWD/$OUT ;; esac
MIRROR=${TETREC_PEER_MIRROR:-}
JOBS=${JOBS:-1}
EIGEN=${EIGEN_DIR:-/usr/include/eigen3}
for tool in git cmake ninja c++; do
  command -v "$tool" >/dev/null ||
    { echo "needs $tool (apt-get install git cmake ninja-build g++)" >&2; exit 1; }
done
[ -f "$EIGEN/Eigen/Core" ] ||
  { echo "$EIGEN/Eigen/Core not found: apt-get install libeigen3-dev, or set EIGEN_DIR" >&2; exit 1; }
[ -f /usr/include/gmp.h ] || [ -f /usr/include/x86_64-linux-gnu/gmp.h ] ||
  echo "gmp.h not found in /usr/include: fTetWild needs GMP (apt-get install libgmp-dev)" >&2
[ -f /usr/include/oneapi/tbb.h ] ||
  echo "oneapi/tbb.h not found in /usr/include: fTetWild needs TBB (apt-get install libtbb-dev)" >&2
mkdir -p "$DIR/src"

# get OWNER/NAME SHA DEST: DEST is a work tree of OWNER/NAME at SHA, cleanly checked out
get() {
  local owner_name=$1 sha=$2 dest=$3 from
  if [ -n "$MIRROR" ]; then
    from=$MIRROR/${owner_name/\//+}/repo
  else
    from=https://github.com/$owner_name
  fi
  if [ ! -d "$dest/.git" ] && [ ! -f "$dest/.git" ]; then
    rm -rf "$dest"
    git clone -q --no-checkout "$from" "$dest" ||
      { echo "cannot clone $from" >&2; exit 1; }
  fi
  if ! git -C "$dest" cat-file -e "$sha^{commit}" 2>/dev/null; then
    git -C "$dest" fetch -q origin "$sha" 2>/dev/null || true
  fi
  git -C "$dest" cat-file -e "$sha^{commit}" 2>/dev/null ||
    { echo "$owner_name: commit $sha is not in $from" >&2; exit 1; }
  # -f: undoes this script's own edit from an earlier run
  git -C "$dest" -c advice.detachedHead=false checkout -q -f "$sha"
  echo "$owner_name at $sha"
}

S=$DIR/src
get wildmeshing/fTetWild d7d99bb4387a07895b9adce058dc7305f6b6e5ab "$S/fTetWild"
get libigl/libigl 40e7900ccbd767f1f360e0eb10f0f1a6432e0993 "$S/libigl"
get libigl/libigl-predicates decb7bc1260e689cbe008109e3cc5d3a5a433aea "$S/predicates"
get BrunoLevy/geogram fc3eb9bf44d2ee29686592e3ef5f5f4daeda27f8 "$S/geogram"
TP=$S/geogram/src/lib/geogram/third_party
get ddemidov/amgcl ab57038d68ee372ed5df280631051b91f17ed2d1 "$TP/amgcl"
get LoicMarechal/libMeshb 952a157c9d516b28cc6c69cd1550c3e48d4792f9 "$TP/libMeshb"
get diegonehab/rply 4296cc91b5c8c26d4e7d7aac0cee2b194ffc5800 "$TP/rply"
get CLIUtils/CLI11 4160d259d961cd393fd8d67590a8c7d210207348 "$S/cli11"
get jdumas/json 0901d33bf6e7dfe6f70fd9d142c8f5c6695c6c5b "$S/json"
get gabime/spdlog 7c02e204c92545f869e2f04edaab1f19fe8b19fd "$S/spdlog"
get fmtlib/fmt e69e5f977d458f2650bb346dadf2ad30c5320281 "$S/fmt"

# the unit tests would download Catch2 at configure time
sed -i 's/^\([[:space:]]*\)add_subdirectory(tests)/\1# add_subdirectory(tests)/' "$S/fTetWild/CMakeLists.txt"
grep -q '^[[:space:]]*add_subdirectory(tests)' "$S/fTetWild/CMakeLists.txt" &&
  { echo "could not turn fTetWild's unit tests off" >&2; exit 1; }

# the system's TBB, found before fTetWild's dependency file would fetch oneTBB
echo 'find_package(TBB REQUIRED)' >"$DIR/system_tbb.cmake"
cmake -S "$S/fTetWild" -B "$DIR/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DFETCHCONTENT_FULLY_DISCONNECTED=ON \
  -DCMAKE_PROJECT_FloatTetwild_INCLUDE="$DIR/system_tbb.cmake" \
  -DFETCHCONTENT_SOURCE_DIR_LIBIGL="$S/libigl" \
  -DFETCHCONTENT_SOURCE_DIR_PREDICATES="$S/predicates" \
  -DFETCHCONTENT_SOURCE_DIR_GEOGRAM="$S/geogram" \
  -DFETCHCONTENT_SOURCE_DIR_CLI11="$S/cli11" \
  -DFETCHCONTENT_SOURCE_DIR_JSON="$S/json" \
  -DFETCHCONTENT_SOURCE_DIR_SPDLOG="$S/spdlog" \
  -DFETCHCONTENT_SOURCE_DIR_FMT="$S/fmt" \
  -DFETCHCONTENT_SOURCE_DIR_EIGEN="$EIGEN" >"$DIR/cmake.log" 2>&1 ||
  { tail -n 30 "$DIR/cmake.log" >&2; echo "cmake failed: $DIR/cmake.log" >&2; exit 1; }
start=$(date +%s)
# fTetWild's and geogram's warnings fill megabytes: they go to the log
if ! ninja -C "$DIR/build" -j "$JOBS" FloatTetwild_bin >"$DIR/build.log" 2>&1; then
  grep -m 20 -B 2 -A 8 'error' "$DIR/build.log" >&2 || tail -n 40 "$DIR/build.log" >&2
  echo "the build failed: $DIR/build.log" >&2
  exit 1
fi
mkdir -p "$(dirname "$OUT")"
cp "$DIR/build/FloatTetwild_bin" "$OUT"
echo "built $OUT (fTetWild d7d99bb) in $(( $(date +%s) - start )) s"
