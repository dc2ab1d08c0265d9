#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Hex mesh of an elastic cylinder (radius R, depth H) whose top face holds a circular punch footprint
of radius a with nodes on r = a exactly: an O-grid (a square core and four blended sectors inside r = a,
a geometrically graded annulus outside) extruded downwards with layers graded from the top. Written as
gmsh .msh 4.1 ASCII (mesh/gmsh_io.hpp reads it): volume block `block`; surfaces `punch` (the top quads
inside r = a: side set and node set), `top` (the whole top face), `bottom`, `side`.

  /usr/bin/python3 make_mesh.py --cells 8 --domain 10 -o punch_n8_L10.msh

--cells n: element edges across the punch radius (n/2 in the core, n/2 blended to the circle);
--domain L: R = H = L a. Lengths in m (a = 10 nm).
"""
import argparse
import math

import numpy as np

A = 10e-9  # punch radius, m


def graded(start, first, length, ratio):
    """Coordinates from `start` over `length`, first step `first`, growing by `ratio`, last one clipped."""
    out, x, step = [0.0], 0.0, first
    while x + step < length * (1 - 1e-9):
        x += step
        out.append(x)
        step *= ratio
    if length - out[-1] < 0.5 * step / ratio and len(out) > 1:
        out[-1] = length
    else:
        out.append(length)
    return [start + v for v in out]


def disk_quads(m, outer_radii):
    """Quads (4 points each, CCW seen from +z) of the O-grid disk and the annulus."""
    s = 0.5 * A
    quads = []
    # core square [-s, s]^2, 2m x 2m cells
    g = np.linspace(-s, s, 2 * m + 1)
    for i in range(2 * m):
        for j in range(2 * m):
            quads.append([(g[i], g[j]), (g[i + 1], g[j]), (g[i + 1], g[j + 1]), (g[i], g[j + 1])])
    # four sectors from the square's sides to the circle r = a, m radial cells each
    nd = m
    for side in range(4):
        c, sn = math.cos(side * math.pi / 2), math.sin(side * math.pi / 2)
        rot = lambda p: (c * p[0] - sn * p[1], sn * p[0] + c * p[1])
        pts = {}
        for i in range(2 * m + 1):
            t = -1 + i / m
            ps = (s, s * t)
            ang = t * math.pi / 4
            pc = (A * math.cos(ang), A * math.sin(ang))
            for k in range(nd + 1):
                w = k / nd
                pts[i, k] = rot(((1 - w) * ps[0] + w * pc[0], (1 - w) * ps[1] + w * pc[1]))
        for i in range(2 * m):
            for k in range(nd):
                quads.append([pts[i, k], pts[i, k + 1], pts[i + 1, k + 1], pts[i + 1, k]])
    # annulus r = a .. R on the circle's 8m angles
    na = 8 * m
    phi = [-math.pi / 4 + p * 2 * math.pi / na for p in range(na + 1)]
    for q in range(len(outer_radii) - 1):
        r0, r1 = outer_radii[q], outer_radii[q + 1]
        for p in range(na):
            quads.append([(r0 * math.cos(phi[p]), r0 * math.sin(phi[p])), (r1 * math.cos(phi[p]), r1 * math.sin(phi[p])),
                          (r1 * math.cos(phi[p + 1]), r1 * math.sin(phi[p + 1])),
                          (r0 * math.cos(phi[p + 1]), r0 * math.sin(phi[p + 1]))])
    fixed = []
    for qd in quads:  # counter-clockwise seen from +z
        area = sum(qd[k][0] * qd[(k + 1) % 4][1] - qd[(k + 1) % 4][0] * qd[k][1] for k in range(4))
        fixed.append(qd if area > 0 else qd[::-1])
    return fixed


def build(cells, domain):
    m = max(1, cells // 2)
    R = H = domain * A
    h = A / cells
    # annulus: first ring about the circle's arc length, growing by 1.2
    arc = 2 * math.pi * A / (8 * m)
    radii = graded(A, arc, R - A, 1.2)
    quads = disk_quads(m, radii)
    key = lambda p: (round(p[0] / A * 1e6), round(p[1] / A * 1e6))
    index, xy = {}, []
    q2 = []
    for qd in quads:
        ids = []
        for p in qd:
            k = key(p)
            if k not in index:
                index[k] = len(xy)
                xy.append(p)
            ids.append(index[k])
        q2.append(ids)
    xy = np.array(xy)
    z = [-v for v in graded(0.0, h, H, 1.15)]  # 0 down to -H
    n2 = len(xy)
    nodes = np.zeros((n2 * len(z), 3))
    for l, zl in enumerate(z):
        nodes[l * n2:(l + 1) * n2, :2] = xy
        nodes[l * n2:(l + 1) * n2, 2] = zl
    hexes = []
    for l in range(len(z) - 1):
        lo, up = (l + 1) * n2, l * n2  # z[l+1] < z[l]
        for ids in q2:
            hexes.append([lo + i for i in ids] + [up + i for i in ids])
    r_xy = np.hypot(xy[:, 0], xy[:, 1])
    top = [ids for ids in q2]
    punch = [ids for ids in q2 if max(r_xy[i] for i in ids) <= A * (1 + 1e-9)]
    top_out = [ids for ids in q2 if max(r_xy[i] for i in ids) > A * (1 + 1e-9)]
    bottom = [[(len(z) - 1) * n2 + i for i in ids[::-1]] for ids in q2]
    side = []
    outer = [i for i in range(n2) if abs(r_xy[i] - R) < 1e-6 * A]
    outer_set = set(outer)
    for ids in q2:
        edge = [i for i in ids if i in outer_set]
        if len(edge) == 2:
            k = [j for j in range(4) if ids[j] in outer_set]
            a, b = (ids[k[0]], ids[k[1]]) if (k[1] - k[0]) == 1 else (ids[k[1]], ids[k[0]])
            for l in range(len(z) - 1):
                lo, up = (l + 1) * n2, l * n2
                side.append([lo + a, lo + b, up + b, up + a])
    return nodes, hexes, {"punch": punch, "top_out": top_out, "bottom": bottom, "side": side}


def write_msh(path, nodes, hexes, surfaces):
    # physical tags: 1 block (3-D); 2 punch, 3 top, 4 bottom, 5 side (2-D)
    surf_entities = [("punch", [2, 3]), ("top_out", [3]), ("bottom", [4]), ("side", [5])]
    with open(path, "w") as f:
        f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n")
        f.write('$PhysicalNames\n5\n3 1 "block"\n2 2 "punch"\n2 3 "top"\n2 4 "bottom"\n2 5 "side"\n$EndPhysicalNames\n')
        lo, hi = nodes.min(axis=0), nodes.max(axis=0)
        box = " ".join(f"{v:.17g}" for v in (*lo, *hi))
        f.write("$Entities\n0 0 %d 1\n" % len(surf_entities))
        for k, (_, tags) in enumerate(surf_entities):
            f.write(f"{k + 1} {box} {len(tags)} {' '.join(map(str, tags))} 0\n")
        f.write(f"1 {box} 1 1 {len(surf_entities)} {' '.join(str(k + 1) for k in range(len(surf_entities)))}\n")
        f.write("$EndEntities\n")
        n = len(nodes)
        f.write(f"$Nodes\n1 {n} 1 {n}\n3 1 0 {n}\n")
        f.write("".join(f"{i + 1}\n" for i in range(n)))
        f.write("".join(f"{x:.17g} {y:.17g} {zz:.17g}\n" for x, y, zz in nodes))
        f.write("$EndNodes\n")
        total = len(hexes) + sum(len(surfaces[name]) for name, _ in surf_entities)
        f.write(f"$Elements\n{1 + len(surf_entities)} {total} 1 {total}\n")
        tag = 1
        f.write(f"3 1 5 {len(hexes)}\n")
        for hx in hexes:
            f.write(f"{tag} {' '.join(str(i + 1) for i in hx)}\n")
            tag += 1
        for k, (name, _) in enumerate(surf_entities):
            f.write(f"2 {k + 1} 3 {len(surfaces[name])}\n")
            for qd in surfaces[name]:
                f.write(f"{tag} {' '.join(str(i + 1) for i in qd)}\n")
                tag += 1
        f.write("$EndElements\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cells", type=int, default=8)
    ap.add_argument("--domain", type=float, default=10.0)
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    nodes, hexes, surfaces = build(a.cells, a.domain)
    write_msh(a.output, nodes, hexes, surfaces)
    print(f"{a.output}: {len(nodes)} nodes, {len(hexes)} hex8, punch {len(surfaces['punch'])} faces")


if __name__ == "__main__":
    main()
