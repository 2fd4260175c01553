//! Bouncing: ballistic flight under constant gravity, stopped at the exact time of impact with a
//! floor or a sphere inside the step (not clamped back afterwards), a bounce with restitution and
//! friction, and resting contact that does not jitter.

use super::integrate::free_fall;
use glam::Vec3;

/// A static sphere particles bounce off (centre in world space, radius in metres).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    pub center: Vec3,
    pub radius: f32,
}

/// A wall: the plane `n · p = offset` with unit normal `n`; particles stay on the side it
/// points to (`n · p ≥ offset`). Its time of impact is the floor's along `n`, with the height,
/// velocity and gravity measured along `n` ([`floor_time_of_impact`]), so a vertical wall, where
/// `n · g = 0`, is reached along a straight line in the horizontal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    pub normal: Vec3,
    pub offset: f32,
}

impl Plane {
    /// The plane through `point` with unit normal `normal`.
    pub fn through(point: Vec3, normal: Vec3) -> Self {
        Self {
            normal,
            offset: normal.dot(point),
        }
    }

    /// Signed distance of `p` from the plane, positive on the side particles keep to.
    pub fn distance(&self, p: Vec3) -> f32 {
        self.normal.dot(p) - self.offset
    }
}

/// What particles bounce on, and how.
#[derive(Clone, Debug, PartialEq)]
pub struct Surfaces {
    /// Acceleration of gravity, m/s² (the floor needs `g.y < 0` to rest on).
    pub gravity: Vec3,
    /// Height of the floor plane `y = floor_y`, metres; `None` for no floor.
    pub floor_y: Option<f32>,
    /// Static spheres.
    pub spheres: Vec<Sphere>,
    /// Walls (planes) besides the floor, e.g. the four sides of a box; nothing rests on them.
    /// The GPU step (`figures::gpu`) knows the floor and spheres only.
    pub walls: Vec<Plane>,
    /// Restitution `e ∈ [0, 1]`: the normal speed after a bounce is `e` times the one before.
    pub restitution: f32,
    /// Friction `μ ≥ 0`: a bounce takes `μ |Δv_n|` off the tangential speed (never reversing
    /// it); resting on the floor takes `μ |g| dt` per step.
    pub friction: f32,
}

impl Default for Surfaces {
    fn default() -> Self {
        Self {
            gravity: Vec3::new(0.0, -9.81, 0.0),
            floor_y: Some(0.0),
            spheres: Vec::new(),
            walls: Vec::new(),
            restitution: 0.7,
            friction: 0.2,
        }
    }
}

/// The most bounces handled inside one step; after that the particle stops where it is (a
/// guard against a particle trapped between two surfaces).
pub const MAX_BOUNCES_PER_STEP: usize = 8;

/// Below this normal speed (m/s) after a bounce the particle stays on the surface: it rests on
/// the floor, or slides on a sphere (or leaves it where the sphere curves away too fast).
pub const REST_SPEED: f32 = 0.05;

/// The first time `t ∈ [0, t_max]` at which a body falling from height `y0` with vertical
/// velocity `vy` under vertical acceleration `gy` (negative: down) reaches the floor `y = floor_y`
/// from above, or `None` if it does not within `t_max`:
/// ```text
/// y(t) = y0 + vy t + ½ gy t² = floor_y
/// h = y0 − floor_y ≥ 0,   t = (−vy − √(vy² − 2 gy h)) / gy     (gy < 0, the later root)
/// ```
/// With `gy = 0` the motion is a line: `t = −h / vy` when `vy < 0`. A body below the floor (or
/// on it and not rising) gives `Some(0)`; one on it and rising gives its landing time. Uses the numerically stable form `t = 2h / (−vy + √(vy² − 2 gy h))`
/// where it can. Exercise 11.1; lesson: lessons/11-particles.
pub fn floor_time_of_impact(y0: f32, vy: f32, gy: f32, floor_y: f32, t_max: f32) -> Option<f32> {
    let h = y0 - floor_y;
    if h < 0.0 || (h == 0.0 && vy <= 0.0) {
        // Below the floor, or on it and not moving up: an impact now unless moving up and away.
        return (vy <= 0.0).then_some(0.0);
    }
    let t = if gy == 0.0 {
        if vy >= 0.0 {
            return None;
        }
        -h / vy
    } else {
        let disc = vy * vy - 2.0 * gy * h;
        if disc < 0.0 {
            return None; // pulled upwards and never gets down
        }
        let root = disc.sqrt();
        // The floor is reached going down: t = (−vy − √disc)/gy for gy < 0. When vy > 0 the
        // two terms add; when vy ≤ 0 the same root written 2h/(−vy + √disc) avoids subtracting
        // nearly equal numbers (the roots' product is 2h/gy).
        if vy > 0.0 {
            if gy >= 0.0 {
                return None;
            }
            (-vy - root) / gy
        } else {
            let denom = -vy + root;
            if denom <= 0.0 {
                return None;
            }
            2.0 * h / denom
        }
    };
    (t <= t_max).then_some(t)
}

/// The first time in `[0, t_max]` at which the ballistic path from `(p, v)` under `g` enters
/// `sphere`, if it does. `|p(t) − c|² = R²` is a quartic in `t`; the path is sampled at a few
/// times in the step (so a graze shorter than a sixteenth of the step can be missed) and the
/// first sign change is refined by bisection to float precision: exact up to rounding. A path
/// that starts on the sphere (or inside, by rounding) is an impact at 0 if it goes in, and
/// otherwise searched like any other (a slow bounce off the surface falls back within the step).
pub fn sphere_time_of_impact(p: Vec3, v: Vec3, g: Vec3, sphere: Sphere, t_max: f32) -> Option<f32> {
    let f = |t: f32| {
        let (q, _) = free_fall(p, v, g, t);
        (q - sphere.center).length_squared() - sphere.radius * sphere.radius
    };
    const SAMPLES: usize = 16;
    if f(0.0) <= 0.0 && ((p - sphere.center).dot(v) < 0.0 || f(t_max / SAMPLES as f32) < 0.0) {
        // Already on or inside, and going in: moving inwards, or inside at the first sample (a
        // particle sliding along the surface ends its step on it, moving along it up to
        // rounding, and gravity pulls it in). One on it and leaving it may still fall back in
        // later in the step: the samples below look for that.
        return Some(0.0);
    }
    let mut lo = 0.0;
    for k in 1..=SAMPLES {
        let hi = t_max * k as f32 / SAMPLES as f32;
        if f(hi) <= 0.0 {
            let (mut a, mut b) = (lo, hi);
            for _ in 0..40 {
                let m = 0.5 * (a + b);
                if f(m) > 0.0 {
                    a = m;
                } else {
                    b = m;
                }
            }
            return Some(a); // the last time still outside
        }
        lo = hi;
    }
    None
}

/// The velocity after a bounce on a surface with unit normal `n`: the normal part reversed and
/// scaled by `e`, the tangential part slowed by `μ |Δv_n|` (Coulomb-like), never reversed.
/// ```text
/// v_n = (v·n) n,  v_t = v − v_n
/// v′ = −e v_n + max(0, 1 − μ (1 + e) |v_n| / |v_t|) v_t
/// ```
pub fn bounce_velocity(v: Vec3, n: Vec3, restitution: f32, friction: f32) -> Vec3 {
    let vn = v.dot(n) * n;
    let vt = v - vn;
    let dvn = (1.0 + restitution) * vn.length();
    let vt_len = vt.length();
    let keep = if vt_len > 0.0 {
        (1.0 - friction * dvn / vt_len).max(0.0)
    } else {
        0.0
    };
    -restitution * vn + keep * vt
}

/// The force per unit mass (m/s²) with which the outside of `sphere` holds a particle on it at
/// the unit normal `n`, moving along the surface with velocity `v` under gravity `g`: the surface
/// supplies what the path's turn needs (`|v|²/R` towards the centre) beyond gravity's pull inwards,
/// `N = −g·n − |v|²/R`. It can only push: where `N ≤ 0` the particle leaves the surface.
pub fn sphere_contact_force(n: Vec3, v: Vec3, g: Vec3, sphere: Sphere) -> f32 {
    -g.dot(n) - v.length_squared() / sphere.radius
}

/// `dt` seconds of sliding on the outside of `sphere` from `p` (on its surface) with velocity `v`
/// (along it): gravity's tangential part speeds it up, Coulomb friction `μ N` slows it (never
/// backwards), a semi-implicit Euler step moves it along the tangent plane, and it is put back
/// on the surface with its velocity along the surface there. Energy only falls: the step along
/// the tangent loses `|g_t|² dt² / 2`, and putting it back moves it inwards, which is down where
/// `N > 0`.
fn slide_on_sphere(p: &mut Vec3, v: &mut Vec3, sphere: Sphere, dt: f32, s: &Surfaces) {
    let g = s.gravity;
    let n = (*p - sphere.center).normalize_or(Vec3::Y);
    let press = sphere_contact_force(n, *v, g, sphere).max(0.0);
    let mut vt = *v + (g - g.dot(n) * n) * dt;
    let slow = s.friction * press * dt;
    let len = vt.length();
    vt = if len > slow {
        vt * (1.0 - slow / len)
    } else {
        Vec3::ZERO
    };
    let n1 = (*p + vt * dt - sphere.center).normalize_or(n);
    *p = sphere.center + n1 * sphere.radius;
    *v = vt - vt.dot(n1) * n1;
}

/// Which surface a step hits first.
#[derive(Clone, Copy)]
enum Surface {
    Floor,
    Sphere(Sphere),
    Wall(Plane),
}

/// Advances one particle by `dt` along its exact ballistic path, bouncing off the floor, the
/// spheres and the walls of `surfaces` at the exact time of impact inside the step. `resting` marks a particle
/// lying on the floor: it then stays at `y = floor_y` with `v.y = 0` and slides with friction
/// until something lifts it. A particle that lands on a sphere too slowly to bounce slides on it
/// ([`sphere_contact_force`]) until it comes to rest or the sphere curves away beneath it. Nothing
/// ends a step below the floor.
pub fn ballistic_step(p: &mut Vec3, v: &mut Vec3, resting: &mut bool, dt: f32, s: &Surfaces) {
    let g = s.gravity;
    if *resting {
        if let Some(floor) = s.floor_y {
            if g.y <= 0.0 {
                // Slide along the floor: gravity's tangential part plus friction μ |g_n|.
                let gt = Vec3::new(g.x, 0.0, g.z);
                let mut vt = Vec3::new(v.x, 0.0, v.z) + gt * dt;
                let slow = s.friction * (-g.y) * dt;
                let len = vt.length();
                vt = if len > slow {
                    vt * (1.0 - slow / len)
                } else {
                    Vec3::ZERO
                };
                *p += vt * dt;
                p.y = floor;
                *v = vt;
                // A slide is a straight line in the step: a wall it crossed is hit at
                // τ = depth / speed before the step's end; bounce there and slide on for τ.
                for wall in &s.walls {
                    let depth = -wall.distance(*p);
                    let vn = v.dot(wall.normal);
                    if depth > 0.0 && vn < 0.0 {
                        let tau = (depth / -vn).min(dt);
                        let hit = *p - *v * tau;
                        *v = bounce_velocity(*v, wall.normal, s.restitution, s.friction);
                        v.y = 0.0;
                        *p = hit + *v * tau;
                        p.y = floor;
                    }
                }
                return;
            }
        }
        *resting = false;
    }
    let mut remaining = dt;
    for _ in 0..MAX_BOUNCES_PER_STEP {
        // The earliest surface hit inside the remaining time.
        let mut hit: Option<(f32, Surface)> = None;
        if let Some(floor) = s.floor_y {
            if let Some(t) = floor_time_of_impact(p.y, v.y, g.y, floor, remaining) {
                hit = Some((t, Surface::Floor));
            }
        }
        for &sphere in &s.spheres {
            if let Some(t) = sphere_time_of_impact(*p, *v, g, sphere, remaining) {
                if hit.is_none_or(|(best, _)| t < best) {
                    hit = Some((t, Surface::Sphere(sphere)));
                }
            }
        }
        for &wall in &s.walls {
            let n = wall.normal;
            if let Some(t) =
                floor_time_of_impact(n.dot(*p), n.dot(*v), n.dot(g), wall.offset, remaining)
            {
                if hit.is_none_or(|(best, _)| t < best) {
                    hit = Some((t, Surface::Wall(wall)));
                }
            }
        }
        let Some((t, surface)) = hit else {
            let (q, w) = free_fall(*p, *v, g, remaining);
            *p = q;
            *v = w;
            break;
        };
        let (q, w) = free_fall(*p, *v, g, t);
        *p = q;
        remaining -= t;
        match surface {
            Surface::Floor => {
                let floor = s.floor_y.unwrap_or(p.y);
                p.y = floor; // the impact point lies on the floor (up to the solver's rounding)
                *v = bounce_velocity(w, Vec3::Y, s.restitution, s.friction);
                // Too slow to leave the floor again in a useful way: rest on it.
                if v.y < REST_SPEED && g.y < 0.0 {
                    v.y = 0.0;
                    *resting = true;
                    ballistic_step(p, v, resting, remaining, s);
                    remaining = 0.0;
                }
            }
            Surface::Wall(wall) => {
                *p -= wall.distance(*p) * wall.normal; // on the wall, not behind it
                *v = bounce_velocity(w, wall.normal, s.restitution, s.friction);
                if v.dot(wall.normal) <= 0.0 {
                    *v -= v.dot(wall.normal) * wall.normal; // e = 0: slide along it
                }
            }
            Surface::Sphere(sphere) => {
                let n = (*p - sphere.center).normalize_or(Vec3::Y);
                *p = sphere.center + n * sphere.radius; // on the surface, not inside
                *v = bounce_velocity(w, n, s.restitution, s.friction);
                if v.dot(n) < REST_SPEED {
                    // Too slow to leave the surface: it moves along it. Pressed on (gravity's
                    // pull inwards more than the turn of its path needs), it slides on the sphere
                    // for the rest of the step; otherwise it flies off, lifted a hair so that the
                    // next search does not find the same impact at t = 0 (otherwise every bounce the
                    // step allows lands at t = 0, and the ball sticks to the sphere's side).
                    *v -= v.dot(n) * n;
                    if sphere_contact_force(n, *v, g, sphere) > 0.0 {
                        slide_on_sphere(p, v, sphere, remaining, s);
                        remaining = 0.0;
                    } else {
                        *p = sphere.center + n * (sphere.radius * (1.0 + 1e-6));
                    }
                }
            }
        }
        if remaining <= 0.0 {
            break;
        }
    }
    if let Some(floor) = s.floor_y {
        // Rounding in the roots can leave a particle a hair below: never report that.
        p.y = p.y.max(floor);
    }
}
