//! Timing and spacing: easing curves, and time warps that apply them to a track.

use core::f32::consts::PI;

use super::segment::Cursor;
use super::{Sample, Track, Value};

/// An easing curve `e: [0, 1] → [0, 1]` with `e(0) = 0` and `e(1) = 1`, increasing: it changes
/// the *spacing* of the in-betweens without changing the path or the keys' timing. A curve with
/// `e′(0) = 0` starts slowly (slow-in), one with `e′(1) = 0` arrives slowly (slow-out), as in the
/// "slow in, slow out" principle of animation.
///
/// Inputs outside `[0, 1]` are clamped. `power` is clamped to at least 1 (1 is linear).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Ease {
    /// No easing.
    /// ```text
    /// e(s) = s
    /// ```
    #[default]
    Linear,
    /// Cubic slow-in and slow-out (C1 at both ends).
    /// ```text
    /// e(s) = 3s² − 2s³
    /// ```
    Smoothstep,
    /// Quintic slow-in and slow-out (C2 at both ends: no jump in acceleration).
    /// ```text
    /// e(s) = 6s⁵ − 15s⁴ + 10s³
    /// ```
    Smootherstep,
    /// Half a cosine wave: slow-in and slow-out.
    /// ```text
    /// e(s) = (1 − cos πs) / 2
    /// ```
    Sine,
    /// Slow-in only (accelerates from rest).
    /// ```text
    /// e(s) = s^power
    /// ```
    In {
        /// Exponent, at least 1; 2 is quadratic, 3 cubic.
        power: f32,
    },
    /// Slow-out only (decelerates to rest).
    /// ```text
    /// e(s) = 1 − (1 − s)^power
    /// ```
    Out {
        /// Exponent, at least 1.
        power: f32,
    },
    /// Slow-in and slow-out: `In` on the first half, `Out` on the second, joined at `(½, ½)`.
    /// ```text
    /// e(s) = 2^(power−1) s^power                 for s ≤ ½
    /// e(s) = 1 − 2^(power−1) (1 − s)^power       for s > ½
    /// ```
    InOut {
        /// Exponent, at least 1; higher means a sharper middle.
        power: f32,
    },
}

/// `x^p` and its first two derivatives, for `x ≥ 0`, `p ≥ 1`.
fn power_with_derivatives(x: f32, p: f32) -> [f32; 3] {
    let second = if p == 1.0 {
        0.0
    } else {
        p * (p - 1.0) * x.powf(p - 2.0)
    };
    [x.powf(p), p * x.powf(p - 1.0), second]
}

impl Ease {
    /// `e(s)`, with `s` clamped to `[0, 1]`.
    pub fn apply(self, s: f32) -> f32 {
        self.apply_with_derivatives(s)[0]
    }

    /// `[e(s), e′(s), e″(s)]`, with `s` clamped to `[0, 1]` (derivatives with respect to `s`;
    /// needed to carry velocity and acceleration through a [`TimeWarp`]).
    pub fn apply_with_derivatives(self, s: f32) -> [f32; 3] {
        let mut e = self.unclamped(s.clamp(0.0, 1.0));
        // The polynomials stay in [0, 1] on [0, 1], but f32 rounding can overshoot by an ulp
        // or two near the ends (smootherstep(0.9988) came out as 1.0000011).
        e[0] = e[0].clamp(0.0, 1.0);
        e
    }

    fn unclamped(self, s: f32) -> [f32; 3] {
        match self {
            Ease::Linear => [s, 1.0, 0.0],
            Ease::Smoothstep => [s * s * (3.0 - 2.0 * s), 6.0 * s * (1.0 - s), 6.0 - 12.0 * s],
            Ease::Smootherstep => {
                let (s2, s3) = (s * s, s * s * s);
                [
                    s3 * (10.0 + s * (6.0 * s - 15.0)),
                    30.0 * s2 * (s - 1.0) * (s - 1.0),
                    60.0 * s * (2.0 * s - 1.0) * (s - 1.0),
                ]
            }
            Ease::Sine => [
                0.5 * (1.0 - (PI * s).cos()),
                0.5 * PI * (PI * s).sin(),
                0.5 * PI * PI * (PI * s).cos(),
            ],
            Ease::In { power } => power_with_derivatives(s, power.max(1.0)),
            Ease::Out { power } => {
                let [f, df, ddf] = power_with_derivatives(1.0 - s, power.max(1.0));
                [1.0 - f, df, -ddf]
            }
            Ease::InOut { power } => {
                let p = power.max(1.0);
                let scale = 2.0_f32.powf(p - 1.0);
                if s <= 0.5 {
                    let [f, df, ddf] = power_with_derivatives(s, p);
                    [scale * f, scale * df, scale * ddf]
                } else {
                    let [f, df, ddf] = power_with_derivatives(1.0 - s, p);
                    [1.0 - scale * f, scale * df, -scale * ddf]
                }
            }
        }
    }
}

/// A time warp `w(t)`: an [`Ease`] stretched over the interval `[start_sec, end_sec]`, and the
/// identity outside it. Evaluating a track at `w(t)` instead of `t` keeps the path and the
/// times at which the interval's ends are reached, but moves the in-betweens.
/// ```text
/// w(t) = t_a + (t_b − t_a) · e((t − t_a) / (t_b − t_a))   for t ∈ [t_a, t_b]
/// w(t) = t                                               otherwise
/// (p ∘ w)′(t) = p′(w) w′(t),   (p ∘ w)″(t) = p″(w) w′(t)² + p′(w) w″(t)
/// ```
/// With `t_a`, `t_b` the first and last key ([`TimeWarp::over`]), a whole move gets slow-in and
/// slow-out; a curve editor would apply one per segment. An empty or reversed interval gives
/// the identity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeWarp {
    /// Start of the warped interval `t_a`, in seconds.
    pub start_sec: f32,
    /// End of the warped interval `t_b`, in seconds.
    pub end_sec: f32,
    /// The easing curve applied inside the interval.
    pub ease: Ease,
}

impl TimeWarp {
    /// `ease` stretched over `[start_sec, end_sec]`.
    pub fn new(start_sec: f32, end_sec: f32, ease: Ease) -> Self {
        Self {
            start_sec,
            end_sec,
            ease,
        }
    }

    /// `ease` over the keyed range of `track`, from its first key to its last.
    pub fn over<T: Value>(track: &Track<T>, ease: Ease) -> Self {
        Self::new(track.start_sec(), track.end_sec(), ease)
    }

    /// `[w(t), w′(t), w″(t)]` at `time_sec` (`w′` has no unit, `w″` is per second).
    pub fn warp(&self, time_sec: f32) -> [f32; 3] {
        let span = self.end_sec - self.start_sec;
        if span.is_nan() || span <= 0.0 || time_sec < self.start_sec || time_sec > self.end_sec {
            return [time_sec, 1.0, 0.0];
        }
        let [e, de, dde] = self
            .ease
            .apply_with_derivatives((time_sec - self.start_sec) / span);
        [self.start_sec + span * e, de, dde / span]
    }
}

impl<T: Value> Track<T> {
    /// Position, velocity and acceleration of the warped motion `p(w(t))` at `time_sec`, by the
    /// chain rule (see [`TimeWarp`]).
    pub fn evaluate_warped(&self, warp: &TimeWarp, time_sec: f32) -> Sample<T> {
        self.evaluate_warped_with(&mut Cursor::new(), warp, time_sec)
    }

    /// As [`Track::evaluate_warped`], with a [`Cursor`].
    pub fn evaluate_warped_with(
        &self,
        cursor: &mut Cursor,
        warp: &TimeWarp,
        time_sec: f32,
    ) -> Sample<T> {
        let [w, dw, ddw] = warp.warp(time_sec);
        let sample = self.evaluate_with(cursor, w);
        Sample {
            position: sample.position,
            velocity: sample.velocity * dw,
            acceleration: sample.acceleration * (dw * dw) + sample.velocity * ddw,
        }
    }
}
