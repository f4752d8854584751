#!/usr/bin/env bash
# Builds rtlab and runs every ctest test, then the exactness tests again built for the native CPU, then the
# formatting check.
#   scripts/test.sh             release preset, warnings as errors
#   scripts/test.sh --sanitize  the asan preset (AddressSanitizer + UndefinedBehaviorSanitizer)
#   --no-debug-info             with --sanitize: builds without -g1 (CI's run; 6-16% less compile time a file, and
#                               reports still name the functions; rebuild with the preset for file:line)
set -euo pipefail
cd "$(dirname "$0")/.."

preset=release
asan_flags=()
for arg in "$@"; do
  case "$arg" in
    --sanitize) preset=asan ;;
    --no-debug-info) asan_flags=(-DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG") ;;
    *) echo "test.sh: unknown option $arg (--sanitize, --no-debug-info)" >&2; exit 2 ;;
  esac
done
if [ "$preset" = release ]; then asan_flags=(); fi

bash scripts/setup.sh
jobs=$(nproc)
# Ninja (setup.sh installs it) for a new build folder: it compiles a target's files while the libraries it
# links are still being built, where make waits for them, which keeps both of a 2-core machine's cores busy
# through the build's long files (kd_mesh.cpp). A folder configured before keeps its generator.
new_build_dir() { [ ! -f "$1/CMakeCache.txt" ] && command -v ninja >/dev/null; }
if new_build_dir "build/$preset"; then export CMAKE_GENERATOR=Ninja; fi
cmake --preset "$preset" -DRTLAB_WARNINGS_AS_ERRORS=ON "${asan_flags[@]}" >/dev/null
unset CMAKE_GENERATOR
start=$SECONDS
cmake --build --preset "$preset" -j "$jobs"
echo "test: the $preset build took $((SECONDS - start)) s"
start=$SECONDS
# The install-tree consumer tests build and run projects against the installed package: that is checked in release;
# under the sanitizers they would only repeat it (about 50 CPU seconds).
if [ "$preset" = asan ]; then
  ctest --preset "$preset" -j "$jobs" -LE '^consumer$'
else
  ctest --preset "$preset" -j "$jobs"
fi
echo "test: the $preset tests took $((SECONDS - start)) s"

# The triangle and slab tests must stay exact when the compiler may contract a*b - c*d into an FMA
# (-march=native on a CPU with FMA; the bench preset): the geometry and accel tests that depend on
# exactness (watertight leaks, t error bound, spawned rays, every accelerator against brute force), built
# apart with -march=native: the libraries they need and two test executables only.
if [ "$preset" = release ]; then
  start=$SECONDS
  if new_build_dir build/native; then export CMAKE_GENERATOR=Ninja; fi
  cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS=-march=native \
    -DRTLAB_BUILD_APPS=OFF -DRTLAB_BUILD_BENCH=OFF -DRTLAB_INSTALL=OFF -DRTLAB_WARNINGS_AS_ERRORS=ON >/dev/null
  unset CMAKE_GENERATOR
  cmake --build build/native -j "$jobs" --target rtlab_geometry_tests rtlab_accel_tests
  (cd build/native/tests/geometry && ../../bin/rtlab_geometry_tests "[triangle],[spawn]")
  (cd build/native/tests/accel && ../../bin/rtlab_accel_tests "[accel],[spawn]")
  echo "test: native-CPU exactness tests took $((SECONDS - start)) s"
fi

# Formatting does not depend on the build: checked once, with the release run.
if [ "$preset" = release ]; then bash scripts/format.sh --check; fi
