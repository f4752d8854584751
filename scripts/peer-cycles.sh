#!/usr/bin/env bash
# The race with Blender's Cycles on the Cornell box (issue 21): rtlab-render against Cycles (Blender 3.4, CPU)
# on scenes/cornell_box*.json, which bench/peer/cycles/cornell_box.py rebuilds in Blender from the same OBJ files
# (settings for a like-for-like race there). Five parts, each renderer's runs alternating with the other's:
#  1. depth: rtlab depth 1 against Cycles at 0 and 1 bounces (a Cycles bounce is one scattering after the first
#     hit, so rtlab depth D is Cycles max_bounces D - 1).
#  2. timing: the box and the bunny at --size, --spp and --depth, 1 and 2 threads, medians of --repeat runs:
#     Cycles' render phase (around bpy.ops.render.render) and whole run, rtlab's render phase and whole run.
#  3. agreement: converged renders (--ref-size, --ref-spp, every core) of the box, the glossy box and the bunny,
#     compared as block means on an 8 x 8 grid: mean and largest relative difference.
#  4. efficiency: the box and the bunny at a ladder of spp (--ladder), RMSE of each render against its own
#     renderer's converged render (another seed; that render's own noise taken out), time to the same RMSE,
#     interpolated in log-log: rtlab's whole run over Cycles' render phase, also over Cycles' whole run and
#     in processor seconds. Target: at most 1 / 1.5 = 0.667.
#  5. docs/data/peer_cycles.csv (the ladder: the chart's points), docs/data/peer_cycles_summary.csv (timing,
#     agreement, efficiency), docs/data/peer_cycles.meta.json, docs/charts/peer_cycles.png (RMSE against time,
#     rtlab path and direct, Cycles).
#
#   scripts/peer-cycles.sh [--quick] [--repeat N] [--threads "1 2"] [--size WxH] [--spp N] [--depth D]
#                          [--ref-size WxH] [--ref-spp N] [--ladder "16 32 ..."] [--out DIR] [--no-build]
#   scripts/peer-cycles.sh --envmap [--quick] [--out DIR] [--no-build]
#
#   --quick      a short check of the whole pipeline (small images, few samples): not the measurement
#   --repeat     timed runs per setting and renderer in part 2, the median is reported (default 3)
#   --size --spp --depth   part 2's renders (default 256x256, 256 spp, depth 8: the scene files' own)
#   --ref-size --ref-spp   the converged renders of parts 3 and 4 (default 128x128, 4096 spp)
#   --ladder     part 4's sample counts (default "8 16 32 64 128 256 512"), rendered at --ref-size
#   --out        images and logs (default out/peer-cycles)
#   --envmap     instead of the box: the environment-map check (issue 22) on bench/peer/cycles/envmap_sphere.json
#                (a clay sphere on a grey disk under envmaps/city.exr), which bench/peer/cycles/envmap.py builds
#                in Cycles. (a) orientation: the background pixels of converged renders (160x120, 4096 spp),
#                rtlab against Cycles, and against Cycles with the map deliberately turned by 90, 180, 270
#                degrees, mirrored left-right, front-back and upside down (those must differ); rtlab's map
#                "rotation" 90 against Cycles' translation of it; (b) the sphere's and the disk's mean colour,
#                rtlab over Cycles; (c) time to equal RMSE, 1 thread, ladder 16-1024 spp. Writes
#                docs/data/peer_cycles_envmap.csv (machine, date, commit and command in every row). 15 minutes
#                on the 2-core machine with other work running.
# The whole run took 2 hours on this project's 2-core machine with other builds running (load 8-10).
# Blender is a peer, not a dependency: scripts/setup.sh does not install it (apt-get install
# --no-install-recommends blender). The bunny needs models/stanford-bunny.obj on the data path
# (RTLAB_SHARED_DIR, default ../shared); without it the bunny parts are left out.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

build=1 repeat=3 threads_list="1 2" size=256x256 spp=256 depth=8 ref_size=128x128 ref_spp=4096
ladder="8 16 32 64 128 256 512" out=out/peer-cycles quick=0 envmap=0
command_line="scripts/peer-cycles.sh $*"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --envmap) envmap=1 ;;
    --no-build) build=0 ;;
    --repeat) repeat=$2; shift ;;
    --threads) threads_list=$2; shift ;;
    --size) size=$2; shift ;;
    --spp) spp=$2; shift ;;
    --depth) depth=$2; shift ;;
    --ref-size) ref_size=$2; shift ;;
    --ref-spp) ref_spp=$2; shift ;;
    --ladder) ladder=$2; shift ;;
    --out) out=$2; shift ;;
    -h|--help) sed -n '2,40p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "peer-cycles: unknown argument '$1' (see --help)" >&2; exit 1 ;;
  esac
  shift
done
if [ "$quick" = 1 ]; then
  repeat=1 size=64x64 spp=16 ref_size=32x32 ref_spp=256 ladder="4 16 64"
  csv=$out/peer_cycles.csv summary=$out/peer_cycles_summary.csv chart=$out/peer_cycles.png meta=$out/peer_cycles.meta.json
else
  csv=docs/data/peer_cycles.csv summary=docs/data/peer_cycles_summary.csv chart=docs/charts/peer_cycles.png
  meta=docs/data/peer_cycles.meta.json
fi
for s in "$size" "$ref_size"; do
  [[ $s =~ ^[0-9]+x[0-9]+$ ]] || { echo "peer-cycles: sizes are WxH, not '$s'" >&2; exit 1; }
done
[[ $repeat =~ ^[1-9][0-9]*$ ]] || { echo "peer-cycles: --repeat must be a positive integer" >&2; exit 1; }

blender=$(command -v blender || true)
if [ -z "$blender" ]; then
  echo "peer-cycles: Blender is not installed. It is a peer for this race, not a dependency of rtlab:" >&2
  echo "  sudo apt-get install --no-install-recommends blender   (Debian 12: Blender 3.4.1, about 90 MB)" >&2
  exit 1
fi
python=/usr/bin/python3
$python -c 'import numpy, matplotlib' 2>/dev/null ||
  { echo "peer-cycles: needs /usr/bin/python3 with numpy and matplotlib (python3-matplotlib)" >&2; exit 1; }
shared=${RTLAB_SHARED_DIR:-$root/../shared}
scenes_timed="box"
if [ -f "$shared/models/stanford-bunny.obj" ]; then
  scenes_timed="box bunny"
else
  echo "peer-cycles: no $shared/models/stanford-bunny.obj (set RTLAB_SHARED_DIR): the bunny is left out" >&2
fi

bin=build/release/bin
if [ "$build" = 1 ]; then
  cmake --preset release >/dev/null
  cmake --build build/release -j2 --target rtlab_app_render >/dev/null
fi
[ -x "$bin/rtlab-render" ] || { echo "peer-cycles: no $bin/rtlab-render; build the release preset" >&2; exit 1; }

mkdir -p "$out" "$(dirname "$csv")" "$(dirname "$chart")"
out=$(cd "$out" && pwd)
images="$python scripts/peer/cycles_images.py"
cycles_script=bench/peer/cycles/cornell_box.py
scene_file() {
  case "$1" in
    box) echo scenes/cornell_box.json ;;
    glossy) echo scenes/cornell_box_glossy.json ;;
    bunny) echo scenes/cornell_box_bunny.json ;;
    envmap) echo bench/peer/cycles/envmap_sphere.json ;;
    envmap_rot90) echo "$out/envmap_sphere_rot90.json" ;;
  esac
}
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.3f", b - a}'; }
median() {
  printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.3f", a / b}'; }
# field NAME "a=1 name=2 ...": the value of NAME= in a line of key=value words.
field() { tr ' ' '\n' <<<"$2" | sed -n "s/^$1=//p"; }

# CPU seconds (user + system) of a whole run, from GNU time's file.
cpu_seconds() { awk '{printf "%.3f", $1 + $2}' "$1"; }

# One Cycles run; prints "wall render cpu render_cpu" (cpu: user + system of the whole run; render_cpu: the
# render phase's processor seconds). Arguments: scene WxH spp depth threads seed image [extra...].
run_cycles() {
  local scene=$1 wh=$2 n=$3 d=$4 t=$5 seed=$6 image=$7
  shift 7
  local log=${image%.*}.log t0 t1
  t0=$(now)
  /usr/bin/time -o "$log.time" -f "%U %S" "$blender" -b --factory-startup -P "$cycles_script" -- "$(scene_file "$scene")" -o "$image" \
    --size "$wh" --spp "$n" --depth "$d" --threads "$t" --seed "$seed" --data-dir "$shared" "$@" >"$log" 2>&1 ||
    { echo "peer-cycles: Cycles failed, see $log" >&2; exit 1; }
  t1=$(now)
  local render render_cpu
  render=$(sed -n 's/^cycles: render phase \([0-9.]*\) s (\([0-9.]*\) CPU s)$/\1/p' "$log")
  render_cpu=$(sed -n 's/^cycles: render phase \([0-9.]*\) s (\([0-9.]*\) CPU s)$/\2/p' "$log")
  [ -n "$render" ] || { echo "peer-cycles: no render phase in $log" >&2; exit 1; }
  echo "$(elapsed "$t0" "$t1") $render $(cpu_seconds "$log.time") $render_cpu"
}

# One rtlab run; prints "wall render cpu" (render: the summary's "total in S s", the render without loading,
# building the kd-trees or writing; cpu: user + system of the whole run). Arguments: scene WxH spp depth
# threads seed image integrator.
run_rtlab() {
  local scene=$1 wh=$2 n=$3 d=$4 t=$5 seed=$6 image=$7 integrator=$8
  local log=${image%.*}.log t0 t1
  t0=$(now)
  /usr/bin/time -o "$log.time" -f "%U %S" "$bin/rtlab-render" "$(scene_file "$scene")" -o "$image" --width "${wh%x*}" --height "${wh#*x}" --spp "$n" \
    --depth "$d" --threads "$t" --seed "$seed" --integrator "$integrator" --data-dir "$shared" >"$log" 2>&1 ||
    { echo "peer-cycles: rtlab-render failed, see $log" >&2; exit 1; }
  t1=$(now)
  local render
  render=$(sed -n 's/.* total in \([0-9.]*\) s, .*/\1/p' "$log" | tail -1)
  [ -n "$render" ] || { echo "peer-cycles: no render time in $log" >&2; exit 1; }
  echo "$(elapsed "$t0" "$t1") $render $(cpu_seconds "$log.time")"
}

machine="$(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1), $(nproc) cores, $(uname -sr)"
date_now=$(date -u '+%Y-%m-%d %H:%M UTC')
load=$(cut -d' ' -f1 /proc/loadavg)
max_threads=$(nproc)
cycles_version=$("$blender" --version 2>/dev/null | head -1)
echo "peer-cycles: $cycles_version against rtlab-render on $machine (load $load at start)"
# One point of an efficiency ladder (part 4, --envmap), appended to $csv at $ref_size, $depth, against $ref_spp.
ladder_row() {  # scene renderer integrator threads spp "wall render cpu [render_cpu]" image reference
  local e w r c rc
  read -r w r c rc <<<"$6"
  e=$($images rmse "$7" "$8" "$5" "$ref_spp")
  echo "$1,$2,$3,$4,${ref_size%x*},${ref_size#*x},$5,$depth,$r,$w,${rc:-},$c,$(sed -n 's/rmse=\([^ ]*\) rel_rmse=\([^ ]*\) rmse_raw=\([^ ]*\)/\1,\2,\3/p' <<<"$e")" >>"$csv"
}

# --- the environment-map check (--envmap, issue 22) ---------------------------------------------------------
if [ "$envmap" = 1 ]; then
  cycles_script=bench/peer/cycles/envmap.py
  env_scene=$(scene_file envmap)
  env=$python' scripts/peer/cycles_envmap.py'
  ref_size=160x120 ref_spp=4096 depth=8 variant_spp=64 ladder="16 64 256 1024"
  env_csv=docs/data/peer_cycles_envmap.csv
  if [ "$quick" = 1 ]; then
    ref_spp=256 variant_spp=8 ladder="4 16 64" env_csv=$out/peer_cycles_envmap.csv
  fi
  commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
  git diff --quiet HEAD 2>/dev/null || commit="$commit+changes"
  echo "machine,date,commit,command,section,renderer,variant,threads,width,height,spp,quantity,value" >"$env_csv"
  env_row() {  # section renderer variant threads spp quantity value
    echo "\"$machine\",$date_now,$commit,\"$command_line\",$1,$2,$3,$4,${ref_size%x*},${ref_size#*x},$5,$6,$7" >>"$env_csv"
  }
  echo "envmap: $env_scene at $ref_size, depth $depth; converged renders at $ref_spp spp, $max_threads threads"
  env_row run "$cycles_version" none "$max_threads" "$ref_spp" load_at_start "$load"
  run_rtlab envmap "$ref_size" "$ref_spp" "$depth" "$max_threads" 1 "$out/env_ref_rtlab.pfm" path >/dev/null
  run_cycles envmap "$ref_size" "$ref_spp" "$depth" "$max_threads" 1 "$out/env_ref_cycles.exr" \
    --pfm "$out/env_ref_cycles.pfm" >/dev/null
  # (a) and (b): the converged renders against each other.
  a=$($env compare "$env_scene" "$out/env_ref_rtlab.pfm" "$out/env_ref_cycles.pfm")
  echo "  (a, b) rtlab against Cycles: $a"
  for q in bg_pixels bg_rel bg_ratio ball_pixels floor_pixels; do
    env_row agreement rtlab_over_cycles none "$max_threads" "$ref_spp" "$q" "$(field "$q" "$a")"
  done
  for shape in ball floor; do
    IFS=: read -r cr cg cb <<<"$(field "${shape}_ratio" "$a")"
    env_row agreement rtlab_over_cycles none "$max_threads" "$ref_spp" "${shape}_ratio_r" "$cr"
    env_row agreement rtlab_over_cycles none "$max_threads" "$ref_spp" "${shape}_ratio_g" "$cg"
    env_row agreement rtlab_over_cycles none "$max_threads" "$ref_spp" "${shape}_ratio_b" "$cb"
  done
  # (a) the wrong maps: Cycles with the map turned or mirrored, against the same rtlab render.
  echo "  (a) background of rtlab's render against Cycles' with the map (bg_rel: sum |dY| / sum Y):"
  for v in none rot90 rot180 rot270 mirror-lr mirror-fb upside-down; do
    run_cycles envmap "$ref_size" "$variant_spp" "$depth" "$max_threads" 2 "$out/env_variant_${v}_cycles.exr" \
      --pfm "$out/env_variant_${v}_cycles.pfm" --variant "$v" >/dev/null
    a=$($env compare "$env_scene" "$out/env_ref_rtlab.pfm" "$out/env_variant_${v}_cycles.pfm")
    printf '      %-12s bg_rel %s\n' "$v" "$(field bg_rel "$a")"
    env_row orientation rtlab_against_cycles_variant "$v" "$max_threads" "$variant_spp" bg_rel "$(field bg_rel "$a")"
  done
  # rtlab's rotation against Cycles' translation of it (the Mapping node's -R).
  sed 's/"rotation": 0}/"rotation": 90}/' "$env_scene" >"$(scene_file envmap_rot90)"
  grep -q '"rotation": 90}' "$(scene_file envmap_rot90)" || { echo "peer-cycles: no rotation 0 in $env_scene" >&2; exit 1; }
  run_rtlab envmap_rot90 "$ref_size" "$variant_spp" "$depth" "$max_threads" 2 "$out/env_rotation90_rtlab.pfm" path >/dev/null
  run_cycles envmap_rot90 "$ref_size" "$variant_spp" "$depth" "$max_threads" 2 "$out/env_rotation90_cycles.exr" \
    --pfm "$out/env_rotation90_cycles.pfm" >/dev/null
  a=$($env compare "$env_scene" "$out/env_rotation90_rtlab.pfm" "$out/env_rotation90_cycles.pfm")
  printf '      %-12s bg_rel %s (both renderers given "rotation": 90)\n' rotation90 "$(field bg_rel "$a")"
  env_row orientation rtlab_against_cycles rotation90 "$max_threads" "$variant_spp" bg_rel "$(field bg_rel "$a")"
  for f in env_ref_rtlab env_ref_cycles env_variant_mirror-lr_cycles env_variant_rot90_cycles; do
    $env png "$out/$f.pfm" "$out/$f.png" --exposure -1
  done
  # (c) time to equal RMSE, 1 thread, against each renderer's own converged render.
  csv=$out/envmap_ladder.csv
  echo "scene,renderer,integrator,threads,width,height,spp,depth,render_s,wall_s,render_cpu_s,cpu_s,rmse,rel_rmse,rmse_raw" >"$csv"
  echo "  (c) ladder at 1 thread, spp $ladder:"
  for n in $ladder; do
    img=$out/env_ladder_s${n}
    res=$(run_cycles envmap "$ref_size" "$n" "$depth" 1 0 "${img}_cycles.exr" --pfm "${img}_cycles.pfm")
    ladder_row envmap cycles path 1 "$n" "$res" "${img}_cycles.pfm" "$out/env_ref_cycles.pfm"
    res=$(run_rtlab envmap "$ref_size" "$n" "$depth" 1 0 "${img}_rtlab.pfm" path)
    ladder_row envmap rtlab path 1 "$n" "$res" "${img}_rtlab.pfm" "$out/env_ref_rtlab.pfm"
  done
  tail -n +2 "$csv" | while IFS=, read -r _ r _ t _ _ n _ rs ws rcs cs e re _; do
    for kv in render_s=$rs wall_s=$ws render_cpu_s=$rcs cpu_s=$cs rmse=$e rel_rmse=$re; do
      if [ -n "${kv#*=}" ]; then env_row ladder "$r" none "$t" "$n" "${kv%%=*}" "${kv#*=}"; fi
    done
  done
  sed 's/^/      /' "$csv"
  $images efficiency "$csv" | tee "$out/envmap_efficiency.txt" | sed 's/^/      /'
  while read -r _ thr basis geo last _; do
    env_row efficiency "$basis" none "${thr#threads=}" "${ladder// /:}" geomean "${geo#geomean=}"
    env_row efficiency "$basis" none "${thr#threads=}" "${ladder// /:}" lowest_rmse "${last#last=}"
  done < <(grep geomean= "$out/envmap_efficiency.txt")
  echo "peer-cycles: $env_csv; images and logs in $out (env_*.png)"
  exit 0
fi

echo "section,scene,threads,width,height,spp,depth,quantity,value" >"$summary"
row() { echo "$1,$2,$3,${4%x*},${4#*x},$5,$6,$7,$8" >>"$summary"; }

# --- 1. depth conventions ---------------------------------------------------------------------------------
d_size=64x64 d_spp=1024
[ "$quick" = 1 ] && d_size=32x32 d_spp=256
run_rtlab box "$d_size" "$d_spp" 1 "$max_threads" 1 "$out/depth1_rtlab.pfm" path >/dev/null
for b in 0 1; do
  run_cycles box "$d_size" "$d_spp" 1 "$max_threads" 1 "$out/depth1_cycles_b$b.exr" --cycles-bounces "$b" \
    --pfm "$out/depth1_cycles_b$b.pfm" >/dev/null
  a=$($images agree "$out/depth1_rtlab.pfm" "$out/depth1_cycles_b$b.pfm")
  echo "1. depth: rtlab depth 1 against Cycles max_bounces $b: $a"
  for q in mean_rel max_rel image_ratio; do
    row depth box "$max_threads" "$d_size" "$d_spp" 1 "cycles_bounces_${b}_$q" "$(field "$q" "$a")"
  done
done

# --- 2. timing ----------------------------------------------------------------------------------------------
printf '2. timing, %s, %s spp, depth %s, medians of %s:\n' "$size" "$spp" "$depth" "$repeat"
printf '   %-6s %3s  %9s %9s  %9s %9s  %9s %9s  %9s %9s\n' scene thr cy_render cy_wall rt_render rt_wall \
  cy_rend/rt cy_wall/rt cy_cpu rt_cpu
for scene in $scenes_timed; do
  for threads in $threads_list; do
    cr=() cw=() cc=() crc=() rr=() rw=() rc=()
    for ((i = 0; i < repeat; ++i)); do
      res=$(run_cycles "$scene" "$size" "$spp" "$depth" "$threads" 0 "$out/time_${scene}_t${threads}_cycles.exr")
      read -r w r c rcpu <<<"$res"
      cw+=("$w") cr+=("$r") cc+=("$c") crc+=("$rcpu")
      res=$(run_rtlab "$scene" "$size" "$spp" "$depth" "$threads" 0 "$out/time_${scene}_t${threads}_rtlab.pfm" path)
      read -r w r c <<<"$res"
      rw+=("$w") rr+=("$r") rc+=("$c")
    done
    c_r=$(median "${cr[@]}") c_w=$(median "${cw[@]}") r_r=$(median "${rr[@]}") r_w=$(median "${rw[@]}")
    c_c=$(median "${cc[@]}") c_rc=$(median "${crc[@]}") r_c=$(median "${rc[@]}")
    printf '   %-6s %3s  %9s %9s  %9s %9s  %9s %9s  %9s %9s\n' "$scene" "$threads" "$c_r" "$c_w" "$r_r" "$r_w" \
      "$(ratio "$c_r" "$r_w")" "$(ratio "$c_w" "$r_w")" "$c_rc" "$r_c"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" cycles_render_s "$c_r"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" cycles_wall_s "$c_w"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" rtlab_render_s "$r_r"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" rtlab_wall_s "$r_w"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" cycles_render_cpu_s "$c_rc"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" cycles_cpu_s "$c_c"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" rtlab_cpu_s "$r_c"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" samples_per_s_cycles_render \
      "$(awk -v w="${size%x*}" -v h="${size#*x}" -v n="$spp" -v t="$c_r" 'BEGIN {printf "%.0f", w * h * n / t}')"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" samples_per_s_rtlab_render \
      "$(awk -v w="${size%x*}" -v h="${size#*x}" -v n="$spp" -v t="$r_r" 'BEGIN {printf "%.0f", w * h * n / t}')"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" cycles_render_over_rtlab_wall "$(ratio "$c_r" "$r_w")"
    row timing "$scene" "$threads" "$size" "$spp" "$depth" cycles_wall_over_rtlab_wall "$(ratio "$c_w" "$r_w")"
  done
done

# --- 3. converged renders and their agreement ---------------------------------------------------------------
echo "3. agreement of converged renders ($ref_size, $ref_spp spp, depth $depth, $max_threads threads, block means on an 8 x 8 grid):"
for scene in box glossy ${scenes_timed#box}; do
  res=$(run_cycles "$scene" "$ref_size" "$ref_spp" "$depth" "$max_threads" 1 "$out/ref_${scene}_cycles.exr" \
    --pfm "$out/ref_${scene}_cycles.pfm")
  read -r cw cr _ <<<"$res"
  res=$(run_rtlab "$scene" "$ref_size" "$ref_spp" "$depth" "$max_threads" 1 "$out/ref_${scene}_rtlab.pfm" path)
  read -r rw rr _ <<<"$res"
  a=$($images agree "$out/ref_${scene}_rtlab.pfm" "$out/ref_${scene}_cycles.pfm" --blocks 8)
  echo "   $scene: $a (Cycles ${cr} s render, rtlab ${rr} s)"
  for q in mean_rel max_rel worst_block channel_max_rel channel_mean_rel dark_blocks dark_max_rel image_ratio; do
    row agreement "$scene" "$max_threads" "$ref_size" "$ref_spp" "$depth" "$q" "$(field "$q" "$a")"
  done
  for r in rtlab cycles; do $images png "$out/ref_${scene}_$r.pfm" "$out/ref_${scene}_$r.png"; done
done
run_rtlab box "$ref_size" "$ref_spp" "$depth" "$max_threads" 1 "$out/ref_box_rtlab_direct.pfm" direct >/dev/null

# --- 4. efficiency: RMSE against time -----------------------------------------------------------------------
# rmse: the reference's own noise taken out (MSE times ref_spp / (ref_spp + spp), scripts/peer/cycles_images.py);
# rmse_raw: as measured.
echo "scene,renderer,integrator,threads,width,height,spp,depth,render_s,wall_s,render_cpu_s,cpu_s,rmse,rel_rmse,rmse_raw" >"$csv"
echo "4. efficiency ladder at $ref_size, spp $ladder:"
for scene in $scenes_timed; do
  for threads in $threads_list; do
    for n in $ladder; do
      img=$out/ladder_${scene}_t${threads}_s${n}
      res=$(run_cycles "$scene" "$ref_size" "$n" "$depth" "$threads" 0 "${img}_cycles.exr" --pfm "${img}_cycles.pfm")
      ladder_row "$scene" cycles path "$threads" "$n" "$res" "${img}_cycles.pfm" "$out/ref_${scene}_cycles.pfm"
      res=$(run_rtlab "$scene" "$ref_size" "$n" "$depth" "$threads" 0 "${img}_rtlab.pfm" path)
      ladder_row "$scene" rtlab path "$threads" "$n" "$res" "${img}_rtlab.pfm" "$out/ref_${scene}_rtlab.pfm"
      if [ "$scene" = box ]; then
        res=$(run_rtlab "$scene" "$ref_size" "$n" "$depth" "$threads" 0 "${img}_rtlab_direct.pfm" direct)
        ladder_row "$scene" rtlab direct "$threads" "$n" "$res" "${img}_rtlab_direct.pfm" "$out/ref_box_rtlab_direct.pfm"
      fi
    done
  done
done
$images efficiency "$csv" | tee "$out/efficiency.txt" | sed 's/^/   /'
# "box threads=1 cycles_render geomean=0.5 last=0.4 levels=...": the summary keeps the geometric mean over the
# RMSE levels both reached and the ratio at the lowest RMSE (least start-up in it).
while read -r scene thr basis geo last _; do
  row efficiency "$scene" "${thr#threads=}" "$ref_size" "${ladder// /:}" "$depth" "${basis}_geomean" "${geo#geomean=}"
  row efficiency "$scene" "${thr#threads=}" "$ref_size" "${ladder// /:}" "$depth" "${basis}_lowest_rmse" "${last#last=}"
done < <(grep geomean= "$out/efficiency.txt")

$python -c 'import json, sys; json.dump(dict(machine=sys.argv[2], date=sys.argv[3], command=sys.argv[4],
  medians=sys.argv[5], peer=sys.argv[6], load_start=sys.argv[7]), open(sys.argv[1], "w"), indent=1)' "$meta" \
  "$machine" "$date_now" "$command_line" \
  "timing: medians of $repeat runs, Cycles and rtlab alternating; ladder: one run per point; times are rtlab's whole run and Cycles' render phase (bpy.ops.render.render) and whole run" \
  "$cycles_version" "$load"
$python scripts/charts/peer_cycles.py "$csv" "$summary" "$meta" "$chart"
echo "peer-cycles: $csv, $summary, $chart; images and logs in $out (ref_*.png: the converged renders)"
