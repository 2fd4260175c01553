//! Figure logic for lesson 01, "Transforms and hierarchies" (see [`crate::figures`]).
//!
//! - [`SingleShape`] (Figure 1): one box placed by `T·R` and, beside it as a wireframe ghost, by
//!   `R·T`, with the arc the `R·T` box swings along; a point (`w = 1`) and a direction (`w = 0`).
//! - [`HierarchyFigure`] (Figures 2 and 3): a human made of boxes, posed joint by joint with
//!   `world = parent · local`, the walk plot computed from the current pose, and the check of the
//!   student's exercises 1.1 and 1.2.

use super::skinning::{off_points, view_of};
use super::{
    check_samples, compare_note, failure_note, finite, in_range, palette, rotation_problem, Frame,
    MeshId, Runner, DEFAULT_RUNNER,
};
use crate::camera::{project_to_canvas, OrbitCamera};
use crate::draw::{Label, StrokeStyle};
use crate::exercises::run;
use crate::transform::{self, Hierarchy, JointShape, LocalTransform, ScaleMode};
use glam::{Mat3, Mat4, Quat, Vec2, Vec3};

/// Degrees to radians.
pub const DEG: f32 = std::f32::consts::PI / 180.0;

const EXERCISE_FILE: &str = "src/exercises/transforms.rs";

/// Points on the canvas (`view`) that stand for the boxes `models` place (the unit cube's
/// [−1, 1]³): a 5 × 5 × 5 grid through each, close enough that a label's box cannot lie on a
/// box between them.
fn boxes_px(models: &[Mat4], view: Option<(Mat4, Vec2)>) -> Vec<Vec2> {
    let Some((view_proj, size)) = view else {
        return Vec::new();
    };
    let grid = (0..125).map(|i| Vec3::new((i % 5) as f32, (i / 5 % 5) as f32, (i / 25) as f32));
    grid.flat_map(|g| {
        models
            .iter()
            .map(move |m| m.transform_point3(g * 0.5 - 1.0))
    })
    .filter_map(|p| project_to_canvas(view_proj, size, p))
    .collect()
}

/// Where `p` lies on the canvas (`view`) relative to `from`: the screen direction a label of
/// `p` looks away from `from` in; `otherwise` without a view.
fn away(view: Option<(Mat4, Vec2)>, p: Vec3, from: Vec3, otherwise: Vec2) -> Vec2 {
    view.and_then(|(m, size)| {
        Some(project_to_canvas(m, size, p)? - project_to_canvas(m, size, from)?)
    })
    .unwrap_or(otherwise)
}

/// Which product places the box.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Order {
    /// `M = T · R`: rotate about the box's own centre, then move it.
    RotateFirst,
    /// `M = R · T`: move the box, then rotate the moved box about the world origin.
    TranslateFirst,
}

impl Order {
    /// The other order (drawn as the ghost).
    pub fn other(self) -> Order {
        match self {
            Order::RotateFirst => Order::TranslateFirst,
            Order::TranslateFirst => Order::RotateFirst,
        }
    }

    /// The product as the text writes it.
    pub fn name(self) -> &'static str {
        match self {
            Order::RotateFirst => "T·R",
            Order::TranslateFirst => "R·T",
        }
    }

    /// The colour of this order's box, its label and (in the text) its name.
    pub fn color(self) -> Vec3 {
        match self {
            Order::RotateFirst => palette::ORANGE,
            Order::TranslateFirst => palette::TEAL,
        }
    }
}

/// Figure 1: one box, its matrix, and the order of translation and rotation.
#[derive(Clone, Debug)]
pub struct SingleShape {
    /// The translation `t`, metres.
    translation: Vec3,
    /// Euler angles, radians, in the order of [`transform::local_matrix`].
    euler_rad: Vec3,
    /// The order drawn solid; the other is the ghost.
    order: Order,
    /// The last frame's camera and canvas size (CSS pixels), which p's and v's names are
    /// placed for ([`SingleShape::set_view`]).
    view: Option<(OrbitCamera, Vec2)>,
}

/// Half-size of Figure 1's box, metres.
pub const BOX_HALF: Vec3 = Vec3::new(0.4, 0.25, 0.15);
/// The length of Figure 1's box's own axes, metres: past the box's faces.
const AXIS_M: f32 = 0.6;
/// Figure 1's point p (w = 1), in the box's frame: the front corner below the box's +x end. The
/// paths of the centres leave the box upwards and to the right (towards t = (1, 0.5, 0) and
/// round the swing), so p's label, which reads rightwards from just outside this corner, stays
/// below them at every stage.
pub const POINT: Vec3 = Vec3::new(BOX_HALF.x, -BOX_HALF.y, BOX_HALF.z);
/// Figure 1's direction v (w = 0), in the box's frame: longer than the box is wide, so it shows
/// outside the box while the box turns at the origin.
pub const DIRECTION: Vec3 = Vec3::new(-0.7, 0.35, 0.0);

impl Default for SingleShape {
    fn default() -> Self {
        Self::new()
    }
}

impl SingleShape {
    pub fn new() -> Self {
        Self {
            translation: Vec3::new(1.0, 0.5, 0.0),
            euler_rad: Vec3::new(0.0, 0.0, 30.0 * DEG),
            order: Order::RotateFirst,
            view: None,
        }
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's).
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// Sets the translation (metres) and the Euler angles (degrees, applied z, then y, then x).
    pub fn set_transform(&mut self, translation: Vec3, euler_deg: Vec3) -> Result<(), String> {
        // Every argument is checked before either field changes: a rejected call changes nothing.
        let translation = Vec3::new(
            finite("tx", translation.x)?,
            finite("ty", translation.y)?,
            finite("tz", translation.z)?,
        );
        let euler_deg = Vec3::new(
            finite("rx", euler_deg.x)?,
            finite("ry", euler_deg.y)?,
            finite("rz", euler_deg.z)?,
        );
        self.translation = translation;
        self.euler_rad = euler_deg * DEG;
        Ok(())
    }

    pub fn set_order(&mut self, order: Order) {
        self.order = order;
    }

    pub fn order(&self) -> Order {
        self.order
    }

    /// The rotation `R` alone.
    pub fn rotation(&self) -> Mat4 {
        transform::local_matrix(Vec3::ZERO, self.euler_rad)
    }

    /// The box's matrix in the given order.
    pub fn matrix(&self, order: Order) -> Mat4 {
        let (t, r) = (Mat4::from_translation(self.translation), self.rotation());
        match order {
            Order::RotateFirst => t * r,
            Order::TranslateFirst => r * t,
        }
    }

    /// The box's matrix part-way through its two steps, `stage` in [0, 2]: from 0 to 1 the
    /// right-hand factor grows from the identity to its full value (a rotation by slerp from the
    /// identity, a translation by a fraction of `t`), from 1 to 2 the left-hand one. At 2 it is
    /// [`SingleShape::matrix`]. So `T·R` turns in place, then slides; `R·T` slides, then swings
    /// about the world origin.
    pub fn matrix_at(&self, order: Order, stage: f32) -> Mat4 {
        let first = stage.clamp(0.0, 1.0);
        let second = (stage - 1.0).clamp(0.0, 1.0);
        let q = Quat::from_mat4(&self.rotation());
        let r = |s: f32| Mat4::from_quat(Quat::IDENTITY.slerp(q, s));
        let t = |s: f32| Mat4::from_translation(self.translation * s);
        match order {
            Order::RotateFirst => t(second) * r(first),
            Order::TranslateFirst => r(second) * t(first),
        }
    }

    /// Where the `R·T` box's centre goes as the rotation grows from none to `R`: `R(s)·t` for
    /// `s` in [0, 1], with `R(s)` the slerp from the identity (for one angle, a circle's arc).
    pub fn swing_arc(&self, samples: usize) -> Vec<Vec3> {
        (0..samples)
            .map(|k| {
                let s = k as f32 / (samples - 1).max(1) as f32;
                self.matrix_at(Order::TranslateFirst, 1.0 + s)
                    .w_axis
                    .truncate()
            })
            .collect()
    }

    /// Draws both orders at `stage` (see [`SingleShape::matrix_at`]; 2 shows the full products):
    /// the chosen one solid, the other as a wireframe ghost, the paths their centres take, the
    /// point and the direction. Returns the note under the figure.
    pub fn draw(&self, frame: &mut Frame, stage: f32) -> Result<String, String> {
        let stage = in_range("stage", stage, 0.0, 2.0)?;
        frame.grid(10, 0.5);
        frame.labelled_axes(Mat4::IDENTITY, 1.0);
        // The world axes' letters go back once p's dot is drawn, placed clear of it.
        let letters = std::mem::take(&mut frame.labels);
        let (shown, ghost) = (self.order, self.order.other());
        let m = self.matrix_at(shown, stage);
        frame.mesh(MeshId::CUBE, m * Mat4::from_scale(BOX_HALF), shown.color());
        // Over the box, which would hide them.
        frame.axes_on_top(m, AXIS_M);
        wire_box(
            frame,
            self.matrix_at(ghost, stage) * Mat4::from_scale(BOX_HALF),
            ghost.color(),
        );
        // The paths of the two centres: T·R stays at the origin while it turns, then slides
        // straight to t; R·T slides to t first (the same segment, drawn wide underneath so both
        // show), then swings about the world origin along the arc.
        let (tr, rt) = (Order::RotateFirst.color(), Order::TranslateFirst.color());
        let t = self.translation;
        frame.wide_line(Vec3::ZERO, t, rt, 5.0);
        frame.stroke(&[Vec3::ZERO, t], tr, StrokeStyle::dashed(2.0, 0.08, 0.06));
        let arc = self.swing_arc(48);
        let tip = self.matrix(Order::TranslateFirst).w_axis.truncate();
        frame.wide_polyline(&arc, rt, crate::draw::CURVE_PX);
        if arc.len() >= 2 && arc[0].distance(tip) > 0.05 {
            frame.arrow(arc[arc.len() - 2], tip, rt, 0.12);
            // The arm of the swing, from the world origin to where R·T ends.
            frame.stroke(&[Vec3::ZERO, tip], rt, StrokeStyle::dashed(1.5, 0.06, 0.06));
        }
        // A point (w = 1) moves with the translation; a direction (w = 0) only turns. The
        // direction points to the box's left and up (its −x side), away from the world axes and
        // from the box's own x axis, and long enough to leave the box while the box turns at
        // the origin. Each name goes to the first place round its dot or the arrow's tip, away
        // from the box's centre or the origin first, that covers neither box nor any dot, line
        // or name (on the last frame's view).
        let centre = m.w_axis.truncate();
        let p = (m * transform::point(POINT)).truncate();
        // Over the box: the corner is on it, and half the dot would sink into the solid box.
        frame.marker_on_top(p, 11.0, palette::PINK);
        let v = (m * transform::direction(DIRECTION)).truncate();
        frame.arrow(Vec3::ZERO, v, palette::PINK, 0.1);
        let view = view_of(self.view);
        let ghost_m = self.matrix_at(ghost, stage);
        // The boxes and a small cube round each tip of the solid box's axes and of the world's:
        // a name there would read as the axis's.
        let mut models = [m, ghost_m]
            .map(|b| b * Mat4::from_scale(BOX_HALF))
            .to_vec();
        for (tip, half) in [Vec3::X, Vec3::Y, Vec3::Z]
            .map(|axis| (m.transform_point3(axis * AXIS_M), 0.1))
            .into_iter()
            .chain([Vec3::X, Vec3::Y, Vec3::Z].map(|axis| (axis, 0.15)))
        {
            models.push(Mat4::from_translation(tip) * Mat4::from_scale(Vec3::splat(half)));
        }
        let boxes = boxes_px(&models, view);
        // Each order's name first, at the end of a thin leader from its box's highest corner,
        // so that it reads as the box's name and not as the name of an axis that ends near it.
        for order in [shown, ghost] {
            let placed = self.matrix_at(order, stage);
            let corner = [-1.0f32, 1.0]
                .into_iter()
                .flat_map(|x| [-1.0f32, 1.0].map(|y| (x, y)))
                .flat_map(|(x, y)| [-1.0f32, 1.0].map(|z| Vec3::new(x, y, z)))
                .map(|c| placed.transform_point3(c * BOX_HALF))
                .fold(Vec3::splat(f32::MIN), |a, b| if b.y > a.y { b } else { a });
            let from = (corner, placed.w_axis.truncate());
            name_on_leader(frame, view, from, order.name(), order.color(), &boxes);
        }
        // The world axes' letters beside their tips, off p's dot, the boxes and the names'
        // leaders where they can be.
        for l in letters {
            let candidates =
                Label::around_dot(l.anchor, 0.0, Vec2::ZERO, &l.text, l.color, 3, 3, 6.0);
            frame.first_clear_label_by(view, 4.0, candidates, off_points(&boxes, 2.0));
        }
        // Without a view: p's name rightwards, v's leftwards from past the tip, off the arrow.
        for (at, from, text, otherwise) in [
            (p, centre, "p (w = 1)", Vec2::X),
            (v, Vec3::ZERO, "v (w = 0)", -Vec2::X),
        ] {
            let toward = away(view, at, from, otherwise);
            let candidates = Label::around_dot(at, 11.0, toward, text, palette::PINK, 2, 10, 8.0);
            frame.first_clear_label_by(view, 2.0, candidates, off_points(&boxes, 2.0));
        }
        // Everything any stage shows stays in view: the boxes wherever their centres go (the
        // origin, t, the arc), and the world axes.
        let (lo, hi) = arc.iter().chain([Vec3::ZERO, t].iter()).fold(
            (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
            |(lo, hi), q| (lo.min(*q), hi.max(*q)),
        );
        let reach = Vec3::splat(BOX_HALF.max_element() + 0.05);
        frame.keep_box_in_view(lo - reach, hi + reach);
        frame
            .keep_in_view
            .extend([Vec3::X, Vec3::Y, Vec3::Z].map(|a| a * 1.1));
        Ok(self.note(stage))
    }

    fn note(&self, stage: f32) -> String {
        // Float noise such as cos 90° = -4e-8 reads as 0.
        let number = |x: f32| super::format_number(if x.abs() < 5e-6 { 0.0 } else { x });
        let fmt = |v: Vec3| format!("({}, {}, {})", number(v.x), number(v.y), number(v.z));
        let swung = self.matrix(Order::TranslateFirst).w_axis.truncate();
        let arm = super::format_number(self.translation.length());
        let step = if stage < 1.0 {
            "Step 1 of 2, the right-hand factor: T·R applies R first, so its box turns in place at \
             the origin; R·T applies T first, so its box slides to t."
                .to_string()
        } else if stage < 2.0 {
            format!(
                "Step 2 of 2, the left-hand factor: T·R now applies T, so its turned box slides to \
                 t; R·T now applies R, which turns about the world origin, so its box swings on an \
                 arm {arm} m long."
            )
        } else {
            "Both steps done.".to_string()
        };
        format!(
            "{step} In the end T·R keeps the box's centre at t = {}; R·T carries it to R·t = {}, \
             on an arm {arm} m long from the world origin; the centres are {} m apart.",
            fmt(self.translation),
            fmt(swung),
            super::format_number(self.translation.distance(swung))
        )
    }
}

/// Names a box of Figure 1 at the end of a thin leader (1 px, in the name's colour) from `corner`
/// (a point on the box) out of the box, upwards and away from its `centre` first, 0.2 to 0.8 m
/// long: the first place whose name covers no dot, line or name on `view`, keeps 8 px off the
/// `boxes`' points (canvas pixels), and whose leader crosses no name. The name sits just past
/// the leader's end, on its side of it on the canvas (above it without a view).
fn name_on_leader(
    frame: &mut Frame,
    view: Option<(Mat4, Vec2)>,
    (corner, centre): (Vec3, Vec3),
    text: &str,
    color: Vec3,
    boxes: &[Vec2],
) {
    let out = ((corner - centre) * Vec3::new(1.0, 0.0, 1.0))
        .try_normalize()
        .unwrap_or(Vec3::X);
    let across = Vec3::Y.cross(out);
    let px = |p: Vec3| view.and_then(|(m, size)| project_to_canvas(m, size, p));
    let placed: Vec<_> = view.map_or(Vec::new(), |(m, size)| {
        frame
            .labels
            .iter()
            .filter_map(|l| l.first_place(m, size))
            .collect()
    });
    // Up and out, straight up, then up and out turning round towards the back, then level,
    // then down.
    let mut directions = Vec::new();
    for rise in [1.0, 0.4, 0.0, -0.6] {
        for k in [0.0f32, 1.0, -1.0, 2.0, -2.0, 3.0, -3.0, 4.0] {
            let (sin, cos) = (k * std::f32::consts::FRAC_PI_4).sin_cos();
            directions.push((out * cos + across * sin + Vec3::Y * rise).normalize());
        }
    }
    directions.insert(1, Vec3::Y);
    let mut candidates = Vec::new();
    for length in [0.2, 0.3, 0.45, 0.6, 0.8] {
        for &d in &directions {
            let anchor = corner + d * length;
            let (a, b) = (px(corner), px(anchor));
            // The nearest of the eight sides of a dot (22.5° either side of each).
            let dir = a
                .zip(b)
                .map_or(-Vec2::Y, |(a, b)| (b - a).normalize_or_zero());
            let s = |x: f32| if x.abs() > 0.38 { x.signum() } else { 0.0 };
            let side = Vec2::new(s(dir.x), s(dir.y));
            let crosses = a.zip(b).is_some_and(|(a, b)| {
                (placed.iter())
                    .any(|r| crate::draw::segment_enters(a, b, r.min - 2.0, r.max() + 2.0))
            });
            if side != Vec2::ZERO && !crosses {
                candidates.push(Label::off_dot(anchor, 0.0, side, text.into(), color, 3));
            }
        }
    }
    if candidates.is_empty() {
        candidates.push(Label::off_dot(
            corner + Vec3::Y * 0.2,
            0.0,
            -Vec2::Y,
            text.into(),
            color,
            3,
        ));
    }
    frame.first_clear_label_by(view, 2.0, candidates, off_points(boxes, 8.0));
    let end = frame.labels.last().map_or(corner, |l| l.anchor);
    frame.wide_line(corner, end, color, 1.0);
}

/// The 12 edges of the cube `[-1, 1]³` placed by `model`.
fn wire_box(frame: &mut Frame, model: Mat4, color: Vec3) {
    let corner = |i: u32| {
        let c = Vec3::new(
            if i & 1 == 0 { -1.0 } else { 1.0 },
            if i & 2 == 0 { -1.0 } else { 1.0 },
            if i & 4 == 0 { -1.0 } else { 1.0 },
        );
        model.transform_point3(c)
    };
    for i in 0..8u32 {
        for bit in [1, 2, 4] {
            if i & bit == 0 {
                frame.line(corner(i), corner(i | bit), color);
            }
        }
    }
}

/// Names the point `at` of Figure 2's body beside the body, joined to it by a thin guide line: at
/// the point itself the name would sit on the boxes. The name goes `right` (the camera's right,
/// world space) of the point, or left of it reading leftwards, 0.3 m past the point or past
/// 0.3 m from the middle, whichever is further, and further out in steps of 0.15 m, at the
/// first place whose box covers none of the `body`'s points (canvas pixels),
/// dots, lines or names on `view`; without a view, to the figure's left (x > 0) for a point there
/// and to its right otherwise.
fn name_beside(
    frame: &mut Frame,
    at: Vec3,
    name: &str,
    color: Vec3,
    right: Vec3,
    view: Option<(Mat4, Vec2)>,
    body: &[Vec2],
) {
    let along = at.dot(right);
    let first = if along > 0.05 { 1.0 } else { -1.0 };
    let candidates = (0..10).flat_map(|k| {
        // At least 0.3 m out along `right` (past the arms, from the body's middle), then 0.3 m
        // and more beyond.
        let out = |side: f32| (along * side).max(0.3) + 0.3 + 0.15 * k as f32;
        [first, -first].map(|side| Label {
            anchor: at + right * (side * out(side) - along) + Vec3::Y * 0.1,
            text: name.to_string(),
            color,
            left: side < 0.0,
            priority: 1,
            offset_px: Vec2::ZERO,
            large: false,
        })
    });
    frame.first_clear_label_by(view, 2.0, candidates, off_points(body, 2.0));
    let beside = frame.labels.last().map_or(at, |l| l.anchor);
    frame.wide_line_on_top(at, beside, color, 1.0);
}

/// A box drawn in a joint's frame that is not a joint of its own: the nose and the feet, so that
/// front (+z) and back can be told apart. `(joint, centre, half-extents, colour)`.
const DETAILS: [(&str, Vec3, Vec3, Vec3); 3] = [
    (
        "head",
        Vec3::new(0.0, 0.12, 0.11),
        Vec3::new(0.02, 0.03, 0.025),
        Vec3::new(0.75, 0.5, 0.4),
    ),
    (
        "shin.L",
        Vec3::new(0.0, -0.37, 0.05),
        Vec3::new(0.06, 0.03, 0.11),
        palette::DARK,
    ),
    (
        "shin.R",
        Vec3::new(0.0, -0.37, 0.05),
        Vec3::new(0.06, 0.03, 0.11),
        palette::DARK,
    ),
];

/// The left wrist in the frame of `forearm.L`: the end of its box.
pub const WRIST_IN_FOREARM: Vec3 = Vec3::new(0.0, -0.28, 0.0);

/// How long one walk cycle takes, seconds.
pub const WALK_PERIOD_SEC: f32 = 1.2;

/// Figures 2 and 3: a human made of boxes, posed by joint angles, with `world = parent · local`.
#[derive(Clone, Debug)]
pub struct HierarchyFigure {
    hierarchy: Hierarchy,
    transforms: Vec<LocalTransform>,
    shapes: Vec<JointShape>,
    mode: ScaleMode,
    animate: bool,
    use_exercise: bool,
    runner: Runner,
    /// What the student's exercises give at [`LOCAL_PROBES`] and [`world_probes`], once per
    /// switch of "use my exercise" (they do not depend on the pose).
    probe_note: Option<String>,
    selected: usize,
    local: Vec<Mat4>,
    world: Vec<Mat4>,
    draw: Vec<Mat4>,
    angles: Vec<Vec3>,
    thigh: usize,
    forearm: usize,
    /// The last frame's camera and canvas size (CSS pixels), which the names are placed for.
    view: Option<(OrbitCamera, Vec2)>,
}

impl Default for HierarchyFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl HierarchyFigure {
    pub fn new() -> Self {
        let (hierarchy, transforms, shapes) = transform::simple_human();
        let n = hierarchy.len();
        let find = |name: &str| hierarchy.find(name).expect("a joint of simple_human");
        Self {
            thigh: find("thigh.L"),
            forearm: find("forearm.L"),
            selected: find("upper_arm.L"),
            hierarchy,
            transforms,
            shapes,
            mode: ScaleMode::NotInherited,
            animate: true,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            probe_note: None,
            view: None,
            local: vec![Mat4::IDENTITY; n],
            world: vec![Mat4::IDENTITY; n],
            draw: vec![Mat4::IDENTITY; n],
            angles: vec![Vec3::ZERO; n],
        }
    }

    pub fn joint_names(&self) -> &[String] {
        self.hierarchy.names()
    }

    fn joint(&self, joint: usize) -> Result<usize, String> {
        if joint < self.hierarchy.len() {
            Ok(joint)
        } else {
            Err(format!(
                "joint index {joint} is out of range: the figure has {} joints",
                self.hierarchy.len()
            ))
        }
    }

    /// Selects the joint whose axes are drawn and whose values the panel edits. Its angles and
    /// scale stay as they are.
    pub fn select(&mut self, joint: usize) -> Result<(), String> {
        self.selected = self.joint(joint)?;
        Ok(())
    }

    pub fn selected(&self) -> usize {
        self.selected
    }

    /// Euler angles of a joint in degrees, as last set or animated.
    pub fn joint_angles_deg(&self, joint: usize) -> Result<Vec3, String> {
        Ok(self.transforms[self.joint(joint)?].euler_xyz_rad / DEG)
    }

    /// Sets a joint's Euler angles, in degrees.
    pub fn set_joint_angles_deg(&mut self, joint: usize, deg: Vec3) -> Result<(), String> {
        let j = self.joint(joint)?;
        self.transforms[j].euler_xyz_rad = Vec3::new(
            finite("x", deg.x)?,
            finite("y", deg.y)?,
            finite("z", deg.z)?,
        ) * DEG;
        Ok(())
    }

    /// A joint's scale along its own axes.
    pub fn joint_scale(&self, joint: usize) -> Result<Vec3, String> {
        Ok(self.transforms[self.joint(joint)?].scale)
    }

    /// Sets a joint's scale along its own axes (each in [0.1, 4]).
    pub fn set_joint_scale(&mut self, joint: usize, scale: Vec3) -> Result<(), String> {
        let j = self.joint(joint)?;
        self.transforms[j].scale = Vec3::new(
            in_range("sx", scale.x, 0.1, 4.0)?,
            in_range("sy", scale.y, 0.1, 4.0)?,
            in_range("sz", scale.z, 0.1, 4.0)?,
        );
        Ok(())
    }

    /// Whether a joint's scale is passed on to its children.
    pub fn set_inherit_scale(&mut self, inherit: bool) {
        self.mode = if inherit {
            ScaleMode::Inherited
        } else {
            ScaleMode::NotInherited
        };
    }

    /// When on, the time drives a walk cycle (the limbs' x angles); everything else keeps its value.
    pub fn set_animate(&mut self, animate: bool) {
        self.animate = animate;
    }

    /// Runs the student's exercises 1.1 and 1.2 (through the runner) instead of the reference.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.probe_note = None;
    }

    /// How the student's code is called (natively in-process; in the page, the sandbox).
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.probe_note = None;
    }

    pub fn local_matrix(&self, joint: usize) -> Result<Mat4, String> {
        Ok(self.local[self.joint(joint)?])
    }

    pub fn world_matrix(&self, joint: usize) -> Result<Mat4, String> {
        Ok(self.world[self.joint(joint)?])
    }

    /// The matrix the shape of `joint` is drawn with (`world · S`, or `world` when inherited).
    pub fn draw_matrix(&self, joint: usize) -> Result<Mat4, String> {
        Ok(self.draw[self.joint(joint)?])
    }

    /// The left wrist (the end of the drawn left forearm) at the last pose, world space.
    pub fn wrist(&self) -> Vec3 {
        self.draw[self.forearm].transform_point3(WRIST_IN_FOREARM)
    }

    /// Poses the figure at `time_sec` with the reference core, then, with "use my exercise",
    /// with the student's. Returns the note: empty, or what the student's code did.
    pub fn pose(&mut self, time_sec: f32) -> Result<String, String> {
        self.pose_reference(finite("time", time_sec)?)?;
        Ok(if self.use_exercise {
            self.pose_with_exercises()
        } else if self.mode == ScaleMode::Inherited
            && self.transforms.iter().all(|x| x.scale == Vec3::ONE)
        {
            "Children inherit scale, but every scale is 1, so nothing changes yet: stretch a \
             joint's scale to see the difference."
                .to_string()
        } else {
            String::new()
        })
    }

    fn pose_reference(&mut self, time_sec: f32) -> Result<(), String> {
        if self.animate {
            for (a, x) in self.angles.iter_mut().zip(&self.transforms) {
                *a = x.euler_xyz_rad;
            }
            transform::walk_cycle(&self.hierarchy, time_sec, WALK_PERIOD_SEC, &mut self.angles);
            for (x, a) in self.transforms.iter_mut().zip(&self.angles) {
                x.euler_xyz_rad = *a;
            }
        }
        self.hierarchy
            .pose(
                &self.transforms,
                self.mode,
                &mut self.local,
                &mut self.world,
                &mut self.draw,
            )
            .map_err(|e| e.to_string())
    }

    /// Replaces the reference's local and world matrices by the student's (each step falls back
    /// to the reference when it gives no answer) and says whether they match.
    fn pose_with_exercises(&mut self) -> String {
        let local_note = self.student_locals();
        let world_note = self.student_worlds();
        for ((d, w), x) in self.draw.iter_mut().zip(&self.world).zip(&self.transforms) {
            *d = match self.mode {
                ScaleMode::NotInherited => *w * Mat4::from_scale(x.scale),
                ScaleMode::Inherited => *w,
            };
        }
        if self.probe_note.is_none() {
            self.probe_note = Some(probe_note(self.runner));
        }
        let probes = self.probe_note.as_deref().unwrap_or_default();
        format!("{local_note} {world_note} {probes}")
            .trim_end()
            .to_string()
    }

    /// Exercise 1.1 at every joint of the current pose; the first joint where it differs is named.
    fn student_locals(&mut self) -> String {
        let exercise = "exercise 1.1 local_matrix";
        let mut first_wrong = None;
        for (i, x) in self.transforms.iter().enumerate() {
            let yours = match run::local_matrix(self.runner, x.translation, x.euler_xyz_rad) {
                Ok(m) => m,
                Err(failure) => {
                    // Keep the reference's matrices for every joint.
                    self.hierarchy
                        .pose(
                            &self.transforms,
                            self.mode,
                            &mut self.local,
                            &mut self.world,
                            &mut self.draw,
                        )
                        .ok();
                    return failure_note(exercise, EXERCISE_FILE, &failure);
                }
            };
            let reference = transform::local_matrix(x.translation, x.euler_xyz_rad);
            if first_wrong.is_none() && !close(yours, reference) {
                first_wrong = Some((i, yours, reference));
            }
            self.local[i] = match self.mode {
                ScaleMode::Inherited => yours * Mat4::from_scale(x.scale),
                ScaleMode::NotInherited => yours,
            };
        }
        match first_wrong {
            None => format!(
                "Your local_matrix matches the reference at all {} joints of this pose.",
                self.transforms.len()
            ),
            Some((i, yours, reference)) => {
                let at = format!("joint {i} ({})", self.hierarchy.names()[i]);
                let (_, note) = compare_note(
                    "local_matrix",
                    &at,
                    &yours.to_cols_array(),
                    &reference.to_cols_array(),
                    TOLERANCE,
                );
                match rotation_problem(Mat3::from_mat4(yours), 1e-3) {
                    Some(problem) => format!("{note} Its upper-left 3×3 block: {problem}."),
                    None => note,
                }
            }
        }
    }

    /// Exercise 1.2 on the local matrices just computed; the first joint where it differs is named.
    fn student_worlds(&mut self) -> String {
        let exercise = "exercise 1.2 world_matrices";
        let parents: Vec<f32> = self.hierarchy.parents().iter().map(|&p| p as f32).collect();
        transform::world_matrices(self.hierarchy.parents(), &self.local, &mut self.world);
        let yours = match run::world_matrices(self.runner, parents, self.local.clone()) {
            Ok(w) if w.len() == self.world.len() => w,
            Ok(w) => {
                return format!(
                    "Your {exercise} returned {} matrices for {} joints. The figure uses the \
                     reference.",
                    w.len(),
                    self.world.len()
                )
            }
            Err(failure) => return failure_note(exercise, EXERCISE_FILE, &failure),
        };
        let wrong = (0..yours.len()).find(|&i| !close(yours[i], self.world[i]));
        let note = match wrong {
            None => format!(
                "Your world_matrices matches the reference at all {} joints.",
                yours.len()
            ),
            Some(i) => {
                let at = format!("joint {i} ({})", self.hierarchy.names()[i]);
                compare_note(
                    "world_matrices",
                    &at,
                    &yours[i].to_cols_array(),
                    &self.world[i].to_cols_array(),
                    TOLERANCE,
                )
                .1
            }
        };
        self.world.copy_from_slice(&yours);
        note
    }

    /// The last frame's camera and canvas size (CSS pixels): the names beside the body take
    /// places off its boxes on it. A size that is not positive and finite is ignored.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 && (width_px * height_px).is_finite() {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// Poses the figure at `time_sec` and draws it. Returns the note for the page.
    pub fn draw(&mut self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let note = self.pose(time_sec)?;
        frame.grid(12, 0.25);
        frame.labelled_axes(Mat4::IDENTITY, 0.4);
        self.draw_body(frame, Mat4::IDENTITY, true);
        frame.contact_shadow(Vec3::ZERO, 0.3);
        // The standing figure and its reach, whatever the pose.
        frame.keep_box_in_view(Vec3::new(-0.75, 0.0, -0.6), Vec3::new(0.75, 1.95, 0.6));
        Ok(note)
    }

    /// The boxes, the face (nose and eyes) and feet, the skeleton, and (with `labels`) the selected joint's
    /// labelled axes, the left thigh and the left wrist, all placed by `placement`.
    pub fn draw_body(&self, frame: &mut Frame, placement: Mat4, labels: bool) {
        // The selected box's colour, warmed towards tan.
        let highlight = |c: Vec3| c * 0.6 + Vec3::new(0.4, 0.35, 0.0);
        for (i, (shape, draw)) in self.shapes.iter().zip(&self.draw).enumerate() {
            let model = placement
                * *draw
                * Mat4::from_translation(shape.center)
                * Mat4::from_scale(shape.half_extents);
            let color = if labels && i == self.selected {
                highlight(shape.color)
            } else {
                shape.color
            };
            frame.mesh(MeshId::CUBE, model, color);
        }
        for (joint, center, half, color) in DETAILS {
            if let Some(i) = self.hierarchy.find(joint) {
                let model = placement
                    * self.draw[i]
                    * Mat4::from_translation(center)
                    * Mat4::from_scale(half);
                frame.mesh(MeshId::CUBE, model, color);
            }
        }
        if let Some(head) = self.hierarchy.find("head") {
            for x in [-0.045, 0.045] {
                let eye = self.draw[head].transform_point3(Vec3::new(x, 0.17, 0.1));
                frame.point(placement.transform_point3(eye), 0.018, palette::KEY);
            }
        }
        // The skeleton: a dot at each pivot, a segment to its parent's pivot.
        let pivot = |i: usize| placement.transform_point3(self.world[i].w_axis.truncate());
        for (i, &parent) in self.hierarchy.parents().iter().enumerate() {
            frame.marker_on_top(pivot(i), 7.0, palette::KEY);
            if parent >= 0 {
                frame.wide_line_on_top(pivot(parent as usize), pivot(i), palette::KEY, 2.0);
            }
        }
        if !labels {
            return;
        }
        let selected = placement * self.world[self.selected];
        // Over the body, which would hide them: a joint's pivot lies inside its boxes.
        frame.labelled_axes_on_top(selected, 0.25);
        let view = view_of(self.view);
        let models: Vec<Mat4> = (self.shapes.iter().zip(&self.draw))
            .map(|(shape, draw)| {
                placement
                    * *draw
                    * Mat4::from_translation(shape.center)
                    * Mat4::from_scale(shape.half_extents)
            })
            .collect();
        let body = boxes_px(&models, view);
        // The forearm's bone ends at the wrist, over everything as the skeleton: a wrist behind
        // the body still shows where its arm runs. The selected box's edges likewise, in its
        // highlight, seen through the body when it is behind it. Both before the names, which
        // keep off them.
        let wrist = placement.transform_point3(self.wrist());
        frame.wide_line_on_top(pivot(self.forearm), wrist, palette::KEY, 2.0);
        let m = models[self.selected];
        let edge = highlight(self.shapes[self.selected].color);
        for (a, b) in super::boids::box_edges(-Vec3::ONE, Vec3::ONE) {
            frame.wide_line_on_top(m.transform_point3(a), m.transform_point3(b), edge, 1.5);
        }
        // The camera's right on the page (world x before the first frame): names go beside
        // the body across the screen, whichever way the camera has turned.
        let right = self
            .view
            .map_or(Vec3::X, |(camera, _)| camera.view().row(0).truncate());
        let mut name = |at: Vec3, text: &str, color: Vec3| {
            name_beside(frame, at, text, color, right, view, &body)
        };
        name(
            pivot(self.selected),
            &self.hierarchy.names()[self.selected],
            palette::DARK,
        );
        // Halfway down the thigh (at the hip it would sit on the wrist's label when the arm hangs).
        let knee = self
            .hierarchy
            .parents()
            .iter()
            .position(|&p| p == self.thigh as i32);
        let thigh_mid = knee.map_or(pivot(self.thigh), |k| (pivot(self.thigh) + pivot(k)) * 0.5);
        name(thigh_mid, "left thigh", palette::PURPLE);
        name(wrist, "left wrist", palette::PINK);
        frame.marker_on_top(wrist, 11.0, palette::PINK);
    }

    /// One walk cycle of the *current* figure (its pose, scales and scale mode, with the walk
    /// driving the limbs' x angles), for the plot: `[t₀, a₀, h₀, t₁, a₁, h₁, …]` with the left
    /// thigh's x angle `a` (degrees) and the height `h` of the left wrist (metres), `t` over
    /// `[0, period_sec]` (the walk itself repeats every [`WALK_PERIOD_SEC`]).
    pub fn sample_cycle(&self, samples: usize, period_sec: f32) -> Result<Vec<f32>, String> {
        check_samples(samples)?;
        let period = in_range("period", period_sec, 0.01, 1000.0)?;
        let mut walker = self.clone();
        walker.animate = true;
        let mut out = Vec::with_capacity(samples * 3);
        for k in 0..samples {
            let t = period * k as f32 / (samples - 1) as f32;
            walker.pose_reference(t)?;
            let thigh_deg = walker.transforms[walker.thigh].euler_xyz_rad.x / DEG;
            out.extend_from_slice(&[t, thigh_deg, walker.wrist().y]);
        }
        Ok(out)
    }
}

/// Inputs at which exercise 1.1 is checked besides the pose (whose walk turns the limbs about x
/// only, where the order of the three rotations cannot show): `(what, translation, angles in
/// degrees)`.
pub const LOCAL_PROBES: [(&str, Vec3, Vec3); 3] = [
    (
        "t = (1, 2, 3), angles (30°, 40°, 50°)",
        Vec3::new(1.0, 2.0, 3.0),
        Vec3::new(30.0, 40.0, 50.0),
    ),
    (
        "t = (0, 0, 0), angles (0°, 90°, 45°)",
        Vec3::ZERO,
        Vec3::new(0.0, 90.0, 45.0),
    ),
    (
        "t = (0.5, 0, -1), angles (-60°, 0°, 120°)",
        Vec3::new(0.5, 0.0, -1.0),
        Vec3::new(-60.0, 0.0, 120.0),
    ),
];

/// Hierarchies on which exercise 1.2 is checked besides the figure: `(what, parents, locals)`,
/// each local a translation and a turn so that the order of every product shows.
pub fn world_probes() -> [(&'static str, Vec<i32>, Vec<Mat4>); 2] {
    let local = |t: Vec3, angles_deg: Vec3| transform::local_matrix(t, angles_deg * DEG);
    [
        (
            "a chain of four joints",
            vec![-1, 0, 1, 2],
            vec![
                local(Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 30.0, 0.0)),
                local(Vec3::new(0.5, 0.0, 0.0), Vec3::new(0.0, 0.0, 45.0)),
                local(Vec3::new(0.0, 0.4, 0.2), Vec3::new(60.0, 0.0, 0.0)),
                local(Vec3::new(0.3, 0.0, 0.0), Vec3::new(0.0, 20.0, 10.0)),
            ],
        ),
        (
            "two roots, each with a child",
            vec![-1, 0, -1, 2],
            vec![
                local(Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 90.0)),
                local(Vec3::new(0.0, 0.5, 0.0), Vec3::new(0.0, 0.0, 0.0)),
                local(Vec3::new(-1.0, 0.0, 0.0), Vec3::new(0.0, 90.0, 0.0)),
                local(Vec3::new(0.0, 0.0, 0.5), Vec3::new(45.0, 0.0, 0.0)),
            ],
        ),
    ]
}

/// Exercises 1.1 and 1.2 at [`LOCAL_PROBES`] and [`world_probes`]: which inputs match, and the
/// first that differs with both answers.
fn probe_note(runner: Runner) -> String {
    let mut notes = Vec::new();
    // Exercise 1.1.
    let mut differ: Vec<&str> = Vec::new();
    let mut first = String::new();
    for (what, t, deg) in LOCAL_PROBES {
        let reference = transform::local_matrix(t, deg * DEG);
        match run::local_matrix(runner, t, deg * DEG) {
            Err(_) => return String::new(),
            Ok(yours) if close(yours, reference) => {}
            Ok(yours) => {
                if first.is_empty() {
                    first = compare_note(
                        "local_matrix",
                        what,
                        &yours.to_cols_array(),
                        &reference.to_cols_array(),
                        TOLERANCE,
                    )
                    .1;
                }
                differ.push(what);
            }
        }
    }
    notes.push(summary(
        "local_matrix",
        &LOCAL_PROBES.map(|p| p.0),
        &differ,
        &first,
    ));
    // Exercise 1.2.
    let mut differ: Vec<&str> = Vec::new();
    let mut first = String::new();
    let probes = world_probes();
    for (what, parents, locals) in &probes {
        let mut reference = vec![Mat4::IDENTITY; locals.len()];
        transform::world_matrices(parents, locals, &mut reference);
        let p: Vec<f32> = parents.iter().map(|&x| x as f32).collect();
        match run::world_matrices(runner, p, locals.clone()) {
            Err(_) => return notes.join(" "),
            Ok(yours) => {
                let wrong = (0..reference.len())
                    .find(|&i| yours.get(i).is_none_or(|y| !close(*y, reference[i])));
                if let Some(i) = wrong {
                    if first.is_empty() {
                        let yours_i = yours.get(i).copied().unwrap_or(Mat4::NAN);
                        first = compare_note(
                            "world_matrices",
                            &format!("joint {i} of {what}"),
                            &yours_i.to_cols_array(),
                            &reference[i].to_cols_array(),
                            TOLERANCE,
                        )
                        .1;
                    }
                    differ.push(what);
                }
            }
        }
    }
    let all: Vec<&str> = probes.iter().map(|p| p.0).collect();
    notes.push(summary("world_matrices", &all, &differ, &first));
    notes.join(" ")
}

/// "Beyond this pose, your `what` also matches at N more inputs (…)" or "… differs at k of N
/// more inputs (…). " followed by `first`, the comparison at the first that differs.
fn summary(what: &str, all: &[&str], differ: &[&str], first: &str) -> String {
    if differ.is_empty() {
        format!(
            "Beyond this pose, your {what} also matches at {} more inputs ({}).",
            all.len(),
            all.join("; ")
        )
    } else {
        format!(
            "Beyond this pose, your {what} differs at {} of {} more inputs ({}). {first}",
            differ.len(),
            all.len(),
            differ.join("; ")
        )
    }
}

/// How close the student's matrices must be to the reference's, per entry.
const TOLERANCE: f32 = 1e-4;

fn close(a: Mat4, b: Mat4) -> bool {
    let scale = 1.0f32.max(b.abs().to_cols_array().iter().fold(0.0, |m, x| m.max(*x)));
    a.abs_diff_eq(b, TOLERANCE * scale)
}

/// Figure 3's outline of the stretched upper arm's side (`c-orange` in the caption): orange
/// against the arm's blue shirt, where a blue-green would sink into it.
pub const ARM_OUTLINE: Vec3 = palette::ORANGE;

/// Figure 3: the same pose twice, side by side: scale not inherited (left) and inherited (right).
#[derive(Clone, Debug)]
pub struct ScaleComparison {
    /// `[not inherited, inherited]`, posed alike.
    figures: [HierarchyFigure; 2],
    arm: usize,
    forearm: usize,
    /// The last frame's camera and canvas size (CSS pixels), which the labels are placed for
    /// ([`ScaleComparison::set_view`]).
    view: Option<(OrbitCamera, Vec2)>,
}

/// How far each copy stands from the centre along z, metres.
const COMPARISON_OFFSET: f32 = 0.8;

impl Default for ScaleComparison {
    fn default() -> Self {
        Self::new()
    }
}

impl ScaleComparison {
    /// The upper arm stretched to twice its length along y, the elbow bent 70°.
    pub fn new() -> Self {
        let mut figure = HierarchyFigure::new();
        figure.set_animate(false);
        let arm = figure.hierarchy.find("upper_arm.L").expect("a joint");
        let forearm = figure.forearm;
        let mut inherited = figure.clone();
        inherited.set_inherit_scale(true);
        let mut comparison = Self {
            figures: [figure, inherited],
            arm,
            forearm,
            view: None,
        };
        comparison
            .set_upper_arm_scale(Vec3::new(1.0, 2.0, 1.0))
            .expect("in range");
        comparison
            .set_forearm_angles_deg(Vec3::new(-70.0, 0.0, 0.0))
            .expect("finite");
        comparison
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's).
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// The left upper arm's scale along its own axes (each in [0.1, 4]), in both copies.
    pub fn set_upper_arm_scale(&mut self, scale: Vec3) -> Result<(), String> {
        let arm = self.arm;
        self.set_both(|f| f.set_joint_scale(arm, scale))
    }

    /// The left forearm's Euler angles, degrees, in both copies.
    pub fn set_forearm_angles_deg(&mut self, deg: Vec3) -> Result<(), String> {
        let forearm = self.forearm;
        self.set_both(|f| f.set_joint_angles_deg(forearm, deg))
    }

    /// Applies `set` to copies of both figures and keeps them only if it succeeded on both: a
    /// rejected value never leaves one copy changed and the other not.
    fn set_both(
        &mut self,
        set: impl Fn(&mut HierarchyFigure) -> Result<(), String>,
    ) -> Result<(), String> {
        let mut figures = self.figures.clone();
        for f in &mut figures {
            set(f)?;
        }
        self.figures = figures;
        Ok(())
    }

    /// The drawn left forearm of copy `k` (0: not inherited): its length (pivot to wrist, metres)
    /// and the angle at the corner of its outline ([`ScaleComparison::forearm_outline`]) that the
    /// figure marks with an arc and labels (degrees; 90 unless sheared in that side's plane).
    pub fn forearm_shape(&self, k: usize) -> (f32, f32) {
        let f = &self.figures[k];
        let length = (f.wrist() - f.draw[self.forearm].w_axis.truncate()).length();
        let c = self.forearm_outline(k);
        (length, (c[1] - c[2]).angle_between(c[3] - c[2]) / DEG)
    }

    /// Where copy `k` stands: one behind the other along z, so that a side view (looking along
    /// −x at the left arm) shows both forearms in the plane where the shear happens.
    pub fn placement(k: usize) -> Mat4 {
        let z = if k == 0 {
            COMPARISON_OFFSET
        } else {
            -COMPARISON_OFFSET
        };
        Mat4::from_translation(Vec3::new(0.0, 0.0, z))
    }

    /// The outline of copy `k`'s drawn left forearm on its face towards +x (the camera's side):
    /// four corners, a rectangle unless the box is sheared, then a parallelogram.
    pub fn forearm_outline(&self, k: usize) -> [Vec3; 4] {
        self.outline(k, self.forearm)
    }

    /// The outline of copy `k`'s drawn box of `joint` on its face towards +x.
    fn outline(&self, k: usize, joint: usize) -> [Vec3; 4] {
        let f = &self.figures[k];
        let shape = &f.shapes[joint];
        let m = Self::placement(k) * f.draw[joint];
        [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)].map(|(y, z)| {
            m.transform_point3(shape.center + shape.half_extents * Vec3::new(1.0, y, z))
        })
    }

    /// Draws both copies with a title above each, each forearm's outline with its corner angle;
    /// returns the note (forearm lengths and shear).
    pub fn draw(&mut self, frame: &mut Frame) -> Result<String, String> {
        frame.grid(12, 0.25);
        let titles = ["scale not inherited", "scale inherited"];
        let outline = StrokeStyle {
            on_top: true,
            ..StrokeStyle::solid(3.5)
        };
        let first_box = frame.meshes.len();
        let mut wrists = [Vec3::ZERO; 2];
        for (k, f) in self.figures.iter_mut().enumerate() {
            f.pose(0.0)?;
            let placement = Self::placement(k);
            f.draw_body(frame, placement, false);
            wrists[k] = placement.transform_point3(f.wrist());
            frame.marker_on_top(wrists[k], 10.0, palette::PINK);
            frame.contact_shadow(placement.transform_point3(Vec3::ZERO), 0.3);
        }
        // Each name goes to the first place round its anchor that covers no box, dot, line or
        // name placed before (on the last frame's view), most important first: the titles above
        // the heads, the corner angles across the corner from the box, the forearms' names
        // above and left of the wrists (the page sees the figures from +x: the forearms point
        // left).
        let view = view_of(self.view);
        let models: Vec<Mat4> = frame.meshes[first_box..].iter().map(|m| m.model).collect();
        let boxes = boxes_px(&models, view);
        let mut names = Vec::new();
        for k in 0..2 {
            let z = Self::placement(k).w_axis.z;
            let top = Vec3::new(0.0, 1.95, z);
            names.push((top, -Vec2::Y, titles[k].to_string(), palette::DARK, 3, 0.0));
        }
        for k in 0..2 {
            // The stretched upper arm's side, then the forearm's.
            let a = self.outline(k, self.arm);
            frame.stroke(&[a[0], a[1], a[2], a[3], a[0]], ARM_OUTLINE, outline);
            let c = self.forearm_outline(k);
            frame.stroke(&[c[0], c[1], c[2], c[3], c[0]], palette::PINK, outline);
            // The angle at the corner between the edges along the forearm and across it.
            let (a, b) = ((c[1] - c[2]).normalize(), (c[3] - c[2]).normalize());
            let angle = self.forearm_shape(k).1 * DEG;
            let r = 0.05;
            let arc: Vec<Vec3> = (0..=12)
                .map(|i| {
                    let s = i as f32 / 12.0;
                    let d = if angle.sin().abs() < 1e-4 {
                        a
                    } else {
                        (a * ((1.0 - s) * angle).sin() + b * (s * angle).sin()) / angle.sin()
                    };
                    c[2] + d * r
                })
                .collect();
            frame.stroke(
                &arc,
                palette::DARK,
                StrokeStyle {
                    on_top: true,
                    ..StrokeStyle::solid(2.0)
                },
            );
            let out = -(a + b).normalize_or_zero();
            let toward = away(view, c[2] + out, c[2], Vec2::new(-out.z, -out.y));
            names.push((
                c[2],
                toward,
                format!("{:.0}°", angle / DEG),
                palette::DARK,
                2,
                0.0,
            ));
        }
        for wrist in wrists {
            let name = "forearm.L".to_string();
            names.push((wrist, Vec2::new(-1.0, -1.0), name, palette::PINK, 1, 10.0));
        }
        for (anchor, toward, text, color, priority, dot_px) in names {
            let candidates =
                Label::around_dot(anchor, dot_px, toward, &text, color, priority, 10, 8.0);
            frame.first_clear_label_by(view, 2.0, candidates, off_points(&boxes, 2.0));
        }
        // Seen from the side, where the shear shows: a drag pans instead of turning the
        // outlines edge-on (and each title away from its figure).
        frame.flat = true;
        frame.keep_box_in_view(
            Vec3::new(-0.45, 0.0, -COMPARISON_OFFSET - 0.5),
            Vec3::new(0.45, 2.05, COMPARISON_OFFSET + 0.5),
        );
        let describe = |k: usize| {
            let (length, angle) = self.forearm_shape(k);
            format!(
                "{}: the forearm is {} m long, the marked corner of its outline {}°",
                titles[k],
                super::format_number(length),
                super::format_number(angle)
            )
        };
        Ok(format!("{}. {}.", describe(0), describe(1)))
    }
}
