//! Lesson 02b core, "Expressive animation": a few of Disney's principles of animation as small
//! formulas.
//!
//! - **Squash and stretch** ([`squash_stretch_scale`], [`squash_stretch_matrix`]): stretch a body
//!   along its motion and thin it across, keeping its volume, so it reads as soft and fast.
//! - **Anticipation** ([`Jump`]): a wind-up in the opposite direction before the action.
//! - **Follow-through and overlapping action** ([`spring_step`], [`Antenna`]): loose parts (a
//!   tail, an antenna) lag behind the body and keep moving after it stops; each joint follows
//!   its target through a damped spring.
//! - **Arcs** ([`arc_point`]): natural motion travels along arcs, not straight lines.
//! - **Timing, spacing, slow in and slow out**: the easing curves of lesson 02
//!   ([`crate::curves::Ease`]).
//!
//! Conventions as in the crate root: Y up, metres, seconds. Lesson: lessons/02b-expressive-animation.

use glam::{Mat3, Vec3};

/// The scale of a volume-preserving squash and stretch: `s` along the axis of motion, `1/√s`
/// across it (the two other axes), so that the volume `s · (1/√s)² = 1` never changes.
/// ```text
/// scale = (s, 1/√s, 1/√s)          s > 1 stretches, s < 1 squashes
/// ```
/// `s` must be positive; the figures clamp it to a sensible range first.
pub fn squash_stretch_scale(s: f32) -> Vec3 {
    let across = 1.0 / s.sqrt();
    Vec3::new(s, across, across)
}

/// The linear map that squashes or stretches by `s` along the unit direction `axis` and by `1/√s`
/// across it: `M = R · diag(s, 1/√s, 1/√s) · Rᵀ`, where `R` turns x onto `axis`. Its determinant
/// is 1 (volume kept). A zero axis gives the identity.
pub fn squash_stretch_matrix(axis: Vec3, s: f32) -> Mat3 {
    let Some(a) = axis.try_normalize() else {
        return Mat3::IDENTITY;
    };
    let r = Mat3::from_quat(glam::Quat::from_rotation_arc(Vec3::X, a));
    r * Mat3::from_diagonal(squash_stretch_scale(s)) * r.transpose()
}

/// The largest stretch the lesson's figures apply: at s = 1.6 a ball is already twice as long as
/// it is wide (s / (1/√s) = s^1.5 ≈ 2.0); beyond that a fast ball reads as a needle.
pub const MAX_STRETCH: f32 = 1.6;

/// How much to stretch at a speed: `s = 1 + k · speed`, at most `max_stretch`. A common rule:
/// stretch with speed, and squash (`s < 1`) only on impact.
pub fn stretch_from_speed(speed: f32, k: f32, max_stretch: f32) -> f32 {
    (1.0 + k * speed.abs()).min(max_stretch.max(1.0))
}

/// One step of a damped spring that pulls a point towards a target (semi-implicit Euler: the new
/// velocity moves the point):
/// ```text
/// a  = k (target − x) − c v          k: stiffness (1/s²), c: damping (1/s)
/// v' = v + a dt
/// x' = x + v' dt
/// ```
/// The point lags behind a moving target and overshoots when it stops: follow-through. With
/// `c² < 4k` it oscillates before it settles (under-damped); with `c² ≥ 4k` it creeps in.
pub fn spring_step(
    x: Vec3,
    v: Vec3,
    target: Vec3,
    stiffness: f32,
    damping: f32,
    dt: f32,
) -> (Vec3, Vec3) {
    let a = stiffness * (target - x) - damping * v;
    let v = v + a * dt;
    (x + v * dt, v)
}

/// A point on the circular arc through `a` and `b` that bulges by `height` metres (its sagitta)
/// along `up`, at parameter `t ∈ [0, 1]` (equal steps of angle). `height = 0` is the straight line.
pub fn arc_point(a: Vec3, b: Vec3, up: Vec3, height: f32, t: f32) -> Vec3 {
    let chord = b - a;
    let half = 0.5 * chord.length();
    let side = up.reject_from(chord).normalize_or_zero();
    if height.abs() < 1e-6 || half < 1e-6 || side == Vec3::ZERO {
        return a.lerp(b, t);
    }
    // Circle through a and b with sagitta h: radius r = (half² + h²) / 2h, centre below the top.
    let h = height;
    let r = (half * half + h * h) / (2.0 * h);
    let mid = a + 0.5 * chord;
    let centre = mid + side * (h - r);
    let (u, w) = (a - centre, b - centre);
    let angle = u.angle_between(w);
    // Sweep from u towards w inside their plane.
    let axis = u.cross(w).normalize_or_zero();
    centre + glam::Quat::from_axis_angle(axis, angle * t) * u
}

/// A jump, written as the height of a ball's bottom over time, with or without the principles.
///
/// Phases (seconds): `[0, wind_up)` crouch (the anticipation), `[wind_up, wind_up + flight)` the
/// flight, a parabola under gravity, then `[.., + settle)` the landing squash that recovers. The
/// plain version interpolates straight lines between the same keys (ground, apex, ground) with no
/// crouch and no squash.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jump {
    /// How deep the crouch goes before take-off, metres (0: no anticipation).
    pub anticipation: f32,
    /// The apex height, metres.
    pub apex: f32,
    /// Crouch duration, flight duration and landing duration, seconds.
    pub wind_up: f32,
    pub flight: f32,
    pub settle: f32,
    /// How much the body stretches per m/s of speed in flight (0: none).
    pub stretch_per_speed: f32,
}

impl Default for Jump {
    fn default() -> Self {
        Jump {
            anticipation: 0.3,
            apex: 1.6,
            wind_up: 0.5,
            flight: 1.0,
            settle: 0.4,
            stretch_per_speed: 0.06,
        }
    }
}

/// One instant of a jump: where the body's bottom is and how it is squashed or stretched
/// (vertically; `1` is at rest).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JumpSample {
    pub height: f32,
    pub vertical_velocity: f32,
    pub stretch: f32,
}

impl Jump {
    pub fn duration(&self) -> f32 {
        self.wind_up + self.flight + self.settle
    }

    /// The vertical speed at take-off and at landing, m/s: `4 apex / flight` (the parabola's
    /// slope at its ends).
    pub fn take_off_speed(&self) -> f32 {
        4.0 * self.apex / self.flight
    }

    /// The stretch in flight at take-off and landing: `1 + k · take_off_speed`, at most
    /// [`MAX_STRETCH`].
    pub fn take_off_stretch(&self) -> f32 {
        stretch_from_speed(self.take_off_speed(), self.stretch_per_speed, MAX_STRETCH)
    }

    /// The principled jump at `time_sec` (clamped to the duration). The stretch is continuous:
    /// the crouch ends in a push-off that stretches the body to the take-off stretch before it
    /// leaves the ground, and the landing squash starts from the stretch it lands with.
    /// ```text
    /// crouch (s = t / wind_up):   stretch = 1 − a·e(sin πs) + (s₀ − 1)·e((s − 0.5) / 0.5)
    /// flight:                     stretch = min(1 + k |v|, 1.6)
    /// landing (s = t' / settle):  stretch = 1 + (s₀ − 1)·(1 − e(s / 0.4)) − q·sin(π min(s / 0.8, 1))
    /// ```
    /// `e` is smoothstep clamped to [0, 1], `a` the anticipation, `s₀` the take-off stretch,
    /// `q = max(a, 0.15)` the landing squash.
    pub fn principled(&self, time_sec: f32) -> JumpSample {
        let t = time_sec.clamp(0.0, self.duration());
        let smooth = |s: f32| crate::curves::Ease::Smoothstep.apply(s.clamp(0.0, 1.0));
        let take_off = self.take_off_stretch();
        if t < self.wind_up {
            // Crouch down (squash while low), then push off: stretch up to the take-off value.
            let s = t / self.wind_up;
            let depth = self.anticipation * smooth((std::f32::consts::PI * s).sin());
            let push = (take_off - 1.0) * smooth((s - 0.5) / 0.5);
            return JumpSample {
                height: 0.0,
                vertical_velocity: 0.0,
                stretch: 1.0 - depth + push,
            };
        }
        let t = t - self.wind_up;
        if t < self.flight {
            // A parabola: y = 4 apex u (1 − u), u = t / flight; gravity g = 8 apex / flight².
            let u = t / self.flight;
            let height = 4.0 * self.apex * u * (1.0 - u);
            let velocity = 4.0 * self.apex * (1.0 - 2.0 * u) / self.flight;
            return JumpSample {
                height,
                vertical_velocity: velocity,
                stretch: stretch_from_speed(velocity, self.stretch_per_speed, MAX_STRETCH),
            };
        }
        // Landing: the stretch relaxes while a squash grows and springs back.
        let s = ((t - self.flight) / self.settle).min(1.0);
        let relax = (take_off - 1.0) * (1.0 - smooth(s / 0.4));
        let squash =
            self.anticipation.max(0.15) * (std::f32::consts::PI * (s / 0.8).min(1.0)).sin();
        JumpSample {
            height: 0.0,
            vertical_velocity: 0.0,
            stretch: 1.0 + relax - squash,
        }
    }

    /// The plain jump: linear interpolation between the keys ground (at take-off time), apex
    /// (half-way through the flight) and ground (at landing); rigid, no crouch.
    pub fn plain(&self, time_sec: f32) -> JumpSample {
        let t = time_sec.clamp(0.0, self.duration()) - self.wind_up;
        let half = 0.5 * self.flight;
        let (height, velocity) = if t <= 0.0 || t >= self.flight {
            (0.0, 0.0)
        } else if t < half {
            (self.apex * t / half, self.apex / half)
        } else {
            (self.apex * (self.flight - t) / half, -self.apex / half)
        };
        JumpSample {
            height,
            vertical_velocity: velocity,
            stretch: 1.0,
        }
    }
}

/// Follow-through: an antenna of `n` joints on top of a moving body. Each joint's target is the
/// joint below it plus the rest segment (straight up); a damped spring pulls the joint towards
/// its target, then the joint is put back at the segment's length from the joint below (so the
/// antenna bends but does not stretch).
#[derive(Clone, Debug, PartialEq)]
pub struct Antenna {
    /// World positions, joint 0 is the base (fixed to the body).
    pub positions: Vec<Vec3>,
    pub velocities: Vec<Vec3>,
    /// Length of each segment, metres.
    pub segment: f32,
}

/// The most joints an [`Antenna`] may have.
pub const MAX_JOINTS: usize = 64;

impl Antenna {
    /// A straight antenna of `joints` joints (2 to [`MAX_JOINTS`]) standing on `base`.
    pub fn new(base: Vec3, joints: usize, segment: f32) -> Self {
        let joints = joints.clamp(2, MAX_JOINTS);
        let positions = (0..joints)
            .map(|i| base + Vec3::Y * segment * i as f32)
            .collect();
        Antenna {
            positions,
            velocities: vec![Vec3::ZERO; joints],
            segment,
        }
    }

    /// Moves the base to `base` and advances every other joint by one spring step of `dt`.
    pub fn step(&mut self, base: Vec3, stiffness: f32, damping: f32, dt: f32) {
        let reference = |x, v, target, k, c, dt| Ok::<_, ()>(spring_step(x, v, target, k, c, dt));
        // The reference cannot fail.
        let _ = self.step_with(base, stiffness, damping, dt, reference);
    }

    /// [`Antenna::step`] with another spring step (a student's, in the lesson): `spring(x, v,
    /// target, k, c, dt)` returns the new position and velocity. The first error stops the step
    /// (the joints before it have moved) and is returned.
    pub fn step_with<E>(
        &mut self,
        base: Vec3,
        stiffness: f32,
        damping: f32,
        dt: f32,
        mut spring: impl FnMut(Vec3, Vec3, Vec3, f32, f32, f32) -> Result<(Vec3, Vec3), E>,
    ) -> Result<(), E> {
        let dt = dt.max(0.0);
        let old_base = self.positions[0];
        self.positions[0] = base;
        self.velocities[0] = if dt > 0.0 {
            (base - old_base) / dt
        } else {
            Vec3::ZERO
        };
        for i in 1..self.positions.len() {
            let below = self.positions[i - 1];
            let target = below + Vec3::Y * self.segment;
            let (x, v) = spring(
                self.positions[i],
                self.velocities[i],
                target,
                stiffness,
                damping,
                dt,
            )?;
            // Keep the segment's length; the velocity keeps only what the constraint allows.
            let fixed = below + (x - below).normalize_or(Vec3::Y) * self.segment;
            self.velocities[i] = if dt > 0.0 { v + (fixed - x) / dt } else { v };
            self.positions[i] = fixed;
        }
        Ok(())
    }

    /// The tip (the last joint).
    pub fn tip(&self) -> Vec3 {
        *self.positions.last().expect("at least 2 joints")
    }
}
