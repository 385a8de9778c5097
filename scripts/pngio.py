"""pngio.py — the one 8-bit PNG reader and writer of Aerial's scripts and
tests (pure Python, zlib only): what `aerial render` and the editor's
screenshots write (stb: 8-bit RGB or RGBA, non-interlaced, any filter).

  width, height, colour, depth, rows = decode_png(path)   # rows: unfiltered bytearrays
  write_png(path, width, height, rgb)                     # 8-bit RGB, Paeth-filtered rows
"""
import os
import struct
import zlib

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


class PngError(ValueError):
    pass


def decode_png(path):
    """(width, height, colour type, bit depth, rows) of a PNG; rows is None
    unless it is 8-bit RGB (colour 2) or RGBA (6), non-interlaced."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != PNG_MAGIC:
        raise PngError("%s: not a PNG file (magic %s)" % (path, data[:8].hex()))
    pos, ihdr, idat = 8, None, b""
    while pos + 8 <= len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            ihdr = body
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if ihdr is None:
        raise PngError("%s: no IHDR chunk" % path)
    width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", ihdr[:13])
    if depth != 8 or colour not in (2, 6) or interlace:
        return width, height, colour, depth, None
    bpp = 3 if colour == 2 else 4
    raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, colour, depth, rows


def read_rgb(path):
    """(width, height, RGB bytes, row-major) of an 8-bit RGB/RGBA PNG (alpha dropped)."""
    width, height, colour, depth, rows = decode_png(path)
    if rows is None:
        raise PngError("%s: only 8-bit RGB/RGBA, non-interlaced PNGs are read (colour %d, depth %d)" %
                       (path, colour, depth))
    bpp = 3 if colour == 2 else 4
    out = bytearray(width * height * 3)
    for y, line in enumerate(rows):
        for x in range(width):
            out[(y * width + x) * 3:(y * width + x) * 3 + 3] = line[x * bpp:x * bpp + 3]
    return width, height, out


def write_png(path, width, height, rgb):
    """8-bit RGB, every row Paeth-filtered (smaller for rendered pictures); atomic."""
    stride = width * 3
    rows = bytearray()
    prev = bytes(stride)
    for y in range(height):
        line = bytes(rgb[y * stride:(y + 1) * stride])
        out = bytearray(stride)
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b = prev[i]
            c = prev[i - 3] if i >= 3 else 0
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            out[i] = (line[i] - (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows += b"\x04" + out
        prev = line

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    data = (PNG_MAGIC + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b""))
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)
