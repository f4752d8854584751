#!/usr/bin/env bash
# A race with POV-Ray 3.7 (issue 15): the Whitted and bunny scenes in both renderers (bench/peer/povray/*.pov
# against rtlab-whitted and rtlab-bunny), without anti-aliasing and with adaptive anti-aliasing at the same
# threshold and depth, on 1 and 2 threads. Per run: wall time (start to image on disk), render-phase time
# (POV-Ray's "Trace Time", rtlab's render seconds), their ratios, and PSNR between the two 8-bit images with
# a difference image. Also the processor seconds of the render phase (POV-Ray's "CPU-seconds total" of the
# trace, rtlab's "CPU s") and of each whole run (user + system), which other work on a shared machine
# disturbs less than wall time. Each time is the median of --repeat runs, POV-Ray and rtlab
# alternating so that both see the same load. Writes docs/data/peer_povray.csv and docs/charts/peer_povray.png.
#
#   scripts/peer-povray.sh [--install] [--size WxH] [--repeat N] [--threshold T] [--aa-depth D]
#                          [--threads "1 2"] [--out DIR] [--no-build] [--csv FILE] [--chart FILE]
#
#   --install     apt-get install povray when /usr/bin/povray is missing (needs root)
#   --size        image size (default 1280x960); a small size gives a quick run
#   --repeat      timed runs per setting and renderer, the median is reported (default 3)
#   --threshold   adaptive threshold for both, POV-Ray's +AM2 colour distance (default 0.3)
#   --aa-depth    adaptive subdivision depth, rtlab's --aa-depth (default 3, the scenes' own): up to 2^D x 2^D
#                 sub-squares a pixel. POV-Ray's +R counts the pixel itself as level 1, so it gets +R(D+1)
#                 (measured: rtlab depth D and POV-Ray +R(D+1) trace the same samples, PSNR 87 dB at 320x240)
#   --out         images, logs and the converted mesh (default out/peer-povray)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

install=0 build=1 size=1280x960 repeat=3 threshold=0.3 aa_depth=3 threads_list="1 2"
out=out/peer-povray csv=docs/data/peer_povray.csv chart=docs/charts/peer_povray.png
command_line="scripts/peer-povray.sh $*"
while [ $# -gt 0 ]; do
  case "$1" in
    --install) install=1 ;;
    --no-build) build=0 ;;
    --size) size=$2; shift ;;
    --repeat) repeat=$2; shift ;;
    --threshold) threshold=$2; shift ;;
    --aa-depth) aa_depth=$2; shift ;;
    --threads) threads_list=$2; shift ;;
    --out) out=$2; shift ;;
    --csv) csv=$2; shift ;;
    --chart) chart=$2; shift ;;
    -h|--help) sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "peer-povray: unknown argument '$1' (see --help)" >&2; exit 1 ;;
  esac
  shift
done
[[ $size =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "peer-povray: --size must be WxH, got '$size'" >&2; exit 1; }
width=${BASH_REMATCH[1]} height=${BASH_REMATCH[2]}
[[ $repeat =~ ^[1-9][0-9]*$ ]] || { echo "peer-povray: --repeat must be a positive integer" >&2; exit 1; }

povray=$(command -v povray || true)
if [ -z "$povray" ]; then
  if [ "$install" = 1 ]; then
    apt-get install -y povray >/dev/null
    povray=$(command -v povray)
  else
    echo "peer-povray: POV-Ray is not installed; run with --install (as root) or apt-get install povray" >&2
    exit 1
  fi
fi
python=/usr/bin/python3
[ -x /usr/bin/time ] || { echo "peer-povray: needs GNU time (/usr/bin/time, package time)" >&2; exit 1; }
shared=${RTLAB_SHARED_DIR:-$root/../shared}
mesh=$shared/models/stanford-bunny.obj
[ -f "$mesh" ] || { echo "peer-povray: no $mesh (set RTLAB_SHARED_DIR)" >&2; exit 1; }
export RTLAB_SHARED_DIR=$shared

bin=build/release/bin
if [ "$build" = 1 ]; then
  cmake --preset release >/dev/null
  cmake --build build/release -j2 --target rtlab_app_whitted rtlab_app_bunny >/dev/null
fi
for app in rtlab-whitted rtlab-bunny; do
  [ -x "$bin/$app" ] || { echo "peer-povray: no $bin/$app; build the release preset (or drop --no-build)" >&2; exit 1; }
done

mkdir -p "$out" "$(dirname "$csv")" "$(dirname "$chart")"
out=$(cd "$out" && pwd)
# POV-Ray cannot read OBJ: the project's converter writes the same mesh, placed and smooth-shaded as
# rtlab-bunny does, as a mesh2 include. This is a one-off conversion, not part of either timed run.
$python scripts/peer/mesh_to_pov.py "$mesh" "$out/bunny_mesh.inc" >/dev/null

now() { date +%s.%N; }
# CPU seconds (user + system) of a whole run, from GNU time's file.
cpu_seconds() { awk '{printf "%.2f", $1 + $2}' "$1"; }
elapsed() { $python -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.3f}')" "$1" "$2"; }
median() {
  printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'
}

# One POV-Ray run; prints "wall render render_cpu cpu". The render phase is the Trace Time POV-Ray prints
# with its statistics ("Trace Time: 0 hours 0 minutes 5 seconds (5.123 seconds)", then "using 1 thread(s)
# with 1.234 CPU-seconds total").
run_pov() {  # scene aa threads image log
  local aa_flags=(-A)
  # No jitter, and the colour distance taken on linear values (Antialias_Gamma 1), as rtlab's
  # display_difference does.
  [ "$2" = adaptive ] && aa_flags=("+A$threshold" +AM2 "+R$((aa_depth + 1))" -J +AG1)
  local t0 t1
  t0=$(now)
  /usr/bin/time -o "$5.time" -f "%U %S" "$povray" "+I$root/bench/peer/povray/$1.pov" "+O$4" +FN8 \
    "+W$width" "+H$height" "${aa_flags[@]}" -D "+WT$3" "+L$out" File_Gamma=sRGB >"$5" 2>&1 ||
    { echo "peer-povray: POV-Ray failed, see $5" >&2; exit 1; }
  t1=$(now)
  local trace trace_cpu
  trace=$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$5" | tail -1)
  trace_cpu=$(sed -n '/Trace Time:/{n;s/.* with \([0-9.]*\) CPU-seconds.*/\1/p}' "$5" | tail -1)
  [ -n "$trace" ] && [ -n "$trace_cpu" ] || { echo "peer-povray: no Trace Time in $5" >&2; exit 1; }
  echo "$(elapsed "$t0" "$t1") $trace $trace_cpu $(cpu_seconds "$5.time")"
}

# One rtlab run; prints "wall render render_cpu cpu". The render phase is the seconds of the app's summary
# line ("whitted: 1280x960 in 1.23 s (2.40 CPU s), ..."): the render alone, without loading or writing.
run_rtlab() {  # scene aa threads image log
  local aa_flags=(--aa none)
  [ "$2" = adaptive ] && aa_flags=(--aa adaptive --aa-threshold "$threshold" --aa-depth "$aa_depth")
  local t0 t1
  t0=$(now)
  /usr/bin/time -o "$5.time" -f "%U %S" "$bin/rtlab-$1" -o "$4" --width "$width" --height "$height" \
    "${aa_flags[@]}" --threads "$3" >"$5" 2>&1 ||
    { echo "peer-povray: rtlab-$1 failed, see $5" >&2; exit 1; }
  t1=$(now)
  local render render_cpu
  render=$(sed -n 's/.* in \([0-9.]*\) s (\([0-9.]*\) CPU s), .*/\1/p' "$5" | tail -1)
  render_cpu=$(sed -n 's/.* in \([0-9.]*\) s (\([0-9.]*\) CPU s), .*/\2/p' "$5" | tail -1)
  [ -n "$render" ] && [ -n "$render_cpu" ] || { echo "peer-povray: no render time in $5" >&2; exit 1; }
  echo "$(elapsed "$t0" "$t1") $render $render_cpu $(cpu_seconds "$5.time")"
}

machine="$(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1), $(nproc) cores"
date_now=$(date -u +%Y-%m-%dT%H:%MZ)
load=$(cut -d' ' -f1 /proc/loadavg)
echo "peer-povray: ${width}x${height}, median of $repeat, on $machine (load $load at start)"
echo "scene,aa,threshold,aa_depth,threads,width,height,pov_wall_s,rtlab_wall_s,wall_ratio,pov_render_s,rtlab_render_s,render_ratio,pov_render_cpu_s,rtlab_render_cpu_s,render_cpu_ratio,pov_cpu_s,rtlab_cpu_s,cpu_ratio,psnr_db,mean_abs,max_abs,over_16,repeat,load_start,machine,date" >"$csv"
printf '%-8s %-8s %3s  %8s %8s %6s  %8s %8s %6s  %6s  %6s  %7s\n' scene aa thr pov_wall rt_wall ratio \
  pov_rend rt_rend ratio r_cpu cpu psnr_db
for scene in whitted bunny; do
  for aa in none adaptive; do
    for threads in $threads_list; do
      tag="${scene}_${aa}_t${threads}"
      pw=() pr=() prc=() pc=() rw=() rr=() rrc=() rc=()
      for ((i = 0; i < repeat; ++i)); do
        times=$(run_pov "$scene" "$aa" "$threads" "$out/pov_$tag.png" "$out/pov_$tag.log")
        read -r w r rcpu c <<<"$times"
        pw+=("$w") pr+=("$r") prc+=("$rcpu") pc+=("$c")
        times=$(run_rtlab "$scene" "$aa" "$threads" "$out/rtlab_$tag.png" "$out/rtlab_$tag.log")
        read -r w r rcpu c <<<"$times"
        rw+=("$w") rr+=("$r") rrc+=("$rcpu") rc+=("$c")
      done
      pov_wall=$(median "${pw[@]}") pov_render=$(median "${pr[@]}")
      rt_wall=$(median "${rw[@]}") rt_render=$(median "${rr[@]}")
      pov_render_cpu=$(median "${prc[@]}") rt_render_cpu=$(median "${rrc[@]}")
      render_cpu_ratio=$(awk -v a="$pov_render_cpu" -v b="$rt_render_cpu" 'BEGIN {printf "%.2f", a / b}')
      pov_cpu=$(median "${pc[@]}") rt_cpu=$(median "${rc[@]}")
      cpu_ratio=$(awk -v a="$pov_cpu" -v b="$rt_cpu" 'BEGIN {printf "%.2f", a / b}')
      # The rtlab summary has two decimals: a render under 5 ms would read 0.00.
      wall_ratio=$(awk -v a="$pov_wall" -v b="$rt_wall" 'BEGIN {printf "%.2f", a / b}')
      render_ratio=$(awk -v a="$pov_render" -v b="$rt_render" \
        'BEGIN {printf (b > 0 ? "%.2f" : "inf"), (b > 0 ? a / b : 0)}')
      similarity=$($python scripts/peer/compare.py "$out/rtlab_$tag.png" "$out/pov_$tag.png" "$out/diff_$tag.png")
      psnr=$(sed -n 's/.*psnr_db=\([^ ]*\).*/\1/p' <<<"$similarity")
      mean_abs=$(sed -n 's/.*mean_abs=\([^ ]*\).*/\1/p' <<<"$similarity")
      max_abs=$(sed -n 's/.*max_abs=\([^ ]*\).*/\1/p' <<<"$similarity")
      over=$(sed -n 's/.*over_16=\([^ ]*\).*/\1/p' <<<"$similarity")
      echo "$scene,$aa,$threshold,$aa_depth,$threads,$width,$height,$pov_wall,$rt_wall,$wall_ratio,$pov_render,$rt_render,$render_ratio,$pov_render_cpu,$rt_render_cpu,$render_cpu_ratio,$pov_cpu,$rt_cpu,$cpu_ratio,$psnr,$mean_abs,$max_abs,$over,$repeat,$load,\"$machine\",$date_now" >>"$csv"
      printf '%-8s %-8s %3s  %8s %8s %6s  %8s %8s %6s  %6s  %6s  %7s\n' "$scene" "$aa" "$threads" "$pov_wall" \
        "$rt_wall" "$wall_ratio" "$pov_render" "$rt_render" "$render_ratio" "$render_cpu_ratio" "$cpu_ratio" "$psnr"
    done
  done
done
$python scripts/peer/peer_chart.py "$csv" "$chart" "$command_line"
echo "peer-povray: $csv, $chart; images, difference images and logs in $out"
