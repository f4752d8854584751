"""POV-Ray's adaptive anti-aliasing (+AM1, +AM2) as peer series for the anti-aliasing chart.

Usage: povray_aa.py OUT.csv [--width W] [--runs N] [--images DIR]

Renders POV-Ray versions of the two scenes of bench/render/antialiasing_tradeoff.cpp (the checkerboard to
the horizon, radiance 1 and 0.02 under a sky of 0.3; the Whitted-like floor with a mirror and a glass
sphere), with the same camera, at Antialias_Gamma 1 (+AG1, linear colours as rtlab compares them) and 16-bit
linear PNG output. POV-Ray shades with its own model, so its RMSE is measured against its own reference:
+AM2 at threshold 0 and recursion depth 5 (33 x 33 corners per pixel at most). Times are the median wall
of `runs` renders on one thread (+WT1) of POV-Ray's own "Trace Time" (the render loop, without start-up and
parsing, which take longer than a small render); `wall_seconds_median` keeps the whole run's wall time.
"""
import csv
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import numpy as np  # noqa: E402

# rtlab's cameras look down -z in a right-handed frame, image x along +x; POV-Ray's frame is left-handed,
# looking down +z with image x along +x: the same picture with z mirrored (z -> -z).
CHECKER = """
#version 3.7;
global_settings {{ assumed_gamma 1.0 max_trace_level 5 }}
camera {{ perspective location <0, 0, 0> look_at <0, -0.35, 1> right x*{aspect} up y angle {hfov} }}
background {{ rgb 0.3 }}
plane {{ y, -1 pigment {{ checker rgb 0.02 rgb 1 translate <0, 0.5, 0> }} finish {{ ambient 1 diffuse 0 }} }}
"""

WHITTED = """
#version 3.7;
global_settings {{ assumed_gamma 1.0 max_trace_level 5 ambient_light 0 }}
camera {{ perspective location <0, 1.5, 0.5> look_at <0, 0.8, 6> right x*{aspect} up y angle {hfov} }}
background {{ rgb <0.25, 0.35, 0.6> }}
light_source {{ <-4, 8, 0> rgb 24 fade_distance 1 fade_power 2 }}
light_source {{ <5, 6, 3> rgb 9.5 fade_distance 1 fade_power 2 }}
plane {{ y, 0 pigment {{ checker rgb 0.9 rgb <0.05, 0.05, 0.3> translate <0, 0.5, 0> }}
        finish {{ ambient 0 diffuse 1 }} }}
sphere {{ <-1.2, 1.0, 6.0>, 1.0 pigment {{ rgb 0 }} finish {{ ambient 0 diffuse 0 reflection 1 }} }}
sphere {{ <1.3, 0.9, 4.5>, 0.9 pigment {{ rgbf 1 }} finish {{ ambient 0 diffuse 0 reflection {{ 0 1 fresnel on }} }}
        interior {{ ior 1.5 }} }}
"""


def render(pov, out_png, width, height, flags):
    cmd = ["povray", f"+I{pov}", f"+O{out_png}", f"+W{width}", f"+H{height}", "+FN16", "File_Gamma=1.0",
           "Display=off", "+WT1", "+AG1.0"] + flags
    start = time.perf_counter()
    done = subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - start
    trace = re.search(r"Trace Time:.*\(([0-9.]+) seconds\)", done.stderr)
    if not trace:
        raise RuntimeError("povray_aa: no Trace Time in POV-Ray's statistics:\n" + done.stderr[-2000:])
    return float(trace.group(1)), wall


def rmse(a, b):
    a = np.clip(a[..., :3].astype(np.float64), 0, 1)
    b = np.clip(b[..., :3].astype(np.float64), 0, 1)
    return float(np.sqrt(np.mean((a - b) ** 2)))


def main():
    args = sys.argv[1:]
    out = args[0]
    width = int(args[args.index("--width") + 1]) if "--width" in args else 160
    runs = int(args[args.index("--runs") + 1]) if "--runs" in args else 3
    images = args[args.index("--images") + 1] if "--images" in args else None
    height = width * 3 // 4
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for scene, template, vfov in (("checker", CHECKER, 50.0), ("whitted", WHITTED, 45.0)):
            aspect = width / height
            hfov = 2 * math.degrees(math.atan(math.tan(math.radians(vfov / 2)) * aspect))
            pov = os.path.join(tmp, scene + ".pov")
            with open(pov, "w") as f:
                f.write(template.format(aspect=aspect, hfov=hfov))
            ref_png = os.path.join(tmp, scene + "_ref.png")
            render(pov, ref_png, width, height, ["+A0.0", "+AM2", "+R5"])
            reference = mpimg.imread(ref_png)
            configs = [("none", "-A", 0, 0.0, [])]
            for method in (1, 2):
                for threshold in (0.3, 0.1, 0.03, 0.01):
                    configs.append((f"POV-Ray +AM{method}", f"+AM{method}", 3, threshold,
                                    [f"+A{threshold}", f"+AM{method}", "+R3"]))
            for series, method, depth, threshold, flags in configs:
                png = os.path.join(tmp, "out.png")
                times = [render(pov, png, width, height, flags if flags else ["-A"]) for _ in range(runs)]
                img = mpimg.imread(png)
                rows.append({"scene": scene, "series": series if series != "none" else "POV-Ray none",
                             "method": method, "max_depth": depth, "threshold": threshold,
                             "seconds_median": statistics.median(t for t, _ in times),
                             "wall_seconds_median": statistics.median(w for _, w in times), "rmse": rmse(img, reference),
                             "width": width, "height": height, "runs": runs})
            if images:
                import shutil
                shutil.copy(ref_png, os.path.join(images, f"povray_{scene}_reference.png"))
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
