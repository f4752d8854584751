"""Charts from rtlab-accel CSV files (FORMATS.md columns): speed against build time per method, and build
seconds per million triangles over the models. Run with Debian's /usr/bin/python3 (python3-matplotlib)."""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(paths):
    rows = []
    for path in paths:
        with open(path, newline="") as f:
            rows.extend(csv.DictReader(f))
    return rows


def speed_vs_build(rows, out_dir):
    """One panel per (mesh, ray set): closest-hit Mrays/s against build seconds, one point per method."""
    groups = defaultdict(list)
    for r in rows:
        if r["method"] != "brute":
            groups[(r["mesh"], r["ray_set"])].append(r)
    for (mesh, ray_set), rs in sorted(groups.items()):
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for r in rs:
            x, y = float(r["build_s"]), float(r["closest_mrays_s"])
            ax.scatter(x, y, s=40)
            label = r["method"] + (f" ({r['mismatches']} mism.)" if r["mismatches"] not in ("", "0") else "")
            ax.annotate(label, (x, y), textcoords="offset points", xytext=(5, 4), fontsize=8)
        ax.set_xscale("log")
        ax.set_xlabel("build time, s (median)")
        ax.set_ylabel("closest-hit throughput, Mrays/s (median)")
        threads = rs[0]["threads"]
        ax.set_title(f"{mesh}, {ray_set} rays, {threads} thread(s): speed against build time", fontsize=10)
        ax.grid(True, alpha=0.3)
        fig.tight_layout()
        name = f"accel_speed_vs_build_{Path(mesh).stem}_{ray_set}.png"
        fig.savefig(out_dir / name, dpi=110)
        plt.close(fig)
        print(f"wrote {out_dir / name}")


def build_scaling(rows, out_dir):
    """Build seconds per million triangles against triangle count, one line per method."""
    per_method = defaultdict(dict)
    for r in rows:
        if r["method"] in ("brute",) or r["build_s"] == "":
            continue
        per_method[r["method"]][int(r["triangles"])] = float(r["build_s"])
    if not per_method:
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for method, points in sorted(per_method.items()):
        xs = sorted(points)
        ax.plot(xs, [points[x] / (x / 1e6) for x in xs], marker="o", label=method)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("triangles")
    ax.set_ylabel("build seconds per million triangles")
    ax.set_title("Build cost over the models (flat = O(N), rising = worse)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out_dir / "accel_build_scaling.png", dpi=110)
    plt.close(fig)
    print(f"wrote {out_dir / 'accel_build_scaling.png'}")


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: accel_charts.py OUT_DIR CSV...")
    out_dir = Path(sys.argv[1])
    out_dir.mkdir(parents=True, exist_ok=True)
    rows = read_rows(sys.argv[2:])
    speed_vs_build(rows, out_dir)
    build_scaling(rows, out_dir)


if __name__ == "__main__":
    main()
