"""Image arithmetic of the Cycles race (scripts/peer-cycles.sh) on PFM files (rtlab-render writes them; the
Blender script converts its EXR to one): Debian's python3 has no EXR reader. Run with /usr/bin/python3.

    cycles_images.py png IN.pfm OUT.png              linear to sRGB 8-bit (clamped), for looking at
    cycles_images.py agree A.pfm B.pfm [--blocks N]  block means of two converged renders on an N x N grid
                                                     (default 8): relative differences of the blocks' mean
                                                     luminance and of every channel (worst_block: x:y from
                                                     the top left)
    cycles_images.py rmse IMG.pfm REF.pfm [SPP REF_SPP]  RMSE over every pixel and channel, and relative to
                                                     the reference's mean; with the sample counts, the
                                                     reference's own noise taken out (rmse_raw keeps it)
    cycles_images.py efficiency LADDER.csv           time to equal RMSE, rtlab against Cycles, from the ladder
                                                     rows of LADDER.csv (docs/data/peer_cycles.csv)
"""
import csv
import math
import sys

import numpy as np


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        if kind not in (b"PF", b"Pf"):
            raise SystemExit(f"cycles_images: {path} is not a PFM file")
        size = f.readline().split()
        while len(size) < 2:  # width and height may sit on separate lines
            size += f.readline().split()
        width, height = int(size[0]), int(size[1])
        scale = float(f.readline())
        channels = 3 if kind == b"PF" else 1
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    if data.size != width * height * channels:
        raise SystemExit(f"cycles_images: {path}: {data.size} values for {width}x{height}x{channels}")
    image = data.reshape(height, width, channels).astype(np.float64)
    return np.flipud(image)  # PFM rows run bottom to top: row 0 is the image's top after this


def luminance(image):
    return image @ np.array([0.2126, 0.7152, 0.0722])


def to_png(src, dst, scale=1, exposure=0.0):
    """PFM to an sRGB PNG, brightened by 2^exposure and each pixel repeated scale x scale times."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x = np.clip(read_pfm(src) * 2.0**exposure, 0.0, 1.0)
    srgb = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    big = np.repeat(np.repeat(srgb, scale, axis=0), scale, axis=1)
    plt.imsave(dst, (big * 255 + 0.5).astype(np.uint8))


def block_means(image, n):
    h, w = image.shape[:2]
    if h % n or w % n:
        raise SystemExit(f"cycles_images: a {w}x{h} image does not split into {n} x {n} equal blocks")
    return image.reshape(n, h // n, n, w // n, -1).mean(axis=(1, 3))


def agree(a_path, b_path, n):
    a, b = read_pfm(a_path), read_pfm(b_path)
    if a.shape != b.shape:
        raise SystemExit(f"cycles_images: {a_path} is {a.shape[1]}x{a.shape[0]}, {b_path} {b.shape[1]}x{b.shape[0]}")
    ya, yb = block_means(luminance(a)[:, :, None], n)[:, :, 0], block_means(luminance(b)[:, :, None], n)[:, :, 0]
    # The criterion takes the blocks at least 5% as bright as the mean block: in darker ones (deep shadow, the
    # black outside the box) the relative difference is mostly noise over little light. dark_max_rel is the
    # largest relative difference among the others that are not black (above 0.1% of the mean).
    lit = yb >= 0.05 * yb.mean()
    dark = (yb < 0.05 * yb.mean()) & (yb > 0.001 * yb.mean())
    rel = np.abs(ya - yb) / np.maximum(yb, 1e-30)
    ca, cb = block_means(a, n), block_means(b, n)
    channel_lit = cb >= 0.05 * cb.mean(axis=(0, 1))
    channel_rel = np.abs(ca - cb)[channel_lit] / cb[channel_lit]
    ratio = ya.sum() / yb.sum()
    worst = np.unravel_index(np.argmax(np.where(lit, rel, -1.0)), rel.shape)
    print(f"blocks={int(lit.sum())} mean_rel={rel[lit].mean():.5f} max_rel={rel[lit].max():.5f} "
          f"worst_block={worst[1]}:{worst[0]} channel_max_rel={channel_rel.max():.5f} "
          f"channel_mean_rel={channel_rel.mean():.5f} dark_blocks={int(dark.sum())} "
          f"dark_max_rel={rel[dark].max() if dark.any() else 0.0:.5f} image_ratio={ratio:.5f}")


def rmse(img_path, ref_path, spp=None, ref_spp=None):
    """The reference's own noise adds to the measured mean square error: with independent samples both fall as
    1 / spp, so MSE_measured = c (1 / spp + 1 / ref_spp), and the image's own part is MSE_measured ref_spp /
    (ref_spp + spp) (given both counts; the raw value otherwise)."""
    img, ref = read_pfm(img_path), read_pfm(ref_path)
    if img.shape != ref.shape:
        raise SystemExit(f"cycles_images: {img_path} and {ref_path} differ in size")
    mse = float(np.mean((img - ref) ** 2))
    own = mse * ref_spp / (ref_spp + spp) if spp and ref_spp else mse
    mean = float(ref.mean())
    print(f"rmse={math.sqrt(own):.6g} rel_rmse={math.sqrt(own) / mean:.6g} rmse_raw={math.sqrt(mse):.6g}")


def time_at(points, target):
    """Seconds at which a ladder [(seconds, rmse)] reaches `target`, interpolated in log-log; None outside."""
    points = sorted(points, key=lambda p: -p[1])  # falling RMSE
    for (t0, r0), (t1, r1) in zip(points, points[1:]):
        if r1 <= target <= r0 and r0 > r1:
            f = (math.log(r0) - math.log(target)) / (math.log(r0) - math.log(r1))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))
    return None


# (rtlab's column, Cycles' column): rtlab's whole run against Cycles' render phase is the race's measure;
# the others show what start-up and a shared machine's load (processor seconds) change.
EFFICIENCY_BASES = [("wall_s", "render_s"), ("wall_s", "wall_s"), ("render_s", "render_s"),
                    ("cpu_s", "render_cpu_s"), ("cpu_s", "cpu_s")]


def efficiency(ladder_path):
    """For every scene and thread count: at each RMSE Cycles reached on its ladder, rtlab path's time to the
    same RMSE (interpolated in log-log on its own ladder) over Cycles' time, on each basis of
    EFFICIENCY_BASES. Prints one line per scene, thread count and basis: the geometric mean of the ratios over
    the levels both reached, the ratio at the lowest common RMSE (the least start-up in it) and every level."""
    with open(ladder_path, newline="") as f:
        rows = list(csv.DictReader(f))
    groups = {}
    for r in rows:
        groups.setdefault((r["scene"], int(r["threads"])), []).append(r)
    for (scene, threads), rs in sorted(groups.items()):
        rt = [r for r in rs if r["renderer"] == "rtlab" and r["integrator"] == "path"]
        cy = sorted((r for r in rs if r["renderer"] == "cycles"), key=lambda r: int(r["spp"]))
        if not rt or not cy:
            continue
        for rt_key, cy_key in EFFICIENCY_BASES:
            name = f"rtlab_{rt_key[:-2]}_over_cycles_{cy_key[:-2]}"
            if not all(r[rt_key] for r in rt) or not all(r[cy_key] for r in cy):
                continue
            points = [(float(r[rt_key]), float(r["rmse"])) for r in rt]
            ratios = []
            for r in cy:
                t_rt = time_at(points, float(r["rmse"]))
                if t_rt is not None:
                    ratios.append((int(r["spp"]), t_rt / float(r[cy_key])))
            if not ratios:
                print(f"{scene} threads={threads} {name} geomean=nan last=nan levels=none")
                continue
            geo = math.exp(sum(math.log(x) for _, x in ratios) / len(ratios))
            levels = " ".join(f"{spp}:{x:.3f}" for spp, x in ratios)
            print(f"{scene} threads={threads} {name} geomean={geo:.3f} last={ratios[-1][1]:.3f} levels={levels}")


def main(argv):
    if len(argv) >= 4 and argv[1] == "png":
        to_png(argv[2], argv[3])
    elif len(argv) >= 4 and argv[1] == "agree":
        n = int(argv[argv.index("--blocks") + 1]) if "--blocks" in argv else 8
        agree(argv[2], argv[3], n)
    elif len(argv) in (4, 6) and argv[1] == "rmse":
        rmse(argv[2], argv[3], *(int(x) for x in argv[4:6]))
    elif len(argv) == 3 and argv[1] == "efficiency":
        efficiency(argv[2])
    else:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
