//! A smooth curve of orientations through several keys: SQUAD (Shoemake 1987).

use glam::Quat;

use super::{check_quat, quat_exp, quat_log, slerp_arc, Arc, RotationError};

/// Spherical quadrangle interpolation (SQUAD) through unit-quaternion keys: the rotation
/// counterpart of a Catmull-Rom spline of positions.
///
/// ```text
/// segment i, t ∈ [0, 1]:
///   squad(t) = slerp(slerp(qᵢ, qᵢ₊₁; t), slerp(sᵢ, sᵢ₊₁; t); 2t(1 − t))
/// inner control points:
///   sᵢ = qᵢ · exp(−¼ (log(qᵢ⁻¹ qᵢ₊₁) + log(qᵢ⁻¹ qᵢ₋₁))),    s₀ = q₀,  sₙ₋₁ = qₙ₋₁
/// ```
/// The curve passes through every key, and its angular velocity is continuous across the
/// interior keys (slerp chains only join with a kink). Keys are first put in one hemisphere
/// (each negated if needed so that `qᵢ₋₁ · qᵢ ≥ 0`), so each segment takes the short arc; the
/// inner slerps then take the arc as given. Everything is allocated by [`QuatSpline::new`];
/// sampling allocates nothing.
#[derive(Clone, Debug, PartialEq)]
pub struct QuatSpline {
    keys: Vec<Quat>,
    inner: Vec<Quat>,
}

impl QuatSpline {
    /// Builds the spline; keys are normalised.
    ///
    /// # Errors
    /// [`RotationError::TooFewKeys`] for fewer than 2 keys; [`RotationError::ZeroQuat`] or
    /// [`RotationError::NonFinite`] for a bad key.
    pub fn new(keys: &[Quat]) -> Result<Self, RotationError> {
        if keys.len() < 2 {
            return Err(RotationError::TooFewKeys {
                needed: 2,
                got: keys.len(),
            });
        }
        let mut q: Vec<Quat> = Vec::with_capacity(keys.len());
        for &key in keys {
            let mut key = check_quat(key)?;
            if let Some(&prev) = q.last() {
                if prev.dot(key) < 0.0 {
                    key = -key;
                }
            }
            q.push(key);
        }
        let n = q.len();
        let mut inner = Vec::with_capacity(n);
        for i in 0..n {
            if i == 0 || i == n - 1 {
                inner.push(q[i]);
                continue;
            }
            let inv = q[i].conjugate();
            let tangent = quat_log(inv * q[i + 1]) + quat_log(inv * q[i - 1]);
            inner.push((q[i] * quat_exp(tangent * -0.25)).normalize());
        }
        Ok(Self { keys: q, inner })
    }

    /// The keys after normalisation and hemisphere alignment.
    pub fn keys(&self) -> &[Quat] {
        &self.keys
    }

    /// Number of segments (`keys − 1`).
    pub fn segment_count(&self) -> usize {
        self.keys.len() - 1
    }

    /// Orientation on segment `i` at `t ∈ [0, 1]` (`t = 0` gives key `i`, `t = 1` key `i + 1`).
    ///
    /// # Panics
    /// If `i >= segment_count()`.
    pub fn sample_segment(&self, i: usize, t: f32) -> Quat {
        let a = slerp_arc(self.keys[i], self.keys[i + 1], t, Arc::Short);
        let b = slerp_raw(self.inner[i], self.inner[i + 1], t);
        // No hemisphere flip for the inner slerps: SQUAD takes them as built.
        slerp_raw(a, b, 2.0 * t * (1.0 - t))
    }

    /// Orientation at `u ∈ [0, keys − 1]`: key `i` sits at `u = i`. `u` is clamped to the range.
    pub fn sample(&self, u: f32) -> Quat {
        let last = self.segment_count();
        let u = u.clamp(0.0, last as f32);
        let i = (u.floor() as usize).min(last - 1);
        self.sample_segment(i, u - i as f32)
    }
}

/// Slerp without choosing an arc (the keys are taken as given).
fn slerp_raw(a: Quat, b: Quat, t: f32) -> Quat {
    if a.dot(b) >= 0.0 {
        slerp_arc(a, b, t, Arc::Short)
    } else {
        slerp_arc(a, b, t, Arc::Long)
    }
}
