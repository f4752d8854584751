#!/usr/bin/env bash
# Measures speed against accuracy (CSV and JSON lines in docs/data/) and draws the PNG charts in docs/charts/.
# Each measurement writes docs/data/<name>.meta.json (machine, date, command, what the points are medians
# of), which the charts print in their footers.
#   scripts/charts.sh              the short benchmarks (about 4 minutes on 2 cores), then every chart
#   scripts/charts.sh --accel      also re-measure the acceleration structures on the shared models (long)
#   scripts/charts.sh --photon     also measure photon mapping: sppm against the path tracer on the Cornell box and
#                                  RMSE against time on the caustics scene (long: each renders a path-traced
#                                  reference first, about 40 min of CPU together on 2 cores)
#   scripts/charts.sh --no-run     chart the data already in docs/data/
# Needs the release build's benchmark programs (built here) and, for --accel, ../shared/models.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/release/bin
data=docs/data
run=1 accel=0 photon=0
for arg in "$@"; do
  case "$arg" in
    --no-run) run=0 ;;
    --accel) accel=1 ;;
    --photon) photon=1 ;;
    *) echo "charts: unknown option $arg"; exit 2 ;;
  esac
done
machine="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores, $(uname -sr)"
# meta NAME COMMAND MEDIANS: the footer of the charts drawn from docs/data/NAME*
meta() {
  /usr/bin/python3 -c 'import json, sys; json.dump(dict(machine=sys.argv[2], date=sys.argv[3], command=sys.argv[4],
    medians=sys.argv[5]), open(sys.argv[1], "w"), indent=1)' "$data/$1.meta.json" "$machine" "$(date -u '+%Y-%m-%d %H:%M UTC')" "$2" "$3"
}
if [ "$run" = 1 ]; then
  cmake --preset release >/dev/null
  cmake --build build/release -j"${JOBS:-2}" --target rtlab_geometry_bench rtlab_shading_optics_tradeoff \
    rtlab_shading_microfacet_energy rtlab_render_aa_tradeoff rtlab_stability_tests \
    $([ "$accel" = 1 ] && echo rtlab_app_accel) \
    $([ "$photon" = 1 ] && echo rtlab_render_sppm_convergence rtlab_render_caustics_rmse)
  mkdir -p "$data"
  scripts/stability.sh >/dev/null  # docs/data/stability.jsonl: leak rates, fallbacks, offsets against scale
  meta stability "scripts/stability.sh (rtlab_stability_tests)" "counts, not timings: no medians"

  cmd="rtlab_geometry_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true --benchmark_min_time=0.2"
  $bin/$cmd --benchmark_out_format=csv --benchmark_out=$data/triangle_tests_bench.csv >/dev/null
  meta triangle_tests_bench "$cmd" "ns: median CPU time of 5 repetitions (4096 ray-triangle pairs, one test per iteration)"

  $bin/rtlab_shading_optics_tradeoff $data/optics_tradeoff.csv --runs 9
  meta optics_tradeoff "rtlab_shading_optics_tradeoff docs/data/optics_tradeoff.csv --runs 9" \
    "ns: median of 9 runs of 200 passes over 4096 inputs; errors by quadrature (200000 steps, double)"

  $bin/rtlab_shading_microfacet_energy $data/microfacet_energy.csv 2>/dev/null
  meta microfacet_energy "rtlab_shading_microfacet_energy docs/data/microfacet_energy.csv" \
    "albedos by deterministic quadrature (adaptive, 1e-7 per starting cell): no timing, no medians"

  $bin/rtlab_render_aa_tradeoff $data/antialiasing.csv --runs 3 --width 160
  meta antialiasing "rtlab_render_aa_tradeoff docs/data/antialiasing.csv --runs 3 --width 160" \
    "time: median wall time of 3 renders (160 x 120, 1 thread); RMSE of the last render"
  if command -v povray >/dev/null; then
    /usr/bin/python3 scripts/charts/povray_aa.py $data/antialiasing_povray.csv --runs 3 --width 160
    meta antialiasing_povray "scripts/charts/povray_aa.py --runs 3 --width 160 ($(povray --version 2>&1 | grep -m1 POV-Ray))" \
      "time: median of 3 renders of POV-Ray's own Trace Time (1 thread, start-up and parsing excluded)"
  else
    rm -f $data/antialiasing_povray.csv $data/antialiasing_povray.meta.json
    echo "charts: povray is not installed: the anti-aliasing charts have no POV-Ray series"
  fi
  if [ "$photon" = 1 ]; then
    cmd="rtlab_render_sppm_convergence --ref-spp 16384 --iterations 1024 --photons 20000 --threads 2"
    $bin/$cmd --csv $data/sppm_convergence.csv
    meta sppm_convergence "$cmd" "one run: wall seconds of the sppm iterations on 2 threads; the reference is path at 16384 spp, seed 1000"
    cmd="rtlab_render_caustics_rmse --width 96 --height 72 --ref-spp 16384 --max-spp 1024 --iterations 512 --photons 50000 --threads 2"
    $bin/$cmd --csv $data/caustics_rmse.csv
    meta caustics_rmse "$cmd" "one run per point: CPU seconds (user + system, 2 threads); one reference, path at 16384 spp (its own RMSE in the chart)"
  fi
  if [ "$accel" = 1 ]; then
    models=${RTLAB_SHARED_DIR:-../shared}/models
    [ -d "$models" ] || { echo "charts: no models folder at $models (set RTLAB_SHARED_DIR)"; exit 1; }
    for mesh in teapot.obj stanford-bunny.obj armadillo.obj buddha.obj dragon_vrip_res2.ply; do
      [ -f "$models/$mesh" ] || continue
      $bin/rtlab-accel --mesh "$models/$mesh" --threads "${THREADS:-1}" --runs 5 \
        --method kd-sah --method kd-sah-binned --method kd-median --method kd-midpoint --method bvh --method octree \
        --method embree --rays random --random-count "${RANDOM_RAYS:-200000}" --csv "$data/accel_${mesh%.*}.csv"
    done
    meta accel "rtlab-accel --threads 1 --runs 5 --rays random --random-count 200000 --csv (scripts/charts.sh --accel)" \
      "build and trace times: medians of 5 runs"
  fi
fi
/usr/bin/python3 scripts/charts/accel_charts.py docs/charts $data/accel_*.csv
/usr/bin/python3 scripts/charts/tradeoff_charts.py $data docs/charts
/usr/bin/python3 scripts/charts/photon_charts.py $data docs/charts
/usr/bin/python3 scripts/charts/shading_charts.py $data docs/charts
# The Cycles race measures with scripts/peer-cycles.sh (Blender needed); its chart is redrawn from its data here.
if [ -f $data/peer_cycles.csv ]; then
  /usr/bin/python3 scripts/charts/peer_cycles.py $data/peer_cycles.csv $data/peer_cycles_summary.csv \
    $data/peer_cycles.meta.json docs/charts/peer_cycles.png
fi
