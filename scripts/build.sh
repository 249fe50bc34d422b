#!/usr/bin/env bash
# Configures and builds genmod in build/<name> (default: release).
# Usage: scripts/build.sh [name] [extra cmake arguments...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
name="${1:-release}"
shift || true
jobs="$(nproc)"
cmake -S "$root" -B "$root/build/$name" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$root/build/$name" -j "$jobs"
