#!/usr/bin/env python3
"""Writes crown.obj, the closed mesh of examples/colonize/mesh_crown.json: a lobed, cloud-like
tree crown around the origin (about 2 units wide, radius ~1), made by displacing the vertices
of a subdivided icosahedron along their directions. Every vertex moves radially, so the surface
stays closed, free of self-intersections and wound counter-clockwise seen from outside.

Usage: python3 make_crown_mesh.py [OUT.obj]   (default: crown.obj next to this script)
"""
import math
import os
import sys

LEVELS = 3  # 20 * 4^3 = 1280 triangles


def icosphere(levels):
    t = (1 + math.sqrt(5)) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
            (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
            (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    norm = lambda v: tuple(c / math.sqrt(sum(x * x for x in v)) for c in v)
    verts = [norm(v) for v in verts]
    for _ in range(levels):
        mid = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                verts.append(norm(tuple((p + q) / 2 for p, q in zip(verts[a], verts[b]))))
                mid[key] = len(verts) - 1
            return mid[key]

        finer = []
        for a, b, c in tris:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        tris = finer
    return verts, tris


def lobe_centres():
    """One lobe on top, five around it tilted 25 degrees up, three smaller ones lower down."""
    centres = [((0.0, 1.0, 0.0), 0.30)]
    for k in range(5):
        a, e = math.radians(72 * k + 10), math.radians(25)
        centres.append(((math.cos(e) * math.cos(a), math.sin(e), math.cos(e) * math.sin(a)), 0.34))
    for k in range(3):
        a, e = math.radians(120 * k + 50), math.radians(-15)
        centres.append(((math.cos(e) * math.cos(a), math.sin(e), math.cos(e) * math.sin(a)), 0.22))
    return centres


def radius(d):
    r = 0.72
    for c, amplitude in lobe_centres():
        dot = sum(p * q for p, q in zip(d, c))
        r += amplitude * math.exp(-(1 - dot) / 0.09)  # a bump of about 25 degrees
    if d[1] < -0.35:  # a flatter underside
        r *= 1 - 0.45 * (-0.35 - d[1]) / 0.65
    return r


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "crown.obj")
    verts, tris = icosphere(LEVELS)
    with open(out, "w") as f:
        f.write("# Lobed tree crown for examples/colonize/mesh_crown.json (make_crown_mesh.py)\n")
        f.write(f"# {len(verts)} vertices, {len(tris)} triangles; closed, counter-clockwise\n")
        for d in verts:
            r = radius(d)
            f.write(f"v {r * d[0]:.6f} {0.9 * r * d[1]:.6f} {r * d[2]:.6f}\n")
        for a, b, c in tris:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")


if __name__ == "__main__":
    main()
