#!/usr/bin/env python3
"""Writes the Cornell box as OBJ files, one per material, into scenes/cornell_box/.

The polygons are Cornell's published measurements of the real box (Cornell University Program of Computer
Graphics, "Cornell Box Data", millimetres), converted to metres. Each quad is written as two triangles in its
published vertex order, which faces every surface into the box. The floor, the back wall and the left wall are
not parallelograms; the light is lowered 0.1 mm below the ceiling so the two never share a plane.

    /usr/bin/python3 scripts/cornell_box.py
"""
import pathlib

MM = 0.001
LIGHT_DROP = 0.1  # millimetres below the ceiling

FLOOR = [(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]
CEILING = [(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2), (0.0, 548.8, 0.0)]
BACK_WALL = [(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2), (556.0, 548.8, 559.2)]
RIGHT_WALL = [(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0), (0.0, 548.8, 559.2)]  # green
LEFT_WALL = [(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0.0)]  # red
LIGHT = [(343.0, 548.8 - LIGHT_DROP, 227.0), (343.0, 548.8 - LIGHT_DROP, 332.0),
         (213.0, 548.8 - LIGHT_DROP, 332.0), (213.0, 548.8 - LIGHT_DROP, 227.0)]

SHORT_BLOCK = [
    [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0), (290.0, 165.0, 114.0)],
    [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0), (240.0, 0.0, 272.0)],
    [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0), (290.0, 0.0, 114.0)],
    [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0), (130.0, 0.0, 65.0)],
    [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0), (82.0, 0.0, 225.0)],
]
TALL_BLOCK = [
    [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0), (472.0, 330.0, 406.0)],
    [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0), (472.0, 0.0, 406.0)],
    [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0), (314.0, 0.0, 456.0)],
    [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0), (265.0, 0.0, 296.0)],
    [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0), (423.0, 0.0, 247.0)],
]

FILES = {
    "white.obj": ("floor, ceiling and back wall", [FLOOR, CEILING, BACK_WALL]),
    "red.obj": ("left wall (seen from the camera)", [LEFT_WALL]),
    "green.obj": ("right wall (seen from the camera)", [RIGHT_WALL]),
    "light.obj": ("the light, facing down", [LIGHT]),
    "short_block.obj": ("the short block", SHORT_BLOCK),
    "tall_block.obj": ("the tall block", TALL_BLOCK),
}


def write(path, what, quads):
    lines = [f"# Cornell box: {what}. Cornell's published polygons (mm) in metres; written by scripts/cornell_box.py"]
    faces = []
    for quad in quads:
        base = len(lines)  # 1-based index of the quad's first vertex
        for x, y, z in quad:
            lines.append(f"v {x * MM:.4f} {y * MM:.5f} {z * MM:.4f}")
        faces.append(f"f {base} {base + 1} {base + 2}")
        faces.append(f"f {base} {base + 2} {base + 3}")
    path.write_text("\n".join(lines + faces) + "\n")


def main():
    out = pathlib.Path(__file__).resolve().parent.parent / "scenes" / "cornell_box"
    out.mkdir(parents=True, exist_ok=True)
    for name, (what, quads) in FILES.items():
        write(out / name, what, quads)


if __name__ == "__main__":
    main()
