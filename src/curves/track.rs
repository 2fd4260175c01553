//! [`Track`]: keyframes (time, value) and the rule that fills the time between them.

use core::fmt;

use super::cardinal::{cardinal_tangents, centripetal_tangents};
use super::hermite::{hermite_position, hermite_segment};
use super::lagrange::lagrange;
use super::natural::natural_spline_tangents;
use super::segment::Cursor;
use super::Value;
use glam::Vec4;

/// How a [`Track`] fills the time between its keys.
///
/// The most keys [`Interpolation::Lagrange`] accepts. Past a few dozen keys the polynomial is
/// meaningless in `f32` (Runge's oscillations dwarf the keys) and each sample costs `O(N²)`, so
/// 10,000 keys would freeze a page: [`Track::set_interpolation`] refuses instead.
pub const MAX_LAGRANGE_KEYS: usize = 64;

/// Every scheme passes through the keys. The cubic schemes (`Hermite`, `Cardinal`, `Natural`,
/// `Centripetal`) are all evaluated as cubic Hermite segments; they differ only in how the
/// tangent at each key is chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Interpolation {
    /// Hold each key's value until the next key (C⁻¹: the value jumps at keys).
    /// ```text
    /// p(t) = p_i   for t ∈ [t_i, t_{i+1})
    /// ```
    Step,
    /// Straight segments at constant speed between keys (C0: the velocity jumps at keys).
    /// ```text
    /// p(t) = (1 − s) p_i + s p_{i+1},   s = (t − t_i) / (t_{i+1} − t_i)
    /// ```
    Linear,
    /// One polynomial of degree N − 1 through all keys (C∞ but oscillating; global). See
    /// [`lagrange`](super::lagrange).
    Lagrange,
    /// Cubic Hermite segments with the tangents stored per key, set by the caller (see
    /// [`Track::new_hermite`], [`Track::set_tangents`]). In and out tangents may differ (a
    /// "broken" tangent): C0 at such a key, C1 where they are equal.
    Hermite,
    /// Cardinal spline with tension `μ ∈ [0, 2]` (C1); `μ = 1` is Catmull-Rom. Tangents from
    /// [`cardinal_tangents`](super::cardinal_tangents).
    Cardinal {
        /// The tension `μ`, in `[0, 2]`: 0 stops at every key, 1 is Catmull-Rom.
        tension: f32,
    },
    /// Natural cubic spline (C2: the acceleration is continuous, and zero at both ends). Tangents
    /// from the global solve in [`natural_spline_tangents`](super::natural_spline_tangents).
    Natural,
    /// Centripetal Catmull-Rom (`α = ½`): the path has no cusps or loops within a segment, but
    /// the speed may jump at keys. Tangents from
    /// [`centripetal_tangents`](super::centripetal_tangents).
    Centripetal,
}

impl Interpolation {
    /// Catmull-Rom: the cardinal spline with tension 1.
    pub const CATMULL_ROM: Self = Self::Cardinal { tension: 1.0 };
}

/// What a [`Track`] does before its first key and after its last key.
///
/// Write `t_0`, `t_N` for the first and last key times and `D = t_N − t_0` for the duration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum EndBehaviour {
    /// Hold the first value before `t_0` and the last value after `t_N`; velocity and
    /// acceleration are zero there.
    #[default]
    Clamp,
    /// Continue in a straight line with the velocity at the end key; acceleration is zero there.
    /// ```text
    /// p(t) = p(t_N) + p′(t_N) (t − t_N)   for t > t_N   (and likewise before t_0)
    /// ```
    Extrapolate,
    /// Repeat the keyed range forever, with period `D`. The time `t_N` itself maps to `t_0`, so
    /// for a seamless cycle give the last key the value of the first.
    /// ```text
    /// p(t) = p(t_0 + (t − t_0) mod D)
    /// ```
    Loop,
    /// Play the keyed range forwards, then backwards, with period `2D`; the velocity changes sign
    /// on the way back.
    /// ```text
    /// φ = (t − t_0) mod 2D,   p(t) = p(t_0 + φ) if φ ≤ D,  else p(t_0 + 2D − φ)
    /// ```
    PingPong,
}

/// Position, velocity and acceleration of a track at one time.
///
/// Velocity is in value units per second, acceleration in value units per second squared.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Sample<T> {
    /// `p(t)`.
    pub position: T,
    /// `p′(t) = dp/dt`. At a key where the velocity jumps, the value just after the key.
    pub velocity: T,
    /// `p″(t) = d²p/dt²`. At a key where it jumps, the value just after the key.
    pub acceleration: T,
}

impl<T: Value> Sample<T> {
    /// A value at rest: zero velocity and acceleration.
    pub fn at_rest(position: T) -> Self {
        Self {
            position,
            velocity: T::ZERO,
            acceleration: T::ZERO,
        }
    }
}

/// What is wrong with keyframe data given to a [`Track`]. Messages are written for students.
#[derive(Clone, Debug, PartialEq)]
pub enum TrackError {
    /// No keys at all.
    Empty,
    /// The number of times and the number of values differ.
    LengthMismatch {
        /// How many key times were given.
        times: usize,
        /// How many key values were given.
        values: usize,
    },
    /// A key time is NaN or infinite.
    NonFiniteTime {
        /// Index of the key.
        index: usize,
        /// The offending time.
        time_sec: f32,
    },
    /// A key value has a NaN or infinite component.
    NonFiniteValue {
        /// Index of the key.
        index: usize,
    },
    /// A key time is not strictly after the previous one.
    TimesNotIncreasing {
        /// Index of the key that comes too early (`index ≥ 1`).
        index: usize,
        /// Time of key `index − 1`.
        previous_sec: f32,
        /// Time of key `index`.
        time_sec: f32,
    },
    /// Hermite tangents were given, but not one in and one out tangent per key.
    TangentCountMismatch {
        /// How many keys the track has.
        keys: usize,
        /// How many in tangents were given.
        tangents_in: usize,
        /// How many out tangents were given.
        tangents_out: usize,
    },
    /// A tangent has a NaN or infinite component.
    NonFiniteTangent {
        /// Index of the key.
        index: usize,
    },
    /// A cardinal tension outside `[0, 2]` (or NaN).
    TensionOutOfRange {
        /// The offending tension.
        tension: f32,
    },
    /// [`Interpolation::Lagrange`] asked of more than [`MAX_LAGRANGE_KEYS`] keys.
    TooManyKeysForLagrange {
        /// How many keys the track has.
        keys: usize,
    },
    /// A key index past the last key.
    KeyOutOfRange {
        /// The index asked for.
        index: usize,
        /// How many keys the track has.
        keys: usize,
    },
}

impl fmt::Display for TrackError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::Empty => write!(f, "a track needs at least one key, but none was given"),
            Self::LengthMismatch { times, values } => write!(
                f,
                "{times} key times but {values} key values were given: each key needs one time and one value"
            ),
            Self::NonFiniteTime { index, time_sec } => {
                write!(f, "key {index} has time {time_sec}, which is not a finite number of seconds")
            }
            Self::NonFiniteValue { index } => {
                write!(f, "key {index} has a value that is NaN or infinite")
            }
            Self::TimesNotIncreasing { index, previous_sec, time_sec } => write!(
                f,
                "key times must strictly increase, but key {index} is at {time_sec} s, \
                 not after key {} at {previous_sec} s",
                index - 1
            ),
            Self::TangentCountMismatch { keys, tangents_in, tangents_out } => write!(
                f,
                "the track has {keys} keys but {tangents_in} in tangents and {tangents_out} out \
                 tangents were given: each key needs one of each"
            ),
            Self::NonFiniteTangent { index } => {
                write!(f, "key {index} has a tangent that is NaN or infinite")
            }
            Self::TensionOutOfRange { tension } => {
                write!(f, "the tension must be between 0 and 2, but it is {tension}")
            }
            Self::TooManyKeysForLagrange { keys } => write!(
                f,
                "Lagrange interpolation takes at most {MAX_LAGRANGE_KEYS} keys, but the track has \
                 {keys}: one polynomial through that many keys is useless (it oscillates wildly) \
                 and costs O(N²) per sample; use a spline"
            ),
            Self::KeyOutOfRange { index, keys } => write!(
                f,
                "there is no key {index}: the track has {keys} keys, numbered from 0 to {}",
                keys.saturating_sub(1)
            ),
        }
    }
}

impl std::error::Error for TrackError {}

/// Checks keyframe data against every rule a [`Track`] needs, in this order: at least one key;
/// as many values as times; then, key by key, a finite time, a finite value, and a time strictly
/// after the previous key's. Returns the first rule broken.
///
/// # Errors
/// [`TrackError::Empty`], [`TrackError::LengthMismatch`], [`TrackError::NonFiniteTime`],
/// [`TrackError::NonFiniteValue`] or [`TrackError::TimesNotIncreasing`].
pub fn validate_keys<T: Value>(times: &[f32], values: &[T]) -> Result<(), TrackError> {
    if times.is_empty() && values.is_empty() {
        return Err(TrackError::Empty);
    }
    if times.len() != values.len() {
        return Err(TrackError::LengthMismatch {
            times: times.len(),
            values: values.len(),
        });
    }
    for (index, (&time_sec, &value)) in times.iter().zip(values).enumerate() {
        if !time_sec.is_finite() {
            return Err(TrackError::NonFiniteTime { index, time_sec });
        }
        if !value.is_finite() {
            return Err(TrackError::NonFiniteValue { index });
        }
        if index > 0 && time_sec <= times[index - 1] {
            let previous_sec = times[index - 1];
            return Err(TrackError::TimesNotIncreasing {
                index,
                previous_sec,
                time_sec,
            });
        }
    }
    Ok(())
}

/// Keyframes `(t_i, p_i)`, `i = 0 … N−1`, with strictly increasing times in seconds, and the
/// [`Interpolation`] and [`EndBehaviour`] that turn them into a curve `p(t)` defined for every
/// time.
///
/// A track is built once from caller data by [`Track::new`], which checks every rule (see
/// [`validate_keys`]); after that, evaluation cannot fail and allocates nothing. Besides times
/// and values, a track stores for every key an *in tangent* (the velocity `p′` just before the
/// key) and an *out tangent* (just after), in value units per second. For the cubic schemes
/// these are the Hermite tangents that define the curve; for the others they describe it (zero
/// for `Step`, the slopes of the neighbouring segments for `Linear`, the polynomial's derivative
/// for `Lagrange`). Switching to [`Interpolation::Hermite`] keeps them, as a curve editor turns
/// automatic tangents into editable ones.
///
/// Evaluation: [`Track::evaluate`] and friends search the segment by binary search;
/// [`Track::evaluate_with`] takes a [`Cursor`] and is `O(1)` for increasing times; the bulk
/// functions ([`Track::positions`], [`Track::evaluate_many`]) fill a caller's slice.
///
/// Lesson: keyframes and splines.
#[derive(Clone, Debug, PartialEq)]
pub struct Track<T: Value> {
    times: Vec<f32>,
    values: Vec<T>,
    tangents_in: Vec<T>,
    tangents_out: Vec<T>,
    interpolation: Interpolation,
    end_behaviour: EndBehaviour,
}

impl<T: Value> Track<T> {
    /// A track through the keys `(times[i], values[i])`, with [`Interpolation::Linear`] and
    /// [`EndBehaviour::Clamp`]; change them with [`Track::with_interpolation`] and
    /// [`Track::with_end_behaviour`]. Times are in seconds and must strictly increase.
    ///
    /// # Errors
    /// The first rule of [`validate_keys`] that the data breaks.
    pub fn new(times: Vec<f32>, values: Vec<T>) -> Result<Self, TrackError> {
        validate_keys(&times, &values)?;
        let n = times.len();
        let mut track = Self {
            times,
            values,
            tangents_in: vec![T::ZERO; n],
            tangents_out: vec![T::ZERO; n],
            interpolation: Interpolation::Linear,
            end_behaviour: EndBehaviour::Clamp,
        };
        track.update_tangents();
        Ok(track)
    }

    /// A cubic Hermite track with explicit tangents: `tangents_in[i]` is the velocity arriving
    /// at key `i`, `tangents_out[i]` the velocity leaving it, in value units per second. They
    /// may differ (a broken tangent). `tangents_in[0]` and `tangents_out[N−1]` point outside the
    /// keyed range and are not used: [`EndBehaviour::Extrapolate`] continues with the velocity
    /// of the end segments, `tangents_out[0]` and `tangents_in[N−1]`.
    ///
    /// # Errors
    /// As [`Track::new`], then [`TrackError::TangentCountMismatch`] or
    /// [`TrackError::NonFiniteTangent`].
    pub fn new_hermite(
        times: Vec<f32>,
        values: Vec<T>,
        tangents_in: Vec<T>,
        tangents_out: Vec<T>,
    ) -> Result<Self, TrackError> {
        validate_keys(&times, &values)?;
        let keys = times.len();
        if tangents_in.len() != keys || tangents_out.len() != keys {
            return Err(TrackError::TangentCountMismatch {
                keys,
                tangents_in: tangents_in.len(),
                tangents_out: tangents_out.len(),
            });
        }
        let bad = tangents_in
            .iter()
            .zip(&tangents_out)
            .position(|(a, b)| !a.is_finite() || !b.is_finite());
        if let Some(index) = bad {
            return Err(TrackError::NonFiniteTangent { index });
        }
        Ok(Self {
            times,
            values,
            tangents_in,
            tangents_out,
            interpolation: Interpolation::Hermite,
            end_behaviour: EndBehaviour::Clamp,
        })
    }

    /// This track with another interpolation (builder form of [`Track::set_interpolation`]).
    ///
    /// # Errors
    /// [`TrackError::TensionOutOfRange`] for a cardinal tension outside `[0, 2]`.
    pub fn with_interpolation(mut self, interpolation: Interpolation) -> Result<Self, TrackError> {
        self.set_interpolation(interpolation)?;
        Ok(self)
    }

    /// This track with another end behaviour.
    pub fn with_end_behaviour(mut self, end_behaviour: EndBehaviour) -> Self {
        self.end_behaviour = end_behaviour;
        self
    }

    /// Changes the interpolation and recomputes the tangents (`O(N)`, or `O(N³)` for
    /// `Lagrange`). Switching to [`Interpolation::Hermite`] keeps the current tangents, so the
    /// curve of a cardinal, natural or linear track is unchanged and its tangents become
    /// editable.
    ///
    /// # Errors
    /// [`TrackError::TensionOutOfRange`] for a cardinal tension outside `[0, 2]` or NaN;
    /// [`TrackError::TooManyKeysForLagrange`] for `Lagrange` with more than
    /// [`MAX_LAGRANGE_KEYS`] keys. The track is then unchanged.
    pub fn set_interpolation(&mut self, interpolation: Interpolation) -> Result<(), TrackError> {
        if interpolation == Interpolation::Lagrange && self.times.len() > MAX_LAGRANGE_KEYS {
            return Err(TrackError::TooManyKeysForLagrange {
                keys: self.times.len(),
            });
        }
        if let Interpolation::Cardinal { tension } = interpolation {
            if !(0.0..=2.0).contains(&tension) {
                return Err(TrackError::TensionOutOfRange { tension });
            }
        }
        self.interpolation = interpolation;
        self.update_tangents();
        Ok(())
    }

    /// Changes what happens before the first key and after the last one.
    pub fn set_end_behaviour(&mut self, end_behaviour: EndBehaviour) {
        self.end_behaviour = end_behaviour;
    }

    /// Sets the in and out tangents of key `index` (value units per second) and switches the
    /// track to [`Interpolation::Hermite`], keeping the other keys' current tangents.
    ///
    /// # Errors
    /// [`TrackError::KeyOutOfRange`] or [`TrackError::NonFiniteTangent`]; the track is then
    /// unchanged.
    pub fn set_tangents(
        &mut self,
        index: usize,
        tangent_in: T,
        tangent_out: T,
    ) -> Result<(), TrackError> {
        let keys = self.times.len();
        if index >= keys {
            return Err(TrackError::KeyOutOfRange { index, keys });
        }
        if !tangent_in.is_finite() || !tangent_out.is_finite() {
            return Err(TrackError::NonFiniteTangent { index });
        }
        self.interpolation = Interpolation::Hermite;
        self.tangents_in[index] = tangent_in;
        self.tangents_out[index] = tangent_out;
        Ok(())
    }

    /// Key times in seconds, strictly increasing.
    pub fn times(&self) -> &[f32] {
        &self.times
    }

    /// Key values, one per time.
    pub fn values(&self) -> &[T] {
        &self.values
    }

    /// Velocity arriving at each key (value units per second); see [`Track`].
    pub fn tangents_in(&self) -> &[T] {
        &self.tangents_in
    }

    /// Velocity leaving each key (value units per second); see [`Track`].
    pub fn tangents_out(&self) -> &[T] {
        &self.tangents_out
    }

    /// The interpolation scheme.
    pub fn interpolation(&self) -> Interpolation {
        self.interpolation
    }

    /// The end behaviour.
    pub fn end_behaviour(&self) -> EndBehaviour {
        self.end_behaviour
    }

    /// Number of keys `N ≥ 1`.
    pub fn key_count(&self) -> usize {
        self.times.len()
    }

    /// Time of the first key, `t_0`, in seconds.
    pub fn start_sec(&self) -> f32 {
        self.times[0]
    }

    /// Time of the last key, `t_{N−1}`, in seconds.
    pub fn end_sec(&self) -> f32 {
        self.times[self.times.len() - 1]
    }

    /// `t_{N−1} − t_0` in seconds (0 for a single key).
    pub fn duration_sec(&self) -> f32 {
        self.end_sec() - self.start_sec()
    }

    /// Position, velocity and acceleration at `time_sec` (binary search for the segment).
    pub fn evaluate(&self, time_sec: f32) -> Sample<T> {
        self.evaluate_with(&mut Cursor::new(), time_sec)
    }

    /// `p(t)` at `time_sec`.
    pub fn position(&self, time_sec: f32) -> T {
        self.position_with(&mut Cursor::new(), time_sec)
    }

    /// `p′(t)` at `time_sec`, in value units per second.
    pub fn velocity(&self, time_sec: f32) -> T {
        self.evaluate(time_sec).velocity
    }

    /// `p″(t)` at `time_sec`, in value units per second squared.
    pub fn acceleration(&self, time_sec: f32) -> T {
        self.evaluate(time_sec).acceleration
    }

    /// As [`Track::evaluate`], but finds the segment with `cursor` (`O(1)` when times increase
    /// from call to call) and leaves it at the segment found. Same result as `evaluate`.
    pub fn evaluate_with(&self, cursor: &mut Cursor, time_sec: f32) -> Sample<T> {
        self.evaluate_at::<true>(cursor, time_sec)
    }

    /// `p(t)` at `time_sec`, with a [`Cursor`] (see [`Track::evaluate_with`]). Skips the
    /// derivatives, so it is the fastest way to sample.
    pub fn position_with(&self, cursor: &mut Cursor, time_sec: f32) -> T {
        self.evaluate_at::<false>(cursor, time_sec).position
    }

    /// The end behaviour, then `evaluate_keyed`. With `DERIVATIVES = false`, velocity
    /// and acceleration are left at zero (except when extrapolating, which needs the velocity).
    fn evaluate_at<const DERIVATIVES: bool>(
        &self,
        cursor: &mut Cursor,
        time_sec: f32,
    ) -> Sample<T> {
        let n = self.times.len();
        if n == 1 {
            return Sample::at_rest(self.values[0]);
        }
        let (t_first, t_last) = (self.times[0], self.times[n - 1]);
        let duration = t_last - t_first;
        match self.end_behaviour {
            EndBehaviour::Clamp => {
                if time_sec < t_first {
                    Sample::at_rest(self.values[0])
                } else if time_sec > t_last {
                    Sample::at_rest(self.values[n - 1])
                } else {
                    self.evaluate_keyed::<DERIVATIVES>(cursor, time_sec)
                }
            }
            EndBehaviour::Extrapolate => {
                let end_sec = if time_sec < t_first {
                    t_first
                } else if time_sec > t_last {
                    t_last
                } else {
                    return self.evaluate_keyed::<DERIVATIVES>(cursor, time_sec);
                };
                let end = self.evaluate_keyed::<true>(cursor, end_sec);
                Sample {
                    position: end.position + end.velocity * (time_sec - end_sec),
                    velocity: end.velocity,
                    acceleration: T::ZERO,
                }
            }
            EndBehaviour::Loop => {
                let phase = (time_sec - t_first).rem_euclid(duration);
                self.evaluate_keyed::<DERIVATIVES>(cursor, t_first + phase)
            }
            EndBehaviour::PingPong => {
                let phase = (time_sec - t_first).rem_euclid(2.0 * duration);
                if phase <= duration {
                    self.evaluate_keyed::<DERIVATIVES>(cursor, t_first + phase)
                } else {
                    // Time runs backwards: dw/dt = −1 flips the velocity, (dw/dt)² = 1 keeps
                    // the acceleration.
                    let mut sample = self
                        .evaluate_keyed::<DERIVATIVES>(cursor, t_first + 2.0 * duration - phase);
                    sample.velocity = sample.velocity * -1.0;
                    sample
                }
            }
        }
    }

    /// Writes `p(times_sec[k])` into `out[k]`. Uses one cursor for the whole slice, so sorted
    /// times cost `O(1)` each; any order gives the same values. Allocates nothing.
    ///
    /// # Panics
    /// If `out.len() != times_sec.len()`.
    pub fn positions(&self, times_sec: &[f32], out: &mut [T]) {
        assert_eq!(
            out.len(),
            times_sec.len(),
            "Track::positions: one output per time"
        );
        let mut cursor = Cursor::new();
        for (slot, &t) in out.iter_mut().zip(times_sec) {
            *slot = self.position_with(&mut cursor, t);
        }
    }

    /// Writes position, velocity and acceleration at `times_sec[k]` into `out[k]` (one cursor
    /// for the whole slice, as [`Track::positions`]).
    ///
    /// # Panics
    /// If `out.len() != times_sec.len()`.
    pub fn evaluate_many(&self, times_sec: &[f32], out: &mut [Sample<T>]) {
        assert_eq!(
            out.len(),
            times_sec.len(),
            "Track::evaluate_many: one output per time"
        );
        let mut cursor = Cursor::new();
        for (slot, &t) in out.iter_mut().zip(times_sec) {
            *slot = self.evaluate_with(&mut cursor, t);
        }
    }

    /// Fills `out` with positions at evenly spaced times from `start_sec` to `end_sec`, both
    /// included (one sample gives `start_sec`): the in-betweens of a ghost trail, whose spacing
    /// shows the speed.
    /// ```text
    /// out[k] = p(start + k (end − start) / (len − 1))
    /// ```
    pub fn positions_evenly(&self, start_sec: f32, end_sec: f32, out: &mut [T]) {
        let step = if out.len() > 1 {
            (end_sec - start_sec) / (out.len() - 1) as f32
        } else {
            0.0
        };
        let mut cursor = Cursor::new();
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = self.position_with(&mut cursor, start_sec + step * k as f32);
        }
    }

    /// Evaluates the keyed curve at a time clamped to `[t_0, t_{N−1}]`, ignoring the end
    /// behaviour (used by end behaviours and arc length). With `DERIVATIVES = false`, only the
    /// position is computed (velocity and acceleration are zero).
    pub(crate) fn evaluate_keyed<const DERIVATIVES: bool>(
        &self,
        cursor: &mut Cursor,
        time_sec: f32,
    ) -> Sample<T> {
        let n = self.times.len();
        if n == 1 {
            return Sample::at_rest(self.values[0]);
        }
        let t = time_sec.clamp(self.times[0], self.times[n - 1]);
        let i = cursor.find(&self.times, t);
        let (t0, t1) = (self.times[i], self.times[i + 1]);
        let (p0, p1) = (self.values[i], self.values[i + 1]);
        match self.interpolation {
            Interpolation::Step => Sample::at_rest(if t >= t1 { p1 } else { p0 }),
            Interpolation::Linear if !DERIVATIVES => {
                Sample::at_rest(p0 + (p1 - p0) * ((t - t0) / (t1 - t0)))
            }
            Interpolation::Linear => {
                let s = (t - t0) / (t1 - t0);
                Sample {
                    position: p0 + (p1 - p0) * s,
                    velocity: (p1 - p0) * (1.0 / (t1 - t0)),
                    acceleration: T::ZERO,
                }
            }
            Interpolation::Lagrange => {
                let [position, velocity, acceleration] = lagrange(&self.times, &self.values, t);
                Sample {
                    position,
                    velocity,
                    acceleration,
                }
            }
            Interpolation::Hermite
            | Interpolation::Cardinal { .. }
            | Interpolation::Natural
            | Interpolation::Centripetal => {
                let (d0, d1) = (self.tangents_out[i], self.tangents_in[i + 1]);
                if !DERIVATIVES {
                    return Sample::at_rest(hermite_position(t0, t1, p0, d0, p1, d1, t));
                }
                let [position, velocity, acceleration] = hermite_segment(t0, t1, p0, d0, p1, d1, t);
                Sample {
                    position,
                    velocity,
                    acceleration,
                }
            }
        }
    }

    /// Recomputes `tangents_in` / `tangents_out` for the current interpolation. Every scheme but
    /// the centripetal one (whose knots need the type's own length) works component by
    /// component, so it runs on the values as `Vec4`s ([`Value::to_vec4`]): one compiled body
    /// for the four value types.
    fn update_tangents(&mut self) {
        match self.interpolation {
            Interpolation::Hermite => {}
            Interpolation::Centripetal => centripetal_tangents(
                &self.times,
                &self.values,
                &mut self.tangents_in,
                &mut self.tangents_out,
            ),
            scheme => {
                let values: Vec<Vec4> = self.values.iter().map(|v| v.to_vec4()).collect();
                let mut tangents_in = vec![Vec4::ZERO; values.len()];
                let mut tangents_out = vec![Vec4::ZERO; values.len()];
                component_tangents(
                    scheme,
                    &self.times,
                    &values,
                    &mut tangents_in,
                    &mut tangents_out,
                );
                for (t, v) in self.tangents_in.iter_mut().zip(tangents_in) {
                    *t = T::from_vec4(v);
                }
                for (t, v) in self.tangents_out.iter_mut().zip(tangents_out) {
                    *t = T::from_vec4(v);
                }
            }
        }
    }
}

/// The in and out tangents of `scheme` (any but [`Interpolation::Hermite`], whose tangents are
/// given, and [`Interpolation::Centripetal`]) for keys `(times, values)`, written into
/// `tangents_in` and `tangents_out` (zeros on entry, the length of `times`).
#[inline(never)]
fn component_tangents(
    scheme: Interpolation,
    times: &[f32],
    values: &[Vec4],
    tangents_in: &mut [Vec4],
    tangents_out: &mut [Vec4],
) {
    let n = times.len();
    match scheme {
        // A step holds each key: its tangents stay zero.
        Interpolation::Hermite | Interpolation::Centripetal | Interpolation::Step => {}
        Interpolation::Linear => {
            for i in 0..n {
                let slope =
                    |a: usize, b: usize| (values[b] - values[a]) * (1.0 / (times[b] - times[a]));
                let before = if i > 0 { slope(i - 1, i) } else { Vec4::ZERO };
                let after = if i + 1 < n { slope(i, i + 1) } else { before };
                tangents_in[i] = if i > 0 { before } else { after };
                tangents_out[i] = after;
            }
        }
        Interpolation::Lagrange => {
            for i in 0..n {
                let [_, velocity, _] = lagrange(times, values, times[i]);
                tangents_in[i] = velocity;
                tangents_out[i] = velocity;
            }
        }
        Interpolation::Cardinal { tension } => {
            cardinal_tangents(times, values, tension, tangents_out);
            tangents_in.copy_from_slice(tangents_out);
        }
        Interpolation::Natural => {
            let mut diagonal = vec![0.0; n];
            let mut rhs = vec![Vec4::ZERO; n];
            natural_spline_tangents(times, values, tangents_out, &mut diagonal, &mut rhs);
            tangents_in.copy_from_slice(tangents_out);
        }
    }
}
