"""Shading charts from the CSV files under docs/data: the energy single-scattering microfacet models lose.

Usage: shading_charts.py DATA_DIR CHARTS_DIR
The footer names the machine, the date and the command, read from DATA_DIR/<name>.meta.json (written by
scripts/charts.sh when it computed the data). Run with Debian's /usr/bin/python3 (python3-matplotlib).
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from tradeoff_charts import footer, meta, read_csv, save  # noqa: E402


# --- directional albedo of cook-torrance (white conductor) and rough-dielectric against alpha --------------
def microfacet_energy(data, out):
    rows = read_csv(Path(data) / "microfacet_energy.csv")
    fig, axes = plt.subplots(1, 2, figsize=(11, 5.0), sharey=True)
    cosines = sorted({float(r["cos_o"]) for r in rows}, reverse=True)
    colours = {c: f"C{i}" for i, c in enumerate(cosines)}
    for ax, surface, title in (
            (axes[0], "conductor", "cook-torrance lobe, white conductor (F = 1)"),
            (axes[1], "dielectric", "rough-dielectric, ior 1.5, entered from outside: R + T")):
        for distribution, style in (("ggx", "-"), ("beckmann", "--")):
            for c in cosines:
                g = [r for r in rows if r["surface"] == surface and r["distribution"] == distribution
                     and float(r["cos_o"]) == c]
                g.sort(key=lambda r: float(r["alpha"]))
                ax.plot([float(r["alpha"]) for r in g], [100.0 * float(r["energy_lost"]) for r in g], style,
                        color=colours[c], marker="o" if distribution == "ggx" else None, ms=3,
                        label=f"{distribution}, cos θo = {c:g}")
        ax.set_xscale("log")
        ax.set_xlim(0.01, 1.0)
        ax.set_xlabel("alpha (the materials' roughness parameter r gives alpha = r²)")
        ax.set_title(title, fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("energy lost: 1 - directional albedo, %")
    axes[0].set_ylim(-1, 72)
    ggx_normal = [r for r in rows if r["surface"] == "conductor" and r["distribution"] == "ggx"
                  and float(r["cos_o"]) == 1.0 and float(r["alpha"]) == 1.0]
    if ggx_normal:
        lost = 100.0 * float(ggx_normal[0]["energy_lost"])
        axes[0].annotate(f"GGX, alpha 1, normal incidence: {lost:.2f}%\n(closed form: ln 2 = 69.31%)", (1.0, lost),
                         textcoords="offset points", xytext=(-12, -6), ha="right", va="top", fontsize=7)
    axes[1].legend(fontsize=7, ncol=2, loc="upper left")
    fig.suptitle("Single scattering: the energy microfacet models lose to the bounces between microfacets they leave out",
                 fontsize=10)
    footer(fig, meta(data, "microfacet_energy"),
           "Directional albedo by adaptive quadrature of f |cos θi| over the sphere (rtlab::shading_testing, "
           "refined around the mirror and refracted directions): deterministic, no Monte Carlo noise.")
    save(fig, out, "microfacet_energy.png", 0.2)


def main():
    data, out = sys.argv[1], sys.argv[2]
    Path(out).mkdir(parents=True, exist_ok=True)
    if not (Path(data) / "microfacet_energy.csv").exists():
        print(f"charts: skipping microfacet_energy: no microfacet_energy.csv in {data}")
        return
    microfacet_energy(data, out)


if __name__ == "__main__":
    main()
