//! Deterministic inputs shared by the grader, the criterion benches and the browser bench page,
//! so that native and browser numbers measure the same work.

use crate::curves::Track;
use crate::transform::local_matrix;
use crate::Valid;
use glam::{Mat4, Vec3};

/// A small deterministic generator (SplitMix64): the same inputs on every machine and in wasm.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        let unit = (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32;
        lo + (hi - lo) * unit
    }
    /// Uniform integer in [0, n).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n.max(1) as u64) as usize
    }
    pub fn vec3(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(self.range(lo, hi), self.range(lo, hi), self.range(lo, hi))
    }
}

/// A branching hierarchy of `joints` joints (joint i hangs off joint (i − 1) / 2) and its local
/// matrices: the forward-kinematics benchmark input.
pub fn binary_tree_hierarchy(joints: usize) -> (Vec<i32>, Vec<Mat4>) {
    let parents = (0..joints as i32)
        .map(|i| if i == 0 { -1 } else { (i - 1) / 2 })
        .collect();
    let local = (0..joints)
        .map(|i| local_matrix(Vec3::new(0.0, 0.1, 0.0), Vec3::splat(i as f32 * 0.01)))
        .collect();
    (parents, local)
}

/// The keyframe benchmark input: a `Vec3` track of `keys` keys at non-uniform times (steps of
/// 0.05 to 0.15 s) with random positions in [0, 10)³, and `samples` sample times over its
/// duration, once in increasing order and once at random.
pub fn sampling_benchmark(
    keys: usize,
    samples: usize,
    rng: &mut Rng,
) -> (Track<Vec3>, Vec<f32>, Vec<f32>) {
    let mut times = Vec::with_capacity(keys);
    let mut values = Vec::with_capacity(keys);
    let mut t = 0.0;
    for _ in 0..keys.max(2) {
        times.push(t);
        t += rng.range(0.05, 0.15);
        values.push(rng.vec3(0.0, 10.0));
    }
    let track = Track::new(times, values).valid("increasing finite keys");
    let (start, duration) = (track.start_sec(), track.duration_sec());
    let increasing = (0..samples)
        .map(|k| start + duration * k as f32 / samples as f32)
        .collect();
    let random = (0..samples)
        .map(|_| start + duration * rng.range(0.0, 1.0))
        .collect();
    (track, increasing, random)
}

/// A small valid glTF file of our own (two joints listed child first, one skinned triangle,
/// one animation, buffers embedded as a data URI), for the importer's tests and bad-input tests
/// that must not depend on third-party samples.
pub fn tiny_skinned_gltf() -> String {
    use base64::Engine;
    let mut bin: Vec<u8> = Vec::new();
    let f = |bin: &mut Vec<u8>, xs: &[f32]| xs.iter().for_each(|x| bin.extend(x.to_le_bytes()));
    // 0: positions (3 × vec3) at 0
    f(&mut bin, &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    // 1: joints (3 × u8vec4) at 36
    bin.extend([0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0]);
    // 2: weights (3 × vec4) at 48
    f(
        &mut bin,
        &[1.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
    );
    // 3: inverse binds (2 × mat4) at 96
    f(&mut bin, &glam::Mat4::IDENTITY.to_cols_array());
    f(
        &mut bin,
        &glam::Mat4::from_translation(glam::Vec3::new(0.0, -1.0, 0.0)).to_cols_array(),
    );
    // 4: times (2) at 224, 5: rotations (2 × vec4) at 232
    f(&mut bin, &[0.0, 1.0]);
    let h = std::f32::consts::FRAC_1_SQRT_2;
    f(&mut bin, &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, h, h]);
    let uri = format!(
        "data:application/octet-stream;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(&bin)
    );
    format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0,1]}}],
"nodes":[{{"mesh":0,"skin":0}},{{"name":"hip","children":[2]}},{{"name":"knee","translation":[0,1,0]}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"JOINTS_0":1,"WEIGHTS_0":2}}}}]}}],
"skins":[{{"joints":[2,1],"inverseBindMatrices":3}}],
"animations":[{{"name":"bend","channels":[{{"sampler":0,"target":{{"node":2,"path":"rotation"}}}}],
  "samplers":[{{"input":4,"output":5,"interpolation":"LINEAR"}}]}}],
"buffers":[{{"byteLength":{len},"uri":"{uri}"}}],
"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":36}},{{"buffer":0,"byteOffset":36,"byteLength":12}},
  {{"buffer":0,"byteOffset":48,"byteLength":48}},{{"buffer":0,"byteOffset":96,"byteLength":128}},
  {{"buffer":0,"byteOffset":224,"byteLength":8}},{{"buffer":0,"byteOffset":232,"byteLength":32}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}},
  {{"bufferView":1,"componentType":5121,"count":3,"type":"VEC4"}},
  {{"bufferView":2,"componentType":5126,"count":3,"type":"VEC4"}},
  {{"bufferView":3,"componentType":5126,"count":2,"type":"MAT4"}},
  {{"bufferView":4,"componentType":5126,"count":2,"type":"SCALAR","min":[0],"max":[1]}},
  {{"bufferView":5,"componentType":5126,"count":2,"type":"VEC4"}}]}}"#,
        len = bin.len()
    )
}
