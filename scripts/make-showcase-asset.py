#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a glTF binary of a panelled torus with every map a game asset has: base colour,
metallic-roughness (brass and painted panels), normal (grooves between panels, rivets), occlusion
(dark grooves) and emissive (a glowing band), 256² each. docs/material-view.png shows it in the
Material view (docs/user-guide.md, "Material channels").

Usage: scripts/make-showcase-asset.py OUT.glb"""
import math
import struct
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from glb_writer import Glb, png  # noqa: E402

SIZE = 256
PANELS_U, PANELS_V = 16, 6


def png_of(pixels):
    """An RGBA8 PNG of SIZE² from a list of rows of (r, g, b, a)."""
    return png(SIZE, SIZE, lambda x, y: pixels[y][x])


def panel_at(u, v):
    """The panel (i, j) at uv and the position inside it, 0..1 each way."""
    pu, pv = u * PANELS_U, v * PANELS_V
    return int(pu) % PANELS_U, int(pv) % PANELS_V, pu - math.floor(pu), pv - math.floor(pv)


def height(u, v):
    """Grooves between panels (0 in a groove, 1 on a panel) and rivets in the corners."""
    _, _, fu, fv = panel_at(u, v)
    edge = min(fu, 1 - fu) * 4.0, min(fv, 1 - fv) * 1.5
    h = min(1.0, min(edge) / 0.08)
    for cu in (0.1, 0.9):
        for cv in (0.18, 0.82):
            d = math.hypot((fu - cu) / 0.04, (fv - cv) / 0.1)
            if d < 1:
                h += 0.6 * math.sqrt(1 - d * d)
    return h


def maps():
    base, mr, normal, occlusion, emissive = ([] for _ in range(5))
    step = 1.0 / SIZE
    for y in range(SIZE):
        rows = ([] for _ in range(5))
        b_row, mr_row, n_row, o_row, e_row = rows
        v = (y + 0.5) * step
        for x in range(SIZE):
            u = (x + 0.5) * step
            i, j, fu, fv = panel_at(u, v)
            h = height(u, v)
            brass = (i + j) % 3 == 0
            groove = h < 0.5
            if groove:
                b_row.append((70, 72, 76, 255))
                mr_row.append((0, 230, 0, 255))
            elif brass:
                b_row.append((214, 170, 92, 255))
                mr_row.append((0, 90, 255, 255))
            else:
                b_row.append((46, 120, 138, 255) if j % 2 else (200, 70, 52, 255))
                mr_row.append((0, 150, 0, 255))
            du = (height(u + step, v) - height(u - step, v)) * 0.5
            dv = (height(u, v + step) - height(u, v - step)) * 0.5
            nx, ny, nz = -du * 3.0, dv * 3.0, 1.0
            length = math.sqrt(nx * nx + ny * ny + nz * nz)
            n_row.append(tuple(int(round((c / length * 0.5 + 0.5) * 255)) for c in (nx, ny, nz)) +
                         (255,))
            ao = int(255 * (0.35 + 0.65 * min(1.0, h)))
            o_row.append((ao, ao, ao, 255))
            glow = j == 2 and 0.35 < fv < 0.65 and 0.15 < fu < 0.85 and not brass
            e_row.append((255, 150, 40, 255) if glow else (0, 0, 0, 255))
        base.append(b_row)
        mr.append(mr_row)
        normal.append(n_row)
        occlusion.append(o_row)
        emissive.append(e_row)
    return [png_of(m) for m in (base, mr, normal, occlusion, emissive)]


def torus(segments_u=96, segments_v=48, major=1.0, minor=0.38):
    """Positions, normals, uvs (u around the ring, v around the tube) and indices."""
    pos, nrm, uv, idx = [], [], [], []
    for a in range(segments_u + 1):
        theta = 2 * math.pi * a / segments_u
        for b in range(segments_v + 1):
            phi = 2 * math.pi * b / segments_v
            n = (math.cos(theta) * math.cos(phi), math.sin(phi), math.sin(theta) * math.cos(phi))
            centre = (major * math.cos(theta), 0.0, major * math.sin(theta))
            pos += [centre[k] + minor * n[k] for k in range(3)]
            nrm += list(n)
            uv += [a / segments_u, b / segments_v]
    row = segments_v + 1
    for a in range(segments_u):
        for b in range(segments_v):
            p, q = a * row + b, (a + 1) * row + b
            idx += [p, p + 1, q, q, p + 1, q + 1]
    return pos, nrm, uv, idx


def main():
    out = Path(sys.argv[1])
    pos, nrm, uv, idx = torus()
    glb = Glb()
    add_view = glb.add_view

    count = len(pos) // 3
    accessors = [
        {"bufferView": add_view(struct.pack(f"<{len(pos)}f", *pos), 34962),
         "componentType": 5126, "count": count, "type": "VEC3",
         "min": [min(pos[k::3]) for k in range(3)], "max": [max(pos[k::3]) for k in range(3)]},
        {"bufferView": add_view(struct.pack(f"<{len(nrm)}f", *nrm), 34962),
         "componentType": 5126, "count": count, "type": "VEC3"},
        {"bufferView": add_view(struct.pack(f"<{len(uv)}f", *uv), 34962),
         "componentType": 5126, "count": count, "type": "VEC2"},
        {"bufferView": add_view(struct.pack(f"<{len(idx)}I", *idx), 34963),
         "componentType": 5125, "count": len(idx), "type": "SCALAR"},
    ]
    images = [{"bufferView": add_view(data), "mimeType": "image/png", "name": name}
              for data, name in zip(maps(), ("base colour", "metallic-roughness", "normal",
                                             "occlusion", "emissive"))]
    material = {
        "name": "panels",
        "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                 "metallicRoughnessTexture": {"index": 1}},
        "normalTexture": {"index": 2},
        "occlusionTexture": {"index": 3},
        "emissiveTexture": {"index": 4},
        "emissiveFactor": [1.0, 1.0, 1.0],
    }
    root = {
        "asset": {"version": "2.0", "generator": "make-showcase-asset.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "ring", "mesh": 0}],
        "meshes": [{"name": "ring", "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
            "indices": 3, "material": 0}]}],
        "materials": [material],
        "textures": [{"source": i} for i in range(5)],
        "images": images, "accessors": accessors,
    }
    glb.write(out, root)


if __name__ == "__main__":
    main()
