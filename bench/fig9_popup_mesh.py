#!/usr/bin/env python3
"""The two-layer pop-up of Lestringant & Kochmann's Figs. 9-10 as a Gmsh
line mesh (format 2.2) for the "gmsh network" generator.

Layer 1 (physical line 1, "layer1"): a cross of four arms of length L = 1
from its centre "centre" to the bonding sites c1..c4 on the +-x and +-y axes.
Layer 2 ("layer2"): a six-branch star, a hexagonal ring of circumradius L / 2
whose corners r1..r6 (the junctions between the branches) sit at the angles
15 + 60 k degrees, each with a radial leg of length L / 2 to its bonding site
s1..s6 at radius L (turned by 15 degrees so that no leg lies over an arm).

Every beam has SEGMENTS line elements. A bonding site is clamped at the
midpoint of its beam's end segment (doc/morphing.md, "How it is lowered"), so
a leg's or arm's end node lies half a segment beyond its site: the arm's free
length is then exactly L at every resolution.

The network is bonded slightly popped up (the bridge's device,
scenes/substrate_bridge.prm): the centre and the ring at height BUMP, each arm
and leg rising as BUMP (1 - cos(pi t)) / 2 between its first and last segment,
which stay level (so the junctions' and clamps' angles are those of the flat
design); the scene makes the rods straight when stress free. A flat
inextensible network cannot start: the length constraints of the straight
beams between held sites are dependent and the tangent is singular.

Usage: fig9_popup_mesh.py SEGMENTS [BUMP (0.01)] > popup.msh
"""
import math
import sys


def beam_points(start, end, z_start, z_end, segments, site_at_start):
    """Vertices of one beam from start to end (x, y); where site_at_start,
    the start is the bonding site and the chain begins half a segment
    beyond it."""
    (x0, y0), (x1, y1) = start, end
    length = math.hypot(x1 - x0, y1 - y0)
    h = length / (segments - 0.5) if site_at_start else length / segments
    shift = h / 2 if site_at_start else 0.0
    ux, uy = (x1 - x0) / length, (y1 - y0) / length
    points = []
    for k in range(segments + 1):
        s = -shift + k * h
        # the rise between the first and the last segment, level outside
        t = min(max((k - 1) / (segments - 2), 0.0), 1.0)
        z = z_start + (z_end - z_start) * (1 - math.cos(math.pi * t)) / 2
        points.append((x0 + s * ux, y0 + s * uy, z))
    return points


def popup_beams(segments, bump):
    """(group tag, start name, end name, points) of every beam."""
    beams = []
    for k, (dx, dy) in enumerate([(1, 0), (0, 1), (-1, 0), (0, -1)]):
        beams.append((1, "c%d" % (k + 1), "centre",
                      beam_points((dx, dy), (0, 0), 0, bump, segments, True)))
    corner = []
    for k in range(6):
        a = math.radians(15 + 60 * k)
        corner.append((math.cos(a), math.sin(a)))
    for k, (cx, cy) in enumerate(corner):
        beams.append((2, "s%d" % (k + 1), "r%d" % (k + 1),
                      beam_points((cx, cy), (cx / 2, cy / 2), 0, bump,
                                  segments, True)))
    for k in range(6):
        (ax, ay), (bx, by) = corner[k], corner[(k + 1) % 6]
        beams.append((2, "r%d" % (k + 1), "r%d" % ((k + 1) % 6 + 1),
                      beam_points((ax / 2, ay / 2), (bx / 2, by / 2), bump,
                                  bump, segments, False)))
    return beams


def write_mesh(segments, bump, out):
    nodes, named, elements = [], {}, []

    def node(point, name=None):
        if name is not None and name in named:
            return named[name]
        nodes.append(point)
        if name is not None:
            named[name] = len(nodes)
        return len(nodes)

    for tag, first, last, points in popup_beams(segments, bump):
        ids = [node(points[0], first)]
        ids += [node(p) for p in points[1:-1]]
        ids.append(node(points[-1], last))
        elements += [(tag, ids[i], ids[i + 1]) for i in range(segments)]
    names = sorted(named, key=lambda n: named[n])
    out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n")
    out.write("%d\n" % (len(names) + 2))
    for i, name in enumerate(names):
        out.write('0 %d "%s"\n' % (i + 3, name))
    out.write('1 1 "layer1"\n1 2 "layer2"\n$EndPhysicalNames\n')
    out.write("$Nodes\n%d\n" % len(nodes))
    for i, (x, y, z) in enumerate(nodes):
        out.write("%d %.17g %.17g %.17g\n" % (i + 1, x, y, z))
    out.write("$EndNodes\n$Elements\n%d\n" % (len(elements) + len(names)))
    for i, (tag, a, b) in enumerate(elements):
        out.write("%d 1 2 %d %d %d %d\n" % (i + 1, tag, tag, a, b))
    for i, name in enumerate(names):
        out.write("%d 15 2 %d %d %d\n" % (len(elements) + i + 1, i + 3,
                                          i + 3, named[name]))
    out.write("$EndElements\n")


if __name__ == "__main__":
    write_mesh(int(sys.argv[1]),
               float(sys.argv[2]) if len(sys.argv) > 2 else 0.01, sys.stdout)
