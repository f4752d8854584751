#!/usr/bin/env bash
# Builds rtlab and runs every ctest test, then the exactness tests again built for the native CPU, then the
# formatting check.
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
# The install-tree consumer tests build and run projects against the installed package: that is checked in release;
# under the sanitizers they would only repeat it (about 50 CPU seconds).
if [ "$preset" = asan ]; then
  ctest --preset "$preset" -j "$jobs" -LE '^consumer$'
else
  ctest --preset "$preset" -j "$jobs"
fi

# The triangle and slab tests must stay exact when the compiler may contract a*b - c*d into an FMA
# (-march=native on a CPU with FMA; the bench preset): the geometry and accel tests that depend on
# exactness (watertight leaks, t error bound, spawned rays, every accelerator against brute force), built
# apart with -march=native: the libraries they need and two test executables only.
if [ "$preset" = release ]; then
  start=$SECONDS
  cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS=-march=native \
    -DRTLAB_BUILD_APPS=OFF -DRTLAB_BUILD_BENCH=OFF -DRTLAB_INSTALL=OFF -DRTLAB_WARNINGS_AS_ERRORS=ON >/dev/null
  cmake --build build/native -j "$jobs" --target rtlab_geometry_tests rtlab_accel_tests
  (cd build/native/tests/geometry && ../../bin/rtlab_geometry_tests "[triangle],[spawn]")
  (cd build/native/tests/accel && ../../bin/rtlab_accel_tests "[accel],[spawn]")
  echo "test: native-CPU exactness tests took $((SECONDS - start)) s"
fi

# Formatting does not depend on the build: checked once, with the release run.
if [ "$preset" = release ]; then bash scripts/format.sh --check; fi
