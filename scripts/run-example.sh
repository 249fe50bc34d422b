#!/usr/bin/env bash
# The main job on the built-in example: installs the Debian packages, builds genmod, prints
# facts about the Prospero model and renders it at 1024x1024 to prospero.png.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" release
genmod="$root/build/release/apps/genmod"
"$genmod" info "$root/data/prospero.vm"
"$genmod" render "$root/data/prospero.vm" --size 1024 -o "${1:-prospero.png}" --stats
