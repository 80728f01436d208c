#!/usr/bin/env bash
# The main job, from a fresh clone: installs what is missing, builds the benchmark (and the Python module) in
# Release and runs the benchmark.
# Without arguments: 1,000,000 uniform points, this package beside CGAL::Delaunay_triangulation_3 (sequential and,
# with TBB, parallel). Arguments go to the benchmark; `bash scripts/benchmark.sh --help` lists them.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --target delaunay_benchmark -j2
# The Python module too (the README's Python example runs on it), when CMake found pybind11.
targets=$(cmake --build build --target help)
if [[ $targets == *fast_delaunay_3_python* ]]; then
  cmake --build build --target fast_delaunay_3_python -j2
fi
./build/benchmark/Fast_Delaunay_triangulation_3/delaunay_benchmark "$@"
