//! Per-vertex joints and weights: validation, normalisation, automatic weights.

use super::{check_len, SkinningError, MAX_INFLUENCES, MAX_SKIN_VERTICES};
use glam::Vec3;

/// Up to four joints and weights per vertex, validated and normalised so each vertex's weights
/// sum to 1. Unused slots have weight 0 (their joint index is still checked, so use 0).
///
/// Normalisation divides by the sum, `wᵢ ← wᵢ / Σ w`, as three.js's `GLTFLoader` does
/// (`SkinnedMesh.normalizeSkinWeights`) for files whose sums are far from 1; an all-zero vertex
/// is an error here rather than silently bound to joint 0.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SkinWeights {
    joints: Vec<[u16; 4]>,
    weights: Vec<[f32; 4]>,
    /// One past the largest joint index any vertex names (so a palette check is O(1) per frame).
    joint_bound: usize,
}

impl SkinWeights {
    /// Checks every rule, then normalises. `joint_count` is the skeleton's joint count.
    ///
    /// # Errors
    /// [`SkinningError::LengthMismatch`] when the arrays differ in length,
    /// [`SkinningError::TooManyVertices`], [`SkinningError::JointOutOfRange`],
    /// [`SkinningError::NonFiniteWeight`], [`SkinningError::NegativeWeight`],
    /// [`SkinningError::ZeroWeights`] (the first offending vertex).
    pub fn new(
        joints: Vec<[u16; 4]>,
        mut weights: Vec<[f32; 4]>,
        joint_count: usize,
    ) -> Result<Self, SkinningError> {
        check_len(
            "weights (one set of four per vertex)",
            joints.len(),
            weights.len(),
        )?;
        if joints.len() > MAX_SKIN_VERTICES {
            return Err(SkinningError::TooManyVertices { got: joints.len() });
        }
        for (vertex, (j, w)) in joints.iter().zip(weights.iter_mut()).enumerate() {
            if let Some(&joint) = j.iter().find(|&&joint| joint as usize >= joint_count) {
                return Err(SkinningError::JointOutOfRange {
                    vertex,
                    joint: joint as usize,
                    joints: joint_count,
                });
            }
            if w.iter().any(|x| !x.is_finite()) {
                return Err(SkinningError::NonFiniteWeight { vertex });
            }
            if let Some(&weight) = w.iter().find(|&&x| x < 0.0) {
                return Err(SkinningError::NegativeWeight { vertex, weight });
            }
            let sum: f32 = w.iter().sum();
            if sum <= 0.0 || !sum.is_finite() {
                return Err(SkinningError::ZeroWeights { vertex });
            }
            for x in w.iter_mut() {
                *x /= sum;
            }
        }
        let joint_bound = joints
            .iter()
            .flat_map(|j| j.iter())
            .map(|&j| j as usize + 1)
            .max()
            .unwrap_or(0);
        Ok(Self {
            joints,
            weights,
            joint_bound,
        })
    }

    /// From eight influences per vertex (glTF's `JOINTS_0`/`WEIGHTS_0` plus `JOINTS_1`/`WEIGHTS_1`):
    /// keeps the four largest weights and renormalises, as renderers limited to four influences
    /// do (Unity's "4 bones" quality setting). Validates all eight first, as [`SkinWeights::new`].
    pub fn from_eight(
        joints: &[[u16; 8]],
        weights: &[[f32; 8]],
        joint_count: usize,
    ) -> Result<Self, SkinningError> {
        check_len(
            "weights (one set of eight per vertex)",
            joints.len(),
            weights.len(),
        )?;
        if joints.len() > MAX_SKIN_VERTICES {
            return Err(SkinningError::TooManyVertices { got: joints.len() });
        }
        let mut j4 = Vec::with_capacity(joints.len());
        let mut w4 = Vec::with_capacity(joints.len());
        for (vertex, (j, w)) in joints.iter().zip(weights).enumerate() {
            // Check the dropped four too: a bad file should be reported, not half-read.
            if let Some(&joint) = j.iter().find(|&&joint| joint as usize >= joint_count) {
                return Err(SkinningError::JointOutOfRange {
                    vertex,
                    joint: joint as usize,
                    joints: joint_count,
                });
            }
            if w.iter().any(|x| !x.is_finite()) {
                return Err(SkinningError::NonFiniteWeight { vertex });
            }
            let mut order: [(f32, u32); 8] = std::array::from_fn(|i| (w[i], i as u32));
            crate::order::sort_desc(&mut order);
            let order = order.map(|(_, i)| i as usize);
            j4.push([j[order[0]], j[order[1]], j[order[2]], j[order[3]]]);
            w4.push([w[order[0]], w[order[1]], w[order[2]], w[order[3]]]);
        }
        Self::new(j4, w4, joint_count)
    }

    pub fn len(&self) -> usize {
        self.joints.len()
    }

    pub fn is_empty(&self) -> bool {
        self.joints.is_empty()
    }

    /// One past the largest joint index any vertex names: a palette needs at least this many
    /// matrices.
    pub fn joint_bound(&self) -> usize {
        self.joint_bound
    }

    /// Joint indices, four per vertex.
    pub fn joints(&self) -> &[[u16; 4]] {
        &self.joints
    }

    /// Weights, four per vertex, each vertex's summing to 1 (to rounding).
    pub fn weights(&self) -> &[[f32; 4]] {
        &self.weights
    }

    /// Vertex `v`'s weight for `joint` (0 when the vertex does not name it).
    pub fn weight_of(&self, v: usize, joint: usize) -> f32 {
        self.joints[v]
            .iter()
            .zip(&self.weights[v])
            .filter(|(j, _)| **j as usize == joint)
            .map(|(_, w)| *w)
            .sum()
    }
}

/// Distance from `p` to the segment `a`–`b` (a point when `a = b`).
pub fn segment_distance(p: Vec3, a: Vec3, b: Vec3) -> f32 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * t)).length()
}

/// Automatic weights for procedural meshes: each joint owns a segment (its bone, in bind-pose
/// model space); a vertex's weight for joint `j` falls off smoothly with how much farther
/// segment `j` is than the nearest one:
/// ```text
/// dⱼ = distance(p, segmentⱼ),   d* = minⱼ dⱼ,   wⱼ = exp(−((dⱼ − d*) / falloff)²)
/// ```
/// then the four largest are kept and normalised. The nearest joint always gets the largest
/// weight; a small `falloff` (metres) gives nearly rigid parts, a large one a wide blend. Where
/// two segments are equally near (an elbow) the weights are ½ and ½ whatever the falloff.
///
/// `candidates(v)` lists the joints vertex `v` may use (all of them for a simple rig; a body part
/// and its neighbours for a character, so the side of the chest does not follow the arm). Joints
/// past the four nearest are dropped.
///
/// # Errors
/// [`SkinningError::BadParameter`] unless `falloff` is finite and in `[1e-4, 100]`, or when a
/// segment or position is not finite or a candidate is out of range; see [`SkinWeights::new`].
pub fn auto_weights<I>(
    positions: &[Vec3],
    segments: &[(Vec3, Vec3)],
    falloff: f32,
    mut candidates: impl FnMut(usize) -> I,
) -> Result<SkinWeights, SkinningError>
where
    I: IntoIterator<Item = usize>,
{
    if !(1e-4..=100.0).contains(&falloff) {
        return Err(SkinningError::BadParameter(format!(
            "falloff must lie in [0.0001, 100] metres, got {falloff}"
        )));
    }
    if positions.len() > MAX_SKIN_VERTICES {
        return Err(SkinningError::TooManyVertices {
            got: positions.len(),
        });
    }
    if segments.is_empty() || segments.len() > u16::MAX as usize {
        return Err(SkinningError::BadParameter(format!(
            "automatic weights need between 1 and {} segments, got {}",
            u16::MAX,
            segments.len()
        )));
    }
    if segments
        .iter()
        .any(|(a, b)| !a.is_finite() || !b.is_finite())
    {
        return Err(SkinningError::BadParameter(
            "a segment is not finite".into(),
        ));
    }
    let mut joints = Vec::with_capacity(positions.len());
    let mut weights = Vec::with_capacity(positions.len());
    for (v, &p) in positions.iter().enumerate() {
        if !p.is_finite() {
            return Err(SkinningError::BadParameter(format!(
                "position {v} is not finite"
            )));
        }
        // The four nearest candidates, nearest first.
        let mut best = [(f32::INFINITY, 0u16); MAX_INFLUENCES];
        for j in candidates(v) {
            let Some(&(a, b)) = segments.get(j) else {
                return Err(SkinningError::BadParameter(format!(
                    "vertex {v}: candidate joint {j} has no segment ({} segments)",
                    segments.len()
                )));
            };
            let d = segment_distance(p, a, b);
            if d < best[MAX_INFLUENCES - 1].0 {
                let mut k = MAX_INFLUENCES - 1;
                while k > 0 && best[k - 1].0 > d {
                    best[k] = best[k - 1];
                    k -= 1;
                }
                best[k] = (d, j as u16);
            }
        }
        if !best[0].0.is_finite() {
            return Err(SkinningError::ZeroWeights { vertex: v });
        }
        let nearest = best[0].0;
        let mut w = [0.0f32; 4];
        let mut j = [0u16; 4];
        for k in 0..MAX_INFLUENCES {
            if best[k].0.is_finite() {
                let x = (best[k].0 - nearest) / falloff;
                w[k] = (-x * x).exp();
                j[k] = best[k].1;
            }
        }
        joints.push(j);
        weights.push(w);
    }
    SkinWeights::new(joints, weights, segments.len())
}
