"""An rtlab Cornell-box scene file rebuilt in Blender and rendered with Cycles: the peer of the race in
scripts/peer-cycles.sh (issue 21). Run headless with Blender's own Python:

    blender -b --factory-startup -P bench/peer/cycles/cornell_box.py -- SCENE.json -o OUT.exr
        [--size WxH] [--spp N] [--depth D] [--threads T] [--seed S] [--pfm OUT.pfm] [--data-dir DIR]

SCENE.json is one of rtlab's Cornell-box scenes (scenes/cornell_box.json, cornell_box_glossy.json,
cornell_box_bunny.json): the script reads its camera, materials and meshes, so both renderers see the same
triangles from the same OBJ files. It knows only what those scenes use and says so for anything else:
- mesh shapes from OBJ files (v and f lines; polygons fanned from their first corner, as rtlab's reader does),
  with rtlab's "fit" (largest extent scaled to fit, centred over the origin, standing on y = 0), "transform"
  (scale, rotation about x then y then z in degrees, translation) and "smooth_normals" (area-weighted vertex
  normals, given to Blender as custom normals so that both shade with the same ones);
- lambert (Diffuse BSDF, roughness 0: pure Lambert) with "emission": an Emission closure of that colour and
  strength 1 (the colour is the radiance) on front faces only: Cycles emits from both sides, so the
  Geometry node's Backfacing output switches the back to the surface without emission;
- cook-torrance with no diffuse part and a conductor whose Fresnel reflectance is 1 at every angle (eta 1,
  k >= 50): Glossy BSDF (GGX or Beckmann, no Fresnel) of colour ks. Both renderers square the roughness
  (alpha = roughness^2) and mask with the separable Smith G1(wo) G1(wi);
- rough-dielectric: Glass BSDF (GGX or Beckmann) of the same roughness and index. Cycles 3.4 splits its glass
  into a reflection and a refraction lobe weighted by the Fresnel term of the shading normal, where Walter's
  model (rtlab's) takes Fresnel per microfacet: the two differ slightly at this roughness.
rtlab y-up becomes Blender z-up by the rotation (x, y, z) -> (x, -z, y), which keeps handedness (the red wall
stays on the left). rtlab's "fov" is the vertical angle, so the camera's sensor fits vertically.

Depth: rtlab counts bounces as pbrt does (1 = direct light only); a Cycles bounce is one more scattering
after the first hit (max_bounces 0 = direct light only), so Cycles gets depth - 1 in every bounce limit
(--cycles-bounces overrides it, to check the convention). Settings for a like-for-like race: no denoiser,
no adaptive sampling, no clamps, filter glossy 0, light threshold 0, no path guiding, box filter of width 1,
Standard view, black world not sampled as a light, float EXR, fixed thread count and seed; Cycles keeps its
default sampling pattern and Russian roulette.

Prints "cycles: render phase S s (C CPU s)" measured around bpy.ops.render.render (scene sync, BVH build,
rendering and writing the EXR; C: the processor seconds of every thread), and with --pfm also writes the EXR's pixels as a little-endian PFM (outside the timed
phase) for readers without an EXR library.
"""
import json
import math
import os
import re
import sys
import time

import bpy
import numpy as np
from mathutils import Matrix, Vector


def fail(message):
    print(f"cornell_box.py: {message}", file=sys.stderr)
    sys.exit(1)


def parse_args(argv):
    args = {"size": None, "spp": None, "depth": None, "threads": 1, "seed": 0, "output": None, "pfm": None,
            "data_dirs": [], "cycles_bounces": None, "scene": None}
    i = 0
    while i < len(argv):
        a = argv[i]
        value = argv[i + 1] if i + 1 < len(argv) else None
        if a in ("-o", "--size", "--spp", "--depth", "--threads", "--seed", "--pfm", "--data-dir",
                 "--cycles-bounces"):
            if value is None:
                fail(f"{a} needs a value")
            i += 1
            if a == "-o":
                args["output"] = value
            elif a == "--size":
                m = re.fullmatch(r"([1-9][0-9]*)x([1-9][0-9]*)", value)
                if not m:
                    fail(f"--size must be WxH, not '{value}'")
                args["size"] = (int(m.group(1)), int(m.group(2)))
            elif a == "--pfm":
                args["pfm"] = value
            elif a == "--data-dir":
                args["data_dirs"].append(value)
            else:
                try:
                    args[a[2:].replace("-", "_")] = int(value)
                except ValueError:
                    fail(f"{a} must be an integer, not '{value}'")
        elif a.startswith("-"):
            fail(f"unknown option '{a}' (see the docstring)")
        elif args["scene"] is None:
            args["scene"] = a
        else:
            fail(f"more than one scene file: '{args['scene']}' and '{a}'")
        i += 1
    if args["scene"] is None or args["output"] is None:
        fail("usage: blender -b --factory-startup -P cornell_box.py -- SCENE.json -o OUT.exr [options]")
    return args


def read_scene(path):
    # rtlab's scene files allow // comments outside strings; none of these scenes has "//" inside a string.
    text = "\n".join(re.sub(r"^\s*//.*$", "", line) for line in open(path).read().splitlines())
    return json.loads(text)


def find_file(name, scene_dir, data_dirs):
    for folder in [scene_dir] + data_dirs:
        candidate = os.path.join(folder, name)
        if os.path.isfile(candidate):
            return candidate
    fail(f"'{name}' is neither next to the scene nor in a --data-dir ({', '.join(data_dirs) or 'none given'})")


def read_obj(path):
    """Positions and triangles (0-based) of an OBJ's v and f lines; polygons fanned from the first corner."""
    positions, triangles = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                positions.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                corners = []
                for token in parts[1:]:
                    k = int(token.split("/")[0])
                    corners.append(k - 1 if k > 0 else len(positions) + k)
                for j in range(1, len(corners) - 1):
                    triangles.append([corners[0], corners[j], corners[j + 1]])
    return np.array(positions, dtype=np.float64), np.array(triangles, dtype=np.int64)


def scene_transform(t):
    """rtlab's transform object: scale, then rotation about x, y, z (degrees), then translation."""
    if "matrix" in t:
        m = np.array(t["matrix"], dtype=np.float64).reshape(4, 4)
        return m
    s = t.get("scale", 1.0)
    s = np.array([s, s, s] if isinstance(s, (int, float)) else s, dtype=np.float64)
    rx, ry, rz = (math.radians(a) for a in t.get("rotate", [0, 0, 0]))
    cx, sx, cy, sy, cz, sz = math.cos(rx), math.sin(rx), math.cos(ry), math.sin(ry), math.cos(rz), math.sin(rz)
    mx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    my = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    mz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    m = np.eye(4)
    m[:3, :3] = mz @ my @ mx @ np.diag(s)
    m[:3, 3] = t.get("translate", [0, 0, 0])
    return m


def shape_matrix(shape, positions, triangles):
    m = np.eye(4)
    if "fit" in shape:
        used = positions[np.unique(triangles)]
        lo, hi = used.min(axis=0), used.max(axis=0)
        scale = float(shape["fit"]) / float((hi - lo).max())
        base = np.array([0.5 * (lo[0] + hi[0]), lo[1], 0.5 * (lo[2] + hi[2])])
        m[:3, :3] *= scale
        m[:3, 3] = -scale * base
    transforms = shape.get("transform", [])
    for t in transforms if isinstance(transforms, list) else [transforms]:
        m = scene_transform(t) @ m
    return m


# rtlab's y-up world to Blender's z-up one: +90 degrees about x.
Y_UP_TO_Z_UP = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], dtype=np.float64)


def to_blender(p):
    return Y_UP_TO_Z_UP @ np.asarray(p, dtype=np.float64)


def make_mesh(name, shape, scene_dir, data_dirs, material):
    allowed = {"name", "type", "filename", "material", "fit", "transform", "smooth_normals"}
    if shape.get("type") != "mesh" or set(shape) - allowed:
        fail(f"shape '{name}': only meshes with {sorted(allowed)} are translated, not {json.dumps(shape)}")
    path = find_file(shape["filename"], scene_dir, data_dirs)
    positions, triangles = read_obj(path)
    m = shape_matrix(shape, positions, triangles)
    world = positions @ m[:3, :3].T + m[:3, 3]
    verts = world @ Y_UP_TO_Z_UP.T
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(verts))
    mesh.vertices.foreach_set("co", verts.astype(np.float32).ravel())
    mesh.loops.add(3 * len(triangles))
    mesh.loops.foreach_set("vertex_index", triangles.astype(np.int32).ravel())
    mesh.polygons.add(len(triangles))
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * len(triangles), 3, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(triangles), 3, dtype=np.int32))
    mesh.update()
    smooth = bool(shape.get("smooth_normals", False))
    if smooth:
        # Area-weighted vertex normals as rtlab computes them (the transform is a rotation and a uniform
        # scale, so taking them after it only rotates them).
        a, b, c = verts[triangles[:, 0]], verts[triangles[:, 1]], verts[triangles[:, 2]]
        n = np.cross(b - a, c - a)
        sums = np.zeros_like(verts)
        for k in range(3):
            np.add.at(sums, triangles[:, k], n)
        length = np.linalg.norm(sums, axis=1)
        normals = np.where(length[:, None] > 0, sums / np.maximum(length, 1e-300)[:, None], [0.0, 0.0, 1.0])
        mesh.polygons.foreach_set("use_smooth", np.ones(len(triangles), dtype=bool))
        mesh.use_auto_smooth = True
        mesh.normals_split_custom_set_from_vertices([tuple(v) for v in normals])
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return len(triangles)


def colour(value):
    if isinstance(value, (int, float)):
        return (float(value),) * 3 + (1.0,)
    if isinstance(value, list) and len(value) == 3:
        return tuple(float(x) for x in value) + (1.0,)
    fail(f"a colour must be a number or [r, g, b] (textures are not translated), not {json.dumps(value)}")


def distribution(m):
    d = m.get("distribution", "ggx")
    if d not in ("ggx", "beckmann"):
        fail(f"material '{m['name']}': unknown distribution '{d}'")
    return d.upper()


def make_material(m):
    kind = m.get("type")
    mat = bpy.data.materials.new(m["name"])
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")

    def check_keys(allowed):
        extra = set(m) - allowed - {"name", "type"}
        if extra:
            fail(f"material '{m['name']}' ({kind}): keys {sorted(extra)} are not translated")

    if kind == "lambert":
        check_keys({"albedo", "emission"})
        albedo = colour(m.get("albedo", 0.5))
        surface = None
        if any(albedo[:3]):
            surface = nodes.new("ShaderNodeBsdfDiffuse")
            surface.inputs["Color"].default_value = albedo
            surface.inputs["Roughness"].default_value = 0.0  # pure Lambert, not Oren-Nayar
        if "emission" in m:
            emit = nodes.new("ShaderNodeEmission")
            emit.inputs["Color"].default_value = colour(m["emission"])
            emit.inputs["Strength"].default_value = 1.0
            front = emit.outputs[0]
            if surface is not None:
                add = nodes.new("ShaderNodeAddShader")
                links.new(surface.outputs[0], add.inputs[0])
                links.new(emit.outputs[0], add.inputs[1])
                front = add.outputs[0]
            # One-sided: the back face is the surface alone (nothing at all for a black fixture, which
            # absorbs like rtlab's albedo 0).
            geometry = nodes.new("ShaderNodeNewGeometry")
            mix = nodes.new("ShaderNodeMixShader")
            links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
            links.new(front, mix.inputs[1])
            if surface is not None:
                links.new(surface.outputs[0], mix.inputs[2])
            links.new(mix.outputs[0], out.inputs["Surface"])
        elif surface is not None:
            links.new(surface.outputs[0], out.inputs["Surface"])
    elif kind == "cook-torrance":
        check_keys({"kd", "ks", "roughness", "distribution", "eta", "k"})
        kd = colour(m.get("kd", 0))
        eta, k = m.get("eta"), m.get("k")
        eta = [eta] * 3 if isinstance(eta, (int, float)) else eta
        k = [k] * 3 if isinstance(k, (int, float)) else k
        if any(kd[:3]) or eta is None or k is None or any(abs(e - 1) > 1e-6 for e in eta) or min(k) < 50:
            fail(f"material '{m['name']}': only cook-torrance with kd 0 and a constant F0 (eta 1, k >= 50) is "
                 "translated (Cycles' Glossy BSDF has no Fresnel)")
        glossy = nodes.new("ShaderNodeBsdfGlossy")
        glossy.distribution = distribution(m)
        glossy.inputs["Color"].default_value = colour(m.get("ks", 1))
        glossy.inputs["Roughness"].default_value = float(m.get("roughness", 0.3))
        links.new(glossy.outputs[0], out.inputs["Surface"])
    elif kind == "rough-dielectric":
        check_keys({"ior", "roughness", "distribution"})
        glass = nodes.new("ShaderNodeBsdfGlass")
        glass.distribution = distribution(m)
        glass.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        glass.inputs["Roughness"].default_value = float(m.get("roughness", 0.2))
        glass.inputs["IOR"].default_value = float(m.get("ior", 1.5))
        links.new(glass.outputs[0], out.inputs["Surface"])
    else:
        fail(f"material '{m['name']}': type '{kind}' is not translated")
    return mat


def make_camera(c, width, height):
    if c.get("type", "perspective") != "perspective" or c.get("aperture", 0):
        fail("only a pinhole perspective camera is translated")
    position = to_blender(c.get("position", [0, 0, 0]))
    forward = to_blender(c["look_at"]) - position
    forward /= np.linalg.norm(forward)
    up = to_blender(c.get("up", [0, 1, 0]))
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    # A Blender camera looks down its local -z with +y up and +x to the right.
    basis = Matrix([list(right), list(true_up), list(-forward)]).transposed()
    cam = bpy.data.cameras.new("camera")
    cam.sensor_fit = "VERTICAL"  # rtlab's fov is the vertical angle
    cam.angle_y = math.radians(float(c.get("fov", 45.0)))
    cam.clip_start = 1e-4
    cam.clip_end = 1e4
    obj = bpy.data.objects.new("camera", cam)
    obj.matrix_world = Matrix.Translation(Vector(position)) @ basis.to_4x4()
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj


def write_pfm_from_exr(exr, pfm, width, height):
    image = bpy.data.images.load(os.path.abspath(exr))
    image.colorspace_settings.name = "Non-Color"  # the raw linear values
    pixels = np.empty(width * height * 4, dtype=np.float32)
    image.pixels.foreach_get(pixels)
    rgb = pixels.reshape(height, width, 4)[:, :, :3]  # rows bottom to top, as PFM stores them
    with open(pfm, "wb") as f:
        f.write(f"PF\n{width} {height}\n-1.0\n".encode())
        f.write(np.ascontiguousarray(rgb, dtype="<f4").tobytes())


def configure_cycles(scene, width, height, spp, bounces, threads, seed, output):
    """The like-for-like settings of the race (the module's docstring) and a float EXR at `output`."""
    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1.0
    r.threads_mode = "FIXED"
    r.threads = threads
    r.use_compositing = False
    r.use_sequencer = False
    r.film_transparent = False
    r.use_persistent_data = False
    c = scene.cycles
    c.device = "CPU"
    c.feature_set = "SUPPORTED"
    c.samples = spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.time_limit = 0
    c.seed = seed
    c.use_animated_seed = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0  # "Filter Glossy"
    c.light_sampling_threshold = 0.0
    c.use_guiding = False
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = bounces
    c.volume_bounces = c.transparent_max_bounces = bounces
    c.min_light_bounces = 0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.film_exposure = 1.0
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = r.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.color_mode = "RGB"
    settings.exr_codec = "NONE"
    r.filepath = os.path.abspath(output)
    r.use_file_extension = False


def render_timed(output, pfm, width, height):
    """bpy.ops.render.render timed (the "render phase" line the race reads), then the PFM copy if asked."""
    t0, c0 = time.perf_counter(), time.process_time()
    bpy.ops.render.render(write_still=True)
    seconds, cpu = time.perf_counter() - t0, time.process_time() - c0
    print(f"cycles: render phase {seconds:.3f} s ({cpu:.3f} CPU s)")
    if not os.path.isfile(output):
        fail(f"Cycles wrote no {output}")
    if pfm:
        write_pfm_from_exr(output, pfm, width, height)
    sys.stdout.flush()


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse_args(argv)
    data = read_scene(args["scene"])
    render = data.get("render", {})
    width, height = args["size"] or (render.get("width", 256), render.get("height", 256))
    spp = args["spp"] or render.get("spp", 1)
    depth = args["depth"] if args["depth"] is not None else render.get("max_depth", 8)
    bounces = args["cycles_bounces"] if args["cycles_bounces"] is not None else max(0, depth - 1)
    if render.get("convention", "physical") != "physical" or render.get("background", 0) not in (0, [0, 0, 0]):
        fail("only the physical convention on a black background is translated")
    if data.get("lights") or data.get("textures") or data.get("environment"):
        fail("only emitting meshes light these scenes; lights, textures and environments are not translated")

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene_dir = os.path.dirname(os.path.abspath(args["scene"]))
    materials = {m["name"]: make_material(m) for m in data.get("materials", [])}
    triangles = 0
    for i, shape in enumerate(data.get("shapes", [])):
        name = shape.get("name", f"shape{i}")
        if shape.get("material") not in materials:
            fail(f"shape '{name}': material '{shape.get('material')}' is not a named material of the scene")
        triangles += make_mesh(name, shape, scene_dir, args["data_dirs"], materials[shape["material"]])
    make_camera(data["camera"], width, height)

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0, 0, 0, 1)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    world.cycles.sampling_method = "NONE"
    scene.world = world

    configure_cycles(scene, width, height, spp, bounces, args["threads"], args["seed"], args["output"])
    c = scene.cycles

    print(f"cycles: {os.path.basename(args['scene'])} {width}x{height}, {triangles} triangles, spp {spp}, "
          f"depth {depth} (max_bounces {bounces}), {args['threads']} threads, seed {args['seed']}, "
          f"pattern {c.sampling_pattern}")
    sys.stdout.flush()
    render_timed(args["output"], args["pfm"], width, height)
    sys.stdout.flush()


if __name__ == "__main__":  # envmap.py imports the helpers
    main()
