#!/usr/bin/env python3
"""Prints a rodnet VTU file as a table for gnuplot: one row per point,
x y z and then the components of the named point arrays, a blank line after
every cell, so that "with lines" draws each segment of a network on its own.

Usage: bench/vtu_table.py FILE.vtu [ARRAY ...]

deal.II writes VTU arrays as base64 zlib blocks (vtkZLibDataCompressor with
a UInt32 header: block count, block size, last block size, then the
compressed size of each block) or as ASCII; the standard library reads both,
so the charts need nothing beyond python3.
"""
import base64
import math
import struct
import sys
import xml.etree.ElementTree as ElementTree
import zlib

FORMATS = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt32": "I",
           "Int64": "q", "UInt8": "B"}


def values(array, compressed):
    """The numbers of one DataArray element."""
    if array.get("format") == "ascii":
        return [float(v) for v in array.text.split()]
    text = "".join(array.text.split())
    code = FORMATS[array.get("type")]
    if not compressed:
        raw = base64.b64decode(text)
        size = struct.unpack_from("<I", raw)[0]
        raw = raw[4:4 + size]
    else:
        # The header is base64 on its own, then the blocks: its length
        # depends on the block count, its first word.
        blocks = struct.unpack_from("<I", base64.b64decode(text[:8]))[0]
        header_chars = 4 * math.ceil(4 * (3 + blocks) / 3)
        header = base64.b64decode(text[:header_chars])
        sizes = struct.unpack_from("<%dI" % blocks, header, 12)
        data = base64.b64decode(text[header_chars:])
        raw, start = b"", 0
        for size in sizes:
            raw += zlib.decompress(data[start:start + size])
            start += size
    return list(struct.unpack("<%d%s" % (len(raw) // struct.calcsize(code),
                                         code), raw))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    root = ElementTree.parse(sys.argv[1]).getroot()
    compressed = root.get("compressor") is not None
    piece = root.find("UnstructuredGrid/Piece")
    points = values(piece.find("Points/DataArray"), compressed)
    columns = []
    for name in sys.argv[2:]:
        array = piece.find("PointData/DataArray[@Name='%s']" % name)
        if array is None:
            sys.exit("%s: no point array \"%s\"" % (sys.argv[1], name))
        columns.append((int(array.get("NumberOfComponents", "1")),
                        values(array, compressed)))
    offsets = values(piece.find("Cells/DataArray[@Name='offsets']"),
                     compressed)
    connectivity = values(
        piece.find("Cells/DataArray[@Name='connectivity']"), compressed)
    start = 0
    for end in offsets:
        for p in connectivity[start:end]:
            row = points[3 * p:3 * p + 3]
            for width, data in columns:
                row += data[width * p:width * p + width]
            print(" ".join("%.7g" % v for v in row))
        print()
        start = end


if __name__ == "__main__":
    main()
