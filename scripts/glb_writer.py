# SPDX-License-Identifier: GPL-3.0-or-later
"""A small binary glTF writer for the scripts that make test and showcase assets: PNG images,
buffer views in one BIN chunk, and the GLB container around a glTF JSON document."""
import json
import struct
import zlib


def png(width, height, pixel):
    """An RGBA8 PNG of width x height whose texel (x, y) is pixel(x, y), an (r, g, b, a) tuple."""
    rows = b"".join(
        b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


class Glb:
    """The BIN chunk and its buffer views, then the file around a glTF document."""

    def __init__(self):
        self.bin = bytearray()
        self.views = []

    def add_view(self, data, target=None):
        """Appends data (4-byte aligned) as a buffer view; its index."""
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.bin.extend(data)
        self.views.append(view)
        return len(self.views) - 1

    def write(self, out, root):
        """Writes root (its bufferViews and buffers set here) with the BIN chunk to out."""
        root["bufferViews"] = self.views
        root["buffers"] = [{"byteLength": len(self.bin)}]
        text = json.dumps(root, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        while len(self.bin) % 4:
            self.bin.append(0)
        glb = (struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(self.bin)) +
               struct.pack("<II", len(text), 0x4E4F534A) + text +
               struct.pack("<II", len(self.bin), 0x004E4942) + bytes(self.bin))
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_bytes(glb)
        print(f"{out}: {len(glb)} bytes")
