#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes tests/data/material/materials.glb: two quads, each with its own glTF material that has
all five maps (base colour, metallic-roughness, normal, occlusion, emissive; ten different small
PNG images), factors, an emissive strength, alphaMode MASK on the second and doubleSided on the
first, and a KHR_texture_transform on the first material's normal map.
io_tests (tests/core/io/material_test.cpp) checks what the loader makes of it.

Usage: scripts/make-material-test-data.py [OUT.glb]"""
import struct
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from glb_writer import Glb, png  # noqa: E402


def images(seed):
    """The five maps of one material, each a different pattern and size."""
    s = seed
    return [
        png(8, 8, lambda x, y: (x * 30 + s, y * 30, 128 + s, 255)),                  # base colour
        png(8, 8, lambda x, y: (0, 40 + x * 20 + s, 200 - y * 20, 255)),             # G rough, B metal
        png(4, 4, lambda x, y: (128 + x * 10, 128 - y * 10, 255 - s, 255)),          # normal
        png(4, 8, lambda x, y: (200 - y * 15 - s, 200 - y * 15 - s, 200 - y * 15 - s, 255)),
        png(8, 4, lambda x, y: (x * 25 + s, 20 + s, y * 60, 255)),                   # emissive
    ]


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else (
        Path(__file__).resolve().parent.parent / "tests/data/material/materials.glb")
    glb = Glb()
    add_view = glb.add_view

    accessors, primitives = [], []
    for q in range(2):  # two quads side by side, one per material
        x0 = float(q) * 1.5
        pos = [x0, 0, 0, x0 + 1, 0, 0, x0 + 1, 1, 0, x0, 1, 0]
        nrm = [0, 0, 1] * 4
        uv = [0, 1, 1, 1, 1, 0, 0, 0]
        idx = [0, 1, 2, 0, 2, 3]
        base = len(accessors)
        accessors += [
            {"bufferView": add_view(struct.pack("<12f", *pos), 34962), "componentType": 5126,
             "count": 4, "type": "VEC3", "min": [x0, 0, 0], "max": [x0 + 1, 1, 0]},
            {"bufferView": add_view(struct.pack("<12f", *nrm), 34962), "componentType": 5126,
             "count": 4, "type": "VEC3"},
            {"bufferView": add_view(struct.pack("<8f", *uv), 34962), "componentType": 5126,
             "count": 4, "type": "VEC2"},
            {"bufferView": add_view(struct.pack("<6H", *idx), 34963), "componentType": 5123,
             "count": 6, "type": "SCALAR"},
        ]
        primitives.append({"attributes": {"POSITION": base, "NORMAL": base + 1,
                                          "TEXCOORD_0": base + 2},
                           "indices": base + 3, "material": q})

    gltf_images, textures = [], []
    for m, seed in enumerate((0, 40)):
        for k, data in enumerate(images(seed)):
            gltf_images.append({"bufferView": add_view(data), "mimeType": "image/png",
                                "name": f"material {m} map {k}"})
            textures.append({"source": len(gltf_images) - 1, "sampler": 0})

    def info(material, map_index, **more):
        return {"index": material * 5 + map_index, **more}

    materials = [
        {"name": "painted",
         "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1],
                                  "baseColorTexture": info(0, 0),
                                  "metallicFactor": 0.25, "roughnessFactor": 0.75,
                                  "metallicRoughnessTexture": info(0, 1)},
         "normalTexture": info(0, 2, scale=0.8, extensions={"KHR_texture_transform": {
             "offset": [0.5, 0.25], "scale": [2, 2]}}),
         "occlusionTexture": info(0, 3, strength=0.6),
         "emissiveTexture": info(0, 4), "emissiveFactor": [0.5, 0.25, 1.0],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2.5}},
         "doubleSided": True},
        {"name": "masked",
         "pbrMetallicRoughness": {"baseColorTexture": info(1, 0),
                                  "metallicFactor": 0.9, "roughnessFactor": 0.2,
                                  "metallicRoughnessTexture": info(1, 1)},
         "normalTexture": info(1, 2), "occlusionTexture": info(1, 3),
         "emissiveTexture": info(1, 4), "emissiveFactor": [1.0, 0.0, 0.0],
         "alphaMode": "MASK", "alphaCutoff": 0.3},
    ]
    root = {
        "asset": {"version": "2.0", "generator": "make-material-test-data.py"},
        "extensionsUsed": ["KHR_texture_transform", "KHR_materials_emissive_strength"],
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": primitives}],
        "materials": materials, "textures": textures, "images": gltf_images,
        "samplers": [{"magFilter": 9728, "minFilter": 9728}],
        "accessors": accessors,
    }
    glb.write(out, root)


if __name__ == "__main__":
    main()
