#!/usr/bin/env python3
"""How many candidate tests a boids step costs per boid with the grid of src/boids/grid.rs, for the
flock of `benchmark_flock` (uniform boids at one per cubic metre, search radius 1.5 m), in two
designs. Pure Python, no dependencies; prints per-boid averages. Usage: scripts/boids-candidates.py [N]

- "current": one boid against four candidate slots at a time (Flock::simd_sums): per row of the
  3 x 3 rows around the boid's cell, the cells its ball's chord crosses (X_SPLIT = 4 cells per
  radius along x), read in whole chunks of four, a `done` cursor so no slot is read twice.
- "group G": G consecutive boids of one row of cells in the lanes, one candidate at a time splatted
  to all lanes: per row, the union of the lanes' chord ranges.
Both make four pair tests per step of their inner loop, so chunks and iterations compare directly.
"""
import math
import random
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 30000
random.seed(1)
r = 1.5
r2 = r * r
half = 0.5 * n ** (1 / 3)
pts = [tuple(random.uniform(-half, half) for _ in range(3)) for _ in range(n)]
origin = -half - r
extent = 2 * half + 2 * r
xs, cs = r / 4, r
dx, dy, dz = math.ceil(extent / xs), math.ceil(extent / cs), math.ceil(extent / cs)


def cell(p):
    clamp = lambda v, size, d: min(max(int((v - origin) / size), 0), d - 1)
    return clamp(p[0], xs, dx), clamp(p[1], cs, dy), clamp(p[2], cs, dz)


cells = [cell(p) for p in pts]
index = [c[0] + dx * (c[1] + dy * c[2]) for c in cells]
order = sorted(range(n), key=lambda i: index[i])
P = [pts[i] for i in order]
C = [cells[i] for i in order]
start = [0] * (dx * dy * dz + 1)
for i in order:
    start[index[i] + 1] += 1
for c in range(dx * dy * dz):
    start[c + 1] += start[c]


def reach(p, c, jj, kk):
    """The first and last cell of row (cj - 1 + jj, ck - 1 + kk) that the ball around p reaches."""
    ci, cj, ck = c
    j, k = cj - 1 + jj, ck - 1 + kk
    if not (0 <= j < dy and 0 <= k < dz):
        return None
    gap = lambda v, cnew: max(origin + cnew * cs - v, 0, v - (origin + (cnew + 1) * cs))
    rest = r2 - gap(p[1], j) ** 2 - gap(p[2], k) ** 2
    if rest < 0:
        return None
    h = math.sqrt(rest)
    x_cell = lambda x: min(max(int(max((x - origin) / xs, 0)), max(ci - 4, 0)), min(ci + 4, dx - 1))
    row = dx * (j + dy * k)
    return row + x_cell(p[0] - h), row + x_cell(p[0] + h)


chunks = runs = 0
for s in range(n):
    done = 0
    for kk in range(3):
        for jj in range(3):
            R = reach(P[s], C[s], jj, kk)
            if not R:
                continue
            a, b = start[R[0]], start[R[1] + 1]
            at = max(a, done)
            if b > at:
                k = (b - at + 3) // 4
                chunks += k
                done = at + 4 * k
            runs += 1
print(f"current: {chunks / n:.2f} chunks of four per boid, {runs / n:.2f} runs per boid")
for G in (2, 3, 4):
    iterations = groups = union_runs = 0
    s = 0
    while s < n:
        e = s
        while e < n and e < s + G and C[e][1:] == C[s][1:]:
            e += 1
        groups += 1
        for kk in range(3):
            for jj in range(3):
                reached = [R for t in range(s, e) if (R := reach(P[t], C[t], jj, kk))]
                if reached:
                    lo, hi = min(R[0] for R in reached), max(R[1] for R in reached)
                    iterations += start[hi + 1] - start[lo]
                    union_runs += 1
        s = e
    print(f"group {G}: {iterations / n:.2f} iterations per boid ({n / groups:.2f} of {G} lanes used), "
          f"{union_runs / n:.2f} runs per boid")
