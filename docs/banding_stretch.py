#!/usr/bin/env python3
"""Crops a PNG screenshot and stretches its contrast about the crop's mean, so 1-level steps
(8-bit banding) or ±1-level dither become visible: docs/frame.md, "8-bit dither".
Usage: banding_stretch.py IN.png OUT.png X Y W H GAIN   (pure Python: zlib and struct only)"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, 'rb').read()
    pos, idat = 8, b''
    while pos < len(data):
        size, kind = struct.unpack('>I4s', data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + size]
        pos += 12 + size
        if kind == b'IHDR':
            w, h, depth, colour = struct.unpack('>IIBB', chunk[:10])
            assert depth == 8 and colour in (2, 6), 'RGB(A) 8-bit PNGs only'
        elif kind == b'IDAT':
            idat += chunk
    bpp = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], (prev[i - bpp] if i >= bpp else 0)
            if kind == 1: line[i] = (line[i] + a) & 255
            elif kind == 2: line[i] = (line[i] + b) & 255
            elif kind == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, bpp, rows


def write_png(path, w, h, rows):
    raw = b''.join(b'\0' + bytes(r) for r in rows)
    chunk = lambda kind, body: struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body))
    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
    open(path, 'wb').write(png + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))


def main():
    src, dst = sys.argv[1], sys.argv[2]
    x0, y0, cw, ch, gain = (int(v) for v in sys.argv[3:8])
    w, h, bpp, rows = read_png(src)
    crop = [[row[(x0 + x) * bpp:(x0 + x) * bpp + 3] for x in range(cw)] for row in rows[y0:y0 + ch]]
    mean = [sum(p[c] for line in crop for p in line) / (cw * ch) for c in range(3)]
    out = [bytearray(min(255, max(0, round(128 + gain * (p[c] - mean[c])))) for p in line for c in range(3)) for line in crop]
    write_png(dst, cw, ch, out)


if __name__ == '__main__':
    main()
