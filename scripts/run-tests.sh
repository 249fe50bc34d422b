#!/usr/bin/env bash
# The whole test suite: installs the Debian packages, builds genmod (Release, with
# -frounding-math) with the Python module, runs every test with ctest (the C++ suites and the
# pytest suite of tests/python), then builds the libraries and their tests again
# under AddressSanitizer + UndefinedBehaviorSanitizer and runs those (the install test is
# skipped there: installed static libraries would need the sanitizer runtime).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
jobs="$(nproc)"
"$root/scripts/install-deps.sh"

"$root/scripts/build.sh" release
ctest --test-dir "$root/build/release" -j "$jobs" --output-on-failure

"$root/scripts/build.sh" sanitize -DGENMOD_SANITIZE=address,undefined -DGENMOD_BUILD_BENCH=OFF \
  -DGENMOD_BUILD_APPS=OFF -DGENMOD_BUILD_PYTHON=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir "$root/build/sanitize" -j "$jobs" --output-on-failure
