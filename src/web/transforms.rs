//! Bindings for lesson 01, "Transforms and hierarchies".

use super::{finite, Viewer};
use crate::exercises::{self, NotDone};
use crate::transform::{self, Hierarchy, JointShape, LocalTransform, ScaleMode};
use glam::{Mat4, Vec3};
use wasm_bindgen::prelude::*;

const DEG: f32 = std::f32::consts::PI / 180.0;

/// Figure 1: one box, its matrix, and the order of translation and rotation.
#[wasm_bindgen]
pub struct SingleShapeScene {
    translation: Vec3,
    euler_rad: Vec3,
    translate_first: bool,
}

#[wasm_bindgen]
impl SingleShapeScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SingleShapeScene {
        SingleShapeScene {
            translation: Vec3::new(1.0, 0.5, 0.0),
            euler_rad: Vec3::new(0.0, 0.0, 30.0 * DEG),
            translate_first: false,
        }
    }

    /// Sets the translation (metres) and Euler angles (degrees, X then Y then Z as in the lesson).
    #[wasm_bindgen(js_name = setTransform)]
    pub fn set_transform(
        &mut self,
        tx: f32,
        ty: f32,
        tz: f32,
        rx_deg: f32,
        ry_deg: f32,
        rz_deg: f32,
    ) -> Result<(), JsError> {
        self.translation = Vec3::new(finite("tx", tx)?, finite("ty", ty)?, finite("tz", tz)?);
        self.euler_rad = Vec3::new(
            finite("rx", rx_deg)?,
            finite("ry", ry_deg)?,
            finite("rz", rz_deg)?,
        ) * DEG;
        Ok(())
    }

    /// `false`: M = T · R (rotate about the shape's own centre, then move it). `true`: M = R · T
    /// (move first, then rotate the moved shape about the world origin).
    #[wasm_bindgen(js_name = setTranslateFirst)]
    pub fn set_translate_first(&mut self, translate_first: bool) {
        self.translate_first = translate_first;
    }

    /// The 4×4 matrix, column-major (16 numbers).
    pub fn matrix(&self) -> Vec<f32> {
        self.model().to_cols_array().to_vec()
    }

    fn model(&self) -> Mat4 {
        let rotation = transform::local_matrix(Vec3::ZERO, self.euler_rad);
        let translation = Mat4::from_translation(self.translation);
        if self.translate_first {
            rotation * translation
        } else {
            translation * rotation
        }
    }

    pub fn draw(&self, viewer: &mut Viewer) -> Result<(), JsError> {
        let m = self.model();
        let frame = &mut viewer.renderer.frame;
        frame.grid(10, 0.5);
        frame.axes(Mat4::IDENTITY, 1.0);
        frame.mesh(
            viewer.renderer.cube,
            m * Mat4::from_scale(Vec3::new(0.4, 0.25, 0.15)),
            Vec3::new(0.95, 0.6, 0.2),
        );
        frame.axes(m, 0.7);
        // A point (w = 1) moves with the translation; a direction (w = 0) only turns.
        let corner = m * transform::point(Vec3::new(0.4, 0.25, 0.15));
        frame.point(corner.truncate(), 0.05, Vec3::new(0.8, 0.1, 0.6));
        let dir = m * transform::direction(Vec3::new(0.6, 0.0, 0.0));
        frame.line(Vec3::ZERO, dir.truncate(), Vec3::new(0.8, 0.1, 0.6));
        frame.point(dir.truncate(), 0.025, Vec3::new(0.8, 0.1, 0.6));
        viewer.present()
    }
}

impl Default for SingleShapeScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 2: a human made of boxes, posed by joint angles, with the world = parent · local rule.
#[wasm_bindgen]
pub struct HierarchyScene {
    hierarchy: Hierarchy,
    transforms: Vec<LocalTransform>,
    shapes: Vec<JointShape>,
    mode: ScaleMode,
    animate: bool,
    use_exercise: bool,
    selected: usize,
    local: Vec<Mat4>,
    world: Vec<Mat4>,
    draw: Vec<Mat4>,
    angles: Vec<Vec3>,
}

#[wasm_bindgen]
impl HierarchyScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> HierarchyScene {
        let (hierarchy, transforms, shapes) = transform::simple_human();
        let n = hierarchy.len();
        HierarchyScene {
            hierarchy,
            transforms,
            shapes,
            mode: ScaleMode::NotInherited,
            animate: true,
            use_exercise: false,
            selected: 3,
            local: vec![Mat4::IDENTITY; n],
            world: vec![Mat4::IDENTITY; n],
            draw: vec![Mat4::IDENTITY; n],
            angles: vec![Vec3::ZERO; n],
        }
    }

    #[wasm_bindgen(js_name = jointNames)]
    pub fn joint_names(&self) -> Vec<String> {
        self.hierarchy.names().to_vec()
    }

    fn joint(&self, joint: usize) -> Result<usize, JsError> {
        if joint < self.hierarchy.len() {
            Ok(joint)
        } else {
            Err(JsError::new(&format!(
                "joint index {joint} is out of range: the figure has {} joints",
                self.hierarchy.len()
            )))
        }
    }

    /// Selects the joint whose axes are drawn and whose values the panel edits.
    pub fn select(&mut self, joint: usize) -> Result<(), JsError> {
        self.selected = self.joint(joint)?;
        Ok(())
    }

    /// Euler angles of a joint in degrees (x, y, z) as last set or animated.
    #[wasm_bindgen(js_name = jointAnglesDeg)]
    pub fn joint_angles_deg(&self, joint: usize) -> Result<Vec<f32>, JsError> {
        let a = self.transforms[self.joint(joint)?].euler_xyz_rad / DEG;
        Ok(a.to_array().to_vec())
    }

    /// Sets a joint's Euler angles, in degrees.
    #[wasm_bindgen(js_name = setJointAnglesDeg)]
    pub fn set_joint_angles_deg(
        &mut self,
        joint: usize,
        x_deg: f32,
        y_deg: f32,
        z_deg: f32,
    ) -> Result<(), JsError> {
        let j = self.joint(joint)?;
        self.transforms[j].euler_xyz_rad = Vec3::new(
            finite("x", x_deg)?,
            finite("y", y_deg)?,
            finite("z", z_deg)?,
        ) * DEG;
        Ok(())
    }

    /// Sets a joint's scale along its own axes (each in [0.1, 4]).
    #[wasm_bindgen(js_name = setJointScale)]
    pub fn set_joint_scale(
        &mut self,
        joint: usize,
        sx: f32,
        sy: f32,
        sz: f32,
    ) -> Result<(), JsError> {
        let j = self.joint(joint)?;
        let s = Vec3::new(
            super::in_range("sx", sx, 0.1, 4.0)?,
            super::in_range("sy", sy, 0.1, 4.0)?,
            super::in_range("sz", sz, 0.1, 4.0)?,
        );
        self.transforms[j].scale = s;
        Ok(())
    }

    /// Whether a joint's scale is passed on to its children (see the lesson).
    #[wasm_bindgen(js_name = setInheritScale)]
    pub fn set_inherit_scale(&mut self, inherit: bool) {
        self.mode = if inherit {
            ScaleMode::Inherited
        } else {
            ScaleMode::NotInherited
        };
    }

    /// When on, the timeline drives a walk cycle and the angle sliders follow it.
    #[wasm_bindgen(js_name = setAnimate)]
    pub fn set_animate(&mut self, animate: bool) {
        self.animate = animate;
    }

    /// Swaps the reference core for the student's functions in `src/exercises/transforms.rs`.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// Poses the figure at `time_sec` and draws it. Returns a note for the page: empty, or which
    /// exercises are not done yet (the figure then uses the reference for those steps).
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let note = self.pose(finite("time", time_sec)?)?;
        let frame = &mut viewer.renderer.frame;
        frame.grid(12, 0.25);
        for (i, (shape, draw)) in self.shapes.iter().zip(&self.draw).enumerate() {
            let model =
                *draw * Mat4::from_translation(shape.center) * Mat4::from_scale(shape.half_extents);
            let color = if i == self.selected {
                shape.color * 0.6 + Vec3::new(0.4, 0.35, 0.0)
            } else {
                shape.color
            };
            frame.mesh(viewer.renderer.cube, model, color);
        }
        // The skeleton: a dot at each pivot, a segment to its parent's pivot.
        for (i, &parent) in self.hierarchy.parents().iter().enumerate() {
            let pivot = self.world[i].w_axis.truncate();
            frame.point(pivot, 0.025, Vec3::new(0.1, 0.1, 0.1));
            if parent >= 0 {
                frame.line(
                    self.world[parent as usize].w_axis.truncate(),
                    pivot,
                    Vec3::new(0.1, 0.1, 0.1),
                );
            }
        }
        frame.axes(self.world[self.selected], 0.25);
        viewer.present()?;
        Ok(note)
    }

    /// World matrix of a joint at the last drawn pose, column-major.
    #[wasm_bindgen(js_name = worldMatrix)]
    pub fn world_matrix(&self, joint: usize) -> Result<Vec<f32>, JsError> {
        Ok(self.world[self.joint(joint)?].to_cols_array().to_vec())
    }

    /// Local matrix of a joint at the last drawn pose, column-major.
    #[wasm_bindgen(js_name = localMatrix)]
    pub fn local_matrix(&self, joint: usize) -> Result<Vec<f32>, JsError> {
        Ok(self.local[self.joint(joint)?].to_cols_array().to_vec())
    }

    /// Samples one walk cycle for the plot: `[t₀, a₀, h₀, t₁, a₁, h₁, …]` with the left thigh's
    /// angle `a` (degrees) and the height `h` (metres) of the left hand's pivot-to-wrist end.
    #[wasm_bindgen(js_name = sampleCycle)]
    pub fn sample_cycle(&self, samples: usize, period_sec: f32) -> Result<Vec<f32>, JsError> {
        super::check_samples(samples)?;
        let period = super::in_range("period", period_sec, 0.01, 1000.0)?;
        let mut scene = HierarchyScene::new();
        scene.animate = true;
        scene.mode = self.mode;
        let thigh = self.hierarchy.find("thigh.L").unwrap_or(0);
        let hand = self.hierarchy.find("forearm.L").unwrap_or(0);
        let mut out = Vec::with_capacity(samples * 3);
        for k in 0..samples {
            let t = period * k as f32 / (samples - 1) as f32;
            scene.pose_at(t, period)?;
            let wrist = scene.world[hand].transform_point3(Vec3::new(0.0, -0.28, 0.0));
            out.extend_from_slice(&[t, scene.transforms[thigh].euler_xyz_rad.x / DEG, wrist.y]);
        }
        Ok(out)
    }
}

impl Default for HierarchyScene {
    fn default() -> Self {
        Self::new()
    }
}

impl HierarchyScene {
    const WALK_PERIOD_SEC: f32 = 1.2;

    fn pose(&mut self, time_sec: f32) -> Result<String, JsError> {
        self.pose_at(time_sec, Self::WALK_PERIOD_SEC)
    }

    fn pose_at(&mut self, time_sec: f32, period_sec: f32) -> Result<String, JsError> {
        if self.animate {
            for (a, x) in self.angles.iter_mut().zip(&self.transforms) {
                *a = x.euler_xyz_rad;
            }
            transform::walk_cycle(&self.hierarchy, time_sec, period_sec, &mut self.angles);
            for (x, a) in self.transforms.iter_mut().zip(&self.angles) {
                x.euler_xyz_rad = *a;
            }
        }
        let to_js = |e: transform::HierarchyError| JsError::new(&e.to_string());
        self.hierarchy
            .pose(
                &self.transforms,
                self.mode,
                &mut self.local,
                &mut self.world,
                &mut self.draw,
            )
            .map_err(to_js)?;
        if !self.use_exercise {
            return Ok(String::new());
        }
        // The student's version of the same steps, each falling back to the reference while undone.
        let mut missing = Vec::new();
        for (i, x) in self.transforms.iter().enumerate() {
            match exercises::transforms::local_matrix(x.translation, x.euler_xyz_rad) {
                Ok(m) => {
                    self.local[i] = if self.mode == ScaleMode::Inherited {
                        m * Mat4::from_scale(x.scale)
                    } else {
                        m
                    };
                }
                Err(NotDone) => {
                    missing.push("exercise 1.1 local_matrix");
                    break;
                }
            }
        }
        if exercises::transforms::world_matrices(
            self.hierarchy.parents(),
            &self.local,
            &mut self.world,
        )
        .is_err()
        {
            missing.push("exercise 1.2 world_matrices");
            transform::world_matrices(self.hierarchy.parents(), &self.local, &mut self.world);
        }
        for ((d, w), x) in self.draw.iter_mut().zip(&self.world).zip(&self.transforms) {
            *d = match self.mode {
                ScaleMode::NotInherited => *w * Mat4::from_scale(x.scale),
                ScaleMode::Inherited => *w,
            };
        }
        Ok(if missing.is_empty() {
            "Showing your exercises.".to_string()
        } else {
            format!("Not done yet: {} (src/exercises/transforms.rs). The figure uses the reference for those steps.", missing.join(", "))
        })
    }
}
