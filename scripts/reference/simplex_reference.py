#!/usr/bin/env python3
"""Generates tests/data/simplex_reference.csv: values of Stefan Gustavson's simplex noise.

Source: Stefan Gustavson, "SimplexNoise1234" (simplexnoise1234.cpp, 2003-2011, released into the
public domain in February 2011; the 2D and 3D functions `SimplexNoise1234::noise(x, y)` and
`noise(x, y, z)`, their `grad` helpers, the skew macros F2 = 0.366025403, G2 = 0.211324865,
F3 = 0.333333333, G3 = 0.166666667, the scale factors 45.23 and 32.74, and Ken Perlin's
permutation). This script transcribes that C++ code into Python operation by operation, in IEEE
single precision as the C++ `float`s compute (each float operation is rounded to float32; the
macros are double literals, so the expressions that use them are computed in double and then
stored to float, as C++ does). FASTFLOOR is the C++ macro, ((x) > 0 ? (int)x : (int)x - 1).

Usage:  python3 scripts/reference/simplex_reference.py > tests/data/simplex_reference.csv
No packages needed (Python 3 standard library only; written with Python 3.11).

Output: '#' lines are comments; then rows "x,y,z,value" with every number printed by repr():
rows with z = "-" are the 2D noise at (x, y), the others the 3D noise at (x, y, z). The inputs
are float32 values (random points from a seeded generator, away from cell boundaries where the
C++ FASTFLOOR and a true floor pick different but equivalent cells).
"""

import random
import struct

PERM = [
    151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69,
    142, 8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219,
    203, 117, 35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175,
    74, 165, 71, 134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230,
    220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76,
    132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173,
    186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206,
    59, 227, 47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163,
    70, 221, 153, 101, 155, 167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232,
    178, 185, 112, 104, 218, 246, 97, 228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162,
    241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192, 214, 31, 181, 199, 106, 157, 184, 84, 204,
    176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93, 222, 114, 67, 29, 24, 72, 243, 141,
    128, 195, 78, 66, 215, 61, 156, 180,
]
perm = PERM + PERM

F2, G2 = 0.366025403, 0.211324865
F3, G3 = 0.333333333, 0.166666667


def f(v):
    """Rounds a Python float (double) to the nearest float32."""
    return struct.unpack("f", struct.pack("f", v))[0]


def fastfloor(x):
    return int(x) if x > 0 else int(x) - 1


def grad2(h, x, y):
    h &= 7
    u, v = (x, y) if h < 4 else (y, x)
    return f((-u if h & 1 else u) + (f(-2.0 * v) if h & 2 else f(2.0 * v)))


def grad3(h, x, y, z):
    h &= 15
    u = x if h < 8 else y
    v = y if h < 4 else (x if h in (12, 14) else z)
    return f((-u if h & 1 else u) + (-v if h & 2 else v))


def corner(r2, d2, g):
    t = f(r2 - d2)
    if t < 0.0:
        return 0.0
    t = f(t * t)
    return f(f(t * t) * g)


def noise2(x, y):
    s = f(f(x + y) * F2)
    i, j = fastfloor(f(x + s)), fastfloor(f(y + s))
    t = f((i + j) * G2)
    x0, y0 = f(x - f(i - t)), f(y - f(j - t))
    i1, j1 = (1, 0) if x0 > y0 else (0, 1)
    x1, y1 = f(x0 - i1 + G2), f(y0 - j1 + G2)
    x2, y2 = f(x0 - 1.0 + 2.0 * G2), f(y0 - 1.0 + 2.0 * G2)
    ii, jj = i & 0xFF, j & 0xFF
    d2 = lambda a, b: f(f(a * a) + f(b * b))
    n0 = corner(0.5, d2(x0, y0), grad2(perm[ii + perm[jj]], x0, y0))
    n1 = corner(0.5, d2(x1, y1), grad2(perm[ii + i1 + perm[jj + j1]], x1, y1))
    n2 = corner(0.5, d2(x2, y2), grad2(perm[ii + 1 + perm[jj + 1]], x2, y2))
    return f(f(45.23) * f(f(n0 + n1) + n2))


def noise3(x, y, z):
    s = f(f(f(x + y) + z) * F3)
    i, j, k = fastfloor(f(x + s)), fastfloor(f(y + s)), fastfloor(f(z + s))
    t = f((i + j + k) * G3)
    x0, y0, z0 = f(x - f(i - t)), f(y - f(j - t)), f(z - f(k - t))
    if x0 >= y0:
        if y0 >= z0:
            o1, o2 = (1, 0, 0), (1, 1, 0)
        elif x0 >= z0:
            o1, o2 = (1, 0, 0), (1, 0, 1)
        else:
            o1, o2 = (0, 0, 1), (1, 0, 1)
    else:
        if y0 < z0:
            o1, o2 = (0, 0, 1), (0, 1, 1)
        elif x0 < z0:
            o1, o2 = (0, 1, 0), (0, 1, 1)
        else:
            o1, o2 = (0, 1, 0), (1, 1, 0)
    ii, jj, kk = i & 0xFF, j & 0xFF, k & 0xFF
    total = 0.0
    for (a, b, c), g in (((0, 0, 0), 0.0), (o1, G3), (o2, 2.0 * G3), ((1, 1, 1), 3.0 * G3)):
        dx, dy, dz = f(x0 - a + g), f(y0 - b + g), f(z0 - c + g)
        d2 = f(f(f(dx * dx) + f(dy * dy)) + f(dz * dz))
        h = perm[ii + a + perm[jj + b + perm[kk + c]]]
        total = f(total + corner(0.6, d2, grad3(h, dx, dy, dz)))
    return f(f(32.74) * total)


def main():
    rng = random.Random(2011)
    print("# Stefan Gustavson's SimplexNoise1234 (public domain), 2D and 3D, float32 transcription.")
    print("# Generated by scripts/reference/simplex_reference.py (Python 3.11, standard library).")
    print("# x,y,z,value  (z = - : the 2D noise)")
    rows = 0
    while rows < 400:
        scale = rng.choice([1.0, 4.0, 30.0, 300.0])
        x, y, z = (f(rng.uniform(-scale, scale)) for _ in range(3))
        if rows < 200:
            s = f(f(x + y) * F2)
            if min(abs(v - round(v)) for v in (f(x + s), f(y + s))) < 1e-3:
                continue
            print(f"{x!r},{y!r},-,{noise2(x, y)!r}")
        else:
            s = f(f(f(x + y) + z) * F3)
            if min(abs(v - round(v)) for v in (f(x + s), f(y + s), f(z + s))) < 1e-3:
                continue
            print(f"{x!r},{y!r},{z!r},{noise3(x, y, z)!r}")
        rows += 1


if __name__ == "__main__":
    main()
