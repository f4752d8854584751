#!/usr/bin/env bash
# The rays a path tracer really traces against one mesh (issue 24): rtlab-render records the closest-hit and the
# shadow (any-hit) queries that the Stanford bunny answers in the path-traced Cornell box (scenes/cornell_box_bunny.json)
# and under the environment map (scenes/bunny_envmap.json), each ray as the bunny's kd-tree receives it (in the OBJ
# file's own coordinates: the scenes' "fit" and "transform" are Instances, undone), kept when its segment overlaps
# the bunny's box; then rtlab-accel replays the four ray files against kd-sah and Embree (rtcIntersect1 and
# rtcOccluded1) on the same file, on 1 and 2 threads. rtlab-accel times closest hits and any hits on every file:
# for a .closest.rays file the closest column is the one the render asked, for a .shadow.rays file the any-hit one.
# Each file is also split by where its rays start (inside the bunny's box or outside; up to 400,000 of each) and the
# parts replayed on 1 thread. Writes docs/data/path_rays_bunny.csv (rtlab-accel's rows, ray_set = the file's name),
# path_rays_bunny_summary.csv (kd-sah/Embree on the column that matters) and path_rays_bunny.meta.json; the ray
# files (about 300 MB) stay in --out.
#
#   scripts/record-path-rays.sh [--out DIR] [--threads "1 2"] [--runs N] [--replay-only] [--no-build]
#
#   --out          the ray files, renders and logs (default out/path-rays)
#   --replay-only  replay the ray files (and logs) an earlier run left in --out, without recording again
#   --threads      thread counts of the replay (default "1 2"); the recording renders on one thread
#   --runs         rtlab-accel's timed rounds, medians reported (default 5)
# Needs ../shared (or RTLAB_SHARED_DIR) for models/stanford-bunny.obj and envmaps/city.exr on the data path
# (../shared or the blender-data package); the release build with Embree.
set -euo pipefail
cd "$(dirname "$0")/.."

out=out/path-rays threads_list="1 2" runs=5 build=1 replay_only=0
data=docs/data name=path_rays_bunny
command_line="scripts/record-path-rays.sh $*"
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out=$2; shift ;;
    --threads) threads_list=$2; shift ;;
    --runs) runs=$2; shift ;;
    --no-build) build=0 ;;
    --replay-only) replay_only=1 ;;
    -h|--help) sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "record-path-rays: unknown argument '$1' (see --help)" >&2; exit 1 ;;
  esac
  shift
done
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "record-path-rays: --runs must be a positive integer" >&2; exit 1; }
shared=${RTLAB_SHARED_DIR:-../shared}
mesh=$shared/models/stanford-bunny.obj
[ -f "$mesh" ] || { echo "record-path-rays: no $mesh (set RTLAB_SHARED_DIR)" >&2; exit 1; }
bin=build/release/bin
if [ "$build" = 1 ]; then
  cmake --preset release >/dev/null
  cmake --build build/release -j"${JOBS:-2}" --target rtlab_app_render rtlab_app_accel
fi
mkdir -p "$out" "$data"

# scene, the bunny's object name, size and samples: about 1.7 M closest-hit and 1.1 M shadow rays from the box,
# 2.6 M and 1.0 M from the environment map (under rtlab-render's --record-max of 4 M each).
record() {
  local scene=$1 object=$2 size=$3 spp=$4 stem
  stem=$(basename "$scene" .json)
  rays+=(--rays "$out/$stem.closest.rays" --rays "$out/$stem.shadow.rays")
  if [ "$replay_only" = 1 ]; then
    [ -f "$out/$stem.shadow.rays" ] && [ -f "$out/$stem.log" ] ||
      { echo "record-path-rays: --replay-only: no $out/$stem.shadow.rays or $out/$stem.log; record first" >&2; exit 1; }
    return
  fi
  echo "record-path-rays: rendering $scene (${size}, $spp spp, path, 1 thread) and recording '$object'"
  "$bin/rtlab-render" "$scene" --data-dir "$shared" --width "${size%x*}" --height "${size#*x}" --spp "$spp" \
    -o "$out/$stem.png" --record-rays "$object" --record-out "$out/$stem" | tee "$out/$stem.log"
}
rays=()
record scenes/cornell_box_bunny.json bunny 256x256 32
record scenes/bunny_envmap.json mesh 320x240 40

# Where kd-sah loses most: each file split by where its rays start, inside the bunny's box (most of them leave its
# surface) or outside, up to 400,000 rays of each (the first, in the render's order), replayed on 1 thread.
split=()
for stem in cornell_box_bunny bunny_envmap; do
  for kind in closest shadow; do
    split+=(--rays "$out/$stem.$kind.inside.rays" --rays "$out/$stem.$kind.outside.rays")
  done
done
/usr/bin/python3 - "$mesh" "$out" <<'EOF'
import numpy as np, sys
mesh, out = sys.argv[1:3]
v = np.array([l.split()[1:4] for l in open(mesh) if l.startswith("v ")], dtype=np.float32)
lo, hi = v.min(0), v.max(0)
margin = 1e-3 * np.linalg.norm(hi - lo)
for stem in ("cornell_box_bunny", "bunny_envmap"):
    for kind in ("closest", "shadow"):
        data = np.fromfile(f"{out}/{stem}.{kind}.rays", dtype=np.uint8)
        rays = np.frombuffer(data[16:], dtype="<f4").reshape(-1, 8)
        inside = np.all((rays[:, :3] >= lo - margin) & (rays[:, :3] <= hi + margin), axis=1)
        for where, mask in (("inside", inside), ("outside", ~inside)):
            part = rays[mask][:400000]
            with open(f"{out}/{stem}.{kind}.{where}.rays", "wb") as f:
                f.write(b"RTRAYS01" + np.uint64(len(part)).tobytes() + part.tobytes())
EOF

csv=$data/$name.csv
rm -f "$csv"
for threads in $threads_list; do
  "$bin/rtlab-accel" --mesh "$mesh" --method kd-sah --method embree --threads "$threads" --runs "$runs" "${rays[@]}" \
    --csv "$out/accel_threads$threads.csv" | tee "$out/accel_threads$threads.log"
  if [ -f "$csv" ]; then tail -n +2 "$out/accel_threads$threads.csv" >>"$csv"; else cp "$out/accel_threads$threads.csv" "$csv"; fi
done
"$bin/rtlab-accel" --mesh "$mesh" --method kd-sah --method embree --threads 1 --runs "$runs" "${split[@]}" \
  --csv "$out/accel_split.csv" | tee "$out/accel_split.log"
tail -n +2 "$out/accel_split.csv" >>"$csv"

machine="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores, $(uname -sr)"
recorded=$(grep -h '^recorded ' "$out"/cornell_box_bunny.log "$out"/bunny_envmap.log | tr '\n' ';')
/usr/bin/python3 - "$csv" "$data/${name}_summary.csv" "$data/$name.meta.json" "$machine" \
  "$(date -u '+%Y-%m-%d %H:%M UTC')" "$command_line (rtlab-accel --method kd-sah --method embree --runs $runs)" \
  "$recorded" <<'EOF'
import csv, json, sys
rows_path, summary_path, meta_path, machine, date, command, recorded = sys.argv[1:8]
rows = list(csv.DictReader(open(rows_path)))
by = {(r["method"], r["threads"], r["ray_set"]): r for r in rows}
with open(summary_path, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["scene", "query", "start", "threads", "rays", "kd_sah_mrays_s", "embree_mrays_s", "ratio",
                "mismatches"])
    for (method, threads, ray_set), r in by.items():
        if method != "kd-sah":
            continue
        e = by[("embree", threads, ray_set)]
        parts = ray_set.split(".")
        scene, kind, start = parts[0], parts[1], parts[2] if len(parts) == 4 else "anywhere"
        column = "closest_mrays_s" if kind == "closest" else "anyhit_mrays_s"
        k, m = float(r[column]), float(e[column])
        w.writerow([scene, "closest-hit" if kind == "closest" else "any-hit", start, threads, r["rays"], f"{k:.3f}",
                    f"{m:.3f}", f"{k / m:.3f}", r["mismatches"]])
        print(f"{scene:18} {kind:8} {start:9} threads {threads}: kd-sah {k:6.2f} Mrays/s, embree {m:6.2f}, "
              f"ratio {k / m:.3f}")
json.dump(dict(machine=machine, date=date, command=command, recorded=recorded,
               medians="throughput: medians of the timed rounds (methods take turns in each round); the ray "
                       "files are recorded on one thread by rtlab-render --record-rays"),
          open(meta_path, "w"), indent=1)
EOF
echo "record-path-rays: wrote $csv, $data/${name}_summary.csv and $data/$name.meta.json"
