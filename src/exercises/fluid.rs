//! Exercises for lesson 15, "Fluids". They work in the lesson's 2D slab: positions are `Vec2`
//! (x along the box, y up), the kernels are the 2D ones.
//!
//! Reference solutions: [`crate::fluid::kernels::poly6`], [`crate::fluid::density`],
//! [`crate::fluid::pair_force`] (its pressure part) and [`crate::fluid::pbf_lambda`], each in 2D.
//! Tick "use my exercise" in the lesson's kernel and density figures to see yours at work.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use crate::fluid::{self, kernels, Dim};
use glam::{Vec2, Vec3};

/// **Exercise 15.1: the poly6 kernel in 2D.**
///
/// A kernel weighs a neighbour by its distance `r` and is zero from the support radius `h` on.
/// poly6 takes the *squared* distance `r2 = r²` (no square root needed) and, in 2D, is
/// ```text
/// W(r) = 4 / (π h⁸) · (h² − r²)³   when r² < h²
/// W(r) = 0                          otherwise
/// ```
/// The constant `4 / (π h⁸)` makes the kernel integrate to 1 over the disc of radius `h`, so
/// that `Σ m W` over neighbours is a density (kg/m² in 2D). Return `W` (units 1/m²).
///
/// Hints: `std::f32::consts::PI`, `h.powi(8)`. The boundary belongs outside: at `r2 == h²` the
/// weight is 0 (it is anyway, `(h² − r²)³ = 0`), and beyond it must not go negative (`(h² − r²)³`
/// would).
pub fn poly6(r2: f32, h: f32) -> Answer<f32> {
    solution!(kernels::poly6(r2, h, Dim::Two));
    let _ = (r2, h);
    Err(NotDone)
}

/// **Exercise 15.2: a particle's density from its neighbours.**
///
/// Every particle carries the mass `m` (kg). The density at particle `i` (at `x`) is the sum of
/// every particle's mass weighed by the poly6 kernel of its distance, the particle's own mass
/// included (at distance 0):
/// ```text
/// ρ_i = m W(0) + Σ_j m W(|x − x_j|)
/// ```
/// `neighbours` holds the other particles' positions near `x` (the grid's candidates: some may
/// lie farther than `h`, and the kernel gives them no weight). Return `ρ_i` (kg/m² in 2D).
///
/// Hints: your 15.1 (or `W` written out again) with `r2 = (x − x_j).length_squared()`. Forgetting
/// the particle's own term makes a lone particle weigh nothing, and every density too low by
/// `m W(0)`: about 17 % of the rest density when `h` is 2.7 lattice spacings, as in the lesson's
/// figures and the grader's lattice case.
pub fn sph_density(x: Vec2, neighbours: &[Vec2], m: f32, h: f32) -> Answer<f32> {
    solution!(fluid::density(
        x.extend(0.0),
        neighbours.iter().map(|p| p.extend(0.0)),
        m,
        h,
        Dim::Two
    ));
    let _ = (x, neighbours, m, h);
    Err(NotDone)
}

/// **Exercise 15.3: the symmetric pressure force between two particles.**
///
/// Particles `i` and `j` (index 0 and 1 of each array) are at `x`, with densities `rho` and
/// pressures `p`, each of mass `m`. The pressure force on `i` from `j` is
/// ```text
/// F_ij = −m² (p_i + p_j) / (2 ρ_i ρ_j) · ∇W_spiky(x_i − x_j)
/// ∇W_spiky(r⃗) = −30 / (π h⁵) · (h − r)² · r⃗ / r     when 0 < r < h, else 0   (r = |r⃗|)
/// ```
/// The spiky kernel's gradient points from `j` towards `i` with a minus sign, so a positive
/// pressure pushes `i` away from `j`. Return `F_ij` (N).
///
/// Hints: the average of the two pressures (not `p_i` alone) makes `F_ji = −F_ij` exactly, so the
/// pair conserves momentum. At `r = 0` there is no direction: return zero rather than dividing by
/// zero.
pub fn pressure_force(x: [Vec2; 2], rho: [f32; 2], p: [f32; 2], m: f32, h: f32) -> Answer<Vec2> {
    solution!(fluid::pair_force(
        x.map(|v| v.extend(0.0)),
        [Vec3::ZERO; 2],
        rho,
        p,
        m,
        0.0,
        h,
        Dim::Two
    )
    .truncate());
    let _ = (x, rho, p, m, h);
    Err(NotDone)
}

/// **Exercise 15.4: the λ of one density constraint (position-based fluids).**
///
/// Particle `i` at `x` has the density `rho`; its constraint asks for the rest density `rho0`:
/// `C_i = ρ_i/ρ₀ − 1`. PBF only pushes apart, so an expanded particle (`C_i ≤ 0`) gets `λ_i = 0`.
/// Otherwise, with `∇W` the spiky gradient of exercise 15.3 and `m` each particle's mass:
/// ```text
/// ∇_j C_i = −(m/ρ₀) ∇W(x − x_j)        for each neighbour j
/// ∇_i C_i =  (m/ρ₀) Σ_j ∇W(x − x_j)
/// λ_i = −C_i / (|∇_i C_i|² + Σ_j |∇_j C_i|² + ε)
/// ```
/// `eps` (the relaxation ε) keeps `λ` finite where a particle has few neighbours. Return `λ_i`
/// (m², in 2D). Moving each particle `k` by `λ_i ∇_k C_i` then fixes `C_i` to first order.
///
/// Hints: one loop over the neighbours adds up both the vector `∇_i C_i` and the squared lengths
/// `|∇_j C_i|²`; `|∇_i C_i|²` is added after the loop (squaring inside the loop is the common
/// mistake).
#[allow(clippy::too_many_arguments)]
pub fn pbf_lambda(
    x: Vec2,
    neighbours: &[Vec2],
    rho: f32,
    m: f32,
    rho0: f32,
    eps: f32,
    h: f32,
) -> Answer<f32> {
    solution!(fluid::pbf_lambda(
        x.extend(0.0),
        neighbours.iter().map(|p| p.extend(0.0)),
        rho,
        m,
        rho0,
        eps,
        h,
        Dim::Two
    ));
    let _ = (x, neighbours, rho, m, rho0, eps, h);
    Err(NotDone)
}

/// A random point in the square `[lo, hi]²`.
fn vec2(rng: &mut super::grade::Rng, lo: f32, hi: f32) -> Vec2 {
    Vec2::new(rng.range(lo, hi), rng.range(lo, hi))
}

fn close(a: f32, b: f32, eps: f32) -> bool {
    (a - b).abs() <= eps * (1.0 + a.abs().max(b.abs()))
}

/// The reference of 15.2 (the core's density in 2D).
fn density_2d(x: Vec2, neighbours: &[Vec2], m: f32, h: f32) -> f32 {
    fluid::density(
        x.extend(0.0),
        neighbours.iter().map(|p| p.extend(0.0)),
        m,
        h,
        Dim::Two,
    )
}

/// Grades this file's exercises against the reference on edge cases and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    const L: &str = "15-fluids";

    let mut kernel = vec![
        ("r = 0: the peak 4 / (π h²)", (0.0, 1.0)),
        ("halfway, h = 0.1 m: the constant has h⁸", (0.0025, 0.1)),
        ("r2 = h² exactly: zero", (0.01, 0.1)),
        ("beyond the support: zero, not negative", (0.04, 0.1)),
        ("r2, not r: r2 = 0.25 with h = 1", (0.25, 1.0)),
    ];
    let mut random_kernel = Vec::new();
    for _ in 0..200 {
        let h = rng.range(0.01, 1.0);
        random_kernel.push((RANDOM, (rng.range(0.0, 1.3) * h * h, h)));
    }
    kernel.extend(random_kernel);
    let w = check_cases(
        L,
        "poly6",
        ["r2", "h"],
        &kernel,
        |&(r2, h)| poly6(r2, h),
        |&(r2, h)| kernels::poly6(r2, h, Dim::Two),
        |a, b| close(*a, *b, 1e-5),
    );

    let lattice: Vec<Vec2> = (-2..=2)
        .flat_map(|i| (-2..=2).map(move |j| Vec2::new(i as f32, j as f32) * 0.02))
        .filter(|p| *p != Vec2::ZERO)
        .collect();
    let mut dens = vec![
        (
            "no neighbours: the particle's own term m W(0)",
            (Vec2::new(0.3, 0.2), vec![], 0.4, 0.05),
        ),
        (
            "one neighbour beyond h: it adds nothing",
            (Vec2::ZERO, vec![Vec2::new(0.06, 0.0)], 0.4, 0.05),
        ),
        (
            "a lattice of 2 cm, h = 5.4 cm: close to 1000 kg/m²",
            (Vec2::ZERO, lattice, 0.4, 0.054),
        ),
        (
            "two neighbours at the same point count twice",
            (Vec2::ZERO, vec![Vec2::new(0.01, 0.0); 2], 1.0, 0.05),
        ),
    ];
    for _ in 0..200 {
        let h = rng.range(0.02, 0.2);
        let x = vec2(rng, 0.0, 1.0);
        let n = (rng.range(0.0, 30.0)) as usize;
        let nbrs = (0..n)
            .map(|_| x + vec2(rng, -1.2 * h, 1.2 * h))
            .collect::<Vec<_>>();
        dens.push((RANDOM, (x, nbrs, rng.range(0.01, 2.0), h)));
    }
    let density = check_cases(
        L,
        "sph_density",
        ["x", "neighbours", "m", "h"],
        &dens,
        |(x, n, m, h)| sph_density(*x, n, *m, *h),
        |(x, n, m, h)| density_2d(*x, n, *m, *h),
        |a, b| close(*a, *b, 1e-5),
    );

    let pressure_reference = |x: [Vec2; 2], rho: [f32; 2], p: [f32; 2], m: f32, h: f32| {
        fluid::pair_force(
            x.map(|v| v.extend(0.0)),
            [Vec3::ZERO; 2],
            rho,
            p,
            m,
            0.0,
            h,
            Dim::Two,
        )
        .truncate()
    };
    let mut pairs = vec![
        (
            "j to the left of i, positive pressures: i is pushed right (+x)",
            (
                [Vec2::new(0.02, 0.0), Vec2::ZERO],
                [1000.0, 1000.0],
                [50.0, 50.0],
                0.4,
                0.05,
            ),
        ),
        (
            "the average of both pressures: p_j = 0 still pushes",
            (
                [Vec2::new(0.0, 0.03), Vec2::ZERO],
                [1100.0, 900.0],
                [80.0, 0.0],
                0.4,
                0.05,
            ),
        ),
        (
            "r = 0: no direction, zero force",
            (
                [Vec2::splat(0.1); 2],
                [1000.0, 1000.0],
                [50.0, 50.0],
                0.4,
                0.05,
            ),
        ),
        (
            "beyond h: zero",
            (
                [Vec2::new(0.1, 0.0), Vec2::ZERO],
                [1000.0, 1000.0],
                [50.0, 50.0],
                0.4,
                0.05,
            ),
        ),
        (
            "(h − r)², not (h − r): a pair close together",
            (
                [Vec2::new(0.004, 0.003), Vec2::ZERO],
                [1200.0, 1200.0],
                [10.0, 30.0],
                0.4,
                0.05,
            ),
        ),
    ];
    for _ in 0..200 {
        let h = rng.range(0.02, 0.2);
        let xi = vec2(rng, 0.0, 1.0);
        let xj = xi + vec2(rng, -h, h);
        pairs.push((
            RANDOM,
            (
                [xi, xj],
                [rng.range(500.0, 1500.0), rng.range(500.0, 1500.0)],
                [rng.range(0.0, 500.0), rng.range(0.0, 500.0)],
                rng.range(0.01, 2.0),
                h,
            ),
        ));
    }
    let force = check_cases(
        L,
        "pressure_force",
        ["x", "rho", "p", "m", "h"],
        &pairs,
        |&(x, rho, p, m, h)| pressure_force(x, rho, p, m, h),
        |&(x, rho, p, m, h)| pressure_reference(x, rho, p, m, h),
        |a, b| {
            let scale = 1.0 + a.abs().max_element().max(b.abs().max_element());
            (*a - *b).abs().max_element() <= 1e-4 * scale
        },
    );

    let ring: Vec<Vec2> = (0..6)
        .map(|k| {
            let a = std::f32::consts::TAU * k as f32 / 6.0;
            0.02 * Vec2::new(a.cos(), a.sin())
        })
        .collect();
    let mut lambdas = vec![
        (
            "expanded (ρ below ρ₀): λ = 0",
            (Vec2::ZERO, ring.clone(), 900.0, 0.4, 1000.0, 1e-4, 0.05),
        ),
        (
            "a symmetric ring: ∇_i C is zero, only the neighbours' terms count",
            (Vec2::ZERO, ring.clone(), 1100.0, 0.4, 1000.0, 1e-4, 0.05),
        ),
        (
            "neighbours on one side: |Σ ∇W|², not Σ |∇W|², for the particle itself",
            (
                Vec2::ZERO,
                vec![Vec2::new(0.02, 0.0), Vec2::new(0.02, 0.01)],
                1050.0,
                0.4,
                1000.0,
                1e-4,
                0.05,
            ),
        ),
        (
            "no neighbours: only ε in the denominator",
            (Vec2::ZERO, vec![], 1200.0, 0.4, 1000.0, 0.01, 0.05),
        ),
    ];
    for _ in 0..200 {
        let h = rng.range(0.02, 0.2);
        let x = vec2(rng, 0.0, 1.0);
        let n = rng.range(0.0, 25.0) as usize;
        let nbrs = (0..n).map(|_| x + vec2(rng, -h, h)).collect::<Vec<_>>();
        lambdas.push((
            RANDOM,
            (
                x,
                nbrs,
                rng.range(800.0, 1500.0),
                rng.range(0.01, 2.0),
                1000.0,
                rng.range(1e-5, 1e-2),
                h,
            ),
        ));
    }
    let lambda = check_cases(
        L,
        "pbf_lambda",
        ["x", "neighbours", "rho", "m", "rho0", "eps", "h"],
        &lambdas,
        |(x, n, rho, m, rho0, eps, h)| pbf_lambda(*x, n, *rho, *m, *rho0, *eps, *h),
        |(x, n, rho, m, rho0, eps, h)| {
            fluid::pbf_lambda(
                x.extend(0.0),
                n.iter().map(|p| p.extend(0.0)),
                *rho,
                *m,
                *rho0,
                *eps,
                *h,
                Dim::Two,
            )
        },
        |a, b| close(*a, *b, 1e-4),
    );
    vec![w, density, force, lambda]
}
