"""Photon mapping charts (issue 22) from docs/data: sppm against the path tracer on the Cornell box, and RMSE against
time for path, photon and sppm on the caustics scene.

Usage: photon_charts.py DATA_DIR CHARTS_DIR
Footers come from DATA_DIR/<name>.meta.json (scripts/charts.sh --photon). Run with Debian's /usr/bin/python3.
"""
import sys
from collections import defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from tradeoff_charts import footer, meta, plt, read_csv, save  # noqa: E402


def sppm_convergence(data, out):
    rows = read_csv(Path(data) / "sppm_convergence.csv")
    it = [int(r["iterations"]) for r in rows]
    fig, ax = plt.subplots(figsize=(7.2, 5.0))
    ax.plot(it, [100 * float(r["block_mean_relative"]) for r in rows], "o-", label="mean over the 8x8 blocks")
    ax.plot(it, [100 * float(r["block_max_relative"]) for r in rows], "s--", alpha=0.7, label="largest block")
    ax.axhline(1.0, color="k", lw=0.8, ls=":", label="1%")
    noise = float(rows[0].get("reference_block_noise", -1) or -1)
    if noise > 0:
        ax.axhline(100 * noise, color="#888", lw=0.8, ls="-.", label=f"the reference's own block noise ({100 * noise:.2g}%)")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel(f"sppm iterations ({int(rows[0]['photons'])} photons each)")
    ax.set_ylabel("relative difference of 8x8 block means to the path tracer (%)")
    ax.set_title("Stochastic progressive photon mapping converges to the path tracer (Cornell box, 32 x 32)", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    footer(fig, meta(data, "sppm_convergence"))
    save(fig, out, "sppm_convergence.png", 0.2)


def caustics_rmse(data, out):
    rows = read_csv(Path(data) / "caustics_rmse.csv")
    series = defaultdict(list)
    for r in rows:
        series[r["method"]].append(r)
    fig, ax = plt.subplots(figsize=(7.6, 5.4))
    styles = {"path": "o-", "photon": "s-", "sppm": "^-"}
    for method, rs in series.items():
        x = [float(r["cpu_seconds"]) for r in rs]
        y = [float(r["rmse"]) for r in rs]
        ax.plot(x, y, styles.get(method, "o-"), label=method)
        for r, xi, yi in zip(rs, x, y):
            if method != "sppm" or r is rs[0] or r is rs[-1]:
                ax.annotate(r["parameter"], (xi, yi), textcoords="offset points", xytext=(4, 3), fontsize=6)
    floor = float(rows[0].get("reference_rmse", -1) or -1)
    if floor > 0:
        ax.axhline(floor, color="#888", lw=0.8, ls="-.", label=f"the reference's own RMSE ({floor:.2g})")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("CPU seconds (every thread, photon shooting included)")
    ax.set_ylabel("RMSE against the converged path-traced reference")
    ax.set_title("Caustics (scenes/caustics.json): error against time", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    footer(fig, meta(data, "caustics_rmse"))
    save(fig, out, "caustics_rmse.png", 0.2)


def main():
    data, out = sys.argv[1], sys.argv[2]
    Path(out).mkdir(parents=True, exist_ok=True)
    for chart, name in ((sppm_convergence, "sppm_convergence.csv"), (caustics_rmse, "caustics_rmse.csv")):
        if not (Path(data) / name).exists():
            print(f"charts: skipping {chart.__name__}: no {name} in {data}")
            continue
        chart(data, out)


if __name__ == "__main__":
    main()
