#!/usr/bin/python3
"""Numbers about PNG pictures, for tests/test_render.pf and tests/test_plots.pf
to check that a picture was drawn: for each file, one line

    width  height  colours  drawn  [count ...]

colours: the number of distinct pixel values; drawn: the share of pixels
that differ from the most frequent one (the background), 0 to 1; with
--count RRGGBB (any number of times), the number of pixels of that colour
(red, green, blue; alpha not compared), in the order given. Python's
standard library only (zlib; the PNG filters undone row by row): 8-bit
grey, RGB, palette, grey + alpha and RGBA, not interlaced, as gnuplot's
pngcairo and ParaView write them. Exit status 1 when a file is not such a
PNG.

usage: png_facts.py [--count RRGGBB ...] FILE.png ...
"""
import collections
import struct
import sys
import zlib

CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def pixels(path):
    """(width, height, rows of raw pixel bytes)."""
    with open(path, 'rb') as f:
        data = f.read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError('not a PNG file')
    pos, idat, head = 8, [], None
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            head = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            idat.append(body)
        elif kind == b'IEND':
            break
        pos += 12 + n
    width, height, depth, colour, _, _, interlace = head
    if depth != 8 or colour not in CHANNELS or interlace:
        raise ValueError(f'bit depth {depth}, colour type {colour}, interlace {interlace}: not read here')
    bpp = CHANNELS[colour]
    raw = zlib.decompress(b''.join(idat))
    stride = width * bpp
    prev = bytearray(stride)
    rows = []
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if kind == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif kind == 2:
            line = bytearray((a + b) & 255 for a, b in zip(line, prev))
        elif kind == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + prev[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                upleft = prev[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + paeth(left, prev[i], upleft)) & 255
        elif kind != 0:
            raise ValueError(f'row {y}: unknown filter {kind}')
        rows.append(bytes(line))
        prev = line
    return width, height, bpp, rows


def facts(path, wanted=()):
    """width, height, distinct pixel values, share drawn, [pixels of each wanted (r, g, b)]."""
    width, height, bpp, rows = pixels(path)
    count = collections.Counter()
    for line in rows:
        count.update(line[i:i + bpp] for i in range(0, len(line), bpp))
    background = count.most_common(1)[0][1]
    rgb = collections.Counter()
    if bpp >= 3:
        for value, n in count.items():
            rgb[bytes(value[:3])] += n
    return width, height, len(count), 1.0 - background / (width * height), [rgb[bytes(c)] for c in wanted]


def main():
    args, wanted, status = sys.argv[1:], [], 0
    while len(args) >= 2 and args[0] == '--count':
        wanted.append(bytes.fromhex(args[1]))
        args = args[2:]
    for path in args:
        try:
            w, h, colours, drawn, counts = facts(path, wanted)
            print(f'{w} {h} {colours} {drawn:.6f}' + ''.join(f' {n}' for n in counts))
        except (OSError, ValueError, TypeError, zlib.error) as e:
            print(f'png_facts.py: {path}: {e}', file=sys.stderr)
            print(' '.join(['0'] * (4 + len(wanted))))
            status = 1
    return status


if __name__ == '__main__':
    sys.exit(main())
