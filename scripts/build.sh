#!/usr/bin/env bash
# Configures and builds genmod in build/<name> (default: release).
# Usage: scripts/build.sh [name] [extra cmake arguments...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
name="${1:-release}"
shift || true
jobs="$(nproc)"
# ccache keys on paths relative to the checkout, so another clone of the same sources (CI's
# fresh clone, a worktree) reuses what this machine has compiled already.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
cmake -S "$root" -B "$root/build/$name" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$root/build/$name" -j "$jobs"
# `import genmod` for Debian's python3 without setting a path: a .pth file in its user site
# directory names the package built here (the release build only; rewritten on each build).
if [ "$name" = release ] && [ -d "$root/build/$name/python/genmod" ] && [ -x /usr/bin/python3 ]; then
  site="$(/usr/bin/python3 -m site --user-site)"
  mkdir -p "$site"
  echo "$root/build/$name/python" > "$site/genmod.pth"
fi
