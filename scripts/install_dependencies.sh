#!/usr/bin/env bash
# Installs, with apt, whatever this package needs that Debian 12 does not have yet: the compiler, CMake, CGAL and
# its number types (GMP, MPFR, Boost), TBB for the parallel engines, GoogleTest, TetGen for the mesher's boundary
# recovery, CGAL's data surfaces (libcgal-demo) for the mesher's CGAL-data test and benchmark, Gmsh's library (HXT,
# OpenCASCADE) for that benchmark; and for Debian's /usr/bin/python3: pybind11 and numpy for the Python module,
# pytest and scipy (the oracle of its tests), meshio to read the mesher's files back in a test, matplotlib for the
# benchmarks' figures (--plot), and Gmsh's Python API, whose tetrahedralize the Python benchmark times beside ours
# and scipy's; Open MPI for the distributed triangulation (its test runs under mpirun). Does nothing if all are
# present.
set -euo pipefail

packages=(build-essential cmake libcgal-dev libboost-dev libgmp-dev libmpfr-dev libtbb-dev libgtest-dev libtet1.5-dev
          libcgal-demo libgmsh-dev python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-scipy
          python3-meshio python3-matplotlib python3-gmsh libopenmpi-dev openmpi-bin)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg -s "$package" 2>/dev/null | grep -q '^Status: install ok installed'; then
    missing+=("$package")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install_dependencies: all of ${packages[*]} are installed"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "install_dependencies: missing ${missing[*]}, and neither root nor sudo is available to install them" >&2
  exit 1
fi

echo "install_dependencies: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
