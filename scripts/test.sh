#!/usr/bin/env bash
# Builds visfeat and runs the whole test suite.
#   scripts/test.sh              Release build in build/ (or $BUILD_DIR)
#   scripts/test.sh --sanitize   ASan+UBSan RelWithDebInfo build in build-asan/
#   scripts/test.sh --fuzz       clang libFuzzer build in build-fuzz/: the fuzz targets
#                                of the readers replay their corpus (ctest -L fuzz),
#                                then each fuzzes for $FUZZ_SECONDS (default 30) s
#   scripts/test.sh --full       also the labels left out by default to keep CI under
#                                20 minutes: invariance (every model under 20
#                                rotations and in survey coordinates, 4-13 minutes on
#                                2 cores) and extended (every model's rotations 2
#                                and 3, the meshes at 1024, the sparse clouds of
#                                20,000 and 40,000 points, four of the seven whole
#                                maps, the whole maps with noise or a cap of 24:
#                                ~11 minutes)
#   scripts/test.sh --invariance the same as --full (its older name)
# Warnings are errors. Exits non-zero on any failure (with --fuzz: a crash, a hang
# over 10 s, a sanitizer report or over 2 GiB of memory; the input is left in
# build-fuzz/fuzz_runs/<target>/).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

mode=normal
full=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) mode=sanitize ;;
    --fuzz) mode=fuzz ;;
    --full|--invariance) full=1 ;;
    -h|--help)
      sed -n '2,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
      exit 0 ;;
    *) echo "test.sh: unknown argument: $arg" >&2; exit 2 ;;
  esac
done

jobs="$(nproc 2>/dev/null || echo 2)"

if [ "$mode" = fuzz ]; then
  bash "$root/scripts/install_deps.sh" --fuzz
  source "$root/scripts/fuzz_run.sh"
  build_dir="${BUILD_DIR:-build-fuzz}"
  echo "== configure ($build_dir, clang, libFuzzer + ASan + UBSan)"
  CC=clang CXX=clang++ cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DVISFEAT_FUZZ=ON -DVISFEAT_WARNINGS_AS_ERRORS=ON -DBUILD_TESTING=ON \
    -DVISFEAT_BUILD_TESTS=OFF -DVISFEAT_BUILD_SAMPLES=OFF -DVISFEAT_PICTURES=OFF
  targets=($(fuzz_targets "$root"))
  echo "== build (${targets[*]})"
  cmake --build "$build_dir" -j"$jobs" --target "${targets[@]}"
  echo "== replay the corpus"
  ctest --test-dir "$build_dir" --output-on-failure -L fuzz
  for t in "${targets[@]}"; do
    fuzz_run "$root" "$build_dir" "$t" "${FUZZ_SECONDS:-30}"
  done
  echo "== fuzzing found nothing (${targets[*]}, ${FUZZ_SECONDS:-30} s each)"
  exit 0
fi

bash "$root/scripts/install_deps.sh"

if [ "$mode" = sanitize ]; then
  build_dir="${BUILD_DIR:-build-asan}"
  cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DVISFEAT_SANITIZE=ON)
  # LeakSanitizer reports one-off allocations in third-party libraries' static
  # state as leaks too; keep it on, but make UBSan print stack traces.
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
else
  build_dir="${BUILD_DIR:-build}"
  cmake_args=(-DCMAKE_BUILD_TYPE=Release)
fi

echo "== configure ($build_dir)"
cmake -S . -B "$build_dir" -DVISFEAT_WARNINGS_AS_ERRORS=ON -DVISFEAT_BUILD_TESTS=ON \
  -DBUILD_TESTING=ON "${cmake_args[@]}"
echo "== build"
cmake --build "$build_dir" -j"$jobs"
echo "== test"
if [ "$full" -eq 1 ]; then
  ctest --test-dir "$build_dir" --output-on-failure -j2
else
  ctest --test-dir "$build_dir" --output-on-failure -j2 -LE 'invariance|extended'
fi
echo "== all tests passed ($build_dir)"
