"""Speed-against-accuracy charts (issue 16) from the CSV and JSON-lines files under docs/data.

Usage: tradeoff_charts.py DATA_DIR CHARTS_DIR
Each chart's footer names the machine, the date, the command and what its points are medians of, read from
DATA_DIR/<name>.meta.json (written by scripts/charts.sh when it measured the data). Run with Debian's
/usr/bin/python3 (python3-matplotlib).
"""
import csv
import json
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def meta(data, name):
    path = Path(data) / f"{name}.meta.json"
    if not path.exists():
        return {"machine": "not recorded", "date": "not recorded", "command": "not recorded", "medians": ""}
    return json.loads(path.read_text())


def footer(fig, m, extra=""):
    import textwrap
    text = f"{m['machine']} | {m['date']} | {m['command']}\n{m['medians']}" + (f"\n{extra}" if extra else "")
    text = "\n".join(textwrap.fill(line, int(fig.get_figwidth() * 20)) for line in text.split("\n"))
    fig.text(0.01, 0.005, text, fontsize=6.5, va="bottom", ha="left", color="#444")


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_jsonl(path):
    return [json.loads(line) for line in open(path) if line.strip()]


def save(fig, out, name, bottom):
    fig.subplots_adjust(bottom=bottom)
    fig.savefig(Path(out) / name, dpi=110)
    plt.close(fig)
    print(f"charts: wrote {Path(out) / name}")


# --- (3) triangle tests: ns per test against leak rate --------------------------------------------------
def triangle_tests(data, out):
    bench = [l for l in open(Path(data) / "triangle_tests_bench.csv") if l.startswith('"')]
    ns = {}
    for row in csv.reader(bench):
        name, cpu = row[0], float(row[3])
        if name.endswith("_median"):
            ns[name[: -len("_median")]] = cpu
    rows = read_jsonl(Path(data) / "stability.jsonl")
    leaks = defaultdict(lambda: [0, 0])
    fallback = [0, 0]
    for r in rows:
        if r["area"] != "triangle test" or "degenerate" in r["input"]:
            continue
        if r["method"] == "watertight double-precision fallback":
            fallback[0] += r["failures"]
            fallback[1] += r["tried"]
        else:
            leaks[r["method"]][0] += r["failures"]
            leaks[r["method"]][1] += r["tried"]
    fig, ax = plt.subplots(figsize=(7.2, 5.0))
    names = {"watertight": "bm_watertight", "moller": "bm_moller", "plane": "bm_plane"}
    floor = 1e-5
    for method, bench_name in names.items():
        if bench_name not in ns or method not in leaks:
            continue
        failures, tried = leaks[method]
        rate = failures / tried
        y = max(rate, floor)
        ax.scatter(ns[bench_name], y, s=60)
        label = f"{method}: {failures}/{tried} leaked" + (" (0: drawn at the floor)" if rate == 0 else "")
        ax.annotate(label, (ns[bench_name], y), textcoords="offset points", xytext=(6, 4), fontsize=8)
    if "bm_watertight_with_setup" in ns and "watertight" in leaks:
        ax.scatter(ns["bm_watertight_with_setup"], floor, s=40, marker="x", color="C0")
        ax.annotate("watertight incl. per-ray shear", (ns["bm_watertight_with_setup"], floor), textcoords="offset points",
                    xytext=(-6, 16), fontsize=8, ha="right")
    ax.set_yscale("log")
    ax.set_ylim(floor / 2, 1)
    ax.set_xlabel("ns per ray-triangle test (median CPU time, random rays near edges)")
    ax.set_ylabel("leak rate at shared edges and vertices")
    fb = fallback[0] / fallback[1] if fallback[1] else float("nan")
    ax.set_title("Triangle tests: cost against leaks through shared edges and vertices\n"
                 f"watertight double-precision fallback: {fallback[0]} of {fallback[1]} tests ({fb:.2%}) on the leak rays",
                 fontsize=9.5)
    ax.grid(True, which="both", alpha=0.3)
    m = meta(data, "triangle_tests_bench")
    footer(fig, m, "leaks: tests/stability triangle_stability_test.cpp (docs/data/stability.jsonl), all scales, "
                   "edges + vertices, unbounded + bounded rays")
    save(fig, out, "triangle_tests.png", 0.2)


# --- (4) secondary-ray offsets against scene scale ------------------------------------------------------
def spawn_offsets(data, out):
    rows = [r for r in read_jsonl(Path(data) / "stability.jsonl") if r["area"].startswith("spawned rays")]
    series = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    for r in rows:
        scale = float(r["input"].rsplit("scale ", 1)[1])
        kind = "leaks" if "wall" in r["input"] else "acne"
        series[(kind, r["method"])][scale][0] += r["failures"]
        series[(kind, r["method"])][scale][1] += r["tried"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8), sharey=True)
    for ax, kind, title in ((axes[0], "acne", "self-hits (acne): reflected + shadow rays off a sphere and a triangle sphere"),
                            (axes[1], "leaks", "light leaks: shadow rays under a wall 1e-3 of the scale thick")):
        for (k, method), by_scale in sorted(series.items()):
            if k != kind:
                continue
            xs = sorted(by_scale)
            ys = [max(by_scale[x][0] / by_scale[x][1], 1e-4) for x in xs]
            style = dict(lw=2.5, color="k") if method.startswith("spawn_ray") else dict(lw=1.2)
            ax.plot(xs, ys, marker="o", label=method, **style)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(5e-5, 1.5)
        ax.set_xlabel("scene scale (object size and distance from the origin)")
        ax.set_title(title, fontsize=8.5)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("fraction of secondary rays that fail (0 drawn at 1e-4)")
    axes[1].legend(fontsize=8)
    fig.suptitle("Secondary-ray offsets: error-derived (spawn.hpp) against fixed epsilons", fontsize=10)
    footer(fig, meta(data, "stability"), "counts of tests/stability/spawn_stability_test.cpp, 1500 rays per shape, "
                                         "scale and method; no timing (no medians)")
    save(fig, out, "spawn_offsets.png", 0.2)


# --- (5) scene-level tree break-even --------------------------------------------------------------------
def scene_breakeven(data, out):
    rows = read_csv(Path(data) / "scene_breakeven.csv")
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.6))
    for ax, query in zip(axes, ("closest", "shadow")):
        rs = [r for r in rows if r["query"] == query]
        x = [int(r["objects"]) for r in rs]
        ax.plot(x, [float(r["list_ns_per_ray"]) for r in rs], marker="o", label="plain list")
        ax.plot(x, [float(r["kdtree_ns_per_ray"]) for r in rs], marker="s", label="kd-tree over objects")
        ax.axvline(24, color="grey", ls="--", lw=1)
        ax.text(25, 0.97, "kSceneTreeThreshold = 24", transform=ax.get_xaxis_transform(), fontsize=7, va="top")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlabel("objects in the scene (spheres)")
        ax.set_ylabel("ns per ray (median CPU time)")
        ax.set_title(f"{query} rays", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Scene-level tree break-even: the measurement behind the renderer's default", fontsize=10)
    footer(fig, meta(data, "scene_breakeven"))
    save(fig, out, "scene_breakeven.png", 0.2)


# --- (1) accelerators: cost growth over the shared models ------------------------------------------------
def accel_growth(data, out):
    rows = []
    for p in sorted(Path(data).glob("accel_*.csv")):
        rows.extend(read_csv(p))
    rows = [r for r in rows if r["method"] != "brute" and r["ray_set"] == "random" and r["threads"] == "1"]
    by_method = defaultdict(list)
    for r in rows:
        by_method[r["method"]].append(r)
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.8))
    fig.subplots_adjust(wspace=0.32)
    for method, rs in sorted(by_method.items()):
        rs.sort(key=lambda r: int(r["triangles"]))
        n = [int(r["triangles"]) for r in rs]
        axes[0].plot(n, [float(r["build_s"]) for r in rs], marker="o", label=method)
        axes[1].plot(n, [1e3 / float(r["closest_mrays_s"]) for r in rs], marker="o", label=method)
        bpt = [float(r["bytes_per_triangle"]) for r in rs if r["bytes_per_triangle"] not in ("", "-1")]
        if bpt:
            axes[2].plot(n[: len(bpt)], bpt, marker="o", label=method)
    lo, hi = min(int(r["triangles"]) for r in rows), max(int(r["triangles"]) for r in rows)
    ref = [lo, hi]
    first_build = min(float(r["build_s"]) for r in rows if int(r["triangles"]) == lo)
    axes[0].plot(ref, [first_build, first_build * hi / lo], "k:", lw=1, label="slope 1 (n)")
    for ax, ylabel, title in ((axes[0], "build time, s", "build time"),
                              (axes[1], "ns per closest-hit ray", "trace time (200k random rays)"),
                              (axes[2], "bytes per triangle", "memory per triangle")):
        ax.set_xscale("log")
        ax.set_yscale("log" if ax is not axes[2] else "linear")
        ax.set_xlabel("triangles")
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    models = sorted({r["mesh"] for r in rows}, key=lambda m: min(int(r["triangles"]) for r in rows if r["mesh"] == m))
    fig.suptitle("Acceleration structures: cost growth over the shared models (" + ", ".join(models) + ")", fontsize=10)
    footer(fig, meta(data, "accel"))
    save(fig, out, "accel_cost_growth.png", 0.2)


# --- (2) anti-aliasing: render time against RMSE ---------------------------------------------------------
def antialiasing(data, out):
    rows = read_csv(Path(data) / "antialiasing.csv")
    pov_path = Path(data) / "antialiasing_povray.csv"
    pov = read_csv(pov_path) if pov_path.exists() else []
    m = meta(data, "antialiasing")
    mp = meta(data, "antialiasing_povray") if pov else None
    for scene, title in (("checker", "high-contrast checkerboard to the horizon"),
                         ("whitted", "Whitted-like scene (checker floor, mirror and glass spheres)")):
        fig, ax = plt.subplots(figsize=(8.6, 5.6))
        rs = [r for r in rows if r["scene"] == scene]
        groups = defaultdict(list)
        for r in rs:
            groups[r["series"]].append(r)
        points = []
        for series, g in groups.items():
            g.sort(key=lambda r: float(r["seconds_median"]))
            x = [float(r["seconds_median"]) for r in g]
            y = [float(r["rmse"]) for r in g]
            points.extend(zip(x, y))
            ax.plot(x, y, marker="o", ms=4, label=f"rtlab {series}")
            for r, xi, yi in zip(g, x, y):
                if r["pattern"] == "adaptive":
                    lab = f"t={float(r['threshold']):g}"
                elif r["pattern"] == "none":
                    lab = "1 spp"
                else:
                    lab = r["spp"]
                ax.annotate(lab, (xi, yi), textcoords="offset points", xytext=(3, 3), fontsize=6)
        # The Pareto front of rtlab's points: nothing both faster and more accurate.
        front, best = [], float("inf")
        for x, y in sorted(points):
            if y < best:
                front.append((x, y))
                best = y
        ax.plot([p[0] for p in front], [p[1] for p in front], color="k", lw=3, alpha=0.25, label="rtlab Pareto front")
        extra = "rtlab RMSE against jittered 400 spp (another seed); linear RGB clamped to [0, 1]."
        if pov:
            pg = defaultdict(list)
            for r in pov:
                if r["scene"] == scene:
                    pg[r["series"]].append(r)
            for series, g in pg.items():
                x = [float(r["seconds_median"]) for r in g]
                y = [float(r["rmse"]) for r in g]
                ax.plot(x, y, marker="^", ls="--", ms=5, label=series)
                for r, xi, yi in zip(g, x, y):
                    ax.annotate(f"+A{float(r['threshold']):g}" if r["threshold"] != "0.0" else "no AA", (xi, yi),
                                textcoords="offset points", xytext=(3, -8), fontsize=6)
            extra += (" POV-Ray 3.7 peer series (dashed): RMSE against its own +AM2 +A0 +R5 render of the same scene, "
                      "time = POV-Ray's own Trace Time (start-up and parsing excluded); " + mp["command"] + " on " + mp["date"] + ".")
        else:
            extra += " POV-Ray series absent: povray was not installed when the data was measured."
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("render time, s (median wall time, 1 thread)")
        ax.set_ylabel("RMSE to the reference")
        ax.set_title(f"Anti-aliasing on the {title}", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
        footer(fig, m, extra)
        save(fig, out, f"antialiasing_{scene}.png", 0.22)


# --- (6) Fresnel and Phong: time per evaluation against energy error -------------------------------------
def optics(data, out):
    rows = read_csv(Path(data) / "optics_tradeoff.csv")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8))
    floor = 1e-9
    for ax, family, title, ylabel in (
            (axes[0], "fresnel", "Fresnel: exact dielectric against Schlick",
             "|hemispherical reflectance error| (fraction of incident light)"),
            (axes[1], "phong", "Phong: energy-normalised against classic ks (r.v)^e",
             "|energy reflected at normal incidence - ks| / ks")):
        rs = [r for r in rows if r["family"] == family]
        for method in sorted({r["method"] for r in rs}):
            g = [r for r in rs if r["method"] == method]
            x = [float(r["ns_per_eval"]) for r in g]
            y = [max(float(r["energy_error"]), floor) for r in g]
            ax.scatter(x, y, s=40, label=method)
            for r, xi, yi in zip(g, x, y):
                ax.annotate(r["parameter"], (xi, yi), textcoords="offset points", xytext=(4, 3), fontsize=7)
        ax.set_yscale("log")
        ax.set_ylim(floor / 3, 5)
        ax.set_xlabel("ns per evaluation (median)")
        ax.set_ylabel(ylabel, fontsize=8)
        ax.set_title(title, fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Shading terms: time per evaluation against the error in reflected energy (exact at 0: drawn at 1e-9)",
                 fontsize=10)
    footer(fig, meta(data, "optics_tradeoff"))
    save(fig, out, "optics_tradeoff.png", 0.2)


def main():
    data, out = sys.argv[1], sys.argv[2]
    Path(out).mkdir(parents=True, exist_ok=True)
    for chart, needs in ((triangle_tests, ["triangle_tests_bench.csv", "stability.jsonl"]),
                         (spawn_offsets, ["stability.jsonl"]), (scene_breakeven, ["scene_breakeven.csv"]),
                         (accel_growth, []), (antialiasing, ["antialiasing.csv"]),
                         (optics, ["optics_tradeoff.csv"])):
        missing = [n for n in needs if not (Path(data) / n).exists()]
        if missing:
            print(f"charts: skipping {chart.__name__}: no {', '.join(missing)} in {data}")
            continue
        chart(data, out)


if __name__ == "__main__":
    main()
