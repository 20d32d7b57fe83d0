#!/usr/bin/env python3
"""Before/after pictures for docs/look.md with the standard library only (no PIL here).

  png_pair.py pair BEFORE.png AFTER.png OUT.png [SCALE]  # side by side, 8 px of white between,
                                                  # each scaled by SCALE (area average; 0.75)
  png_pair.py clip LIT.png DARK.png               # the glitter path (pixels LIT brightens by
                                                  # more than 8 levels over DARK) and its
                                                  # share at white (any channel 255)
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path
    pos, idat, w = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, color, _, _, interlace = struct.unpack('>IIBBBBB', body)
            assert depth == 8 and color in (2, 6) and interlace == 0, 'RGB(A)8 only: ' + path
            bpp = 3 if color == 2 else 4
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        prev = line
        rows.append(bytes(line) if bpp == 3 else bytes(v for j, v in enumerate(line) if j % 4 != 3))
    return w, h, rows


def write_png(path, w, h, rows):
    chunk = lambda k, b: struct.pack('>I', len(b)) + k + b + struct.pack('>I', zlib.crc32(k + b))
    # Paeth-filtered rows (PNG filter 4): smooth pictures compress a third better than unfiltered.
    raw, prev = bytearray(), bytes(len(rows[0]))
    for r in rows:
        line = bytearray(len(r))
        for i in range(len(r)):
            a, b = r[i - 3] if i >= 3 else 0, prev[i]
            c = prev[i - 3] if i >= 3 else 0
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (r[i] - (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        raw += b'\x04' + line
        prev = r
    open(path, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
                           + chunk(b'IDAT', zlib.compress(bytes(raw), 9)) + chunk(b'IEND', b''))


def weights(n, m):
    """For each of m outputs over n inputs: the (input, share) pairs of its area average."""
    out, step = [], n / m
    for j in range(m):
        lo, hi, row = j * step, (j + 1) * step, []
        for i in range(int(lo), min(n, int(hi) + 1)):
            share = min(hi, i + 1) - max(lo, i)
            if share > 1e-9: row.append((i, share / step))
        out.append(row)
    return out


def scale(w, h, rows, factor):
    m, k = round(w * factor), round(h * factor)
    wx, wy = weights(w, m), weights(h, k)
    wide = [[sum(r[3 * i + c] * s for i, s in wx[x]) for x in range(m) for c in range(3)] for r in rows]
    return m, k, [bytes(min(255, int(sum(wide[i][j] * s for i, s in wy[y]) + 0.5)) for j in range(3 * m)) for y in range(k)]


def pair(before, after, out, factor='1'):
    (w1, h1, a), (w2, h2, b) = read_png(before), read_png(after)
    assert h1 == h2, 'same heights'
    if float(factor) != 1.0:
        (w1, h1, a), (w2, h2, b) = scale(w1, h1, a, float(factor)), scale(w2, h2, b, float(factor))
    gap = b'\xff' * 24
    write_png(out, w1 + w2 + 8, h1, [a[y] + gap + b[y] for y in range(h1)])


def clip(lit, dark):
    (w, h, a), (_, _, b) = read_png(lit), read_png(dark)
    path = white = 0
    for y in range(h):
        for x in range(w):
            p, q = a[y][3 * x:3 * x + 3], b[y][3 * x:3 * x + 3]
            if sum(p) - sum(q) > 24:
                path += 1
                white += 255 in p
    print(f'path {path} px, at white {white} px ({100.0 * white / max(path, 1):.1f} %)')


if __name__ == '__main__':
    {'pair': pair, 'clip': clip}[sys.argv[1]](*sys.argv[2:])
