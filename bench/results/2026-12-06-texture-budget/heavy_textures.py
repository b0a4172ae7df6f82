#!/usr/bin/env python3
"""Writes a synthetic texture-heavy glTF: COUNT unit quads side by side along +X, each with its
own SIZE x SIZE RGB PNG (four flat quadrants under a one-pixel checker, tinted per image).

usage: heavy_textures.py OUT_DIR [COUNT=8] [SIZE=8192]
Standard library only (zlib, struct, base64)."""
import base64, json, os, struct, sys, zlib


def png(path, size, tint):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    quads = [(200, 60, 60), (60, 180, 70), (70, 90, 200), (190, 180, 60)]
    quads = [tuple(min(255, max(24, c + tint)) for c in q) for q in quads]
    half = size // 2

    def row(top, odd):
        out = bytearray(b"\0")  # filter: none
        for side in (0, 1):
            q = quads[side + (0 if top else 2)]
            hi = bytes(min(255, c + 24) for c in q)
            lo = bytes(c - 24 for c in q)
            pair = (hi + lo) if (odd ^ (side * half) % 2) else (lo + hi)
            out += pair * (half // 2)
        return bytes(out)

    z = zlib.compressobj(1)
    body = bytearray()
    for top in (True, False):
        rows = [row(top, 0), row(top, 1)]
        for y in range(half):
            body += z.compress(rows[y % 2])
    body += z.flush()
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", bytes(body)))
        f.write(chunk(b"IEND", b""))


def main():
    out = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    size = int(sys.argv[3]) if len(sys.argv) > 3 else 8192
    os.makedirs(out, exist_ok=True)
    binary, views, accessors, meshes, nodes, images, textures, materials = bytearray(), [], [], [], [], [], [], []

    def add(values, fmt, ctype, kind, count):
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data)})
        binary.extend(data + b"\0" * (-len(data) % 4))
        accessors.append({"bufferView": len(views) - 1, "componentType": ctype, "count": count, "type": kind})
        return len(accessors) - 1

    for i in range(count):
        x0, x1 = float(i), float(i + 1)
        pos = add([x0, 0, 0, x1, 0, 0, x1, 1, 0, x0, 1, 0], "f", 5126, "VEC3", 4)
        accessors[pos].update({"min": [x0, 0, 0], "max": [x1, 1, 0]})
        uv = add([0, 1, 1, 1, 1, 0, 0, 0], "f", 5126, "VEC2", 4)
        idx = add([0, 1, 2, 0, 2, 3], "H", 5123, "SCALAR", 6)
        name = "image-%d.png" % i
        png(os.path.join(out, name), size, (i * 17) % 48 - 24)
        images.append({"uri": name})
        textures.append({"source": i})
        materials.append({"pbrMetallicRoughness": {"baseColorTexture": {"index": i}}})
        meshes.append({"primitives": [{"attributes": {"POSITION": pos, "TEXCOORD_0": uv}, "indices": idx, "material": i}]})
        nodes.append({"mesh": i})
    uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(binary)).decode()
    gltf = {"asset": {"version": "2.0"}, "scenes": [{"nodes": list(range(count))}], "nodes": nodes,
            "meshes": meshes, "materials": materials, "textures": textures, "images": images,
            "accessors": accessors, "bufferViews": views, "buffers": [{"byteLength": len(binary), "uri": uri}]}
    with open(os.path.join(out, "model.gltf"), "w") as f:
        json.dump(gltf, f)


if __name__ == "__main__":
    main()
