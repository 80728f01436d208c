#!/usr/bin/env bash
# The whole test suite, from a fresh clone: installs what is missing, then
#   1. Release build of everything (tests, examples, benchmarks) in build/, all tests;
#   2. ASan + UBSan build of the tests in build-asan/, all tests;
#   3. if some test carries the label `parallel`: ThreadSanitizer build in build-tsan/, the parallel tests.
# Every stage runs even if an earlier one failed; the exit status is non-zero if any failed.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_dependencies.sh

jobs=2
# A finding aborts the test with its report (the build also passes -fno-sanitize-recover=all).
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:halt_on_error=1:detect_leaks=1:print_summary=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-abort_on_error=1:halt_on_error=1:print_stacktrace=1}"
export TSAN_OPTIONS="${TSAN_OPTIONS:-abort_on_error=1:halt_on_error=1:second_deadlock_stack=1}"

# GCC 12's sanitizer runtimes cannot map their shadow memory on kernels with 32 bits of mmap randomisation;
# without address randomisation they work everywhere. Used only where the sandbox allows it.
sanitizer_runner=()
if setarch "$(uname -m)" -R true 2>/dev/null; then
  sanitizer_runner=(setarch "$(uname -m)" -R)
fi

# Sanitizer builds: -O1 with line tables only. Reports keep function names and lines, and the CGAL-heavy test
# programs, whose compilation dominates the time of this script, compile faster than with RelWithDebInfo's -O2 -g.
sanitizer_flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG")

release_build() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release &&
    cmake --build build -j"$jobs" &&
    ctest --test-dir build --output-on-failure -j"$jobs"
}

asan_ubsan_build() {
  cmake -S . -B build-asan "${sanitizer_flags[@]}" -DFDT3_SANITIZE='address;undefined' \
        -DFDT3_BUILD_BENCHMARKS=OFF -DFDT3_BUILD_EXAMPLES=OFF &&
    "${sanitizer_runner[@]}" cmake --build build-asan -j"$jobs" &&
    "${sanitizer_runner[@]}" ctest --test-dir build-asan --output-on-failure -j"$jobs"
}

# The number of tests labelled `parallel` in the Release build.
parallel_test_count() {
  ctest --test-dir build -N -L parallel 2>/dev/null | sed -n 's/^Total Tests: *//p'
}

# The test programs the test CMakeLists labels `parallel`: those with "parallel" in their name. Only they are
# built with ThreadSanitizer.
parallel_test_targets() {
  local file
  for file in test/Fast_Delaunay_triangulation_3/test_*parallel*.cpp; do
    if [ -e "$file" ]; then basename "$file" .cpp; fi
  done
}

tsan_build() {
  local targets
  mapfile -t targets < <(parallel_test_targets)
  [ "${#targets[@]}" -gt 0 ] &&
    cmake -S . -B build-tsan "${sanitizer_flags[@]}" -DFDT3_SANITIZE=thread \
          -DFDT3_BUILD_BENCHMARKS=OFF -DFDT3_BUILD_EXAMPLES=OFF &&
    "${sanitizer_runner[@]}" cmake --build build-tsan -j"$jobs" --target "${targets[@]}" &&
    "${sanitizer_runner[@]}" ctest --test-dir build-tsan -L parallel --output-on-failure -j"$jobs"
}

failed=()
stage() {
  local name=$1
  echo
  echo "=== $name"
  local start=$SECONDS
  if "$name"; then
    echo "=== $name: passed ($((SECONDS - start)) s)"
  else
    echo "=== $name: FAILED ($((SECONDS - start)) s)"
    failed+=("$name")
  fi
}

stage release_build
stage asan_ubsan_build
if [ "$(parallel_test_count)" -gt 0 ] 2>/dev/null; then
  stage tsan_build
else
  echo
  echo "=== tsan_build: skipped (no test labelled 'parallel')"
fi

echo
if [ "${#failed[@]}" -gt 0 ]; then
  echo "test.sh: FAILED stages: ${failed[*]}"
  exit 1
fi
echo "test.sh: all stages passed"
