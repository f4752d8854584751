"""An rtlab scene lit by an environment map, rebuilt in Blender and rendered with Cycles: the peer of the
environment-map check in scripts/peer-cycles.sh --envmap (issue 22). Run headless with Blender's own Python:

    blender -b --factory-startup -P bench/peer/cycles/envmap.py -- SCENE.json -o OUT.exr
        [--size WxH] [--spp N] [--depth D] [--threads T] [--seed S] [--pfm OUT.pfm] [--data-dir DIR]
        [--variant none|rot90|rot180|rot270|mirror-lr|mirror-fb|upside-down] [--segments N] [--map-resolution N]

SCENE.json is bench/peer/cycles/envmap_sphere.json or a scene like it: a pinhole camera, lambert materials,
spheres, disks and OBJ meshes (as cornell_box.py translates them), and render.environment an equirectangular
"envmap" with "filename" and "rotation". The map is found next to the scene, in a --data-dir, or through
rtlab's manifest data/assets.tsv (envmaps/city.exr is blender-data's studio light). Spheres become UV spheres
of --segments x --segments/2 quads (default 256) whose custom normals are the exact radial ones; disks become
--segments-gons: both inscribed, so their outlines differ from rtlab's by under 1/10,000 of the radius.

The map's directions. rtlab (y up) reads a direction d at u = 0.5 + atan2(d.z, d.x) / 2 pi, v = acos(d.y) / pi
(row 0 up): the centre column faces +x, u = 0.25 faces -z, u = 0.75 faces +z. Cycles' Environment Texture
(z up) reads a direction b at u = 0.5 - atan2(b.y, b.x) / 2 pi, v up from the bottom row by the elevation: the
centre column faces +x, u = 0.25 faces +y, u = 0.75 faces -y. The scenes' y-up to z-up rotation (x, y, z) ->
(x, -z, y) takes rtlab's -z to Blender's +y and +z to -y, and up to up, so the two already agree texel for
texel: no turn and no mirror goes between them. rtlab's "rotation" R turns the map counter-clockwise seen from
above (right-handed about +y), which is right-handed about Blender's +z too; the Mapping node (type Point)
turns the looked-up direction, so it gets -R. scripts/peer/cycles_envmap.py checks all of this on the
renders: the background pixels of both must agree, and those of the deliberately wrong --variant maps (turned
by 90, 180, 270 degrees more, mirrored left-right or front-back as the camera sees them, upside down) must not.

Settings as cornell_box.py's (its docstring: no denoiser, clamps, adaptive sampling, box filter of width 1,
depth D as max_bounces D - 1...) and bilinear lookups as rtlab's. The world is importance-sampled on a map of
--map-resolution columns (Manual; default twice the image's width, as rtlab's distribution): Cycles builds it
from the shader's value at each cell's centre, so at the image's own resolution a cell next to the sun (whose
bilinear spread reaches half-way into it) is drawn as if it held sky alone, and the BSDF samples that land
there are fireflies (RMSE 34 times rtlab's at 16 spp on city.exr); at twice the resolution the value
of a cell is within a factor of about 2 of every point in it. rtlab weighs each of its 2w x 2h cells by the
largest texel its lookups blend. Prints "cycles: render phase S s (C CPU s)" as cornell_box.py does.
"""
import math
import os
import re
import sys

import bmesh
import bpy
import numpy as np
from mathutils import Matrix, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cornell_box as cb  # noqa: E402 (the race's shared translation: camera, materials, settings, timing)

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))

# Deliberately wrong maps, in rtlab's terms: (extra turn in degrees, scale of Blender's x, y, z in the lookup).
# The camera looks along rtlab's -z, so mirroring x swaps its left and right, mirroring z (Blender's y) puts
# what is behind the camera in front of it.
VARIANTS = {
    "none": (0.0, (1, 1, 1)),
    "rot90": (90.0, (1, 1, 1)),
    "rot180": (180.0, (1, 1, 1)),
    "rot270": (270.0, (1, 1, 1)),
    "mirror-lr": (0.0, (-1, 1, 1)),
    "mirror-fb": (0.0, (1, -1, 1)),
    "upside-down": (0.0, (1, 1, -1)),
}


def fail(message):
    print(f"envmap.py: {message}", file=sys.stderr)
    sys.exit(1)


def parse_args(argv):
    """cornell_box.py's options and --variant, --segments."""
    extra = {"variant": "none", "segments": 256, "map-resolution": 0}
    rest = []
    i = 0
    while i < len(argv):
        if argv[i] in ("--variant", "--segments", "--map-resolution"):
            if i + 1 >= len(argv):
                fail(f"{argv[i]} needs a value")
            extra[argv[i][2:]] = argv[i + 1]
            i += 2
        else:
            rest.append(argv[i])
            i += 1
    if extra["variant"] not in VARIANTS:
        fail(f"--variant must be one of {', '.join(VARIANTS)}, not '{extra['variant']}'")
    if not re.fullmatch(r"[1-9][0-9]*", str(extra["segments"])) or int(extra["segments"]) < 8:
        fail(f"--segments must be an integer of at least 8, not '{extra['segments']}'")
    if not re.fullmatch(r"[0-9]+", str(extra["map-resolution"])):
        fail(f"--map-resolution must be a whole number, not '{extra['map-resolution']}'")
    args = cb.parse_args(rest)
    args["map_resolution"] = int(extra["map-resolution"])
    args["variant"] = extra["variant"]
    args["segments"] = int(extra["segments"])
    return args


def find_data(name, scene_dir, data_dirs):
    """A data file by its logical name: next to the scene, in a --data-dir, else where rtlab's manifest says."""
    for folder in [scene_dir] + data_dirs:
        candidate = os.path.join(folder, name)
        if os.path.isfile(candidate):
            return candidate
    with open(os.path.join(ROOT, "data", "assets.tsv")) as f:
        for line in f:
            cols = line.rstrip("\n").split("\t")
            if len(cols) >= 3 and not line.startswith("#") and cols[0] == name and os.path.isfile(cols[2]):
                return cols[2]
    fail(f"'{name}' is not next to the scene, in a --data-dir or where data/assets.tsv puts it")


def link(name, mesh, material):
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)


def make_sphere(name, shape, material, segments):
    centre = cb.to_blender(shape.get("center", [0, 0, 0]))
    radius = float(shape.get("radius", 1.0))
    bm = bmesh.new()
    bmesh.ops.create_uvsphere(bm, u_segments=segments, v_segments=max(4, segments // 2), radius=radius)
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    # Radial normals, exact at the vertices: smooth shading then differs from rtlab's true sphere by the
    # interpolation across a quad only.
    co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3).astype(np.float64)
    normals = co / np.linalg.norm(co, axis=1)[:, None]
    mesh.vertices.foreach_set("co", (co + centre).astype(np.float32).ravel())
    mesh.polygons.foreach_set("use_smooth", np.ones(len(mesh.polygons), dtype=bool))
    mesh.use_auto_smooth = True
    mesh.normals_split_custom_set_from_vertices([tuple(n) for n in normals])
    mesh.update()
    link(name, mesh, material)


def make_disk(name, shape, material, segments):
    if shape.get("inner_radius", 0):
        fail(f"shape '{name}': an annulus (inner_radius) is not translated")
    centre = Vector(cb.to_blender(shape.get("center", [0, 0, 0])))
    normal = Vector(cb.to_blender(shape.get("normal", [0, 1, 0]))).normalized()
    bm = bmesh.new()
    bmesh.ops.create_circle(bm, cap_ends=True, cap_tris=False, segments=segments,
                            radius=float(shape.get("radius", 1.0)))
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    # bmesh's circle lies in z = 0 facing +z: turned to face the disk's normal.
    mesh.transform(Matrix.Translation(centre) @ Vector((0, 0, 1)).rotation_difference(normal).to_matrix().to_4x4())
    mesh.update()
    link(name, mesh, material)


def make_world(env, scene_dir, data_dirs, variant, resolution):
    allowed = {"type", "filename", "rotation"}
    if env.get("type") != "envmap" or "filename" not in env or set(env) - allowed:
        fail(f"only an equirectangular envmap with {sorted(allowed)} is translated, not {env}")
    path = find_data(env["filename"], scene_dir, data_dirs)
    extra_turn, scale = VARIANTS[variant]
    turn = float(env.get("rotation", 0.0)) + extra_turn

    world = bpy.data.worlds.new("envmap")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    coords = nodes.new("ShaderNodeTexCoord")  # Generated: the direction, in the world shader
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "POINT"
    mapping.inputs["Scale"].default_value = scale
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, -math.radians(turn))
    tex = nodes.new("ShaderNodeTexEnvironment")
    tex.image = bpy.data.images.load(path, check_existing=True)
    tex.image.colorspace_settings.name = "Linear"  # the EXR's values, as rtlab reads them
    tex.projection = "EQUIRECTANGULAR"
    tex.interpolation = "Linear"  # bilinear, as rtlab's lookup
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Strength"].default_value = 1.0
    out = nodes.new("ShaderNodeOutputWorld")
    links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], tex.inputs["Vector"])
    links.new(tex.outputs["Color"], background.inputs["Color"])
    links.new(background.outputs["Background"], out.inputs["Surface"])
    world.cycles.sampling_method = "MANUAL"
    world.cycles.sample_map_resolution = resolution or 2 * tex.image.size[0]
    bpy.context.scene.world = world
    return path, tex.image.size[:]


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse_args(argv)
    data = cb.read_scene(args["scene"])
    render = data.get("render", {})
    width, height = args["size"] or (render.get("width", 256), render.get("height", 256))
    spp = args["spp"] or render.get("spp", 1)
    depth = args["depth"] if args["depth"] is not None else render.get("max_depth", 8)
    bounces = args["cycles_bounces"] if args["cycles_bounces"] is not None else max(0, depth - 1)
    if render.get("convention", "physical") != "physical":
        fail("only the physical convention is translated")
    if data.get("lights") or data.get("textures") or "environment" not in render:
        fail("only scenes lit by render.environment alone are translated (no lights, no textures)")

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene_dir = os.path.dirname(os.path.abspath(args["scene"]))
    materials = {m["name"]: cb.make_material(m) for m in data.get("materials", [])}
    for i, shape in enumerate(data.get("shapes", [])):
        name = shape.get("name", f"shape{i}")
        if shape.get("material") not in materials:
            fail(f"shape '{name}': material '{shape.get('material')}' is not a named material of the scene")
        kind = shape.get("type")
        allowed = {"name", "type", "material", "center", "radius", "normal", "inner_radius"}
        if kind in ("sphere", "disk") and set(shape) - allowed:
            fail(f"shape '{name}': keys {sorted(set(shape) - allowed)} are not translated")
        if kind == "sphere":
            make_sphere(name, shape, materials[shape["material"]], args["segments"])
        elif kind == "disk":
            make_disk(name, shape, materials[shape["material"]], args["segments"])
        else:
            cb.make_mesh(name, shape, scene_dir, args["data_dirs"], materials[shape["material"]])
    cb.make_camera(data["camera"], width, height)
    path, size = make_world(render["environment"], scene_dir, args["data_dirs"], args["variant"],
                            args["map_resolution"])

    cb.configure_cycles(scene, width, height, spp, bounces, args["threads"], args["seed"], args["output"])
    print(f"cycles: {os.path.basename(args['scene'])} {width}x{height}, map {path} {size[0]}x{size[1]}, "
          f"importance map {scene.world.cycles.sample_map_resolution}, variant {args['variant']}, spp {spp}, "
          f"depth {depth} (max_bounces {bounces}), {args['threads']} threads, seed {args['seed']}")
    sys.stdout.flush()
    cb.render_timed(args["output"], args["pfm"], width, height)


if __name__ == "__main__":
    main()
