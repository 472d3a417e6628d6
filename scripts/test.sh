#!/usr/bin/env bash
# Builds visfeat and runs the whole test suite.
#   scripts/test.sh              Release build in build/ (or $BUILD_DIR)
#   scripts/test.sh --sanitize   ASan+UBSan RelWithDebInfo build in build-asan/
# Warnings are errors. Exits non-zero on any failure.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

sanitize=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) sanitize=1 ;;
    -h|--help)
      sed -n '2,5p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
      exit 0 ;;
    *) echo "test.sh: unknown argument: $arg" >&2; exit 2 ;;
  esac
done

bash "$root/scripts/install_deps.sh"

jobs="$(nproc 2>/dev/null || echo 2)"
if [ "$sanitize" -eq 1 ]; then
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
ctest --test-dir "$build_dir" --output-on-failure -j2
echo "== all tests passed ($build_dir)"
