#!/usr/bin/env bash
# One bounded libFuzzer run of a visfeat fuzz target, shared by scripts/test.sh --fuzz
# and by hand:
#   scripts/fuzz_run.sh BUILD_DIR TARGET SECONDS     e.g. build-fuzz fuzz_pcd 600
# The target starts from its checked-in corpus (test/fuzz/corpus/<reader>/, read only)
# and keeps what it finds in BUILD_DIR/fuzz_runs/<target>/corpus/; a crash, a hang
# (-timeout=10 s an input), a sanitizer report or more than 2 GiB of memory
# leaves the input in BUILD_DIR/fuzz_runs/<target>/ (crash-*, timeout-*, oom-*,
# leak-*) and fails. FUZZ_JOBS=N runs N processes (-fork=N) instead of one.

# The fuzz targets, from test/fuzz/CMakeLists.txt's VISFEAT_FUZZ_TARGETS.
fuzz_targets() {
  sed -n 's/^set(VISFEAT_FUZZ_TARGETS \(.*\))$/\1/p' "$1/test/fuzz/CMakeLists.txt" |
    tr ' ' '\n' | sed 's/^/fuzz_/'
}

# fuzz_run ROOT BUILD_DIR TARGET SECONDS
fuzz_run() {
  local root="$1" build_dir target="$3" seconds="$4"
  build_dir="$(cd "$2" && pwd)"
  local reader="${target#fuzz_}"
  local exe="$build_dir/test/fuzz/$target"
  local work="$build_dir/fuzz_runs/$target"
  mkdir -p "$work/corpus"
  local fork=()
  if [ "${FUZZ_JOBS:-1}" -gt 1 ]; then
    fork=(-fork="$FUZZ_JOBS" -ignore_crashes=0)
  fi
  echo "== fuzz $target for $seconds s (log: $work/log.txt)"
  local rc=0
  (cd "$work" && ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" \
    UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}" \
    "$exe" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$work/" "${fork[@]}" \
    corpus "$root/test/fuzz/corpus/$reader") >"$work/log.txt" 2>&1 || rc=$?
  grep -E '^stat::number_of_executed_units|^#[0-9]+ *DONE' "$work/log.txt" | tail -2 || true
  if [ "$rc" -ne 0 ]; then
    echo "fuzz: $target failed (exit $rc); the end of $work/log.txt:" >&2
    tail -40 "$work/log.txt" >&2
    ls "$work"/crash-* "$work"/timeout-* "$work"/oom-* "$work"/leak-* 2>/dev/null >&2 || true
    return 1
  fi
}

if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  set -euo pipefail
  if [ $# -ne 3 ]; then
    sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
  fi
  fuzz_run "$(cd "$(dirname "$0")/.." && pwd)" "$1" "$2" "$3"
fi
