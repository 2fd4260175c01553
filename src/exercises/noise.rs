//! Exercises for lesson 05, "Noise and terrain".
//!
//! Reference solutions: [`crate::noise::fade`] with [`crate::noise::fade_derivative`],
//! [`crate::noise::cell2`], [`crate::noise::Fractal::sum2`] and [`crate::terrain::terrain_normal`].
//! Tick "use my exercise" in the lesson page to see your versions drive the figures.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use glam::{Vec2, Vec3};

/// **Exercise 5.1: the fade curve and its derivative.**
///
/// Return `[fade(t), fade′(t)]` for Perlin's quintic blend, `t ∈ [0, 1]`:
/// ```text
/// fade(t)  = 6t⁵ − 15t⁴ + 10t³
/// fade′(t) = 30t⁴ − 60t³ + 30t²
/// ```
/// Check yourself: `fade(0) = 0`, `fade(1) = 1`, `fade(½) = ½`, and `fade′` is 0 at both ends
/// (that is why neighbouring cells join without a kink). Horner's form `t³(t(6t − 15) + 10)`
/// needs fewer multiplications.
pub fn fade(t: f32) -> Answer<[f32; 2]> {
    solution!([crate::noise::fade(t), crate::noise::fade_derivative(t)]);
    let _ = t;
    Err(NotDone)
}

/// **Exercise 5.2: one 2D Perlin noise evaluation inside a cell.**
///
/// The cell is the unit square; `p = (x, y) ∈ [0, 1]²` is the point, and `g00, g10, g01, g11` are
/// the gradients at the corners `(0, 0), (1, 0), (0, 1), (1, 1)`. Each corner contributes the ramp
/// `g · (p − corner)`; blend the four with the fade curve:
/// ```text
/// n₀₀ = g00·p,  n₁₀ = g10·(p − (1, 0)),  n₀₁ = g01·(p − (0, 1)),  n₁₁ = g11·(p − (1, 1))
/// u = fade(x),  v = fade(y),   lerp(t, a, b) = a + t (b − a)
/// n = lerp(v, lerp(u, n₀₀, n₁₀), lerp(u, n₀₁, n₁₁))
/// ```
/// Hints: `Vec2::dot`, `Vec2::X`, `Vec2::Y`, `Vec2::ONE`; `crate::noise::fade` is there for you
/// (or use your 5.1). At a corner the answer is exactly 0, whatever the gradients.
pub fn perlin_cell(p: Vec2, g00: Vec2, g10: Vec2, g01: Vec2, g11: Vec2) -> Answer<f32> {
    solution!(crate::noise::cell2(p, [g00, g10, g01, g11]));
    let _ = (p, g00, g10, g01, g11);
    Err(NotDone)
}

/// **Exercise 5.3: the fractal sum.**
///
/// Add `n + 1` octaves of Perlin's 2D noise `f` (his own permutation) at the point `p`:
/// ```text
/// g(p) = Σ_{k=0}^{n} αᵏ f(ωᵏ p)
/// ```
/// `alpha` = α is the attenuation, `omega` = ω the frequency gain; `n = 0` is plain noise.
/// Hints: `let perm = crate::noise::Permutation::perlin();` then `perm.noise2(x, y)`. Keep a
/// running amplitude and frequency (multiply by α and ω each octave) rather than calling `powi`.
pub fn fractal_sum(p: Vec2, n: usize, alpha: f32, omega: f32) -> Answer<f32> {
    solution!(crate::noise::Fractal {
        n: n as u32,
        alpha,
        omega
    }
    .sum2(&crate::noise::Permutation::perlin(), p.x, p.y));
    let _ = (p, n, alpha, omega);
    Err(NotDone)
}

/// **Exercise 5.4: the terrain normal from the height derivative.**
///
/// The terrain is `y(u, v) = h g(s(u + o), s(v + o))` (y up). You are given `grad_g` =
/// `(∂g/∂x, ∂g/∂y)` at the point `(s(u + o), s(v + o))`. Return the unit normal:
/// ```text
/// ∂y/∂u = h s ∂g/∂x,     ∂y/∂v = h s ∂g/∂y          (chain rule)
/// n = (−∂y/∂u, 1, −∂y/∂v) / ‖(−∂y/∂u, 1, −∂y/∂v)‖
/// ```
/// Why: the surface's tangents are `(1, ∂y/∂u, 0)` along u and `(0, ∂y/∂v, 1)` along v; their
/// cross product, in the order that points up, is the vector above. A flat terrain (`h = 0`)
/// has the normal `(0, 1, 0)`.
pub fn terrain_normal(h: f32, s: f32, grad_g: Vec2) -> Answer<Vec3> {
    solution!(crate::terrain::terrain_normal(h, s, grad_g));
    let _ = (h, s, grad_g);
    Err(NotDone)
}

/// Grades this file's exercises against the reference on random and edge-case inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    const L05: &str = "05-noise";
    let close = |a: f32, b: f32, eps: f32| (a - b).abs() <= eps * (1.0 + a.abs().max(b.abs()));

    // 5.1
    let mut ts = vec![
        ("t = 0: fade 0, slope 0", 0.0),
        ("t = 1: fade 1, slope 0", 1.0),
        ("t = ½: fade ½, slope 15/8", 0.5),
        ("t = ¼: not symmetric by accident", 0.25),
        ("t near 1: the slope must vanish", 0.999),
    ];
    for _ in 0..200 {
        ts.push((RANDOM, rng.range(0.0, 1.0)));
    }
    let fade_report = check_cases(
        L05,
        "fade",
        ["t"],
        &ts,
        |&t| fade(t),
        |&t| [crate::noise::fade(t), crate::noise::fade_derivative(t)],
        |a, b| close(a[0], b[0], 1e-5) && close(a[1], b[1], 1e-4),
    );

    // 5.2
    type Cell = (Vec2, Vec2, Vec2, Vec2, Vec2);
    let (x, y) = (Vec2::X, Vec2::Y);
    let mut cells: Vec<(&str, Cell)> = vec![
        ("a corner: exactly 0", (Vec2::ZERO, x, y, -x, Vec2::ONE)),
        (
            "the far corner (1, 1): exactly 0",
            (Vec2::ONE, x, y, -x, Vec2::ONE),
        ),
        (
            "only g00 set: the ramp g00·p faded by (1 − u)(1 − v)",
            (Vec2::new(0.25, 0.5), x, Vec2::ZERO, Vec2::ZERO, Vec2::ZERO),
        ),
        (
            "only g11 set: the ramp g11·(p − (1, 1))",
            (
                Vec2::new(0.7, 0.6),
                Vec2::ZERO,
                Vec2::ZERO,
                Vec2::ZERO,
                Vec2::ONE,
            ),
        ),
        (
            "the centre: every corner weighs ¼",
            (
                Vec2::splat(0.5),
                x,
                -y,
                Vec2::new(1.0, 1.0),
                Vec2::new(-1.0, 1.0),
            ),
        ),
        (
            "p on the edge y = 0: only the bottom corners count",
            (Vec2::new(0.3, 0.0), Vec2::new(1.0, 1.0), -x, y, y),
        ),
    ];
    for _ in 0..200 {
        let mut g = || Vec2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let c = (g(), g(), g(), g(), g());
        let p = Vec2::new(rng.range(0.0, 1.0), rng.range(0.0, 1.0));
        cells.push((RANDOM, (p, c.1, c.2, c.3, c.4)));
    }
    let cell_report = check_cases(
        L05,
        "perlin_cell",
        ["p", "g00", "g10", "g01", "g11"],
        &cells,
        |&(p, a, b, c, d)| perlin_cell(p, a, b, c, d),
        |&(p, a, b, c, d)| crate::noise::cell2(p, [a, b, c, d]),
        |a, b| close(*a, *b, 1e-5),
    );

    // 5.3
    type Sum = (Vec2, usize, f32, f32);
    let mut sums: Vec<(&str, Sum)> = vec![
        ("n = 0: plain noise", (Vec2::new(0.3, 0.7), 0, 0.5, 2.0)),
        (
            "a lattice point: every octave is 0",
            (Vec2::new(2.0, -3.0), 6, 0.5, 2.0),
        ),
        (
            "α = 0: only octave 0 survives",
            (Vec2::new(0.3, 0.7), 5, 0.0, 2.0),
        ),
        (
            "the course's N = 9, α = 0.4, ω = 2",
            (Vec2::new(0.41, -0.27), 9, 0.4, 2.0),
        ),
        (
            "ω = 3: not only doubling",
            (Vec2::new(1.3, 0.2), 4, 0.6, 3.0),
        ),
        ("α = 1: no attenuation", (Vec2::new(-0.6, 0.9), 3, 1.0, 2.0)),
    ];
    for _ in 0..200 {
        let p = Vec2::new(rng.range(-4.0, 4.0), rng.range(-4.0, 4.0));
        sums.push((
            RANDOM,
            (p, rng.below(10), rng.range(0.0, 1.0), rng.range(1.0, 3.0)),
        ));
    }
    let sum_report = check_cases(
        L05,
        "fractal_sum",
        ["p", "n", "alpha", "omega"],
        &sums,
        |&(p, n, a, w)| fractal_sum(p, n, a, w),
        |&(p, n, a, w)| {
            crate::noise::Fractal {
                n: n as u32,
                alpha: a,
                omega: w,
            }
            .sum2(&crate::noise::Permutation::perlin(), p.x, p.y)
        },
        |a, b| close(*a, *b, 1e-4),
    );

    // 5.4
    let mut normals: Vec<(&str, (f32, f32, Vec2))> = vec![
        ("h = 0: flat, (0, 1, 0)", (0.0, 1.0, Vec2::new(0.7, -0.3))),
        ("zero gradient: (0, 1, 0)", (0.3, 1.0, Vec2::ZERO)),
        (
            "a slope along u only: the normal leans to −x",
            (1.0, 1.0, Vec2::new(1.0, 0.0)),
        ),
        (
            "a slope along v only: the normal leans to −z",
            (1.0, 1.0, Vec2::new(0.0, 1.0)),
        ),
        (
            "s = 2 doubles the slope (chain rule)",
            (0.5, 2.0, Vec2::new(0.4, 0.2)),
        ),
        (
            "very steep: still unit length",
            (2.0, 16.0, Vec2::new(3.0, -2.0)),
        ),
    ];
    for _ in 0..200 {
        let g = Vec2::new(rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
        normals.push((RANDOM, (rng.range(0.0, 1.0), rng.range(0.1, 4.0), g)));
    }
    let normal_report = check_cases(
        L05,
        "terrain_normal",
        ["h", "s", "grad_g"],
        &normals,
        |&(h, s, g)| terrain_normal(h, s, g),
        |&(h, s, g)| crate::terrain::terrain_normal(h, s, g),
        |a, b| (*a - *b).abs().max_element() <= 1e-4,
    );

    vec![fade_report, cell_report, sum_report, normal_report]
}
