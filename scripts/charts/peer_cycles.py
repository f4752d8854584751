"""The chart of the race with Blender's Cycles (scripts/peer-cycles.sh): RMSE against time, log-log, for rtlab
`path`, rtlab `direct` and Cycles, each render measured against its own renderer's converged render; one panel
per scene and thread count. rtlab's points are its whole run; Cycles' are its render phase (filled) and its
whole run (hollow, Blender's start included). The title of each panel gives rtlab's time to Cycles' RMSE over
Cycles' render-phase time (geometric mean over the RMSE levels both reached; target <= 0.667), and the same in
processor seconds (rtlab's whole run, Cycles' render phase), which a shared machine's load disturbs less.

Usage: peer_cycles.py LADDER.csv SUMMARY.csv META.json OUT.png   (Debian's /usr/bin/python3)
"""
import csv
import json
import sys
import textwrap
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main(argv):
    if len(argv) != 5:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    ladder, summary = read_csv(argv[1]), read_csv(argv[2])
    meta = json.loads(Path(argv[3]).read_text()) if Path(argv[3]).exists() else {}
    if not ladder:
        print(f"peer_cycles: {argv[1]} has no rows", file=sys.stderr)
        return 1
    panels = sorted({(r["scene"], int(r["threads"])) for r in ladder}, key=lambda p: (p[0] != "box", p))
    def efficiency_of(quantity):
        return {(r["scene"], int(r["threads"])): float(r["value"]) for r in summary
                if r["section"] == "efficiency" and r["quantity"] == quantity}

    efficiency = efficiency_of("rtlab_wall_over_cycles_render_geomean")
    efficiency_cpu = efficiency_of("rtlab_cpu_over_cycles_render_cpu_geomean")
    cols = len({t for _, t in panels})
    rows = (len(panels) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 4.2 * rows + 0.6), squeeze=False)
    series = [("cycles", "path", "render_s", "Cycles, render phase", "#c44e52", "o", "full"),
              ("cycles", "path", "wall_s", "Cycles, whole run", "#c44e52", "o", "none"),
              ("rtlab", "path", "wall_s", "rtlab path, whole run", "#4c72b0", "s", "full"),
              ("rtlab", "direct", "wall_s", "rtlab direct (own reference), whole run", "#55a868", "^", "full")]
    for ax, (scene, threads) in zip(axes.ravel(), panels):
        for renderer, integrator, key, label, colour, marker, fill in series:
            pts = sorted((int(r["spp"]), float(r[key]), float(r["rmse"])) for r in ladder
                         if r["scene"] == scene and int(r["threads"]) == threads and r["renderer"] == renderer
                         and r["integrator"] == integrator)
            if not pts:
                continue
            ax.loglog([p[1] for p in pts], [p[2] for p in pts], marker=marker, color=colour, fillstyle=fill,
                      linestyle="-" if fill == "full" else "--", linewidth=1, label=label)
            if key != "wall_s" or renderer == "rtlab":
                for spp, t, e in (pts[0], pts[-1]):
                    ax.annotate(f"{spp}", (t, e), textcoords="offset points", xytext=(4, 3), fontsize=6.5,
                                color=colour)
        ratio = efficiency.get((scene, threads))
        r0 = next(r for r in ladder if r["scene"] == scene)
        title = f"{scene}, {r0['width']}x{r0['height']}, depth {r0['depth']}, {threads} thread{'s' * (threads > 1)}"
        if ratio is not None:
            cpu = efficiency_cpu.get((scene, threads))
            title += f"\nrtlab / Cycles time at equal RMSE: {ratio:.2f}"
            title += f", processor s {cpu:.2f}" if cpu is not None else ""
            title += " (target <= 0.67)"
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("seconds")
        ax.set_ylabel("RMSE against own converged render")
        ax.grid(True, which="both", linewidth=0.3, alpha=0.5)
        ax.legend(fontsize=7)
    for ax in axes.ravel()[len(panels):]:
        ax.axis("off")
    text = " | ".join(str(meta.get(k, "not recorded")) for k in ("machine", "date", "peer", "command"))
    text += f" | load {meta.get('load_start', '?')} at start\n{meta.get('medians', '')}"
    text = "\n".join(textwrap.fill(line, int(fig.get_figwidth() * 19)) for line in text.split("\n"))
    fig.text(0.01, 0.005, text, fontsize=6.5, va="bottom", ha="left", color="#444")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    fig.savefig(argv[4], dpi=100)
    print(f"charts: wrote {argv[4]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
