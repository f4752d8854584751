#!/usr/bin/env bash
# Installs rtlab's build dependencies from Debian 12 packages. Idempotent: quiet when everything is
# already installed; uses sudo when not run as root.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  ninja-build        # scripts/test.sh builds new folders with it (cmake's Makefiles work as well)
  clang-format-14    # scripts/format.sh names this version, so every machine formats alike
  libglm-dev libstb-dev catch2 libtbb-dev libcli11-dev nlohmann-json3-dev
  libfmt-dev libpcg-cpp-dev libbenchmark-dev libopenexr-dev zlib1g-dev
  libembree-dev      # optional reference backend; the build works without it
  python3-matplotlib # charts (scripts/charts.sh, run with /usr/bin/python3)
  python3-pil        # the demo's animated GIF (scripts/demo.sh, run with /usr/bin/python3)
  glmark2-data       # the course data without ../shared: the Stanford bunny (data/assets.tsv)
  openuniverse-common # ... and the planet maps and Saturn's ring strip (data/assets.tsv)
  blender-data       # eight CC0 studio-light HDR maps, envmaps/<name>.exr (data/assets.tsv)
  libglfw3-dev libimgui-dev # rtlab-view (optional: built when found)
  xvfb xauth libgl1-mesa-dri # rtlab-view's window tests: a virtual X server and Mesa's software OpenGL
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
