#!/usr/bin/env bash
# The main job, from a fresh clone: installs what is missing, builds the benchmark (and the Python module) in
# Release and runs the benchmark.
# Without arguments: 1,000,000 uniform points, this package beside CGAL::Delaunay_triangulation_3 (sequential and,
# with TBB, parallel) and TetGen's Delaunay tetrahedralization. Arguments go to the benchmark;
# `bash scripts/benchmark.sh --help` lists them, and one more:
#
#   --plot FIGURE.png|FIGURE.svg   also draw the table (scripts/plot_benchmark.py): seconds and Mtets/s against n,
#                                  and the speed-up against the thread count when --threads lists several; the
#                                  medians go to FIGURE.csv beside it (the benchmark's --csv), to redraw without
#                                  running again: /usr/bin/python3 scripts/plot_benchmark.py FIGURE.csv FIGURE.png
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# Debian's interpreter, where python3-matplotlib installs matplotlib (a python3 earlier on PATH may lack it).
python=/usr/bin/python3

figure=""
arguments=()
while [ $# -gt 0 ]; do
  case "$1" in
    --plot)
      if [ $# -lt 2 ]; then
        echo "benchmark.sh: --plot needs a file name ending in .png or .svg" >&2
        exit 2
      fi
      figure="$2"
      shift 2
      ;;
    *)
      arguments+=("$1")
      shift
      ;;
  esac
done

if [ -n "$figure" ]; then
  case "$figure" in
    *.png | *.svg | *.pdf) ;;
    *)
      echo "benchmark.sh: --plot $figure: the figure must end in .png, .svg or .pdf" >&2
      exit 2
      ;;
  esac
  for argument in ${arguments[@]+"${arguments[@]}"}; do
    if [ "$argument" = "--csv" ]; then
      echo "benchmark.sh: --plot writes its own CSV (${figure%.*}.csv); leave out --csv" >&2
      exit 2
    fi
  done
fi

bash scripts/install_dependencies.sh
# Checked before the benchmark runs, so that a long run is not lost for want of matplotlib.
if [ -n "$figure" ] && ! "$python" -c 'import matplotlib' 2>/dev/null; then
  echo "benchmark.sh: --plot needs matplotlib for $python (Debian: apt-get install python3-matplotlib)" >&2
  exit 1
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --target delaunay_benchmark -j2
# The Python module too (the README's Python example runs on it), when CMake found pybind11.
targets=$(cmake --build build --target help)
if [[ $targets == *fast_delaunay_3_python* ]]; then
  cmake --build build --target fast_delaunay_3_python -j2
fi

if [ -z "$figure" ]; then
  exec ./build/benchmark/Fast_Delaunay_triangulation_3/delaunay_benchmark ${arguments[@]+"${arguments[@]}"}
fi
# The benchmark exits with 1 when the engines' cell counts disagree; the figure is drawn all the same (its title
# repeats the warning) and that status is returned.
status=0
./build/benchmark/Fast_Delaunay_triangulation_3/delaunay_benchmark ${arguments[@]+"${arguments[@]}"} \
  --csv "${figure%.*}.csv" || status=$?
if [ -s "${figure%.*}.csv" ]; then
  "$python" scripts/plot_benchmark.py "${figure%.*}.csv" "$figure"
fi
exit "$status"
