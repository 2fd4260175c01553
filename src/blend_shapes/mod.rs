//! # Blend shapes (morph targets): a mesh as a weighted mix of sculpted versions of itself
//!
//! A base mesh `b₀` and targets `b₁ … b_K` share one vertex order. Two ways to mix them:
//! ```text
//! full form:          p = Σₖ wₖ bₖ                   (k = 0 … K; the weights must sum to 1)
//! differential form:  p = b₀ + Σₖ wₖ (bₖ − b₀)       (any weights; all zero gives the base)
//! ```
//! With weights summing to 1 the two agree. Otherwise the full form, `(Σ w) b₀ + Σₖ wₖ dₖ`, scales
//! the base by `Σ w` about the origin (half of every target shrinks the face towards it), which is
//! why animation systems store and blend **deltas** `dₖ = bₖ − b₀` (glTF morph targets are deltas
//! too). Normals are blended the same way and renormalised.
//!
//! | topic | items |
//! |---|---|
//! | targets as deltas, validation | [`BlendShapes`], [`BlendShapeError`], [`MAX_TARGETS`] |
//! | the two forms | [`BlendShapes::apply_differential`], [`BlendShapes::apply_full`], [`blend_full`] |
//!
//! Nothing allocates per frame: outputs go into the caller's slices. Lesson: `lessons/10-blend-shapes`.

use crate::Valid;
use glam::Vec3;
use std::fmt;

/// The most targets one mesh may have (each costs a pass over the vertices).
pub const MAX_TARGETS: usize = 256;

/// What is wrong with blend-shape input.
#[derive(Clone, Debug, PartialEq)]
pub enum BlendShapeError {
    /// A target, a weight list or an output has the wrong length.
    LengthMismatch {
        what: String,
        expected: usize,
        got: usize,
    },
    /// More targets than [`MAX_TARGETS`].
    TooManyTargets { got: usize },
    /// A position, normal or weight is NaN or infinite.
    NonFinite { what: String },
    /// The full form needs weights summing to 1.
    WeightsDoNotSumToOne { sum: f32 },
}

impl fmt::Display for BlendShapeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::LengthMismatch {
                what,
                expected,
                got,
            } => {
                write!(f, "{what}: expected {expected} entries, got {got}")
            }
            Self::TooManyTargets { got } => {
                write!(f, "{got} targets is too many (at most {MAX_TARGETS})")
            }
            Self::NonFinite { what } => write!(f, "{what} holds NaN or infinity"),
            Self::WeightsDoNotSumToOne { sum } => write!(
                f,
                "the full form needs weights summing to 1, got {sum}: the mesh would be scaled by \
                 {sum}; use the differential form"
            ),
        }
    }
}

impl std::error::Error for BlendShapeError {}

fn check_len(what: impl Into<String>, expected: usize, got: usize) -> Result<(), BlendShapeError> {
    if expected == got {
        Ok(())
    } else {
        Err(BlendShapeError::LengthMismatch {
            what: what.into(),
            expected,
            got,
        })
    }
}

fn check_finite(what: impl Into<String>, v: &[Vec3]) -> Result<(), BlendShapeError> {
    if v.iter().all(|p| p.is_finite()) {
        Ok(())
    } else {
        Err(BlendShapeError::NonFinite { what: what.into() })
    }
}

/// A base mesh and its targets, stored as deltas `dₖ = bₖ − b₀` (positions and normals).
#[derive(Clone, Debug, PartialEq)]
pub struct BlendShapes {
    base_positions: Vec<Vec3>,
    base_normals: Vec<Vec3>,
    position_deltas: Vec<Vec<Vec3>>,
    normal_deltas: Vec<Vec<Vec3>>,
}

impl BlendShapes {
    /// From the base and the full targets (each a whole mesh, as sculpted).
    ///
    /// # Errors
    /// [`BlendShapeError::LengthMismatch`] unless every target has one position and normal per
    /// base vertex, [`BlendShapeError::TooManyTargets`], [`BlendShapeError::NonFinite`].
    pub fn from_targets(
        base_positions: Vec<Vec3>,
        base_normals: Vec<Vec3>,
        targets: &[(Vec<Vec3>, Vec<Vec3>)],
    ) -> Result<Self, BlendShapeError> {
        let n = base_positions.len();
        check_len("base normals", n, base_normals.len())?;
        if targets.len() > MAX_TARGETS {
            return Err(BlendShapeError::TooManyTargets { got: targets.len() });
        }
        check_finite("the base positions", &base_positions)?;
        check_finite("the base normals", &base_normals)?;
        let mut position_deltas = Vec::with_capacity(targets.len());
        let mut normal_deltas = Vec::with_capacity(targets.len());
        for (k, (p, nn)) in targets.iter().enumerate() {
            check_len(format!("target {} positions", k + 1), n, p.len())?;
            check_len(format!("target {} normals", k + 1), n, nn.len())?;
            check_finite(format!("target {} positions", k + 1), p)?;
            check_finite(format!("target {} normals", k + 1), nn)?;
            position_deltas.push(
                p.iter()
                    .zip(&base_positions)
                    .map(|(a, b)| *a - *b)
                    .collect(),
            );
            normal_deltas.push(nn.iter().zip(&base_normals).map(|(a, b)| *a - *b).collect());
        }
        Ok(Self {
            base_positions,
            base_normals,
            position_deltas,
            normal_deltas,
        })
    }

    pub fn vertex_count(&self) -> usize {
        self.base_positions.len()
    }

    pub fn target_count(&self) -> usize {
        self.position_deltas.len()
    }

    fn check_io(&self, weights: &[f32], p: &[Vec3], n: &[Vec3]) -> Result<(), BlendShapeError> {
        check_len(
            "weights (one per target)",
            self.target_count(),
            weights.len(),
        )?;
        check_len("output positions", self.vertex_count(), p.len())?;
        check_len("output normals", self.vertex_count(), n.len())?;
        if weights.iter().any(|w| !w.is_finite()) {
            return Err(BlendShapeError::NonFinite {
                what: "a weight".into(),
            });
        }
        Ok(())
    }

    /// The differential form, for any weights (one per target):
    /// ```text
    /// p = b₀ + Σₖ wₖ dₖ,     n = normalize(n₀ + Σₖ wₖ eₖ)      (eₖ: normal deltas)
    /// ```
    /// All weights zero give the base; weight 1 on target `k` alone gives target `k`. Targets
    /// with weight 0 are skipped (a face rig has dozens, most idle in any frame).
    ///
    /// # Errors
    /// Lengths, or a non-finite weight.
    pub fn apply_differential(
        &self,
        weights: &[f32],
        out_positions: &mut [Vec3],
        out_normals: &mut [Vec3],
    ) -> Result<(), BlendShapeError> {
        self.check_io(weights, out_positions, out_normals)?;
        out_positions.copy_from_slice(&self.base_positions);
        out_normals.copy_from_slice(&self.base_normals);
        for (k, &w) in weights.iter().enumerate() {
            if w == 0.0 {
                continue;
            }
            for (o, d) in out_positions.iter_mut().zip(&self.position_deltas[k]) {
                *o += w * *d;
            }
            for (o, d) in out_normals.iter_mut().zip(&self.normal_deltas[k]) {
                *o += w * *d;
            }
        }
        for n in out_normals.iter_mut() {
            *n = n.normalize_or_zero();
        }
        Ok(())
    }

    /// The full form over the base and the targets, with one weight per mesh: `weights[0]` for
    /// the base, `weights[k]` for target `k` (so `target_count() + 1` weights):
    /// ```text
    /// p = Σₖ wₖ bₖ        (k = 0 … K)
    /// ```
    /// Computed as `b₀ Σ w + Σ_{k≥1} wₖ dₖ`, which is the same thing. When the weights do not sum
    /// to 1 this returns the (scaled) result anyway and the caller reports it: the lesson shows
    /// what goes wrong. See [`blend_full`] for the strict version.
    ///
    /// # Errors
    /// Lengths, or a non-finite weight.
    pub fn apply_full(
        &self,
        weights: &[f32],
        out_positions: &mut [Vec3],
        out_normals: &mut [Vec3],
    ) -> Result<(), BlendShapeError> {
        let Some((&w0, rest)) = weights.split_first() else {
            return Err(BlendShapeError::LengthMismatch {
                what: "weights (the base, then one per target)".into(),
                expected: self.target_count() + 1,
                got: 0,
            });
        };
        self.check_io(rest, out_positions, out_normals)?;
        if !w0.is_finite() {
            return Err(BlendShapeError::NonFinite {
                what: "a weight".into(),
            });
        }
        let sum: f32 = weights.iter().sum();
        for (o, b) in out_positions.iter_mut().zip(&self.base_positions) {
            *o = sum * *b;
        }
        for (o, b) in out_normals.iter_mut().zip(&self.base_normals) {
            *o = sum * *b;
        }
        for (k, &w) in rest.iter().enumerate() {
            if w == 0.0 {
                continue;
            }
            for (o, d) in out_positions.iter_mut().zip(&self.position_deltas[k]) {
                *o += w * *d;
            }
            for (o, d) in out_normals.iter_mut().zip(&self.normal_deltas[k]) {
                *o += w * *d;
            }
        }
        for n in out_normals.iter_mut() {
            *n = n.normalize_or_zero();
        }
        Ok(())
    }
}

/// The full form on whole meshes, strict: `p = Σₖ wₖ bₖ` with the weights required to sum to 1
/// (within 1e-4).
///
/// # Errors
/// [`BlendShapeError::WeightsDoNotSumToOne`], lengths, non-finite input.
pub fn blend_full(
    meshes: &[&[Vec3]],
    weights: &[f32],
    out: &mut [Vec3],
) -> Result<(), BlendShapeError> {
    check_len("weights (one per mesh)", meshes.len(), weights.len())?;
    if weights.iter().any(|w| !w.is_finite()) {
        return Err(BlendShapeError::NonFinite {
            what: "a weight".into(),
        });
    }
    let sum: f32 = weights.iter().sum();
    if (sum - 1.0).abs() > 1e-4 {
        return Err(BlendShapeError::WeightsDoNotSumToOne { sum });
    }
    for (k, m) in meshes.iter().enumerate() {
        check_len(format!("mesh {k}"), out.len(), m.len())?;
    }
    out.fill(Vec3::ZERO);
    for (m, &w) in meshes.iter().zip(weights) {
        for (o, p) in out.iter_mut().zip(m.iter()) {
            *o += w * *p;
        }
    }
    Ok(())
}

/// A procedural face-like head for the lesson: a squashed sphere painted with a mouth, lips,
/// brows and cheeks (vertex colours), and four sculpted targets, each a smooth displacement of one
/// of those features.
pub struct Face {
    pub shapes: BlendShapes,
    /// The base mesh (positions, normals, indices).
    pub mesh: crate::mesh::MeshData,
    /// Linear RGBA per vertex: skin, lips, the mouth's opening, brows and cheeks. The paint moves
    /// with the vertices, so each target visibly moves its feature.
    pub colors: Vec<glam::Vec4>,
    /// The targets' names, in order.
    pub names: Vec<&'static str>,
    /// The targets' positions (the full form needs the whole meshes).
    pub targets: Vec<Vec<Vec3>>,
}

/// The targets of [`face`], in order.
pub const FACE_TARGETS: [&str; 4] = ["smile", "jaw open", "brows up", "puff cheeks"];

/// Segments (around) and rings (pole to pole) of the face's sphere: rings 2.8125° apart, so the
/// mouth's opening spans two rings (41 and 42, y = −0.428 and −0.471) and each lip one more.
pub const FACE_SEGMENTS: u32 = 96;
pub const FACE_RINGS: u32 = 64;
/// Height of the middle of the mouth (between rings 41 and 42) and of the brows (between rings
/// 22 and 23), metres from the head's centre.
pub const MOUTH_Y: f32 = -0.4495;
pub const BROW_Y: f32 = 0.4495;

/// Ramps from 0 at `lo` to 1 at `hi` with zero slope at both ends (a plain clamp leaves a crease
/// in the shading where a displacement starts). `lo > hi` ramps the other way.
fn smoothstep(lo: f32, hi: f32, v: f32) -> f32 {
    let t = ((v - lo) / (hi - lo)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// A Gaussian bump of `width` around `centre`: 1 there, about 0.37 one width away.
fn bump(v: f32, centre: f32, width: f32) -> f32 {
    (-((v - centre) / width).powi(2)).exp()
}

/// How much a base-mesh point lies on the front of the face: 0 behind z = 0.2, 1 beyond z = 0.6.
fn front(p: Vec3) -> f32 {
    smoothstep(0.2, 0.6, p.z)
}

/// The displacement of base point `p` in target `k` (0 smile, 1 jaw open, 2 brows up, 3 puff
/// cheeks), metres.
pub fn face_displacement(k: usize, p: Vec3) -> Vec3 {
    match k {
        // Smile: the mouth's corners rise 16 cm and pull back; its middle stays, and the rise
        // fades out beyond the corners (by |x| = 0.55) so the cheeks do not fold.
        0 => {
            let x = p.x.abs();
            let corners = smoothstep(0.0, 0.25, x) * smoothstep(0.55, 0.3, x);
            let f = front(p) * bump(p.y, MOUTH_Y, 0.12) * corners;
            Vec3::new(0.05 * p.x.signum(), 0.16, -0.05) * f
        }
        // Jaw open: everything below the middle of the mouth drops 25 cm (less towards the
        // sides). Across the mouth the drop starts between its two dark rings, so the opening
        // gapes; beside the mouth it ramps in over 45 cm of height, so the cheeks stretch
        // smoothly instead of creasing along the mouth's line.
        1 => {
            let side = smoothstep(0.2, 0.4, p.x.abs());
            let top = -0.43 + 0.15 * side;
            let bottom = -0.47 - 0.25 * side;
            let f = front(p) * smoothstep(top, bottom, p.y) * bump(p.x, 0.0, 0.4);
            Vec3::new(0.0, -0.25, 0.03) * f
        }
        // Brows up: the brows and the band around them rise 12 cm.
        2 => {
            let f = front(p) * bump(p.y, BROW_Y, 0.1) * bump(p.x.abs(), 0.27, 0.2);
            Vec3::new(0.0, 0.12, 0.02) * f
        }
        // Puff cheeks: the cheeks swell outwards and forwards.
        3 => {
            let f = front(p) * bump(p.y, -0.2, 0.18) * bump(p.x.abs(), 0.5, 0.18);
            Vec3::new(p.x.signum() * 0.14, 0.0, 0.08) * f
        }
        _ => Vec3::ZERO,
    }
}

/// The paint of base point `p` (linear RGBA): the mouth's opening, the lips, the brows, the
/// cheeks' blush, or skin.
pub fn face_color(p: Vec3) -> glam::Vec4 {
    const SKIN: Vec3 = Vec3::new(0.85, 0.62, 0.48);
    const LIPS: Vec3 = Vec3::new(0.55, 0.1, 0.1);
    const OPENING: Vec3 = Vec3::new(0.1, 0.02, 0.02);
    const BROW: Vec3 = Vec3::new(0.16, 0.08, 0.04);
    const BLUSH: Vec3 = Vec3::new(0.9, 0.38, 0.38);
    let on_front = p.z > 0.3;
    let mouth = (p.y - MOUTH_Y).abs();
    let c = if on_front && mouth < 0.03 && p.x.abs() < 0.24 {
        OPENING
    } else if on_front && mouth < 0.075 && p.x.abs() < 0.28 {
        LIPS
    } else if on_front && (p.y - BROW_Y).abs() < 0.03 && (0.1..0.44).contains(&p.x.abs()) {
        BROW
    } else {
        let blush = 0.6 * front(p) * bump(p.y, -0.2, 0.1) * bump(p.x.abs(), 0.48, 0.1);
        SKIN.lerp(BLUSH, blush)
    };
    c.extend(1.0)
}

/// Builds [`Face`].
pub fn face() -> Face {
    // Closed (no seam, one vertex per pole): the normals are recomputed from the faces for every
    // target, and a UV sphere's seam would show as a crease down the middle of the face.
    let mut mesh = crate::mesh::closed_sphere(1.0, FACE_SEGMENTS, FACE_RINGS);
    for p in &mut mesh.positions {
        *p *= Vec3::new(0.8, 1.0, 0.85);
    }
    let mut targets = Vec::new();
    let mut pairs = Vec::new();
    for k in 0..FACE_TARGETS.len() {
        let p: Vec<Vec3> = mesh
            .positions
            .iter()
            .map(|&p| p + face_displacement(k, p))
            .collect();
        let mut n = vec![Vec3::ZERO; p.len()];
        crate::raster::vertex_normals(&p, &mesh.indices, &mut n).valid("valid indices");
        pairs.push((p.clone(), n));
        targets.push(p);
    }
    let mut base_normals = vec![Vec3::ZERO; mesh.positions.len()];
    crate::raster::vertex_normals(&mesh.positions, &mesh.indices, &mut base_normals)
        .valid("valid indices");
    mesh.normals = base_normals.clone();
    let colors = mesh.positions.iter().map(|&p| face_color(p)).collect();
    let shapes = BlendShapes::from_targets(mesh.positions.clone(), base_normals, &pairs)
        .valid("the face's targets match its base");
    Face {
        shapes,
        mesh,
        colors,
        names: FACE_TARGETS.to_vec(),
        targets,
    }
}

/// One vertex in the differential form: `p = b₀ + Σₖ wₖ (bₖ − b₀)` (the reference for exercise
/// 10.1; `targets[k]` is target `k`'s position of this vertex; extra entries of the longer slice
/// are ignored).
pub fn differential_vertex(base: Vec3, targets: &[Vec3], weights: &[f32]) -> Vec3 {
    base + targets
        .iter()
        .zip(weights)
        .map(|(t, &w)| w * (*t - base))
        .sum::<Vec3>()
}
