#!/usr/bin/env bash
# Installs every Debian 12 package genmod needs to build, test and benchmark.
# Idempotent: packages already present are skipped, and apt-get is not touched at all
# when nothing is missing. Runs as root, or through sudo when it is available.
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  libboost-dev            # Boost.Interval
  libeigen3-dev           # linear algebra
  libtbb-dev              # oneTBB parallelism
  libpng-dev              # PNG output of the renderer
  libgtest-dev libgmock-dev
  libbenchmark-dev
  libmpfi-dev libmpfr-dev libgmp-dev   # interval oracle for tests
  libcgal-dev             # mesh validation (tessellate layer)
  libopenmesh-dev         # mesh data structure and I/O
  pybind11-dev python3-dev python3-numpy python3-pytest
  python3-distributed     # Dask distributed batch (Python side)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
