"""The point data of a VTU written by deal.II's DataOut, for the tests that
read the fields a run writes."""
import base64
import re
import struct
import zlib


def data_arrays(path):
    """name -> (n_components, values) of the point data of a deal.II VTU
    (ascii, or base64 binary with or without zlib compression)."""
    text = open(path).read()
    header = re.search(r'<VTKFile[^>]*>', text).group(0)
    compressed = "vtkZLibDataCompressor" in header
    header_type = "Q" if 'header_type="UInt64"' in header else "I"
    size = struct.calcsize(header_type)
    arrays = {}
    for m in re.finditer(r'<DataArray([^>]*)>(.*?)</DataArray>', text, re.S):
        attributes, body = m.group(1), m.group(2).strip()
        name = re.search(r'Name="([^"]*)"', attributes)
        preceding = text[max(0, m.start() - 40):m.start()]
        if not name and "<Points>" not in preceding:
            continue
        components = re.search(r'NumberOfComponents="(\d+)"', attributes)
        n_components = int(components.group(1)) if components else 1
        kind = re.search(r'type="(\w+)"', attributes).group(1)
        fmt = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B",
               "Int64": "q"}[kind]
        if 'format="ascii"' in attributes:
            values = [float(v) for v in body.split()]
        elif compressed:
            # Header (block count, block size, last size, compressed sizes)
            # base64-encoded on its own, then the concatenated blocks.
            n_header = 3
            first = base64.b64decode(body[:((n_header * size + 2) // 3) * 4])
            n_blocks = struct.unpack(header_type, first[:size])[0]
            header_length = ((( 3 + n_blocks) * size + 2) // 3) * 4
            head = base64.b64decode(body[:header_length])
            counts = struct.unpack(header_type * (3 + n_blocks), head)
            raw = base64.b64decode(body[header_length:])
            data, offset = b"", 0
            for c in counts[3:]:
                data += zlib.decompress(raw[offset:offset + c])
                offset += c
            values = list(struct.unpack("<%d%s" % (len(data) //
                                        struct.calcsize(fmt), fmt), data))
        else:
            raw = base64.b64decode(body)
            data = raw[size:]
            values = list(struct.unpack("<%d%s" % (len(data) //
                                        struct.calcsize(fmt), fmt), data))
        arrays[name.group(1) if name else "Points"] = (n_components, values)
    return arrays
