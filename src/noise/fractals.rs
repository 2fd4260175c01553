//! Two classic fractals: simple recursive rules that produce detail at every scale.
//!
//! ```text
//! Koch:        every segment [a, b] becomes four: a → p₁ → peak → p₂ → b, with p₁, p₂ at thirds
//!              and the peak the apex of an equilateral triangle on [p₁, p₂]; 3 · 4ᵈ segments
//! Sierpinski:  every triangle becomes its three corner triangles (the middle one is removed);
//!              3ᵈ triangles
//! ```
//! Lesson: lessons/05-noise (section "Fractals").

use glam::Vec2;

/// The deepest recursion drawn: Koch at depth 7 is 3 · 4⁷ = 49 152 segments and Sierpinski 3⁷ =
/// 2 187 triangles; each further level multiplies the work by 4 or 3.
pub const MAX_DEPTH: u32 = 7;

fn check_depth(depth: u32) -> Result<(), String> {
    if depth > MAX_DEPTH {
        Err(format!("depth must be at most {MAX_DEPTH}, got {depth}"))
    } else {
        Ok(())
    }
}

/// The Koch snowflake of `depth` as a closed polyline (first point repeated at the end), on the
/// equilateral triangle inscribed in the circle of `radius` around the origin, clockwise so the
/// bumps point outwards. Writes into `out` (cleared first).
pub fn koch_snowflake(depth: u32, radius: f32, out: &mut Vec<Vec2>) -> Result<(), String> {
    check_depth(depth)?;
    out.clear();
    let corner = |k: f32| {
        let a = std::f32::consts::FRAC_PI_2 - k * std::f32::consts::TAU / 3.0;
        radius * Vec2::new(a.cos(), a.sin())
    };
    let corners = [corner(0.0), corner(1.0), corner(2.0)];
    out.push(corners[0]);
    for i in 0..3 {
        koch_segment(corners[i], corners[(i + 1) % 3], depth, out);
    }
    Ok(())
}

/// Appends the Koch curve from `a` to `b` (without `a`).
fn koch_segment(a: Vec2, b: Vec2, depth: u32, out: &mut Vec<Vec2>) {
    if depth == 0 {
        out.push(b);
        return;
    }
    let d = (b - a) / 3.0;
    let p1 = a + d;
    let p2 = a + 2.0 * d;
    // The apex sits on the left of a → b for a clockwise outline: d turned by +60°.
    let peak = p1 + Vec2::from_angle(std::f32::consts::FRAC_PI_3).rotate(d);
    koch_segment(a, p1, depth - 1, out);
    koch_segment(p1, peak, depth - 1, out);
    koch_segment(peak, p2, depth - 1, out);
    koch_segment(p2, b, depth - 1, out);
}

/// The filled triangles of the Sierpinski triangle of `depth` inside the triangle `corners`,
/// written into `out` (cleared first): `3^depth` triangles, each half the size of its parent.
pub fn sierpinski(depth: u32, corners: [Vec2; 3], out: &mut Vec<[Vec2; 3]>) -> Result<(), String> {
    check_depth(depth)?;
    out.clear();
    sierpinski_rec(corners, depth, out);
    Ok(())
}

fn sierpinski_rec(t: [Vec2; 3], depth: u32, out: &mut Vec<[Vec2; 3]>) {
    if depth == 0 {
        out.push(t);
        return;
    }
    let [a, b, c] = t;
    let (ab, bc, ca) = ((a + b) / 2.0, (b + c) / 2.0, (c + a) / 2.0);
    sierpinski_rec([a, ab, ca], depth - 1, out);
    sierpinski_rec([ab, b, bc], depth - 1, out);
    sierpinski_rec([ca, bc, c], depth - 1, out);
}
