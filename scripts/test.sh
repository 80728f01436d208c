#!/usr/bin/env bash
# The whole test suite, from a fresh clone: installs what is missing, then
#   1. Release build of everything (tests, examples, benchmarks, tools, the Python module) in build/, all tests
#      (GoogleTest programs and the pytest suite python/tests);
#   2. ASan + UBSan build of the tests in build-asan/, all tests;
#   3. ThreadSanitizer build of the parallel tests (program test_parallel) in build-tsan/;
#   4. the kernel's tests built without -march=native (a plain Release build: AVX2 paths chosen at run time, the
#      scalar ones forced by the tests) in build-portable/;
#   5. the kernel's tests built without TBB in build-no-tbb/.
# Every stage runs even if an earlier one failed and prints its seconds; the exit status is non-zero if any failed.
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

# Sanitizer builds without debug information (and at -O0 for the programs whose tests are short, see
# FDT3_SANITIZER_O0_PROGRAMS in CMakeLists.txt): the CGAL-heavy test programs' compilation is most of the time of
# this script. Reports name the functions; rebuild with -g1 for their lines.
# ASan+UBSan at -Og: UBSan's checks double the optimiser's work at -O1 (test_parallel's unit: 103 s of compiling
# under ASan alone, 212 s with UBSan, 117 s with both at -Og), and -Og leaves out the passes that cost most on them.
# Measured on the 2-core Xeon VM, one build after the other: the stage's build took 463 s (813 s of CPU) instead of
# 517 s (963 s); its tests, at 172-176 s at -O1, took 189 s (test_sequential's 66 s instead of 55 s run alone).
# ThreadSanitizer's build is one program whose tests are most of its stage (56 s of compiling, 280 s of test CPU at
# -O1): it stays at -O1.
asan_ubsan_flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-Og -g0 -DNDEBUG")
tsan_flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g0 -DNDEBUG")

release_build() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release &&
    cmake --build build -j"$jobs" &&
    ctest --test-dir build --output-on-failure -j"$jobs"
}

asan_ubsan_build() {
  cmake -S . -B build-asan "${asan_ubsan_flags[@]}" -DFDT3_SANITIZE='address;undefined' \
        -DFDT3_BUILD_BENCHMARKS=OFF -DFDT3_BUILD_EXAMPLES=OFF &&
    "${sanitizer_runner[@]}" cmake --build build-asan -j"$jobs" &&
    "${sanitizer_runner[@]}" ctest --test-dir build-asan --output-on-failure -j"$jobs"
}

tsan_build() {
  cmake -S . -B build-tsan "${tsan_flags[@]}" -DFDT3_SANITIZE=thread \
        -DFDT3_BUILD_BENCHMARKS=OFF -DFDT3_BUILD_EXAMPLES=OFF -DFDT3_BUILD_TOOLS=OFF -DFDT3_BUILD_PYTHON=OFF &&
    "${sanitizer_runner[@]}" cmake --build build-tsan -j"$jobs" --target test_parallel &&
    "${sanitizer_runner[@]}" ctest --test-dir build-tsan -L parallel --output-on-failure -j"$jobs"
}

# The kernel's tests (predicates and their filters, agreement with CGAL on every distribution, degenerate inputs,
# the partitioned engine): the code paths that a build option selects.
kernel_tests="test_predicates;test_agreement_with_cgal;test_degenerate_inputs;test_parallel_insertion"

# Without -march=native, as a user's plain Release build: the predicates' AVX2 forms as functions for that target,
# chosen at run time where the processor has them, and the scalar forms (which the tests also force) and sorts.
portable_build() {
  cmake -S . -B build-portable -DCMAKE_BUILD_TYPE=Release -DFDT3_NATIVE=OFF -DFDT3_TEST_FILES="$kernel_tests" \
        -DFDT3_BUILD_BENCHMARKS=OFF -DFDT3_BUILD_EXAMPLES=OFF -DFDT3_BUILD_TOOLS=OFF -DFDT3_BUILD_PYTHON=OFF &&
    cmake --build build-portable -j"$jobs" &&
    ctest --test-dir build-portable --output-on-failure -j"$jobs"
}

# Without TBB: the parallel engine's partitions run one after the other, and parallel data structures fall back.
no_tbb_build() {
  cmake -S . -B build-no-tbb -DCMAKE_BUILD_TYPE=Release -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DFDT3_BUILD_PYTHON=OFF \
        -DFDT3_TEST_FILES="$kernel_tests" -DFDT3_BUILD_BENCHMARKS=OFF -DFDT3_BUILD_EXAMPLES=OFF \
        -DFDT3_BUILD_TOOLS=OFF &&
    cmake --build build-no-tbb -j"$jobs" &&
    ctest --test-dir build-no-tbb --output-on-failure -j"$jobs"
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

suite_start=$SECONDS
stage release_build
stage asan_ubsan_build
stage tsan_build
stage portable_build
stage no_tbb_build

echo
if [ "${#failed[@]}" -gt 0 ]; then
  echo "test.sh: FAILED stages: ${failed[*]} ($((SECONDS - suite_start)) s in all)"
  exit 1
fi
echo "test.sh: all stages passed ($((SECONDS - suite_start)) s in all)"
