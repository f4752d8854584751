#!/usr/bin/env bash
# Measures the acceleration structures on the shared models with rtlab-accel (CSV in docs/data/) and
# turns the CSV into PNG charts under docs/charts/. Needs the release build and ../shared/models.
#   scripts/charts.sh            measure, then chart
#   scripts/charts.sh --no-run   chart the CSV already in docs/data/
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/release/bin
models=${RTLAB_SHARED_DIR:-../shared}/models
if [ "${1:-}" != "--no-run" ]; then
  [ -x "$bin/rtlab-accel" ] || { echo "charts: build the release preset first"; exit 1; }
  [ -d "$models" ] || { echo "charts: no models folder at $models (set RTLAB_SHARED_DIR)"; exit 1; }
  mkdir -p docs/data
  for mesh in teapot.obj stanford-bunny.obj armadillo.obj buddha.obj dragon_vrip_res2.ply; do
    [ -f "$models/$mesh" ] || continue
    "$bin/rtlab-accel" --mesh "$models/$mesh" --threads "${THREADS:-1}" --runs 5 \
      --method kd-sah --method kd-sah-binned --method kd-median --method kd-midpoint --method bvh --method octree \
      --method embree --rays random --random-count "${RANDOM_RAYS:-200000}" --csv "docs/data/accel_${mesh%.*}.csv"
  done
fi
/usr/bin/python3 scripts/charts/accel_charts.py docs/charts docs/data/accel_*.csv
