#!/usr/bin/env python3
"""vtu_compare.py ASCII.vtu BINARY.vtu: the binary file's arrays, decoded here with the
standard library only (base64 + struct; VTK's inline uncompressed binary: a UInt64
little-endian byte count, then the values), equal the ASCII file's, value for value;
the binary file's header is the one ParaView reads (version 1.0, UInt64 headers)."""
import base64
import re
import struct
import sys

HEADER = '<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64">'
CODES = {'Float64': ('d', 8), 'Int64': ('q', 8), 'UInt8': ('B', 1)}


def arrays(path):
    text = open(path).read()
    out = {}
    for attrs, body in re.findall(r'<DataArray([^>]*)>(.*?)</DataArray>', text, re.S):
        a = dict(re.findall(r'(\w+)="([^"]*)"', attrs))
        code, size = CODES[a['type']]
        if a['format'] == 'ascii':
            values = [float(w) if code == 'd' else int(w) for w in body.split()]
        else:
            raw = base64.b64decode(''.join(body.split()))
            (count,) = struct.unpack('<Q', raw[:8])
            assert count == len(raw) - 8, f"{a['Name']}: header says {count} bytes, data has {len(raw) - 8}"
            values = list(struct.unpack(f'<{count // size}{code}', raw[8:]))
        out[a['Name']] = (a['type'], a['format'], values)
    return text, out


def main():
    _, ascii_arrays = arrays(sys.argv[1])
    text, binary_arrays = arrays(sys.argv[2])
    assert HEADER in text, 'binary file header: ' + text[:200]
    assert ascii_arrays.keys() == binary_arrays.keys(), (ascii_arrays.keys(), binary_arrays.keys())
    for name, (t, fmt, values) in ascii_arrays.items():
        bt, bfmt, bvalues = binary_arrays[name]
        assert (fmt, bfmt, t) == ('ascii', 'binary', bt), (name, fmt, bfmt, t, bt)
        assert values == bvalues, f'{name}: values differ'
    print(f'{sys.argv[2]}: {len(binary_arrays)} arrays equal to the ASCII file\'s')


if __name__ == '__main__':
    main()
