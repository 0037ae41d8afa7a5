#!/usr/bin/python3
"""Writes a closed Wigley hull as an STL: both sides y = ±(B/2)(1 − (2x/L)²)(1 − (z/T)²) for
x in [−L/2, L/2], z in [−T, 0] (ship frame: x stern→bow, y to port, z up; waterline at z = 0),
closed by a flat deck at z = 0. Facets wind counter-clockwise seen from outside.

Example: tools/make_wigley_hull.py wigley.stl --length 100 --beam 10 --draft 8
"""
import argparse
import math
import struct
import sys


def half_breadth(x, z, length, beam, draft):
    return 0.5 * beam * (1 - (2 * x / length) ** 2) * (1 - (z / draft) ** 2)


def facets(length, beam, draft, nx, nz):
    xs = [-length / 2 + length * i / nx for i in range(nx + 1)]
    zs = [-draft + draft * k / nz for k in range(nz + 1)]

    def point(i, k, sign):
        x, z = xs[i], zs[k]
        return (x, sign * half_breadth(x, z, length, beam, draft), z)

    def oriented(a, b, c, outward):
        u = [b[j] - a[j] for j in range(3)]
        v = [c[j] - a[j] for j in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        if math.sqrt(sum(t * t for t in n)) < 1e-12:
            return None  # the sides meet at the ends and the keel
        return (a, b, c) if sum(n[j] * outward[j] for j in range(3)) > 0 else (a, c, b)

    out = []
    for sign in (-1, 1):  # starboard (y < 0), port (y > 0)
        for i in range(nx):
            for k in range(nz):
                p00, p10 = point(i, k, sign), point(i + 1, k, sign)
                p01, p11 = point(i, k + 1, sign), point(i + 1, k + 1, sign)
                for tri in ((p00, p10, p11), (p00, p11, p01)):
                    t = oriented(*tri, (0, sign, 0))
                    if t:
                        out.append(t)
    for i in range(nx):  # the deck at z = 0, facing up
        a, b = point(i, nz, -1), point(i + 1, nz, -1)
        c, d = point(i, nz, 1), point(i + 1, nz, 1)
        for tri in ((a, b, d), (a, d, c)):
            t = oriented(*tri, (0, 0, 1))
            if t:
                out.append(t)
    return out


def normal(t):
    a, b, c = t
    u = [b[j] - a[j] for j in range(3)]
    v = [c[j] - a[j] for j in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    s = math.sqrt(sum(x * x for x in n))
    return tuple(x / s for x in n)


def write_ascii(path, tris):
    lines = ["solid wigley"]
    for t in tris:
        lines.append(" facet normal %.9g %.9g %.9g" % normal(t))
        lines.append("  outer loop")
        for p in t:
            lines.append("   vertex %.9g %.9g %.9g" % p)
        lines.append("  endloop")
        lines.append(" endfacet")
    lines.append("endsolid wigley")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_binary(path, tris):
    with open(path, "wb") as f:
        f.write(b"wigley hull".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", *normal(t)))
            for p in t:
                f.write(struct.pack("<3f", *p))
            f.write(b"\0\0")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", help="STL file to write")
    parser.add_argument("--length", type=float, default=100.0, help="L, metres (100)")
    parser.add_argument("--beam", type=float, default=10.0, help="B, metres (10)")
    parser.add_argument("--draft", type=float, default=8.0, help="T, metres (8)")
    parser.add_argument("--nx", type=int, default=200, help="panels along x (200)")
    parser.add_argument("--nz", type=int, default=40, help="panels along z (40)")
    parser.add_argument("--binary", action="store_true", help="binary STL (default ASCII)")
    a = parser.parse_args()
    if min(a.length, a.beam, a.draft) <= 0 or a.nx < 1 or a.nz < 1:
        sys.exit("make_wigley_hull.py: --length, --beam, --draft must be > 0 and --nx, --nz >= 1")
    tris = facets(a.length, a.beam, a.draft, a.nx, a.nz)
    (write_binary if a.binary else write_ascii)(a.out, tris)
    print("%s: %d facets, L = %g m, B = %g m, T = %g m" % (a.out, len(tris), a.length, a.beam,
                                                          a.draft))


if __name__ == "__main__":
    main()
