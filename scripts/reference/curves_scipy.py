#!/usr/bin/env python3
"""Reference values for the keyframe curves core (src/curves), checked by tests/curves.rs.

Draws random keys at non-uniform times, then evaluates two established implementations:
  * scipy.interpolate.CubicHermiteSpline  (explicit tangents: our Interpolation::Hermite)
  * scipy.interpolate.CubicSpline(bc_type="natural")  (our Interpolation::Natural)
at sample times inside the keyed range and at the keys themselves.

Keys are rounded to float32 before scipy sees them, so that the Rust test (in f32) and scipy
(in f64) interpolate exactly the same data; only the evaluation precision differs.

Usage:  python3 scripts/reference/curves_scipy.py > tests/data/curves_scipy.csv

Output format (parsed by hand in the test, no serde): lines starting with '#' are comments;
a line 'section NAME' starts a table whose rows are comma-separated numbers, columns named in
the comment just after it.
"""

import sys

import numpy as np
import scipy
from scipy.interpolate import CubicHermiteSpline, CubicSpline

SEED = 20240603


def f32(values):
    """Round to float32, return float64 (exactly representable in f32)."""
    return np.asarray(values, dtype=np.float32).astype(np.float64)


def random_times(rng, count):
    """Strictly increasing, non-uniform times: steps between 0.15 s and 1.6 s."""
    start = rng.uniform(-1.0, 1.0)
    return f32(start + np.concatenate([[0.0], np.cumsum(rng.uniform(0.15, 1.6, count - 1))]))


def sample_times(rng, times, count):
    """Sorted random times inside the keyed range, plus every key time."""
    inside = f32(rng.uniform(times[0], times[-1], count))
    return np.sort(np.concatenate([inside, times]))


def write_section(out, name, columns, rows):
    out.write(f"section {name}\n")
    out.write("# " + ",".join(columns) + "\n")
    for row in rows:
        out.write(",".join(f"{v:.9g}" for v in row) + "\n")


def main():
    rng = np.random.default_rng(SEED)
    out = sys.stdout
    out.write("# Reference values for tests/curves.rs, written by scripts/reference/curves_scipy.py\n")
    out.write(f"# scipy {scipy.__version__}, numpy {np.__version__}, python {sys.version.split()[0]}, "
              f"seed {SEED}\n")

    # Cubic Hermite with explicit tangents (one tangent per key: in = out).
    times = random_times(rng, 8)
    values = f32(rng.uniform(-2.0, 2.0, times.size))
    tangents = f32(rng.uniform(-3.0, 3.0, times.size))
    spline = CubicHermiteSpline(times, values, tangents)
    write_section(out, "hermite_keys", ["t", "p", "d"], zip(times, values, tangents))
    ts = sample_times(rng, times, 24)
    write_section(out, "hermite_samples", ["t", "p", "dp/dt", "d2p/dt2"],
                  zip(ts, spline(ts), spline(ts, 1), spline(ts, 2)))

    # Natural cubic spline (zero second derivative at both ends).
    times = random_times(rng, 9)
    values = f32(rng.uniform(-2.0, 2.0, times.size))
    spline = CubicSpline(times, values, bc_type="natural")
    write_section(out, "natural_keys", ["t", "p"], zip(times, values))
    ts = sample_times(rng, times, 24)
    write_section(out, "natural_samples", ["t", "p", "dp/dt", "d2p/dt2"],
                  zip(ts, spline(ts), spline(ts, 1), spline(ts, 2)))


if __name__ == "__main__":
    main()
