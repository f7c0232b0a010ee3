#!/usr/bin/env python3
"""The least distance D between opposite points of a closed ring, per
converged point of a rodnet run: reads RUN/probes.csv and the VTU file of
every row (solution-NNNNN.vtu, one per step), takes the first point of each
cell as the ring's vertex (cell k is the segment from vertex k to k + 1)
and prints "O D/L stable jump", with O = OFFSET + load factor, D the
minimum of |x_k - x_{k + N/2}| over k (N even), jump 1 on the row the path
snapped to (Limit points = snap; 0 elsewhere, and where the run has no
such column).

Usage: bench/overcurved_ring_distance.py RUN_DIR LENGTH OFFSET
"""
import csv
import math
import os
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_table import values  # noqa: E402


def vertices(path):
    """The ring's vertices, in the order of its segments."""
    root = ElementTree.parse(path).getroot()
    compressed = root.get("compressor") is not None
    piece = root.find("UnstructuredGrid/Piece")
    points = values(piece.find("Points/DataArray"), compressed)
    offsets = values(piece.find("Cells/DataArray[@Name='offsets']"),
                     compressed)
    connectivity = values(
        piece.find("Cells/DataArray[@Name='connectivity']"), compressed)
    result, start = [], 0
    for end in offsets:
        p = int(connectivity[start])
        result.append(points[3 * p:3 * p + 3])
        start = int(end)
    return result


def least_opposite_distance(x):
    n = len(x)
    if n % 2:
        sys.exit("a ring of %d segments has no opposite vertices" % n)
    return min(math.dist(x[k], x[k + n // 2]) for k in range(n // 2))


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    run, length, offset = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    with open(os.path.join(run, "probes.csv")) as f:
        rows = list(csv.DictReader(f))
    for i, row in enumerate(rows):
        vtu = os.path.join(run, "solution-%05d.vtu" % i)
        d = least_opposite_distance(vertices(vtu))
        print("%.10g %.10g %s %s" % (offset + float(row["load_factor"]),
                                     d / length, row["stable"],
                                     row.get("jump", "0")))


if __name__ == "__main__":
    main()
