"""Writes a triangle mesh (OBJ, or ASCII / binary PLY) as a POV-Ray mesh2 include file, placed the way
apps/bunny/scene.cpp places it: scaled so that its largest extent is 2, centred over the origin in x and z,
standing on y = 0. A mesh without normals gets the same area-weighted vertex normals as
rtlab::bunny::with_smooth_normals, so that both renderers interpolate the same shading normals.

The include declares PeerMesh (the mesh2), PeerMeshTop (its height after scaling, from which bunny.pov
places the camera as the app does) and PeerMeshTriangles.

    /usr/bin/python3 scripts/peer/mesh_to_pov.py ../shared/models/stanford-bunny.obj out/bunny_mesh.inc
"""
import struct
import sys
from pathlib import Path

import numpy as np


class MeshError(Exception):
    pass


def read_obj(path):
    positions, normals, faces, face_normals = [], [], [], []
    with open(path, encoding="utf-8", errors="replace") as f:
        for line_no, line in enumerate(f, 1):
            words = line.split()
            if not words:
                continue
            try:
                if words[0] == "v":
                    positions.append([float(w) for w in words[1:4]])
                elif words[0] == "vn":
                    normals.append([float(w) for w in words[1:4]])
                elif words[0] == "f":
                    refs = [w.split("/") for w in words[1:]]
                    if len(refs) < 3:
                        raise MeshError("a face needs 3 vertices")

                    def index(text, count):
                        i = int(text)
                        return i - 1 if i > 0 else count + i  # OBJ counts from 1; negative counts back

                    vs = [index(r[0], len(positions)) for r in refs]
                    ns = [index(r[2], len(normals)) if len(r) > 2 and r[2] else -1 for r in refs]
                    # Polygons become fans around their first corner, as rtlab's OBJ reader does.
                    for k in range(1, len(vs) - 1):
                        faces.append((vs[0], vs[k], vs[k + 1]))
                        face_normals.append((ns[0], ns[k], ns[k + 1]))
            except (ValueError, IndexError, MeshError) as e:
                raise MeshError(f"{path}:{line_no}: bad '{words[0]}' line: {e}") from None
    pos = np.array(positions, dtype=np.float64).reshape(-1, 3)
    tri = np.array(faces, dtype=np.int64).reshape(-1, 3)
    if tri.size and (tri.min() < 0 or tri.max() >= len(pos)):
        raise MeshError(f"{path}: a face names a vertex that does not exist")
    nrm = None
    if normals and all(min(fn) >= 0 for fn in face_normals):
        # rtlab keeps one normal per position; OBJ files that share v and vn indices map one to one.
        fn = np.array(face_normals, dtype=np.int64)
        if np.array_equal(fn, tri) and len(normals) == len(positions):
            nrm = np.array(normals, dtype=np.float64)
    return pos, tri, nrm


PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h", "ushort": "H",
             "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}


def read_ply(path):
    data = Path(path).read_bytes()
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise MeshError(f"{path}: not a PLY file (no 'ply' ... 'end_header')")
    header = data[:end].decode("ascii", "replace").splitlines()
    body = data[data.index(b"\n", end) + 1:]
    fmt, elements = None, []
    for line_no, line in enumerate(header, 1):
        w = line.split()
        if not w:
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w[0] == "property":
            if not elements:
                raise MeshError(f"{path}:{line_no}: property before any element")
            elements[-1][2].append(tuple(w[1:]))
    if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
        raise MeshError(f"{path}: unknown PLY format '{fmt}'")
    positions, faces = [], []
    if fmt == "ascii":
        tokens = body.split()
        at = 0
        for name, count, props in elements:
            for _ in range(count):
                row = {}
                for p in props:
                    if p[0] == "list":
                        n = int(tokens[at])
                        row[p[3]] = [int(t) for t in tokens[at + 1:at + 1 + n]]
                        at += 1 + n
                    else:
                        row[p[1]] = float(tokens[at])
                        at += 1
                keep(name, row, positions, faces)
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        at = 0
        for name, count, props in elements:
            for _ in range(count):
                row = {}
                for p in props:
                    if p[0] == "list":
                        (n,) = struct.unpack_from(order + PLY_TYPES[p[1]], body, at)
                        at += struct.calcsize(PLY_TYPES[p[1]])
                        code = order + str(n) + PLY_TYPES[p[2]]
                        row[p[3]] = list(struct.unpack_from(code, body, at))
                        at += struct.calcsize(code)
                    else:
                        (row[p[1]],) = struct.unpack_from(order + PLY_TYPES[p[0]], body, at)
                        at += struct.calcsize(PLY_TYPES[p[0]])
                keep(name, row, positions, faces)
    pos = np.array(positions, dtype=np.float64).reshape(-1, 3)
    tri = np.array(faces, dtype=np.int64).reshape(-1, 3)
    if tri.size and (tri.min() < 0 or tri.max() >= len(pos)):
        raise MeshError(f"{path}: a face names a vertex that does not exist")
    return pos, tri, None


def keep(name, row, positions, faces):
    if name == "vertex":
        positions.append([row["x"], row["y"], row["z"]])
    elif name == "face":
        vs = row.get("vertex_indices", row.get("vertex_index", []))
        for k in range(1, len(vs) - 1):
            faces.append((vs[0], vs[k], vs[k + 1]))


def smooth_normals(pos, tri):
    """Area-weighted vertex normals (the cross product's length is twice the area: the weight)."""
    # rtlab works in float: round the corners the same way before the cross products.
    p = pos.astype(np.float32).astype(np.float64)
    n = np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]])
    total = np.zeros_like(p)
    for k in range(3):
        np.add.at(total, tri[:, k], n)
    length = np.linalg.norm(total, axis=1)
    out = np.tile([0.0, 1.0, 0.0], (len(p), 1))  # a vertex no triangle uses: any unit normal
    good = length > 0
    out[good] = total[good] / length[good, None]
    return out


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    source, target = Path(argv[1]), Path(argv[2])
    try:
        suffix = source.suffix.lower()
        if suffix == ".obj":
            pos, tri, nrm = read_obj(source)
        elif suffix == ".ply":
            pos, tri, nrm = read_ply(source)
        else:
            raise MeshError(f"{source}: unknown mesh format '{suffix}' (known: .obj, .ply)")
    except OSError as e:
        print(f"mesh_to_pov: {e}", file=sys.stderr)
        return 1
    except MeshError as e:
        print(f"mesh_to_pov: {e}", file=sys.stderr)
        return 1
    if len(tri) == 0:
        print(f"mesh_to_pov: {source}: the mesh has no triangles", file=sys.stderr)
        return 1
    if nrm is None:
        nrm = smooth_normals(pos, tri)
    # The bounds of the corners of every triangle, degenerate ones included, as TriangleMesh::bounds.
    used = np.unique(tri)
    # Collinear corners have no plane; POV-Ray would drop them with a warning, rtlab's kd-tree skips them.
    p32 = pos.astype(np.float32).astype(np.float64)
    area2 = np.cross(p32[tri[:, 1]] - p32[tri[:, 0]], p32[tri[:, 2]] - p32[tri[:, 0]])
    tri = tri[np.any(area2 != 0.0, axis=1)]
    lo, hi = pos[used].min(axis=0), pos[used].max(axis=0)
    extent = hi - lo
    scale = 2.0 / extent.max()
    base = np.array([0.5 * (lo[0] + hi[0]), lo[1], 0.5 * (lo[2] + hi[2])])
    world = (pos - base) * scale

    target.parent.mkdir(parents=True, exist_ok=True)
    with open(target, "w") as out:
        out.write(f"// {source.name} converted by scripts/peer/mesh_to_pov.py: {len(tri)} triangles\n")
        out.write(f"#declare PeerMeshTop = {scale * extent[1]:.9g};\n")
        out.write(f"#declare PeerMeshTriangles = {len(tri)};\n")
        out.write("#declare PeerMesh = mesh2 {\n")
        out.write(f"  vertex_vectors {{ {len(world)},\n")
        out.write(",\n".join(f"<{x:.9g},{y:.9g},{z:.9g}>" for x, y, z in world))
        out.write("\n  }\n")
        out.write(f"  normal_vectors {{ {len(nrm)},\n")
        out.write(",\n".join(f"<{x:.9g},{y:.9g},{z:.9g}>" for x, y, z in nrm))
        out.write("\n  }\n")
        out.write(f"  face_indices {{ {len(tri)},\n")
        out.write(",\n".join(f"<{a},{b},{c}>" for a, b, c in tri))
        out.write("\n  }\n}\n")
    print(f"{target}: {len(tri)} triangles, {len(world)} vertices, height {scale * extent[1]:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
