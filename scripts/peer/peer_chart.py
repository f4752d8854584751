"""The chart of the POV-Ray race (scripts/peer-povray.sh): for every setting, how many times faster rtlab is
than POV-Ray in wall time, in render-phase time, and in processor seconds of the render phase and of the
whole run, against issue 24's targets (5x wall, 3.5x render; issue 15's were 3x and 2x), with the PSNR of the two pictures over each group.
Run with Debian's /usr/bin/python3 (python3-matplotlib).

    /usr/bin/python3 scripts/peer/peer_chart.py docs/data/peer_povray.csv docs/charts/peer_povray.png "COMMAND"
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) != 4:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    with open(argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        print(f"peer_chart: {argv[1]} has no rows", file=sys.stderr)
        return 1
    def aa(r):
        return f"AA {r['threshold']}, depth {r['aa_depth']}" if r["aa"] == "adaptive" else "no AA"

    labels = [f"{r['scene']}\n{aa(r)}\n{r['threads']} thr" for r in rows]
    wall = [float(r["wall_ratio"]) for r in rows]
    render = [float(r["render_ratio"]) for r in rows]
    render_cpu = [float(r["render_cpu_ratio"]) for r in rows]
    cpu = [float(r["cpu_ratio"]) for r in rows]
    x = range(len(rows))
    fig, ax = plt.subplots(figsize=(10, 5.4))
    bw = 0.2
    ax.bar([i - 1.5 * bw for i in x], wall, bw, label="wall time (start to image on disk)", color="#4c72b0")
    ax.bar([i - 0.5 * bw for i in x], render, bw, label="render phase (POV-Ray Trace Time / rtlab render)",
           color="#dd8452")
    ax.bar([i + 0.5 * bw for i in x], render_cpu, bw, label="render phase, processor seconds", color="#c44e52")
    ax.bar([i + 1.5 * bw for i in x], cpu, bw, label="whole run, processor seconds (user + system)",
           color="#55a868")
    ax.axhline(5.0, color="#4c72b0", linestyle="--", linewidth=1, label="target, wall: 5x")
    ax.axhline(3.5, color="#dd8452", linestyle="--", linewidth=1, label="target, render: 3.5x")
    top = max(wall + render + render_cpu + cpu)
    for i, r in enumerate(rows):
        ax.text(i, max(wall[i], render[i], render_cpu[i], cpu[i]) + 0.02 * top, f"{float(r['psnr_db']):.1f} dB",
                ha="center", fontsize=8)
    ax.set_xticks(list(x))
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("POV-Ray time / rtlab time (higher: rtlab faster)")
    ax.set_ylim(0, top * 1.5)  # headroom for the legend above the bars
    r0 = rows[0]
    ax.set_title(f"rtlab against POV-Ray 3.7, {r0['width']}x{r0['height']}, median of {r0['repeat']} runs "
                 f"(PSNR of the two 8-bit images above each group)", fontsize=10)
    ax.legend(fontsize=8, loc="upper center", ncol=3, framealpha=0.95)
    fig.text(0.01, 0.01, f"{r0['machine']}, load {r0['load_start']} at start; {r0['date']}; {argv[3]}",
             fontsize=7, color="#555555")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(argv[2], dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
