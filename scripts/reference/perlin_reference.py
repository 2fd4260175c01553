#!/usr/bin/env python3
"""Generates tests/data/perlin_reference.csv: values of Ken Perlin's improved noise (2002).

Source: Ken Perlin, "Improving Noise", SIGGRAPH 2002, and his Java reference implementation
"ImprovedNoise" published at https://mrl.cs.nyu.edu/~perlin/noise/ (class ImprovedNoise,
methods noise, fade, lerp, grad, and the 256-entry permutation). This script transcribes that
algorithm into Python floats (IEEE doubles, as Java's double) operation by operation, so its
values are the reference's own, to the last bit: noise(3.14, 42, 7) = 0.13691995878400012.

Usage:  python3 scripts/reference/perlin_reference.py > tests/data/perlin_reference.csv
No packages needed (Python 3 standard library only; written with Python 3.11).

Output: '#' lines are comments; then rows "x,y,z,noise" with every number printed by repr()
(shortest digits that round-trip a double). Rows with z = 0 check the 2D slice
noise2(x, y) = noise(x, y, 0) as well.
"""

import math
import random

PERMUTATION = [
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
P = PERMUTATION + PERMUTATION


def fade(t):
    return t * t * t * (t * (t * 6 - 15) + 10)


def lerp(t, a, b):
    return a + t * (b - a)


def grad(hash_, x, y, z):
    h = hash_ & 15
    u = x if h < 8 else y
    v = y if h < 4 else (x if h == 12 or h == 14 else z)
    return (u if (h & 1) == 0 else -u) + (v if (h & 2) == 0 else -v)


def noise(x, y, z):
    X = math.floor(x) & 255
    Y = math.floor(y) & 255
    Z = math.floor(z) & 255
    x -= math.floor(x)
    y -= math.floor(y)
    z -= math.floor(z)
    u, v, w = fade(x), fade(y), fade(z)
    A = P[X] + Y
    AA = P[A] + Z
    AB = P[A + 1] + Z
    B = P[X + 1] + Y
    BA = P[B] + Z
    BB = P[B + 1] + Z
    return lerp(w,
                lerp(v, lerp(u, grad(P[AA], x, y, z), grad(P[BA], x - 1, y, z)),
                     lerp(u, grad(P[AB], x, y - 1, z), grad(P[BB], x - 1, y - 1, z))),
                lerp(v, lerp(u, grad(P[AA + 1], x, y, z - 1), grad(P[BA + 1], x - 1, y, z - 1)),
                     lerp(u, grad(P[AB + 1], x, y - 1, z - 1), grad(P[BB + 1], x - 1, y - 1, z - 1))))


def main():
    assert noise(3.14, 42, 7) == 0.13691995878400012
    rng = random.Random(20021)
    points = [(3.14, 42.0, 7.0), (0.5, 0.5, 0.5), (-0.5, -1.25, 2.75), (255.5, 256.5, -0.25)]
    for _ in range(400):  # 3D, around the origin and across the wrap at 256
        points.append(tuple(rng.uniform(-300.0, 300.0) for _ in range(3)))
    for _ in range(300):  # small coordinates, where terrains sample
        points.append(tuple(rng.uniform(-4.0, 4.0) for _ in range(3)))
    for _ in range(300):  # the 2D slice, z = 0
        points.append((rng.uniform(-50.0, 50.0), rng.uniform(-50.0, 50.0), 0.0))
    print("# Ken Perlin's improved noise (2002), reference algorithm transcribed in")
    print("# scripts/reference/perlin_reference.py (Python doubles); x,y,z,noise")
    for x, y, z in points:
        print(f"{x!r},{y!r},{z!r},{noise(x, y, z)!r}")


if __name__ == "__main__":
    main()
