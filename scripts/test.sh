#!/usr/bin/env bash
# Builds rtlab and runs every ctest test.
#   scripts/test.sh             release preset, warnings as errors
#   scripts/test.sh --sanitize  the asan preset (AddressSanitizer + UndefinedBehaviorSanitizer)
set -euo pipefail
cd "$(dirname "$0")/.."

preset=release
if [ "${1:-}" = "--sanitize" ]; then preset=asan; fi

bash scripts/setup.sh
jobs=$(nproc)
cmake --preset "$preset" -DRTLAB_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build --preset "$preset" -j "$jobs"
ctest --preset "$preset" -j "$jobs"
