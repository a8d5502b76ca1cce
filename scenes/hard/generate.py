#!/usr/bin/env python3
"""Writes the mesh files of scenes/hard/ (issue 7, item 6). Run from anywhere; the output is committed.

All meshes lie in the plane z = 0 and are seen by a pixel-aligned orthographic camera (the scenes' JSON):
world (x, y) is at screen (x + W/2, H/2 - y), so integer world coordinates are pixel edges and
half-integers pixel centres (W and H even). Faces are counter-clockwise seen from +z."""
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def write_obj(name, comment, vertices, faces):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("# " + comment.replace("\n", "\n# ") + "\n# written by generate.py\n")
        for x, y in vertices:
            f.write("v %s %s 0\n" % (fmt(x), fmt(y)))
        for a, b, c in faces:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def fmt(v):
    s = "%.6f" % v
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def grid(x0, y0, cells_x, cells_y, step, vertices, faces):
    """Cells of step x step, each split into two triangles (diagonals alternating)."""
    base = len(vertices)
    for j in range(cells_y + 1):
        for i in range(cells_x + 1):
            vertices.append((x0 + i * step, y0 + j * step))
    row = cells_x + 1
    for j in range(cells_y):
        for i in range(cells_x):
            a, b = base + j * row + i, base + j * row + i + 1
            c, d = a + row, b + row  # c above a, d above b
            if (i + j) % 2 == 0:
                faces += [(a, b, d), (a, d, c)]
            else:
                faces += [(a, b, c), (b, d, c)]


# Slivers: the 200 x 2 pixel rectangle [-100, 100] x [-1, 1] as a fan from the middle of its left edge:
# 100 needles onto its right edge (base 0.02 px, length 200 px: aspect ratio 10^4) and two long
# triangles along the top and bottom edges. Covers exactly 400 pixels.
v = [(-100.0, 0.0)] + [(100.0, -1.0 + 0.02 * k) for k in range(101)] + [(-100.0, 1.0), (-100.0, -1.0)]
f = [(0, k, k + 1) for k in range(1, 101)] + [(0, 101, 102), (0, 103, 1)]
write_obj("slivers.obj", "100 needles of aspect ratio 10^4 and two long triangles tiling [-100,100]x[-1,1]", v, f)

# A fan of 10 000 triangles around one vertex: the square [-50, 50]^2 from its centre, its perimeter cut
# into 10 000 pieces of 0.04 px. Covers exactly 10 000 pixels.
n = 10000
per_side = n // 4
perimeter = []
for k in range(per_side):
    t = -50.0 + 100.0 * k / per_side
    perimeter.append((t, -50.0))
for k in range(per_side):
    t = -50.0 + 100.0 * k / per_side
    perimeter.append((50.0, t))
for k in range(per_side):
    t = 50.0 - 100.0 * k / per_side
    perimeter.append((t, 50.0))
for k in range(per_side):
    t = 50.0 - 100.0 * k / per_side
    perimeter.append((-50.0, t))
v = [(0.0, 0.0)] + perimeter
f = [(0, 1 + k, 1 + (k + 1) % n) for k in range(n)]
write_obj("fan.obj", "10 000 triangles around the vertex (0, 0), tiling the square [-50,50]^2", v, f)

# One-pixel triangles: [-10, 10]^2 in cells of one pixel (vertices on pixel corners, edges on pixel
# edges: 800 triangles of half a pixel), and [20, 24] x [0, 4] in cells of a quarter pixel (512
# triangles of 1/32 pixel, most covering no pixel centre). Covers exactly 400 + 16 pixels.
v, f = [], []
grid(-10.0, -10.0, 20, 20, 1.0, v, f)
grid(20.0, 0.0, 16, 16, 0.25, v, f)
write_obj("one_pixel.obj", "one-pixel and sub-pixel triangles on the pixel grid", v, f)

# Vertices exactly on pixel centres: [-9.5, 9.5]^2 in cells of one pixel. The boundary runs through pixel
# centres; the top-left rule takes one of each pair of opposite sides: 19 x 19 = 361 pixels.
v, f = [], []
grid(-9.5, -9.5, 19, 19, 1.0, v, f)
write_obj("pixel_centres.obj", "vertices and edges exactly on pixel centres", v, f)

# Triangles larger than the screen: [-5000, 5000]^2 as two triangles. Covers every pixel once.
write_obj("big.obj", "two triangles far larger than the screen", [(-5000, -5000), (5000, -5000), (5000, 5000), (-5000, 5000)],
          [(0, 1, 2), (0, 2, 3)])

# T-junctions: the diamond |x| + |y| <= 40, its lower half one triangle, its upper half two triangles
# that meet at (0, 0), a vertex in the middle of the lower triangle's long edge (not a vertex of it).
write_obj("t_junction.obj", "a vertex of two triangles in the middle of a third triangle's edge",
          [(-40, 0), (40, 0), (0, -40), (0, 0), (0, 40)], [(0, 2, 1), (0, 3, 4), (3, 1, 4)])

# Coplanar overlapping quads, one per object (the scene gives them two materials): [-60, 20] x [-40, 40]
# and [-20, 60] x [-40, 40], both at z = 0.
write_obj("quad_left.obj", "[-60,20]x[-40,40]", [(-60, -40), (20, -40), (20, 40), (-60, 40)], [(0, 1, 2), (0, 2, 3)])
write_obj("quad_right.obj", "[-20,60]x[-40,40]", [(-20, -40), (60, -40), (60, 40), (-20, 40)], [(0, 1, 2), (0, 2, 3)])

# Back faces: the same quad wound clockwise (seen from +z).
write_obj("quad_back.obj", "[-40,40]x[-30,30], wound clockwise", [(-40, -30), (40, -30), (40, 30), (-40, 30)],
          [(0, 2, 1), (0, 3, 2)])

# The 12-bit limit, for a 4096 x 16 frame (world x = screen x - 2048): a strip [-2048, 2048] x [-4, 4] across
# the whole width as two triangles (vertices on the frame's first and last pixel edge, x = 0 and
# x = 4096 = 2^12 on screen) and one-pixel triangles in [2032, 2048] x [4, 8], the last 16 columns.
# Covers exactly 4096 * 8 + 64 pixels.
v = [(-2048, -4), (2048, -4), (2048, 4), (-2048, 4)]
f = [(0, 1, 2), (0, 2, 3)]
grid(2032.0, 4.0, 16, 4, 1.0, v, f)
write_obj("limit_12bit.obj", "a strip across a 4096-pixel-wide frame and one-pixel triangles in its last columns", v, f)
