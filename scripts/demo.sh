#!/usr/bin/env bash
# Builds the course apps and rtlab-render (release) and renders the three course scenes into out/, plus an orbit
# animation of the solar system as an animated GIF. A few minutes on 2 cores from a fresh checkout.
#   scripts/demo.sh            everything
# The data (data/assets.tsv): a folder laid out like ../shared when there is one (RTLAB_SHARED_DIR, or ../shared
# beside the checkout), else the Debian packages scripts/setup.sh installs: the Stanford bunny from glmark2-data,
# the planet maps and Saturn's rings from openuniverse-common (the Sun's surface and the star field are then
# procedural). Each app prints one "data: ..." line: where each asset came from, and its credit.
#   RTLAB_NO_SHARED=1          ignore ../shared and RTLAB_SHARED_DIR: what a user without them sees
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake --preset release >/dev/null
jobs=$(nproc)
cmake --build build/release -j "$jobs" --target rtlab_app_whitted rtlab_app_solar-system rtlab_app_bunny \
  rtlab_app_render
bin=build/release/bin
mkdir -p out out/orbit
start=$SECONDS

echo "demo: the 1980 Whitted scene -> out/whitted.png"
"$bin/rtlab-whitted" -o out/whitted.png --width 640 --height 480

echo "demo: the solar system -> out/solar-system.png"
"$bin/rtlab-solar-system" -o out/solar-system.png --width 640 --height 480

echo "demo: the Stanford bunny -> out/bunny.png"
"$bin/rtlab-bunny" -o out/bunny.png --width 640 --height 480 --material phong
"$bin/rtlab-bunny" -o out/bunny-glass.png --width 640 --height 480 --material glass --aa none --quiet

echo "demo: the Cornell box, path traced -> out/cornell-box.png, and by sppm -> out/cornell-box-glossy.png"
"$bin/rtlab-render" scenes/cornell_box.json -o out/cornell-box.png --spp 256 --quiet
# The glossy box by sppm: its frosted block's caustic is photons' work; a path tracer shows it as specks.
"$bin/rtlab-render" scenes/cornell_box_glossy.json -o out/cornell-box-glossy.png --integrator sppm --spp 256 --quiet

frames=48
echo "demo: an orbit of the solar system, $frames frames -> out/orbit/solar-0000.png ... and out/solar-orbit.gif"
"$bin/rtlab-solar-system" -o out/orbit/solar.png --width 320 --height 240 --frames "$frames" --quiet
/usr/bin/python3 - "$frames" <<'PY'
import sys
from PIL import Image
n = int(sys.argv[1])
frames = [Image.open(f"out/orbit/solar-{i:04d}.png").convert("RGB") for i in range(n)]
# One shared palette (taken from the first frame) keeps the colours from flickering between frames.
palette = frames[0].quantize(colors=255, method=Image.Quantize.MEDIANCUT)
gif = [f.quantize(palette=palette, dither=Image.Dither.NONE) for f in frames]
gif[0].save("out/solar-orbit.gif", save_all=True, append_images=gif[1:], duration=80, loop=0, optimize=False)
PY

echo "demo: done in $((SECONDS - start)) s of rendering; results in $(pwd)/out:"
ls -l out | grep -v '^total' | grep -v ' orbit$'
echo "  out/orbit/ holds the $frames animation frames"
echo "demo: the data and its credits are in the 'data:' lines above (data/assets.tsv, README's Data section)."
echo "demo: scene files render with $bin/rtlab-render (docs/scene-format.md), e.g."
echo "  $bin/rtlab-render scenes/whitted.json -o out/whitted-file.png"
