//! Running a student's exercise from a figure, so that a panic in it cannot take the page down.
//!
//! # Why this indirection
//! On wasm a Rust panic aborts: the module instance traps, and every figure that lives in it
//! stops for good. So the figures never call a student's function directly. A scene holds a
//! [`Runner`] and calls the exercise through the typed wrappers below (`run::slerp(runner, a, b,
//! t)`), which flatten the arguments into `f32`s and call the runner by the exercise's name:
//!
//! - natively (tests, the grader) the runner is [`direct`]: it decodes the arguments and calls the
//!   exercise in the same process;
//! - in the page the runner is `web::sandbox::run`, which hands the numbers to a *second*
//!   instance of the same wasm module (the sandbox, created by `www/lesson.js`). If the student's
//!   code panics there, only the sandbox dies: the page catches the trap, keeps the panic message,
//!   starts a fresh sandbox, and the figure gets [`Failure::Panicked`], falls back to the reference
//!   and says so next to itself. The figures' own instance never runs student code.
//!
//! Tests can pass any other runner, for instance one that returns a deliberately wrong answer, to
//! check what a figure says about it.

use super::Answer;
use crate::rigid::DualQuat;
use glam::{Mat3, Mat4, Quat, Vec3};

/// Why a student's exercise gave no answer.
#[derive(Clone, Debug, PartialEq)]
pub enum Failure {
    /// The exercise still returns `Err(NotDone)`.
    NotDone,
    /// It panicked; the message says where (`file:line`) and why.
    Panicked(String),
    /// The call itself went wrong (unknown exercise, arguments that do not decode): a bug.
    Call(String),
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::NotDone => f.write_str("not done yet"),
            Failure::Panicked(m) => write!(f, "panicked: {m}"),
            Failure::Call(m) => write!(f, "could not be called: {m}"),
        }
    }
}

/// Calls the exercise named `name` on flattened arguments and returns its flattened answer.
pub type Runner = fn(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure>;

/// A value that travels between module instances as a run of `f32`s.
pub trait Flat: Sized {
    fn put(&self, out: &mut Vec<f32>);
    /// Reads one value from the front of `input` and advances it; `None` if there are too few.
    fn take(input: &mut &[f32]) -> Option<Self>;
}

fn take_n<const N: usize>(input: &mut &[f32]) -> Option<[f32; N]> {
    if input.len() < N {
        return None;
    }
    let (head, rest) = input.split_at(N);
    *input = rest;
    head.try_into().ok()
}

impl Flat for f32 {
    fn put(&self, out: &mut Vec<f32>) {
        out.push(*self);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        take_n::<1>(input).map(|[x]| x)
    }
}

/// Indices and counts (exact as `f32` up to 2²⁴).
impl Flat for usize {
    fn put(&self, out: &mut Vec<f32>) {
        out.push(*self as f32);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        let x = f32::take(input)?;
        (x >= 0.0 && x.fract() == 0.0).then_some(x as usize)
    }
}

impl Flat for () {
    fn put(&self, _: &mut Vec<f32>) {}
    fn take(_: &mut &[f32]) -> Option<Self> {
        Some(())
    }
}

impl<const N: usize> Flat for [f32; N] {
    fn put(&self, out: &mut Vec<f32>) {
        out.extend_from_slice(self);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        take_n::<N>(input)
    }
}

/// Two points, as the pair exercises take them (`[i, j]`).
impl Flat for [glam::Vec2; 2] {
    fn put(&self, out: &mut Vec<f32>) {
        self[0].put(out);
        self[1].put(out);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        Some([glam::Vec2::take(input)?, glam::Vec2::take(input)?])
    }
}

impl Flat for Vec3 {
    fn put(&self, out: &mut Vec<f32>) {
        self.to_array().put(out);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        take_n::<3>(input).map(Vec3::from_array)
    }
}

impl Flat for glam::Vec2 {
    fn put(&self, out: &mut Vec<f32>) {
        self.to_array().put(out);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        take_n::<2>(input).map(glam::Vec2::from_array)
    }
}

impl Flat for Quat {
    fn put(&self, out: &mut Vec<f32>) {
        self.to_array().put(out);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        take_n::<4>(input).map(Quat::from_array)
    }
}

impl Flat for Mat3 {
    fn put(&self, out: &mut Vec<f32>) {
        self.to_cols_array().put(out);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        take_n::<9>(input).map(|a| Mat3::from_cols_array(&a))
    }
}

impl Flat for Mat4 {
    fn put(&self, out: &mut Vec<f32>) {
        self.to_cols_array().put(out);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        take_n::<16>(input).map(|a| Mat4::from_cols_array(&a))
    }
}

impl Flat for DualQuat {
    fn put(&self, out: &mut Vec<f32>) {
        self.real.put(out);
        self.dual.put(out);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        Some(DualQuat {
            real: Quat::take(input)?,
            dual: Quat::take(input)?,
        })
    }
}

/// A length, then the items.
impl<T: Flat> Flat for Vec<T> {
    fn put(&self, out: &mut Vec<f32>) {
        self.len().put(out);
        for x in self {
            x.put(out);
        }
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        let n = usize::take(input)?;
        if n > input.len() {
            return None; // every item takes at least one number
        }
        (0..n).map(|_| T::take(input)).collect()
    }
}

impl<A: Flat, B: Flat> Flat for (A, B) {
    fn put(&self, out: &mut Vec<f32>) {
        self.0.put(out);
        self.1.put(out);
    }
    fn take(input: &mut &[f32]) -> Option<Self> {
        Some((A::take(input)?, B::take(input)?))
    }
}

/// Exercise `name`'s answer read from its flattened numbers: one `T` and nothing after it.
/// Out of line, so that the wrappers share one body per answer type rather than each holding
/// its own decoding and error message.
#[inline(never)]
fn answer<T: Flat>(name: &str, out: &[f32]) -> Result<T, Failure> {
    let mut rest = out;
    T::take(&mut rest)
        .filter(|_| rest.is_empty())
        .ok_or_else(|| malformed(name))
}

#[cold]
#[inline(never)]
fn malformed(name: &str) -> Failure {
    Failure::Call(format!("{name}: malformed answer"))
}

/// Declares each exercise once: its typed wrapper (for scenes) and its arm in [`direct`].
macro_rules! exercises {
    ($( $(#[$doc:meta])* fn $name:ident($($arg:ident: $ty:ty),*) -> $ret:ty = $call:expr; )*) => {
        $(
            $(#[$doc])*
            #[allow(clippy::too_many_arguments)] // one argument per input of the exercise
            pub fn $name(run: Runner, $($arg: $ty),*) -> Result<$ret, Failure> {
                let mut args = Vec::new();
                $( Flat::put(&$arg, &mut args); )*
                answer(stringify!($name), &run(stringify!($name), &args)?)
            }
        )*

        /// The names of every exercise a figure can run.
        pub const NAMES: &[&str] = &[$(stringify!($name)),*];

        /// Runs the exercise `name` in this instance (natively, and inside the page's sandbox).
        pub fn direct(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
            #[cfg(any(feature = "student-bugs", debug_assertions))]
            if super::student_bugs_on() {
                if let Some(result) = student_bugs(name, args) {
                    return result;
                }
            }
            match name {
                $(
                    stringify!($name) => {
                        let mut rest = args;
                        $(
                            let $arg = <$ty as Flat>::take(&mut rest).ok_or_else(|| {
                                Failure::Call(format!("{}: bad argument {}", name, stringify!($arg)))
                            })?;
                        )*
                        let answer: Answer<$ret> = $call;
                        let mut out = Vec::new();
                        answer.map_err(|_| Failure::NotDone)?.put(&mut out);
                        Ok(out)
                    }
                )*
                _ => Err(Failure::Call(format!("no exercise named {name:?}"))),
            }
        }
    };
}

use super::blend_shapes as bs;
use super::blending as bl;
use super::cloth as cl;
use super::fluid as fl;
use super::ik as ik7;
use super::noise as nz;
use super::rigid_body as rb;
use super::skinning as sn;
use super::{boids as bo, particles as pa};
use super::{
    curves as c, expressive as ex, raster as ra, rotations as r, skeleton as sk, transforms as tr,
};

exercises! {
    /// Exercise 1.1, [`tr::local_matrix`].
    fn local_matrix(translation: Vec3, euler_xyz_rad: Vec3) -> Mat4 =
        tr::local_matrix(translation, euler_xyz_rad);
    /// Exercise 1.2, [`tr::world_matrices`]: parents as `f32`s (exact), one world matrix per joint.
    fn world_matrices(parents: Vec<f32>, local: Vec<Mat4>) -> Vec<Mat4> = {
        let parents: Vec<i32> = parents.iter().map(|&p| p as i32).collect();
        let mut world = vec![Mat4::IDENTITY; local.len()];
        tr::world_matrices(&parents, &local, &mut world).map(|()| world)
    };
    /// Exercise 2.1, [`c::hermite_basis`].
    fn hermite_basis(s: f32) -> [f32; 4] = c::hermite_basis(s);
    /// Exercise 2.2, [`c::cardinal_tangents`]: one tangent per key.
    fn cardinal_tangents(times: Vec<f32>, values: Vec<f32>, mu: f32) -> Vec<f32> = {
        let mut out = vec![0.0; values.len()];
        c::cardinal_tangents(&times, &values, mu, &mut out).map(|()| out)
    };
    /// Exercise 2.3, [`c::find_segment`].
    fn find_segment(times: Vec<f32>, t: f32) -> usize = c::find_segment(&times, t);
    /// Exercise 2.4, [`c::arc_length_invert`].
    fn arc_length_invert(params: Vec<f32>, lengths: Vec<f32>, s: f32) -> f32 =
        c::arc_length_invert(&params, &lengths, s);
    /// Exercise 3.1, [`r::quat_from_axis_angle`].
    fn quat_from_axis_angle(axis: Vec3, angle_rad: f32) -> Quat =
        r::quat_from_axis_angle(axis, angle_rad);
    /// Exercise 3.2, [`r::slerp`].
    fn slerp(a: Quat, b: Quat, t: f32) -> Quat = r::slerp(a, b, t);
    /// Exercise 3.3, [`r::rodrigues_matrix`].
    fn rodrigues_matrix(axis: Vec3, angle_rad: f32) -> Mat3 = r::rodrigues_matrix(axis, angle_rad);
    /// Exercise 4.1, [`r::dual_quat_apply`].
    fn dual_quat_apply(rotation: Quat, translation: Vec3, point: Vec3) -> (DualQuat, Vec3) =
        r::dual_quat_apply(rotation, translation, point);
    /// Exercise 4.2, [`r::polar_step`].
    fn polar_step(m: Mat3) -> Mat3 = r::polar_step(m);
    /// Exercise 0.1, [`ra::perspective_matrix`].
    fn perspective_matrix(fov_y_rad: f32, aspect: f32, near: f32, far: f32) -> Mat4 =
        ra::perspective_matrix(fov_y_rad, aspect, near, far);
    /// Exercise 0.2, [`ra::vertex_normals`]: indices as `f32`s (exact below 2²⁴), checked first.
    fn vertex_normals(positions: Vec<Vec3>, indices: Vec<f32>) -> Vec<Vec3> = {
        let indices: Vec<u32> = indices.iter().map(|&i| i as u32).collect();
        match crate::raster::storage::check_indices(&indices, positions.len()) {
            Ok(()) => ra::vertex_normals(&positions, &indices),
            Err(e) => return Err(Failure::Call(e.to_string())),
        }
    };
    /// Exercise 2b.1, [`ex::squash_stretch_scale`].
    fn squash_stretch_scale(s: f32) -> Vec3 = ex::squash_stretch_scale(s);
    /// Exercise 2b.2, [`ex::spring_step`]: returns `(x', v')`.
    fn spring_step(x: Vec3, v: Vec3, target: Vec3, k: f32, c: f32, dt: f32) -> (Vec3, Vec3) =
        ex::spring_step(x, v, target, k, c, dt);
    /// Exercise 0.3, [`ra::blinn_phong`].
    fn blinn_phong(n: Vec3, l: Vec3, v: Vec3, color: Vec3, weights: [f32; 3], shininess: f32) -> Vec3 =
        ra::blinn_phong(n, l, v, color, weights, shininess);
    /// Exercise 6.1, [`sk::local_to_model`]: parents as `f32`s (exact), one model matrix per joint.
    fn local_to_model(parents: Vec<f32>, translations: Vec<Vec3>, rotations: Vec<Quat>, scales: Vec<Vec3>) -> Vec<Mat4> = {
        let parents: Vec<i32> = parents.iter().map(|&p| p as i32).collect();
        let mut model = vec![Mat4::IDENTITY; parents.len()];
        sk::local_to_model(&parents, &translations, &rotations, &scales, &mut model).map(|()| model)
    };
    /// Exercise 6.2, [`sk::sample_rotation_slerp`].
    fn sample_rotation_slerp(times: Vec<f32>, keys: Vec<Quat>, time_sec: f32) -> Quat =
        sk::sample_rotation_slerp(&times, &keys, time_sec);
    /// Exercise 6.3, [`sk::crossfade_joint`].
    fn crossfade_joint(translation_a: Vec3, rotation_a: Quat, translation_b: Vec3, rotation_b: Quat, w: f32) -> (Vec3, Quat) =
        sk::crossfade_joint(translation_a, rotation_a, translation_b, rotation_b, w);
    /// Exercise 8.1, [`bl::weight_for_speed`].
    fn weight_for_speed(d_a: f32, travel_a: f32, d_b: f32, travel_b: f32, v: f32) -> f32 =
        bl::weight_for_speed(d_a, travel_a, d_b, travel_b, v);
    /// Exercise 7.1, [`ik7::two_joint`]: `(new_middle, new_end)`.
    fn two_joint(root: Vec3, middle: Vec3, end: Vec3, target: Vec3, pole: Vec3) -> (Vec3, Vec3) =
        ik7::two_joint(root, middle, end, target, pole);
    /// Exercise 7.2, [`ik7::ccd_iteration`]: the chain after one sweep.
    fn ccd_iteration(chain: Vec<Vec3>, target: Vec3) -> Vec<Vec3> = {
        let mut chain = chain;
        ik7::ccd_iteration(&mut chain, target).map(|()| chain)
    };
    /// Exercise 5.1, [`nz::fade`]: `[fade, fade′]`.
    fn fade(t: f32) -> [f32; 2] = nz::fade(t);
    /// Exercise 5.2, [`nz::perlin_cell`].
    fn perlin_cell(p: glam::Vec2, g00: glam::Vec2, g10: glam::Vec2, g01: glam::Vec2, g11: glam::Vec2) -> f32 =
        nz::perlin_cell(p, g00, g10, g01, g11);
    /// Exercise 5.3, [`nz::fractal_sum`].
    fn fractal_sum(p: glam::Vec2, n: usize, alpha: f32, omega: f32) -> f32 =
        nz::fractal_sum(p, n, alpha, omega);
    /// Exercise 5.4, [`nz::terrain_normal`].
    fn terrain_normal(h: f32, s: f32, grad_g: glam::Vec2) -> Vec3 = nz::terrain_normal(h, s, grad_g);
    /// Exercise 9.1, [`sn::lbs_vertex`].
    fn lbs_vertex(matrices: Vec<Mat4>, weights: Vec<f32>, position: Vec3) -> Vec3 =
        sn::lbs_vertex(&matrices, &weights, position);
    /// Exercise 9.2, [`sn::blend_dual_quats`].
    fn blend_dual_quats(dual_quats: Vec<DualQuat>, weights: Vec<f32>) -> DualQuat =
        sn::blend_dual_quats(&dual_quats, &weights);
    /// Exercise 10.1, [`bs::differential_vertex`].
    fn differential_vertex(base: Vec3, targets: Vec<Vec3>, weights: Vec<f32>) -> Vec3 =
        bs::differential_vertex(base, &targets, &weights);
    /// Exercise 11.1, [`pa::time_of_impact`].
    fn time_of_impact(y0: f32, vy: f32, gy: f32, floor_y: f32) -> f32 = pa::time_of_impact(y0, vy, gy, floor_y);
    /// Exercise 11.2, [`pa::semi_implicit_euler_step`]: returns `(p', v')`.
    fn semi_implicit_euler_step(p: Vec3, v: Vec3, a: Vec3, dt: f32) -> (Vec3, Vec3) =
        pa::semi_implicit_euler_step(p, v, a, dt);
    /// Exercise 12.1, [`bo::three_rules`]: `[cohesion, alignment, separation]` as a list.
    fn three_rules(p: Vec3, v: Vec3, positions: Vec<Vec3>, velocities: Vec<Vec3>) -> Vec<Vec3> =
        bo::three_rules(p, v, &positions, &velocities).map(|r| r.to_vec());
    /// Exercise 12.2, [`bo::cell_index`]: `dims` as `f32`s (exact).
    fn cell_index(p: Vec3, origin: Vec3, cell_size: f32, dims: [f32; 3]) -> usize =
        bo::cell_index(p, origin, cell_size, dims.map(|d| d as u32));
    /// Exercise 13.1, [`cl::spring_force`]: the force on `a`.
    fn spring_force(pa: Vec3, pb: Vec3, va: Vec3, vb: Vec3, k: f32, c: f32, rest: f32) -> Vec3 =
        cl::spring_force(pa, pb, va, vb, k, c, rest);
    /// Exercise 13.2, [`cl::cloth_euler_step`]: returns `(p', v')`.
    fn cloth_euler_step(p: Vec3, v: Vec3, f: Vec3, w: f32, dt: f32) -> (Vec3, Vec3) =
        cl::cloth_euler_step(p, v, f, w, dt);
    /// Exercise 13.3, [`cl::project_distance`]: returns `(pa', pb')`.
    fn project_distance(pa: Vec3, pb: Vec3, wa: f32, wb: f32, rest: f32, alpha: f32, dt: f32) -> (Vec3, Vec3) =
        cl::project_distance(pa, pb, wa, wb, rest, alpha, dt);
    /// Exercise 14.1, [`rb::box_inertia`]: the three principal moments.
    fn box_inertia(mass: f32, half: Vec3) -> Vec3 = rb::box_inertia(mass, half);
    /// Exercise 14.2, [`rb::orientation_step`].
    fn orientation_step(q: Quat, omega: Vec3, dt: f32) -> Quat = rb::orientation_step(q, omega, dt);
    /// Exercise 14.3, [`rb::world_inverse_inertia`].
    fn world_inverse_inertia(orientation: Quat, inertia: Vec3) -> Mat3 =
        rb::world_inverse_inertia(orientation, inertia);
    /// Exercise 14.4, [`rb::normal_impulse`]: the impulse's magnitude.
    fn normal_impulse(v_rel: Vec3, normal: Vec3, r: Vec3, inv_mass: f32, inv_inertia: Mat3, e: f32) -> f32 =
        rb::normal_impulse(v_rel, normal, r, inv_mass, inv_inertia, e);
    /// Exercise 15.1, [`fl::poly6`] (2D).
    fn poly6(r2: f32, h: f32) -> f32 = fl::poly6(r2, h);
    /// Exercise 15.2, [`fl::sph_density`] (2D).
    fn sph_density(x: glam::Vec2, neighbours: Vec<glam::Vec2>, m: f32, h: f32) -> f32 =
        fl::sph_density(x, &neighbours, m, h);
    /// Exercise 15.3, [`fl::pressure_force`] (2D): the force on particle 0.
    fn pressure_force(x: [glam::Vec2; 2], rho: [f32; 2], p: [f32; 2], m: f32, h: f32) -> glam::Vec2 =
        fl::pressure_force(x, rho, p, m, h);
    /// Exercise 15.4, [`fl::pbf_lambda`] (2D).
    fn pbf_lambda(x: glam::Vec2, neighbours: Vec<glam::Vec2>, rho: f32, m: f32, rho0: f32, eps: f32, h: f32) -> f32 =
        fl::pbf_lambda(x, &neighbours, rho, m, rho0, eps, h);
}

/// The numbers the lessons' quizzes ask for (`lessons/*/quiz.json`, `"answer": {"core": name,
/// "args": [...]}`), computed by the reference cores, never by the student's code and never in
/// JavaScript. Each entry takes its arguments as plain numbers and returns one number.
pub const QUIZ_ANSWERS: &[&str] = &[
    "hermite_basis",
    "slerp_angle_about_z_deg",
    "floor_time_of_impact",
    "spring_force_magnitude",
    "fade",
    "wgpu_depth",
    "soup_over_indexed",
    "depth_fighting_distance",
    "squash_stretch_across",
    "jump_take_off_stretch",
    "screw_slide",
    "polar_step_scale",
    "nlerp_angle_deg",
    "two_joint_root_angle_deg",
    "two_joint_error",
    "weight_for_speed",
    "lbs_elbow_area_percent",
    "blend_full_vertex",
    "box_moment",
    "unnormalised_quat_length",
    "poly6_share",
];

/// The answer to a quiz's numeric question: the core named `name` on `args` (see
/// [`QUIZ_ANSWERS`]); an unknown name or a wrong number of arguments is an error that says so.
pub fn quiz_answer(name: &str, args: &[f32]) -> Result<f32, String> {
    let want = |n: usize| {
        if args.len() == n {
            Ok(())
        } else {
            Err(format!("{name} takes {n} numbers, got {}", args.len()))
        }
    };
    if args.iter().any(|a| !a.is_finite()) {
        return Err(format!("{name}: the arguments must be finite numbers"));
    }
    let answer = match name {
        // (s, i): the Hermite basis function h_i (h00, h10, h01, h11) at s.
        "hermite_basis" => {
            want(2)?;
            let i = usize::take(&mut &args[1..]).filter(|&i| i < 4);
            let i = i.ok_or("hermite_basis: i must be 0, 1, 2 or 3")?;
            crate::curves::hermite_basis(args[0])[i]
        }
        // (a_deg, b_deg, t): keys turned a and b degrees about z, slerped at t; the signed angle
        // about z of the result, in degrees, in (−180, 180].
        "slerp_angle_about_z_deg" => {
            want(3)?;
            let key = |deg: f32| Quat::from_rotation_z(deg.to_radians());
            let q = crate::rotation::slerp(key(args[0]), key(args[1]), args[2]);
            let (axis, angle) = q.to_axis_angle();
            let signed = if axis.z < 0.0 { -angle } else { angle };
            let deg = signed.to_degrees();
            if deg > 180.0 {
                deg - 360.0
            } else if deg <= -180.0 {
                deg + 360.0
            } else {
                deg
            }
        }
        // (y0, vy, gy, floor_y): when a particle in free fall reaches the floor, in seconds.
        "floor_time_of_impact" => {
            want(4)?;
            crate::particles::collide::floor_time_of_impact(args[0], args[1], args[2], args[3], 1e6)
                .ok_or("floor_time_of_impact: the particle never reaches the floor")?
        }
        // (length, k, rest): the force of a spring of stiffness k stretched (or squeezed) to
        // `length`, at rest, in newtons.
        "spring_force_magnitude" => {
            want(3)?;
            let b = Vec3::new(args[0], 0.0, 0.0);
            crate::cloth::spring_force(Vec3::ZERO, b, Vec3::ZERO, Vec3::ZERO, args[1], 0.0, args[2])
                .length()
        }
        // (t): Perlin's fade curve 6t⁵ − 15t⁴ + 10t³.
        "fade" => {
            want(1)?;
            crate::noise::perlin::fade(args[0])
        }
        // (d, near, far): the wgpu depth, in [0, 1], of a point d metres in front of a camera
        // with these planes.
        "wgpu_depth" => {
            want(3)?;
            let (d, near, far) = (args[0], args[1], args[2]);
            if !(near > 0.0 && far > near && d > 0.0) {
                return Err("wgpu_depth: need 0 < near < far and d > 0".into());
            }
            crate::raster::ndc_depth_wgpu(d, near, far)
        }
        // (V, T): how many times larger the triangle soup is than the indexed form, for V
        // distinct positions and T triangles.
        "soup_over_indexed" => {
            want(2)?;
            let count = |x: f32, what: &str| {
                if x >= 1.0 && x <= 1e7 && x.fract() == 0.0 {
                    Ok(x as usize)
                } else {
                    Err(format!(
                        "soup_over_indexed: {what} must be a whole number from 1"
                    ))
                }
            };
            let sizes = crate::raster::mesh_sizes(count(args[0], "V")?, count(args[1], "T")?);
            sizes.soup_bytes as f32 / sizes.indexed_bytes as f32
        }
        // (near, far, gap, bits): lesson 00's two floors `gap` metres apart under a camera 3 m
        // up: the distance in metres beyond which one depth step outgrows their separation.
        "depth_fighting_distance" => {
            want(4)?;
            let mut scene = crate::figures::raster::DepthPrecision::new();
            scene.set(args[0], args[1], args[2], args[3])?;
            scene.fighting_from()
        }
        // (s): the scale across the motion of a volume-preserving stretch by s along it.
        "squash_stretch_across" => {
            want(1)?;
            if args[0] <= 0.0 {
                return Err("squash_stretch_across: s must be positive".into());
            }
            crate::expressive::squash_stretch_scale(args[0]).y
        }
        // (k): lesson 02b's jump (apex 1.6 m, 1 s of flight) with k stretch per m/s; the
        // stretch it takes off with, capped as in the figures.
        "jump_take_off_stretch" => {
            want(1)?;
            if args[0] < 0.0 {
                return Err("jump_take_off_stretch: k must not be negative".into());
            }
            let jump = crate::expressive::Jump {
                stretch_per_speed: args[0],
                ..Default::default()
            };
            jump.take_off_stretch()
        }
        // (angle_deg, ax, ay, az, tx, ty, tz): the rigid motion that turns angle_deg about the
        // axis (ax, ay, az), then translates by t; how far it slides along its screw axis (m).
        "screw_slide" => {
            want(7)?;
            let axis = Vec3::new(args[1], args[2], args[3])
                .try_normalize()
                .ok_or("screw_slide: the axis must not be zero")?;
            let rotation = Quat::from_axis_angle(axis, args[0].to_radians());
            let t = Vec3::new(args[4], args[5], args[6]);
            DualQuat::from_rotation_translation(rotation, t)
                .screw_axis()
                .displacement
                .abs()
        }
        // (sx): one step of the polar iteration on diag(sx, 1, 1); the x scale it leaves.
        "polar_step_scale" => {
            want(1)?;
            if args[0].abs() < 1e-6 {
                return Err("polar_step_scale: sx must not be 0 (no polar decomposition)".into());
            }
            crate::rotation::polar_step(Mat3::from_diagonal(Vec3::new(args[0], 1.0, 1.0)))
                .x_axis
                .x
        }
        // (angle_deg, s): keys 0 and angle_deg about y, nlerped at s; the in-between's angle, in
        // degrees.
        "nlerp_angle_deg" => {
            want(2)?;
            let (angle, s) = (args[0], args[1]);
            if !(0.0..=180.0).contains(&angle) || !(0.0..=1.0).contains(&s) {
                return Err(
                    "nlerp_angle_deg: the angle must be in [0, 180] and s in [0, 1]".into(),
                );
            }
            let b = Quat::from_rotation_y(angle.to_radians());
            crate::rotation::nlerp(Quat::IDENTITY, b, s)
                .angle_between(Quat::IDENTITY)
                .to_degrees()
        }
        // (a, b, d): two-joint IK with segments a and b and the target d metres from the root;
        // the angle at the root between the line to the target and the first segment, degrees.
        "two_joint_root_angle_deg" => {
            want(3)?;
            let (u, solution) = two_joint_quiz(name, args)?;
            solution
                .middle
                .normalize()
                .dot(u)
                .clamp(-1.0, 1.0)
                .acos()
                .to_degrees()
        }
        // (a, b, d): the same; how far the end is left from the target, metres.
        "two_joint_error" => {
            want(3)?;
            two_joint_quiz(name, args)?.1.result.error
        }
        // (travel_a, duration_a, travel_b, duration_b, speed): the weight of clip B that makes
        // the synchronised blend of two travelling cycles move at `speed` m/s.
        "weight_for_speed" => {
            want(5)?;
            if !(args[1] > 0.0 && args[3] > 0.0 && args[0] >= 0.0 && args[2] >= 0.0) {
                return Err("weight_for_speed: travels must be ≥ 0 and durations > 0".into());
            }
            let clip = |travel: f32, duration_sec: f32| crate::skeleton::RootMotion {
                start: Vec3::ZERO,
                cycle_travel: Vec3::new(0.0, 0.0, travel),
                duration_sec,
            };
            crate::skeleton::weight_for_speed(
                &clip(args[0], args[1]),
                &clip(args[2], args[3]),
                args[4],
            )
        }
        // (bend_deg, twist_deg): lesson 09's tube bent and twisted at the elbow; the percentage
        // of its rest area that the elbow ring keeps under linear blend skinning.
        "lbs_elbow_area_percent" => {
            want(2)?;
            let mut tube = crate::figures::skinning::CylinderFigure::new();
            tube.set_bend_deg(args[0])?;
            tube.set_twist_deg(args[1])?;
            tube.update()?;
            100.0 * tube.elbow_areas().0
        }
        // (base, target_1, target_2, w0, w1, w2): one coordinate of one vertex, blended by the
        // full form w0 b0 + w1 b1 + w2 b2 (whatever the weights' sum).
        "blend_full_vertex" => {
            want(6)?;
            let point = |x: f32| vec![Vec3::new(0.0, x, 0.0)];
            let shapes = crate::blend_shapes::BlendShapes::from_targets(
                point(args[0]),
                vec![Vec3::Y],
                &[
                    (point(args[1]), vec![Vec3::Y]),
                    (point(args[2]), vec![Vec3::Y]),
                ],
            )
            .map_err(|e| e.to_string())?;
            let (mut p, mut n) = ([Vec3::ZERO], [Vec3::ZERO]);
            shapes
                .apply_full(&args[3..6], &mut p, &mut n)
                .map_err(|e| e.to_string())?;
            p[0].y
        }
        // (m, hx, hy, hz, axis): the moment of inertia (kg m²) of a solid box of mass m and
        // these half-extents about its own axis 0 (x), 1 (y) or 2 (z).
        // (r, h): the 2D poly6 kernel at distance r as a share of its peak W(0).
        "poly6_share" => {
            want(2)?;
            if !(args[1] > 0.0 && args[0] >= 0.0) {
                return Err("poly6_share: r must be at least 0 and h positive".into());
            }
            let (r, h) = (args[0], args[1]);
            let w = |r2| crate::fluid::kernels::poly6(r2, h, crate::fluid::Dim::Two);
            w(r * r) / w(0.0)
        }
        "box_moment" => {
            want(5)?;
            if !(args[0] > 0.0 && args[1..4].iter().all(|&h| h > 0.0)) {
                return Err("box_moment: the mass and the half-extents must be positive".into());
            }
            let axis = usize::take(&mut &args[4..]).filter(|&i| i < 3);
            let axis = axis.ok_or("box_moment: the axis must be 0, 1 or 2")?;
            let half = Vec3::new(args[1], args[2], args[3]);
            crate::rigid_body::inertia::solid_box(args[0], half).col(axis)[axis]
        }
        // (spin, dt, steps): |q| after `steps` unnormalised additive steps of `dt` seconds at
        // `spin` rad/s, from a unit quaternion, stepped by the core.
        "unnormalised_quat_length" => {
            want(3)?;
            let steps = usize::take(&mut &args[2..]).filter(|&n| n <= 100_000);
            let steps = steps
                .ok_or("unnormalised_quat_length: steps must be a whole number up to 100000")?;
            if !(args[1] >= 0.0 && args[1] <= 0.1) {
                return Err("unnormalised_quat_length: dt must be in [0, 0.1] s".into());
            }
            let omega = Vec3::new(0.0, args[0], 0.0);
            let how = crate::rigid_body::OrientationStep::AdditiveUnnormalised;
            (0..steps)
                .fold(Quat::IDENTITY, |q, _| {
                    crate::rigid_body::orientation_step(q, omega, args[1], how)
                })
                .length()
        }
        _ => {
            return Err(format!(
                "no quiz answer named {name:?}; the names are {}",
                QUIZ_ANSWERS.join(", ")
            ))
        }
    };
    if answer.is_finite() {
        Ok(answer)
    } else {
        Err(format!("{name}: no finite answer for these arguments"))
    }
}

/// Two-joint IK for the quiz: a straight chain of segments `a` and `b` up the y axis, the
/// target `d` metres along x, the pole on the chain's side; returns the direction to the target
/// and the solution.
fn two_joint_quiz(name: &str, args: &[f32]) -> Result<(Vec3, crate::ik::TwoJointSolution), String> {
    let (a, b, d) = (args[0], args[1], args[2]);
    if !(a > 0.0 && b > 0.0 && d > 0.0) {
        return Err(format!(
            "{name}: the segments and the distance must be positive"
        ));
    }
    let u = Vec3::X;
    let solution = crate::ik::two_joint(
        Vec3::ZERO,
        Vec3::new(0.0, a, 0.0),
        Vec3::new(0.0, a + b, 0.0),
        u * d,
        Vec3::Y,
        1e-4,
    )
    .map_err(|e| e.to_string())?;
    Ok((u, solution))
}

/// The student mistakes of the isolation test (feature `student-bugs`, or
/// [`super::with_student_bugs`] in a build with debug assertions; a release build without the
/// feature has none of this code): a panic in slerp, a transposed Rodrigues matrix, vertex
/// normals with the middle one reversed (see [`reverse_middle_normal`]) and, in the browser, a
/// `polar_step` that never returns, as in the grader (`grade::planted_mistakes`): the page must
/// never call it on its own thread.
#[cfg(any(feature = "student-bugs", debug_assertions))]
pub(super) fn student_bugs(name: &str, args: &[f32]) -> Option<Result<Vec<f32>, Failure>> {
    match name {
        "vertex_normals" => {
            let mut rest = args;
            let positions = Vec::<Vec3>::take(&mut rest)?;
            let indices: Vec<u32> = Vec::<f32>::take(&mut rest)?
                .iter()
                .map(|&i| i as u32)
                .collect();
            let mut normals = vec![Vec3::ZERO; positions.len()];
            // Invalid indices: the exercise's own path reports them.
            crate::raster::vertex_normals(&positions, &indices, &mut normals).ok()?;
            reverse_middle_normal(&mut normals);
            let mut out = Vec::new();
            normals.put(&mut out);
            Some(Ok(out))
        }
        "slerp" => {
            let keys = [0usize; 3];
            let index = args.len(); // 9 numbers: past the end, as an off-by-one would be
            Some(Ok(vec![keys[index] as f32]))
        }
        #[cfg(target_arch = "wasm32")]
        "polar_step" => loop {
            std::hint::black_box(args);
        },
        "rodrigues_matrix" => {
            let mut rest = args;
            let axis = Vec3::take(&mut rest)?;
            let angle = f32::take(&mut rest)?;
            let mut out = Vec::new();
            crate::rotation::rodrigues_mat3(axis, angle)
                .transpose()
                .put(&mut out);
            Some(Ok(out))
        }
        _ => None,
    }
}

/// The `student-bugs` build's vertex normals: the one in the middle of the list (index
/// `len / 2`) points the wrong way, as if its triangles were wound backwards. A wrong element in
/// the middle of a long list, for the grader's report of where a list is wrong.
#[cfg(any(feature = "student-bugs", debug_assertions))]
pub(super) fn reverse_middle_normal(normals: &mut [Vec3]) {
    if let Some(n) = normals.get_mut(normals.len() / 2) {
        *n = -*n;
    }
}

/// How a figure's note compares the student's answer with the reference at the current inputs.
/// `max_error` is the largest absolute difference; returns "matches the reference" or
/// "differs at `at`: yours (…), reference (…)".
pub fn compare_note(
    what: &str,
    at: &str,
    yours: &[f32],
    reference: &[f32],
    tolerance: f32,
) -> (bool, String) {
    let max_error = yours
        .iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs())
        .fold(
            0.0f32,
            |m, e| if e.is_nan() { f32::INFINITY } else { m.max(e) },
        );
    let fmt = |v: &[f32]| {
        v.iter()
            .map(|x| format_number(*x))
            .collect::<Vec<_>>()
            .join(", ")
    };
    if yours.len() == reference.len() && max_error <= tolerance {
        (true, format!("Your {what} matches the reference at {at}."))
    } else {
        (
            false,
            format!(
                "Your {what} differs at {at}: yours ({}), reference ({}).",
                fmt(yours),
                fmt(reference)
            ),
        )
    }
}

/// A number for a note: 3 decimals, no "-0.000", scientific only when huge or tiny but not zero.
pub fn format_number(x: f32) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    let a = x.abs();
    if a != 0.0 && !(1e-3..1e5).contains(&a) {
        return format!("{x:.3e}");
    }
    let s = format!("{x:.3}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        "0.000".to_string()
    } else {
        s
    }
}
