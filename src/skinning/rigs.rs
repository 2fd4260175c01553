//! Skinned test subjects built in code (no asset files) and the measures the lesson plots.
//!
//! - [`cylinder_rig`]: the classic bend-and-twist test, a capped tube over two bones.
//! - [`skinned_human`]: the built-in simple human ([`crate::skeleton::human`]) with one ellipsoid
//!   per joint, skinned with [`auto_weights`] so the parts blend at the joints.
//!
//! A character loaded from a file (glTF, later) is the same [`SkinnedCharacter`]: a skeleton whose
//! inverse bind matrices come from the file, the bind-pose mesh, and its [`SkinWeights`].

use super::{auto_weights, SkinWeights, SkinningError};
use crate::mesh::MeshData;
use crate::skeleton::{human, Skeleton, Transform};
use crate::Valid;
use glam::{Affine3A, Vec3, Vec4};

/// A skeleton and a mesh bound to it: what the skinning functions need, from code or a file.
#[derive(Clone, Debug)]
pub struct SkinnedCharacter {
    pub skeleton: Skeleton,
    /// The mesh in the bind pose, model space.
    pub mesh: MeshData,
    /// Linear RGBA, one per vertex.
    pub colors: Vec<Vec4>,
    pub skin: SkinWeights,
}

/// The bend-and-twist cylinder: three joints along +x (`shoulder` at the origin, `elbow` at
/// `segment_length`, `wrist` at twice that), a capped tube of `radius` around the two bones.
#[derive(Clone, Debug)]
pub struct CylinderRig {
    pub skeleton: Skeleton,
    /// Bind-pose mesh: `rings × around` tube vertices (ring `r` at `x = 2 L r / (rings − 1)`),
    /// then the two cap centres.
    pub mesh: MeshData,
    /// Each joint's bone in the bind pose (the wrist's is a point at the tip).
    pub segments: Vec<(Vec3, Vec3)>,
    pub rings: usize,
    pub around: usize,
    pub radius: f32,
    pub segment_length: f32,
}

/// The most rings or vertices around the cylinder may have.
pub const MAX_CYLINDER_RESOLUTION: usize = 512;

impl CylinderRig {
    /// Index of the first vertex of ring `r`.
    pub fn ring_start(&self, r: usize) -> usize {
        r * self.around
    }

    /// The ring at the elbow (halfway along).
    pub fn elbow_ring(&self) -> usize {
        (self.rings - 1) / 2
    }

    /// Area of one ring in the bind pose (a regular polygon of `around` sides).
    pub fn rest_ring_area(&self) -> f32 {
        let a = self.around as f32;
        0.5 * a * self.radius * self.radius * (std::f32::consts::TAU / a).sin()
    }

    /// Automatic weights over the shoulder and elbow bones (the wrist bears no vertex).
    pub fn weights(&self, falloff: f32) -> Result<SkinWeights, SkinningError> {
        let segments = &self.segments[..2];
        let skin = auto_weights(&self.mesh.positions, segments, falloff, |_| 0..2)?;
        // Re-validate against the whole skeleton (three joints).
        SkinWeights::new(
            skin.joints().to_vec(),
            skin.weights().to_vec(),
            self.skeleton.len(),
        )
    }
}

/// Builds the bend-and-twist cylinder. `rings` is odd so one ring sits exactly at the elbow.
///
/// # Errors
/// [`SkinningError::BadParameter`] for a non-positive or non-finite size, `rings` below 3 or even,
/// `around` below 3, or either over [`MAX_CYLINDER_RESOLUTION`].
pub fn cylinder_rig(
    segment_length: f32,
    radius: f32,
    rings: usize,
    around: usize,
) -> Result<CylinderRig, SkinningError> {
    let bad = |m: String| Err(SkinningError::BadParameter(m));
    if !(segment_length.is_finite() && segment_length > 0.0 && radius.is_finite() && radius > 0.0) {
        return bad(format!(
            "segment length and radius must be positive, got {segment_length} and {radius}"
        ));
    }
    if !(3..=MAX_CYLINDER_RESOLUTION).contains(&rings) || rings.is_multiple_of(2) {
        return bad(format!(
            "rings must be odd and in [3, {MAX_CYLINDER_RESOLUTION}], got {rings}"
        ));
    }
    if !(3..=MAX_CYLINDER_RESOLUTION).contains(&around) {
        return bad(format!(
            "vertices around must be in [3, {MAX_CYLINDER_RESOLUTION}], got {around}"
        ));
    }
    let l = segment_length;
    let skeleton = Skeleton::new(
        vec!["shoulder".into(), "elbow".into(), "wrist".into()],
        vec![-1, 0, 1],
        vec![
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(l, 0.0, 0.0)),
            Transform::from_translation(Vec3::new(l, 0.0, 0.0)),
        ],
    )
    .map_err(|e| SkinningError::BadParameter(e.to_string()))?;
    let mut mesh = MeshData::default();
    for r in 0..rings {
        let x = 2.0 * l * r as f32 / (rings - 1) as f32;
        for k in 0..around {
            let theta = std::f32::consts::TAU * k as f32 / around as f32;
            let n = Vec3::new(0.0, theta.cos(), theta.sin());
            mesh.positions.push(Vec3::new(x, 0.0, 0.0) + radius * n);
            mesh.normals.push(n);
        }
    }
    let c0 = (rings * around) as u32;
    mesh.positions.push(Vec3::ZERO);
    mesh.normals.push(-Vec3::X);
    mesh.positions.push(Vec3::new(2.0 * l, 0.0, 0.0));
    mesh.normals.push(Vec3::X);
    let a = around as u32;
    for r in 0..rings as u32 - 1 {
        for k in 0..a {
            let k1 = (k + 1) % a;
            let (p00, p01, p10, p11) = (r * a + k, r * a + k1, (r + 1) * a + k, (r + 1) * a + k1);
            mesh.indices
                .extend_from_slice(&[p00, p01, p10, p01, p11, p10]);
        }
    }
    let last = (rings as u32 - 1) * a;
    for k in 0..a {
        let k1 = (k + 1) % a;
        mesh.indices.extend_from_slice(&[c0, k1, k]);
        mesh.indices
            .extend_from_slice(&[c0 + 1, last + k, last + k1]);
    }
    let segments = vec![
        (Vec3::ZERO, Vec3::new(l, 0.0, 0.0)),
        (Vec3::new(l, 0.0, 0.0), Vec3::new(2.0 * l, 0.0, 0.0)),
        (Vec3::new(2.0 * l, 0.0, 0.0), Vec3::new(2.0 * l, 0.0, 0.0)),
    ];
    Ok(CylinderRig {
        skeleton,
        mesh,
        segments,
        rings,
        around,
        radius,
        segment_length,
    })
}

/// Area enclosed by a closed loop of points (a skinned ring), by its vector area:
/// ```text
/// A = ½ ‖Σₖ (pₖ − c) × (pₖ₊₁ − c)‖,     c = the loop's centroid
/// ```
/// Exact for a planar polygon; for a warped loop it is the area of its projection on the best
/// plane. Returns 0 for fewer than three points.
pub fn ring_area(ring: &[Vec3]) -> f32 {
    if ring.len() < 3 {
        return 0.0;
    }
    let c = ring.iter().sum::<Vec3>() / ring.len() as f32;
    let mut s = Vec3::ZERO;
    for (k, p) in ring.iter().enumerate() {
        let q = ring[(k + 1) % ring.len()];
        s += (*p - c).cross(q - c);
    }
    0.5 * s.length()
}

/// Volume enclosed by a closed triangle mesh (counter-clockwise seen from outside), by the
/// divergence theorem:
/// ```text
/// V = ⅙ Σ_triangles a · (b × c)
/// ```
/// Indices past the end of `positions` are skipped.
pub fn mesh_volume(positions: &[Vec3], indices: &[u32]) -> f32 {
    indices
        .chunks_exact(3)
        .filter_map(|t| {
            let a = positions.get(t[0] as usize)?;
            let b = positions.get(t[1] as usize)?;
            let c = positions.get(t[2] as usize)?;
            Some(a.dot(b.cross(*c)))
        })
        .sum::<f32>()
        / 6.0
}

/// The built-in simple human with a skinned body: one ellipsoid per joint (its box from
/// [`human::simple_human`], enlarged so neighbours overlap), weighted by [`auto_weights`] over
/// each joint's bone. A vertex of joint `i`'s part may follow `i`, its parent and its children
/// only, so the side of the chest does not follow the upper arm.
///
/// # Errors
/// [`SkinningError::BadParameter`] for a falloff outside [`auto_weights`]'s range.
pub fn skinned_human(falloff: f32) -> Result<SkinnedCharacter, SkinningError> {
    let (skeleton, shapes) = human::simple_human();
    let n = skeleton.len();
    let mut model = vec![Affine3A::IDENTITY; n];
    skeleton
        .model_matrices(&skeleton.rest_pose(), &mut model)
        .map_err(|e| SkinningError::BadParameter(e.to_string()))?;
    let parents = skeleton.parents();
    // A joint's bone: from its pivot through its box to the far side (limbs hang along −y).
    let segments: Vec<(Vec3, Vec3)> = (0..n)
        .map(|i| {
            let a = model[i].transform_point3(Vec3::ZERO);
            let b = model[i].transform_point3(2.0 * shapes[i].center);
            (a, b)
        })
        .collect();
    let sphere = crate::mesh::uv_sphere(1.0, 14, 9);
    let mut mesh = MeshData::default();
    let mut colors = Vec::new();
    let mut part = Vec::new();
    for (i, shape) in shapes.iter().enumerate() {
        // Stretch along the longest axis more, so limbs overlap at the joints.
        let h = shape.half_extents;
        let longest = h.max_element();
        let s = Vec3::new(
            h.x * if h.x == longest { 1.3 } else { 1.15 },
            h.y * if h.y == longest { 1.3 } else { 1.15 },
            h.z * if h.z == longest { 1.3 } else { 1.15 },
        );
        let base = mesh.positions.len() as u32;
        for (p, nrm) in sphere.positions.iter().zip(&sphere.normals) {
            mesh.positions
                .push(model[i].transform_point3(shape.center + *p * s));
            mesh.normals
                .push(model[i].transform_vector3(*nrm / s).normalize_or_zero());
            colors.push(shape.color.extend(1.0));
            part.push(i);
        }
        mesh.indices
            .extend(sphere.indices.iter().map(|&k| base + k));
    }
    let skin = auto_weights(&mesh.positions, &segments, falloff, |v| {
        let i = part[v];
        let parent = parents[i];
        std::iter::once(i)
            .chain((parent >= 0).then_some(parent as usize))
            .chain((i + 1..n).filter(move |&c| parents[c] == i as i32))
    })?;
    Ok(SkinnedCharacter {
        skeleton,
        mesh,
        colors,
        skin,
    })
}

impl CylinderRig {
    /// The pose that bends the elbow by `bend_rad` about z, then twists it by `twist_rad` about
    /// its own bone (x); the shoulder and wrist keep their rest transforms.
    pub fn pose(&self, bend_rad: f32, twist_rad: f32) -> crate::skeleton::Pose {
        let mut pose = self.skeleton.rest_pose();
        pose.local[1].rotation =
            glam::Quat::from_rotation_z(bend_rad) * glam::Quat::from_rotation_x(twist_rad);
        pose
    }

    /// The skinning palette `K_j = M_j B_j⁻¹` of [`CylinderRig::pose`] into `out` (3 joints).
    ///
    /// # Errors
    /// A length mismatch, or a non-finite angle.
    pub fn palette(
        &self,
        bend_rad: f32,
        twist_rad: f32,
        model: &mut [Affine3A],
        out: &mut [Affine3A],
    ) -> Result<(), SkinningError> {
        let pose = self.pose(bend_rad, twist_rad);
        self.skeleton
            .model_matrices(&pose, model)
            .map_err(|e| SkinningError::BadParameter(e.to_string()))?;
        super::skinning_palette(model, self.skeleton.inverse_bind(), out)
    }
}

/// The benchmark's input (native criterion and the browser bench page): `vertices` random
/// vertices in a 2 m box, each bound to four distinct joints of the 60-joint benchmark humanoid
/// with random normalised weights, and the skinning palette of that humanoid at 0.37 s of its clip
/// with the scale keys dropped (rigid joints, so DQS accepts it).
pub struct BenchmarkSkin {
    pub palette: Vec<Affine3A>,
    pub skin: SkinWeights,
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
}

/// See [`BenchmarkSkin`]. `vertices` is capped at [`super::MAX_SKIN_VERTICES`].
pub fn benchmark_input(vertices: usize, seed: u64) -> BenchmarkSkin {
    use crate::fixtures::Rng;
    let mut rng = Rng::new(seed);
    let (skeleton, raw) = human::benchmark_humanoid(&mut rng);
    let n = skeleton.len();
    let clip = crate::skeleton::Clip::from_raw(&raw, &skeleton).valid("the benchmark clip builds");
    let mut pose = skeleton.rest_pose();
    clip.sample(0.37, &mut crate::skeleton::ClipCursor::new(), &mut pose);
    // The clip keys scale too; DQS takes rigid joints only, so drop it.
    for x in &mut pose.local {
        x.scale = Vec3::ONE;
    }
    let mut model = vec![Affine3A::IDENTITY; n];
    skeleton
        .model_matrices(&pose, &mut model)
        .valid("the benchmark pose is valid");
    let mut palette = vec![Affine3A::IDENTITY; n];
    super::skinning_palette(&model, skeleton.inverse_bind(), &mut palette).valid("finite matrices");
    let vertices = vertices.min(super::MAX_SKIN_VERTICES);
    let mut joints = Vec::with_capacity(vertices);
    let mut weights = Vec::with_capacity(vertices);
    let mut positions = Vec::with_capacity(vertices);
    let mut normals = Vec::with_capacity(vertices);
    for _ in 0..vertices {
        let first = rng.below(n);
        let j = [0, 7, 19, 31].map(|d| ((first + d) % n) as u16);
        joints.push(j);
        weights.push([0; 4].map(|_| rng.range(0.05, 1.0)));
        positions.push(rng.vec3(-1.0, 1.0));
        normals.push(rng.vec3(-1.0, 1.0).normalize_or(Vec3::Y));
    }
    let skin = SkinWeights::new(joints, weights, n).valid("valid benchmark weights");
    BenchmarkSkin {
        palette,
        skin,
        positions,
        normals,
    }
}

/// Flat arrays: `(palette, joints, weights, positions, normals)`.
pub type FlatSkin = (Vec<f32>, Vec<u16>, Vec<f32>, Vec<f32>, Vec<f32>);

impl BenchmarkSkin {
    /// The same data as flat arrays for [`super::skin_lbs_plain_loop`] (and JavaScript):
    /// `(palette, joints, weights, positions, normals)`.
    pub fn flat(&self) -> FlatSkin {
        let palette = self
            .palette
            .iter()
            .flat_map(|k| {
                let m = glam::Mat4::from(*k).to_cols_array();
                [
                    m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10], m[12], m[13], m[14],
                ]
            })
            .collect();
        let joints = self.skin.joints().iter().flatten().copied().collect();
        let weights = self.skin.weights().iter().flatten().copied().collect();
        let positions = self.positions.iter().flat_map(|p| p.to_array()).collect();
        let normals = self.normals.iter().flat_map(|p| p.to_array()).collect();
        (palette, joints, weights, positions, normals)
    }
}
