#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Prints the glyphs 32..126 of an X11 PCF bitmap font as the C++ rows of
# view/detail/font_6x13.cpp (one byte per row, the leftmost pixel in the top bit), and the cell
# size on stderr. The table was made with:
#   scripts/font-from-pcf.py /usr/share/fonts/X11/misc/6x13.pcf.gz   (xfonts-base, public domain)
import gzip, struct, sys
data = gzip.open(sys.argv[1]).read()
assert data[:4] == b'\x01fcp'
n = struct.unpack('<i', data[4:8])[0]
tables = {}
for i in range(n):
    t, f, s, o = struct.unpack('<iiii', data[8+16*i:24+16*i])
    tables[t] = (f, o)
def reader(t):
    f, o = tables[t]
    fmt = struct.unpack('<i', data[o:o+4])[0]
    e = '>' if fmt & 4 else '<'
    return fmt, e, o + 4
fmt, e, p = reader(4)
metrics = []
if fmt & 0x100:
    cnt = struct.unpack(e+'h', data[p:p+2])[0]; p += 2
    for i in range(cnt):
        lb, rb, w, a, d = [b - 0x80 for b in data[p:p+5]]; p += 5
        metrics.append((lb, rb, w, a, d))
else:
    cnt = struct.unpack(e+'i', data[p:p+4])[0]; p += 4
    for i in range(cnt):
        lb, rb, w, a, d, _ = struct.unpack(e+'hhhhhh', data[p:p+12]); p += 12
        metrics.append((lb, rb, w, a, d))
fmt, e, p = reader(8)
gc = struct.unpack(e+'i', data[p:p+4])[0]; p += 4
offs = struct.unpack(e+'%di' % gc, data[p:p+4*gc]); p += 4*gc
p += 16
bits = p
pad = 1 << (fmt & 3)
msbit = bool(fmt & 8)
fmt2, e2, q = reader(32)
min2, max2, min1, max1, dflt = struct.unpack(e2+'hhhhh', data[q:q+10]); q += 10
cnt = (max2-min2+1)*(max1-min1+1)
idx = struct.unpack(e2+'%dH' % cnt, data[q:q+2*cnt])
asc = max(m[3] for m in metrics); desc = max(m[4] for m in metrics)
cellw = max(m[2] for m in metrics)
H = asc + desc
out = []
for ch in range(32, 127):
    g = idx[ch - min2]
    lb, rb, w, a, d = metrics[g]
    rowbytes = ((rb - lb + 7)//8 + pad - 1)//pad*pad
    rows = [0]*H
    for r in range(a + d):
        row = data[bits+offs[g]+r*rowbytes: bits+offs[g]+(r+1)*rowbytes]
        for x in range(rb - lb):
            byte = row[x//8]
            bit = (byte >> (7 - x % 8)) & 1 if msbit else (byte >> (x % 8)) & 1
            if bit:
                cx = lb + x
                if 0 <= cx < 8:
                    rows[asc - a + r] |= 0x80 >> cx
    out.append(rows)
print(cellw, H, file=sys.stderr)
for ch, rows in zip(range(32,127), out):
    c = chr(ch)
    name = {'\\': 'backslash', "'": 'quote'}.get(c, c)
    print('    {' + ', '.join('0x%02x' % r for r in rows) + '},  // ' + name)
