"""Reads the binary (zlib) DataArrays of a deal.II .vtu file: the points
and every named field, as (components, values) per piece. Used by the chart
scripts of doc/ (python3 without numpy).

Usage: python3 bench/vtu_fields.py FILE.vtu  (lists the fields)
"""
import base64
import re
import struct
import sys
import zlib

_ARRAY = re.compile(
    r'<DataArray type="(\w+)"( Name="([^"]*)")?'
    r'( NumberOfComponents="(\d+)")? format="binary">\s*(\S+)\s*</DataArray>')
_FORMATS = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B",
            "Int64": "q"}


def read(path):
    """Field name ("points" for the points) -> list of (components, values)."""
    text = open(path).read()
    fields = {}
    for match in _ARRAY.finditer(text):
        kind, name = match.group(1), match.group(3) or "points"
        components, data = int(match.group(5) or 1), match.group(6)
        # A 4-word header (blocks, block size, last size, compressed size)
        # in its own base64 run, then the compressed block.
        raw = zlib.decompress(base64.b64decode(data[24:]))
        code = _FORMATS[kind]
        count = len(raw) // struct.calcsize(code)
        values = struct.unpack("<%d%s" % (count, code), raw)
        fields.setdefault(name, []).append((components, values))
    return fields


if __name__ == "__main__":
    for name, pieces in read(sys.argv[1]).items():
        print(name, [(c, len(v)) for c, v in pieces])
