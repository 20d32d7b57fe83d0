#!/usr/bin/env python3
"""A screenshot's luminance minus its mean over a (2R+1)² box, times GAIN about mid-grey: the
picture's detail under about R pixels (a wake's crests) with the sky's and the sea's smooth
gradients taken out, as tests/scenario/test_wake_picture.cpp measures it (docs/look.md, "The
wake scene"). Usage: highpass.py IN.png OUT.png [R=6] [GAIN=12]   (pure Python: zlib and struct)"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
from banding_stretch import read_png, write_png  # noqa: E402


def box_mean(line, radius):
    n, prefix = len(line), [0.0]
    for v in line:
        prefix.append(prefix[-1] + v)
    return [(prefix[min(n, i + radius + 1)] - prefix[max(0, i - radius)]) / (min(n, i + radius + 1) - max(0, i - radius))
            for i in range(n)]


def main():
    src, dst = sys.argv[1], sys.argv[2]
    radius = int(sys.argv[3]) if len(sys.argv) > 3 else 6
    gain = float(sys.argv[4]) if len(sys.argv) > 4 else 12.0
    w, h, bpp, rows = read_png(src)
    lum = [[0.2126 * r[x * bpp] + 0.7152 * r[x * bpp + 1] + 0.0722 * r[x * bpp + 2] for x in range(w)] for r in rows]
    along_rows = [box_mean(line, radius) for line in lum]
    columns = [box_mean([along_rows[y][x] for y in range(h)], radius) for x in range(w)]
    out = [bytearray(v for x in range(w) for v in [max(0, min(255, round(128 + gain * (lum[y][x] - columns[x][y]))))] * 3)
           for y in range(h)]
    write_png(dst, w, h, out)


if __name__ == '__main__':
    main()
