#!/usr/bin/env bash
# Builds the release preset and renders the course scenes into out/.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
mkdir -p out
bin=build/release/bin
shared=${RTLAB_SHARED_DIR:-../shared}

ran=0
run() {  # run <description> <command...>
  echo "demo: $1"
  shift
  "$@"
  ran=$((ran + 1))
}

# The course scenes, once their apps exist.
for scene in whitted solar-system bunny; do
  if [ -x "$bin/rtlab-$scene" ]; then
    run "rendering $scene -> out/$scene.png" "$bin/rtlab-$scene" -o "out/$scene.png"
  fi
done

# Until then: the tools that exist, on the data that exists.
if [ -x "$bin/rtlab-mesh-info" ] && [ -d "$shared/models" ]; then
  run "mesh statistics -> out/mesh-info.txt" sh -c "'$bin/rtlab-mesh-info' '$shared'/models/*.obj '$shared'/models/*.ply > out/mesh-info.txt"
fi
if [ -x "$bin/rtlab-accel" ] && [ -f "$shared/models/stanford-bunny.obj" ]; then
  run "kd-tree on the bunny -> out/accel-bunny.csv" "$bin/rtlab-accel" --mesh "$shared/models/stanford-bunny.obj" \
    --method kd-sah --method bvh --csv out/accel-bunny.csv
fi
echo "demo: $ran step(s) run; results in out/"
ls -l out
