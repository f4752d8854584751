"""Image checks of the environment-map race (scripts/peer-cycles.sh --envmap, issue 22) on PFM files. Run with
/usr/bin/python3 (numpy, matplotlib).

    cycles_envmap.py compare SCENE.json RTLAB.pfm CYCLES.pfm
        Which pixels see what is found from the scene itself: rtlab's pinhole camera traced through a 4 x 4 grid
        in every pixel against the scene's spheres and disks. A pixel whose sixteen rays all escape is
        background, one whose rays all end on the same shape is that shape's. Prints key=value words:
          bg_pixels, bg_rel   background: sum |Y_rtlab - Y_cycles| / sum Y_cycles (Y: luminance), the mean
                              relative difference of the map as the two renderers put it on the screen
          bg_ratio            background: sum Y_rtlab / sum Y_cycles
          <shape>_pixels, <shape>_ratio   a shape's mean colour, rtlab over Cycles, per channel (r:g:b)
    cycles_envmap.py png IN.pfm OUT.png [--scale K] [--exposure STOPS]
        linear to sRGB 8-bit, clamped after the exposure (default 0), each pixel K x K (default 3), to look at
"""
import json
import math
import re
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from cycles_images import luminance, read_pfm, to_png  # noqa: E402


def read_scene(path):
    text = "\n".join(re.sub(r"^\s*//.*$", "", line) for line in open(path).read().splitlines())
    return json.loads(text)


def camera_rays(camera, width, height, grid=4):
    """Unit directions (height, width, grid * grid, 3) of rtlab's pinhole camera (libs/render/src/camera.cpp:
    x to the right, y down, the vertical fov) through a grid x grid pattern in every pixel."""
    eye = np.array(camera.get("position", [0, 0, 0]), dtype=np.float64)
    forward = np.array(camera["look_at"], dtype=np.float64) - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, np.array(camera.get("up", [0, 1, 0]), dtype=np.float64))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    t = math.tan(math.radians(float(camera.get("fov", 45.0))) / 2)
    offsets = (np.arange(grid) + 0.5) / grid
    x = (np.arange(width)[:, None] + offsets[None, :]).reshape(-1)
    y = (np.arange(height)[:, None] + offsets[None, :]).reshape(-1)
    px = (2 * x / width - 1) * t * width / height
    py = (1 - 2 * y / height) * t
    d = forward + px[None, :, None] * right + py[:, None, None] * up  # (H*grid, W*grid, 3)
    d /= np.linalg.norm(d, axis=2, keepdims=True)
    d = d.reshape(height, grid, width, grid, 3).transpose(0, 2, 1, 3, 4).reshape(height, width, grid * grid, 3)
    return eye, d


def hit_ids(scene, eye, d):
    """Index of the nearest sphere or disk each ray hits (-1: none) and the shapes' names."""
    best = np.full(d.shape[:-1], np.inf)
    ids = np.full(d.shape[:-1], -1)
    names = []
    for k, s in enumerate(scene.get("shapes", [])):
        names.append(s.get("name", f"shape{k}"))
        c = np.array(s.get("center", [0, 0, 0]), dtype=np.float64)
        r = float(s.get("radius", 1.0))
        if s["type"] == "sphere":
            oc = eye - c
            b = d @ oc
            disc = b * b - (oc @ oc - r * r)
            root = np.sqrt(np.maximum(disc, 0))
            t0, t1 = -b - root, -b + root
            t = np.where(t0 > 1e-6, t0, t1)
            t = np.where((disc > 0) & (t > 1e-6), t, np.inf)
        elif s["type"] == "disk":
            n = np.array(s.get("normal", [0, 1, 0]), dtype=np.float64)
            n /= np.linalg.norm(n)
            dn = d @ n
            with np.errstate(divide="ignore", invalid="ignore"):
                t = ((c - eye) @ n) / dn
            p = eye + t[..., None] * d
            inside = np.linalg.norm(p - c, axis=-1) <= r
            t = np.where((np.abs(dn) > 1e-12) & (t > 1e-6) & inside, t, np.inf)
        else:
            raise SystemExit(f"cycles_envmap: shape '{names[-1]}' is a {s['type']}: only spheres and disks are traced")
        closer = t < best
        best = np.where(closer, t, best)
        ids = np.where(closer, k, ids)
    return ids, names


def pixel_classes(scene_path, width, height):
    scene = read_scene(scene_path)
    eye, d = camera_rays(scene["camera"], width, height)
    ids, names = hit_ids(scene, eye, d)
    same = (ids == ids[..., :1]).all(axis=-1)
    cls = np.where(same, ids[..., 0], -2)  # -2: a pixel on an outline
    return cls, names


def compare(scene_path, rtlab_path, cycles_path):
    a, b = read_pfm(rtlab_path), read_pfm(cycles_path)
    if a.shape != b.shape:
        raise SystemExit(f"cycles_envmap: {rtlab_path} and {cycles_path} differ in size")
    cls, names = pixel_classes(scene_path, a.shape[1], a.shape[0])
    bg = cls == -1
    ya, yb = luminance(a)[bg], luminance(b)[bg]
    words = [f"bg_pixels={int(bg.sum())}", f"bg_rel={np.abs(ya - yb).sum() / yb.sum():.5f}",
             f"bg_ratio={ya.sum() / yb.sum():.5f}"]
    for k, name in enumerate(names):
        m = cls == k
        if m.any():
            ratio = a[m].mean(axis=0) / b[m].mean(axis=0)
            words += [f"{name}_pixels={int(m.sum())}", f"{name}_ratio={':'.join(f'{x:.4f}' for x in ratio)}"]
    print(" ".join(words))


def option(argv, name, default):
    return float(argv[argv.index(name) + 1]) if name in argv else default


def main(argv):
    if len(argv) == 5 and argv[1] == "compare":
        compare(argv[2], argv[3], argv[4])
    elif len(argv) >= 4 and argv[1] == "png":
        to_png(argv[2], argv[3], int(option(argv, "--scale", 3)), option(argv, "--exposure", 0.0))
    else:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
