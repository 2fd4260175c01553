//! Deterministic inputs shared by the grader, the criterion benches and the browser bench page,
//! so that native and browser numbers measure the same work.

use crate::curves::Track;
use crate::transform::local_matrix;
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
    let track = Track::new(times, values).expect("increasing finite keys");
    let (start, duration) = (track.start_sec(), track.duration_sec());
    let increasing = (0..samples)
        .map(|k| start + duration * k as f32 / samples as f32)
        .collect();
    let random = (0..samples)
        .map(|_| start + duration * rng.range(0.0, 1.0))
        .collect();
    (track, increasing, random)
}
