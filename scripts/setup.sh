#!/usr/bin/env bash
# Installs the Debian 12 packages rodnet needs, and those named as
# arguments; does nothing when all are present. Safe to run any number of
# times.
set -euo pipefail

packages=(
  build-essential cmake     # compiler and build system
  libdeal.ii-dev            # deal.II 9.4 with Trilinos 13.2, MPI, Debug + Release
  libeigen3-dev             # small dense algebra in the kernels
  libgtest-dev              # the ctest programs
  numdiff                   # tolerant comparison of numeric outputs
  gnuplot-nox               # PNG plots of probes and benchmark charts
  libsuitesparse-dev        # KLU, the sparse LU of Newton's systems
  libmumps-dev              # MUMPS, their multifrontal LDL^T (Linear solver = mumps)
  libopenblas0-serial       # the BLAS of MUMPS's dense fronts; becomes the system's
                            # BLAS and LAPACK (doc/performance.md, "OpenBLAS and our own band LU")
  libpng-dev                # the tests read the pictures runs draw
  python3-minimal           # writes the pop-up's Gmsh meshes (bench/fig9_popup_mesh.py)
)
# Callers add what only they need (scripts/fuzz.sh: clang and libFuzzer).
packages+=("$@")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
