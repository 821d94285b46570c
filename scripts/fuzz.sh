#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) and runs every fuzz_* executable
# under BUILD/fuzz/ for SECONDS each (default 60), one at a time, on a scratch copy of
# its seed corpus fuzz/corpus/<name without "fuzz_">/ (or fuzz/corpus/<name>/), so the
# repository corpus is never modified. Prints executions and executions/s per target
# and exits non-zero if any target found a crash, leak, timeout or sanitizer report;
# the reproducing inputs are copied to BUILD/fuzz-findings/ (slow units too, which are
# reported but do not fail the run).
#
#   scripts/fuzz.sh [SECONDS] [TARGET_SUBSTRING...]
#   FUZZ_BUILD_DIR=build-x scripts/fuzz.sh 600 fuzz_pred_predicates
set -euo pipefail

secs=${1:-60}
shift || true
filters=("$@")
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD_DIR:-build-fuzz}
case $build in /*) ;; *) build=$root/$build ;; esac

if [ ! -f "$build/build.ninja" ]; then
  # -Db_lundef=false: the sanitizer runtimes are linked into executables only.
  # fuzzer-no-link instruments every object (library included) for coverage;
  # fuzz/meson.build links the targets with -fsanitize=fuzzer.
  CC=clang CXX=clang++ meson setup "$build" "$root" -Dfuzz=true \
    -Db_sanitize=address,undefined -Db_lundef=false \
    -Dc_args=-fsanitize=fuzzer-no-link -Dcpp_args=-fsanitize=fuzzer-no-link \
    -Dbench=false
fi
ninja -C "$build" -j "${FUZZ_JOBS:-2}"

mapfile -t targets < <(find "$build/fuzz" -type f -name 'fuzz_*' -perm -u+x 2>/dev/null | sort)
if [ ${#filters[@]} -gt 0 ]; then
  keep=()
  for t in "${targets[@]}"; do
    for f in "${filters[@]}"; do
      case $(basename "$t") in *"$f"*) keep+=("$t"); break ;; esac
    done
  done
  targets=("${keep[@]+"${keep[@]}"}")
fi
if [ ${#targets[@]} -eq 0 ]; then
  echo "fuzz.sh: no fuzz_* executables under $build/fuzz" >&2
  exit 1
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/tetrec-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT
findings=$build/fuzz-findings
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:abort_on_error=1:print_stacktrace=1}

failed=0
summary=()
for exe in "${targets[@]}"; do
  name=$(basename "$exe")
  seed=""
  for d in "$root/fuzz/corpus/${name#fuzz_}" "$root/fuzz/corpus/$name"; do
    if [ -d "$d" ]; then
      seed=$d
      break
    fi
  done
  mkdir -p "$work/$name/corpus" "$work/$name/artifacts"
  if [ -n "$seed" ]; then
    cp -R "$seed/." "$work/$name/corpus/"
  fi
  echo "== $name: ${secs}s, seed corpus ${seed:-<none>} ($(find "$work/$name/corpus" -type f | wc -l) files)"
  log=$work/$name/log
  rc=0
  "$exe" -max_total_time="$secs" -timeout=60 -print_final_stats=1 \
    -artifact_prefix="$work/$name/artifacts/" "$work/$name/corpus" >"$log" 2>&1 || rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  # slow units (an input over libFuzzer's 10 s report threshold) are listed, not failures:
  # a hang is a timeout artifact (-timeout=60) and fails
  nslow=$(find "$work/$name/artifacts" -type f -name 'slow-unit-*' | wc -l)
  ncrash=$(find "$work/$name/artifacts" -type f ! -name 'slow-unit-*' | wc -l)
  status=ok
  if [ "$nslow" -ne 0 ]; then
    mkdir -p "$findings/$name"
    cp "$work/$name/artifacts/"slow-unit-* "$findings/$name/" 2>/dev/null || true
    status="ok ($nslow slow unit(s) over 10 s, copied to $findings/$name/)"
  fi
  if [ "$rc" -ne 0 ] || [ "$ncrash" -ne 0 ]; then
    status="FAILED (exit $rc, $ncrash finding(s))"
    failed=1
    mkdir -p "$findings/$name"
    cp -R "$work/$name/artifacts/." "$findings/$name/" 2>/dev/null || true
    cp "$log" "$findings/$name/log"
    grep -E 'MISMATCH|ERROR|runtime error|==[0-9]+==|SUMMARY|^  ' "$log" | head -40 >&2 || true
    echo "   findings and log in $findings/$name/" >&2
  fi
  line="$name: ${secs}s, ${execs:-?} executions, ${rate:-?} exec/s, $status"
  echo "   $line"
  summary+=("$line")
done

echo "== summary"
printf '   %s\n' "${summary[@]}"
exit $failed
