# tests/vtu.py -- read the VTU files lac writes (for the shell cases)
#
# read(path) -> (piece, arrays): the Piece element and {name: [floats]}
# for ascii and appended raw DataArrays (UInt64 headers, little endian),
# the two encodings of io/lac_vtu.h.  Standard library only.
import struct
import xml.etree.ElementTree as ET

FMT = {"Float64": "d", "Int64": "q", "UInt8": "B", "Int32": "i"}


def read(path):
    data = open(path, "rb").read()
    cut = data.find(b"<AppendedData")
    raw = data[data.index(b"_", cut) + 1:] if cut >= 0 else b""
    root = ET.fromstring(data[:cut] + b"</VTKFile>" if cut >= 0 else data)
    assert root.get("header_type") == "UInt64", "header_type"
    piece = root.find("UnstructuredGrid/Piece")
    arrays = {}
    for a in piece.iter("DataArray"):
        if a.get("format") == "appended":
            off = int(a.get("offset"))
            nb = struct.unpack("<Q", raw[off:off + 8])[0]
            t = FMT[a.get("type")]
            n = nb // struct.calcsize(t)
            vals = struct.unpack("<%d%s" % (n, t), raw[off + 8:off + 8 + nb])
        else:
            vals = a.text.split()
        arrays[a.get("Name")] = [float(v) for v in vals]
    return piece, arrays
