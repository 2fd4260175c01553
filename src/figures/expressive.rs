//! Lesson 02b, "Expressive animation": timing and spacing on one path, a jump plain and with the
//! principles applied, and follow-through on an antenna. Native and tested natively
//! (tests/figures_expressive.rs); `web::expressive` only wraps these for JavaScript.

use super::curves::{probe_note, Probe};
use super::{check_samples, compare_note, failure_note, format_number, in_range, palette};
use super::{Failure, Frame, MeshId, Runner, DEFAULT_RUNNER};
use crate::curves::Ease;
use crate::exercises::run;
use crate::expressive::{self, arc_point, Antenna, Jump};
use glam::{Mat3, Mat4, Vec3};

const FILE: &str = "src/exercises/expressive.rs";
const TOLERANCE: f32 = 1e-4;
/// Radius of the balls, metres.
const RADIUS: f32 = 0.3;

/// The model matrix of a ball of [`RADIUS`] at `centre`, stretched by `scale` (along, across,
/// across) along the unit direction `axis`.
fn ball(centre: Vec3, axis: Vec3, scale: Vec3) -> Mat4 {
    let r = match axis.try_normalize() {
        Some(a) => Mat3::from_quat(glam::Quat::from_rotation_arc(Vec3::X, a)),
        None => Mat3::IDENTITY,
    };
    let m = r * Mat3::from_diagonal(scale) * r.transpose();
    Mat4::from_translation(centre) * Mat4::from_mat3(m) * Mat4::from_scale(Vec3::splat(RADIUS))
}

/// The scale of squash and stretch `s`: the student's (exercise 2b.1) when asked and usable.
fn stretch_scale(runner: Runner, use_exercise: bool, s: f32) -> Vec3 {
    use_exercise
        .then(|| run::squash_stretch_scale(runner, s).ok())
        .flatten()
        .filter(|v| v.is_finite() && v.min_element() > 0.0)
        .unwrap_or_else(|| expressive::squash_stretch_scale(s))
}

/// The note about exercise 2b.1 at stretch `s` (the figure's input) and at a squash, at rest
/// and at the largest stretch: the comparison and the volume the answer keeps at `s`.
fn scale_note(runner: Runner, s: f32) -> String {
    let probe = |u: f32| -> Result<Probe, Failure> {
        Ok(Probe {
            at: format!("s = {}", format_number(u)),
            yours: run::squash_stretch_scale(runner, u)?.to_array().to_vec(),
            reference: expressive::squash_stretch_scale(u).to_array().to_vec(),
        })
    };
    let probes: Result<Vec<Probe>, Failure> = std::iter::once(s)
        .chain([0.6, 1.0, MAX_STRETCH].into_iter().filter(|&u| u != s))
        .map(probe)
        .collect();
    match probes {
        Err(f) => failure_note("exercise 2b.1 squash_stretch_scale", FILE, &f),
        Ok(probes) => {
            let (_, note) = probe_note("squash_stretch_scale", &probes, TOLERANCE);
            let volume: f32 = probes[0].yours.iter().product();
            format!(
                "{note} At s = {} your scale keeps {} of the volume.",
                format_number(s),
                format_number(volume)
            )
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 1: timing and spacing.

/// Colours of Figure 1.
pub const BALL: Vec3 = palette::BLUE;
/// Pale grey: the arc's ghosts read as copies of the ball, apart from the twin's purple ones.
pub const GHOST: Vec3 = palette::GRID;
/// The straight-line twin, its line and name (purple, as the caption names it), and its ghosts
/// (pale purple): where the two rows of ghosts cross on the canvas, each keeps its own colour.
pub const TWIN: Vec3 = palette::PURPLE;
pub const TWIN_GHOST: Vec3 = Vec3::new(0.62, 0.45, 0.8);
pub const CHART: Vec3 = palette::ORANGE;
/// Radius of a ghost, metres: smaller than the ball, so the ball stands out where it passes one
/// and bunched ghosts stay apart, and large enough to read as a copy of it.
pub const GHOST_RADIUS: f32 = 0.6 * RADIUS;

/// Where the path of Figure 1 starts and ends.
const START: Vec3 = Vec3::new(-2.5, 0.3, 0.0);
const END: Vec3 = Vec3::new(2.5, 0.3, 0.0);
/// Where Figure 1 puts its straight-line twin, behind the arc: the same keys and spacing.
const TWIN_OFFSET: Vec3 = Vec3::new(0.0, 0.0, -1.4);

/// The most ghosts Figure 1 draws.
pub const MAX_GHOSTS: usize = 60;
pub use crate::expressive::MAX_STRETCH;

/// Figure 1: one ball between two keys along an arc (or a straight line), with the spacing of an
/// easing curve: ghosts at equal time steps, a spacing chart under the path, and optional squash
/// and stretch along the motion. Optionally a twin ball behind it takes the straight line with the
/// same keys and spacing, so the two paths are compared at the same moment.
pub struct Spacing {
    ease: Ease,
    arc_height: f32,
    twin: bool,
    ghosts: usize,
    squash: bool,
    use_exercise: bool,
    runner: Runner,
    /// Seconds from key to key.
    pub duration: f32,
    /// The last frame's camera and canvas size (CSS pixels), which the labels are placed for.
    view: Option<(crate::camera::OrbitCamera, glam::Vec2)>,
}

impl Default for Spacing {
    fn default() -> Self {
        Self::new()
    }
}

impl Spacing {
    pub fn new() -> Self {
        Spacing {
            ease: Ease::InOut { power: 3.0 },
            arc_height: 1.2,
            twin: true,
            ghosts: 12,
            squash: true,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            duration: 1.5,
            view: None,
        }
    }

    /// The last frame's camera and canvas size (CSS pixels): the paths' names take places clear
    /// of the ghosts, balls and lines on it. A size that is not positive and finite is ignored.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 && (width_px * height_px).is_finite() {
            self.view = Some((camera, glam::Vec2::new(width_px, height_px)));
        }
    }

    /// "linear", "slow in and out", "ease in" (starts slowly), "ease out" (arrives slowly).
    pub fn set_ease(&mut self, name: &str) -> Result<(), String> {
        self.ease = match name {
            "linear" => Ease::Linear,
            // Cubic in and out: the ghosts bunch visibly at the keys (smoothstep's do less).
            "slow in and out" => Ease::InOut { power: 3.0 },
            "ease in" => Ease::In { power: 2.0 },
            "ease out" => Ease::Out { power: 2.0 },
            _ => return Err(format!("unknown spacing {name:?}")),
        };
        Ok(())
    }

    /// The arc's height above the straight line, 0 to 3 m (0: a straight line).
    pub fn set_arc_height(&mut self, h: f32) -> Result<(), String> {
        self.arc_height = in_range("arc height", h, 0.0, 3.0)?;
        Ok(())
    }

    /// Shows the straight-line twin behind the ball.
    pub fn set_twin(&mut self, on: bool) {
        self.twin = on;
    }

    /// Ghosts at equal time steps, 2 to [`MAX_GHOSTS`].
    pub fn set_ghosts(&mut self, n: f32) -> Result<(), String> {
        self.ghosts = super::whole_number("ghosts", n, 2, MAX_GHOSTS)?;
        Ok(())
    }

    pub fn set_squash(&mut self, on: bool) {
        self.squash = on;
    }

    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// The fraction of the path covered at `t ∈ [0, 1]` of the time (the spacing).
    pub fn spacing(&self, t: f32) -> f32 {
        self.ease.apply(t)
    }

    /// The ball's position at `t ∈ [0, 1]` of the time from key 1 to key 2.
    pub fn position(&self, t: f32) -> Vec3 {
        arc_point(START, END, Vec3::Y, self.arc_height, self.spacing(t))
    }

    /// Seconds of one loop: key 1 to key 2, then back to key 1 with the same spacing.
    pub fn loop_sec(&self) -> f32 {
        2.0 * self.duration
    }

    /// At `time_sec` into the loop: whether the ball is on its way back, and `t ∈ [0, 1]`, the
    /// fraction of the time of the current trip.
    pub fn trip(&self, time_sec: f32) -> (bool, f32) {
        let u = (time_sec / self.duration).clamp(0.0, 2.0);
        if u <= 1.0 {
            (false, u)
        } else {
            (true, u - 1.0)
        }
    }

    /// How far along the path from key 1 the ball is at `time_sec` into the loop, as a fraction
    /// of the path: `e(t)` on the way out, `1 − e(t)` on the way back (each trip starts and ends
    /// with the same spacing).
    pub fn along(&self, time_sec: f32) -> f32 {
        match self.trip(time_sec) {
            (false, t) => self.spacing(t),
            (true, t) => 1.0 - self.spacing(t),
        }
    }

    /// The ball's position at `time_sec` into the loop.
    pub fn position_at(&self, time_sec: f32) -> Vec3 {
        arc_point(START, END, Vec3::Y, self.arc_height, self.along(time_sec))
    }

    /// The ball's velocity (central difference over 2 ms) and its stretch `s = 1 + 0.06 · speed`
    /// (m/s), at most [`MAX_STRETCH`], at `time_sec` into the loop.
    pub fn stretch(&self, time_sec: f32) -> (Vec3, f32) {
        let h = 1e-3;
        let (t0, t1) = ((time_sec - h).max(0.0), (time_sec + h).min(self.loop_sec()));
        let velocity = (self.position_at(t1) - self.position_at(t0)) / (t1 - t0);
        (
            velocity,
            expressive::stretch_from_speed(velocity.length(), 0.06, MAX_STRETCH),
        )
    }

    /// `(time, fraction of the path from key 1, the same with linear spacing)` over one loop,
    /// time in seconds.
    pub fn sample_spacing(&self, samples: usize) -> Result<Vec<[f32; 3]>, String> {
        check_samples(samples)?;
        let linear = |time: f32| {
            let u = time / self.duration;
            if u <= 1.0 {
                u
            } else {
                2.0 - u
            }
        };
        Ok((0..samples)
            .map(|k| {
                let time = self.loop_sec() * k as f32 / (samples - 1) as f32;
                [time, self.along(time), linear(time)]
            })
            .collect())
    }

    /// Draws the path, ghosts, spacing chart and the ball at `time_sec` into the loop; returns
    /// the note.
    pub fn draw(&self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let time = in_range("time", time_sec, 0.0, self.loop_sec())?;
        let back = self.trip(time).0;
        // Where the k-th of n ghosts of the current trip is, as a fraction of the path.
        let ghost = |k: usize| {
            let f = self.spacing(k as f32 / (self.ghosts - 1) as f32);
            if back {
                1.0 - f
            } else {
                f
            }
        };
        frame.grid(14, 0.5);
        // The path, its straight twin behind and the chart in front: fitted at every canvas size.
        frame.keep_box_in_view(
            Vec3::new(START.x - 0.3, 0.0, TWIN_OFFSET.z - 0.3),
            Vec3::new(END.x + 0.3, START.y + self.arc_height + 0.45, 1.0),
        );
        let path: Vec<Vec3> = (0..=64)
            .map(|k| arc_point(START, END, Vec3::Y, self.arc_height, k as f32 / 64.0))
            .collect();
        frame.wide_polyline(&path, palette::DARK, crate::draw::CURVE_PX);
        // Over everything: the first and last ghosts sit on the keys.
        frame.marker_on_top(START, crate::draw::DOT_PX, palette::KEY);
        frame.marker_on_top(END, crate::draw::DOT_PX, palette::KEY);
        frame.label(START + Vec3::new(0.0, -0.35, 0.0), "key 1", palette::KEY);
        frame.label(END + Vec3::new(0.0, -0.35, 0.0), "key 2", palette::KEY);
        // The spacing chart: a ruler below the path with a tick at each ghost.
        let ruler = |f: f32| Vec3::new(START.x + (END.x - START.x) * f, 0.02, 0.8);
        frame.line(ruler(0.0), ruler(1.0), CHART);
        for k in 0..self.ghosts {
            let f = ghost(k);
            frame.point(
                arc_point(START, END, Vec3::Y, self.arc_height, f),
                GHOST_RADIUS,
                GHOST,
            );
            frame.line(ruler(f), ruler(f) + Vec3::new(0.0, 0.0, 0.25), CHART);
        }
        frame.label(
            ruler(0.5) + Vec3::new(0.0, 0.0, 0.45),
            "spacing chart",
            CHART,
        );
        if self.twin {
            // The straight twin: same keys, same spacing, no arc.
            let (a, b) = (START + TWIN_OFFSET, END + TWIN_OFFSET);
            frame.line(a, b, TWIN);
            for k in 0..self.ghosts {
                frame.point(a.lerp(b, ghost(k)), GHOST_RADIUS, TWIN_GHOST);
            }
            let q = a.lerp(b, self.along(time));
            frame.mesh(MeshId::SPHERE, ball(q, Vec3::X, Vec3::ONE), TWIN);
        }
        let p = self.position_at(time);
        if self.twin {
            self.name_paths(frame, ghost, p, time);
        }
        let (velocity, s) = self.stretch(time);
        let (s, scale) = if self.squash {
            (s, stretch_scale(self.runner, self.use_exercise, s))
        } else {
            (1.0, Vec3::ONE)
        };
        frame.mesh(MeshId::SPHERE, ball(p, velocity, scale), BALL);
        let speed = velocity.length();
        let mut note = format!(
            "At {} s the ball is {:.3} % of the way along the path from key 1{}, at {} m/s \
             (stretch s = {}). {} ghosts of this trip at equal time steps: bunched where it is \
             slow, spread where it is fast.",
            format_number(time),
            // As the plot counts it, in fixed notation like the other percentages.
            100.0 * self.along(time),
            if back { " (on the way back)" } else { "" },
            format_number(speed),
            format_number(s),
            self.ghosts,
        );
        if self.use_exercise {
            note += " ";
            note += &scale_note(self.runner, s);
        }
        Ok(note)
    }
}

impl Spacing {
    /// The names of the arc and of its straight twin: above the arc's top and under the middle
    /// of the twin's row at the page's camera; else the first place round the arc's top and the
    /// twin's end that covers no ghost, ball (the frame draws them as meshes and points, which
    /// the search does not see), line or the other name, on the last frame's view.
    fn name_paths(&self, frame: &mut Frame, ghost: impl Fn(usize) -> f32, p: Vec3, time: f32) {
        use crate::draw::Label;
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let (a, b) = (START + TWIN_OFFSET, END + TWIN_OFFSET);
        // Every round thing (centre, radius in metres) and the twin's thin line, sampled.
        let mut round: Vec<(Vec3, f32)> = (0..self.ghosts)
            .flat_map(|k| {
                let f = ghost(k);
                [
                    (
                        arc_point(START, END, Vec3::Y, self.arc_height, f),
                        GHOST_RADIUS,
                    ),
                    (a.lerp(b, f), GHOST_RADIUS),
                ]
            })
            .collect();
        round.push((p, RADIUS * MAX_STRETCH));
        round.push((a.lerp(b, self.along(time)), RADIUS));
        round.extend((0..=16).map(|k| (a.lerp(b, k as f32 / 16.0), 0.0)));
        let clear = |rect: crate::draw::layout::Rect| {
            let Some((view_proj, size)) = view else {
                return true;
            };
            let at = |p| crate::camera::project_to_canvas(view_proj, size, p);
            round.iter().all(|&(c, r)| {
                let (Some(centre), Some(edge)) = (at(c), at(c + Vec3::Y * r)) else {
                    return true;
                };
                rect.nearest(centre).distance(centre) > centre.distance(edge) + 3.0
            })
        };
        let top = START.lerp(END, 0.5) + Vec3::Y * self.arc_height;
        // The twin's name goes round its start (key 1's end, left first) before its end: the
        // two rows meet near key 2 when orbited, and a name there would name either.
        for (anchor, toward, first, text, color) in [
            (top, -glam::Vec2::Y, top + Vec3::Y * 0.4, "arc", BALL),
            // Under the middle of the twin's row of ghosts, where the arc, high above, leaves
            // room.
            (a, -glam::Vec2::X, a.lerp(b, 0.5) - Vec3::Y * 0.4, "straight line", TWIN),
        ] {
            let mut around = Label::around_dot(anchor, 0.0, toward, text, color, 1, 8, 10.0);
            around.insert(
                0,
                Label::off_dot(first, 0.0, glam::Vec2::ZERO, text.into(), color, 1),
            );
            frame.first_clear_label_by(view, 3.0, around, &clear);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 2: a jump, plain and with the principles.

/// Colours of Figure 2.
pub const PLAIN: Vec3 = palette::GREY;
pub const PRINCIPLED: Vec3 = palette::ORANGE;

/// Figure 2: the same jump twice, side by side: left, plain interpolation between the keys
/// (ground, apex, ground); right, with anticipation, a gravity arc (slow in and out at the apex),
/// stretch in flight and squash on landing.
pub struct JumpComparison {
    jump: Jump,
    use_exercise: bool,
    runner: Runner,
}

impl Default for JumpComparison {
    fn default() -> Self {
        Self::new()
    }
}

impl JumpComparison {
    /// A pause after landing, seconds, so the loop shows the settle.
    pub const PAUSE: f32 = 0.5;

    pub fn new() -> Self {
        JumpComparison {
            jump: Jump::default(),
            use_exercise: false,
            runner: DEFAULT_RUNNER,
        }
    }

    /// Crouch depth 0 to 0.6 (a fraction of the height), stretch per m/s 0 to 0.2.
    pub fn set_principles(
        &mut self,
        anticipation: f32,
        stretch_per_speed: f32,
    ) -> Result<(), String> {
        let anticipation = in_range("anticipation", anticipation, 0.0, 0.6)?;
        let stretch_per_speed = in_range("stretch", stretch_per_speed, 0.0, 0.2)?;
        self.jump.anticipation = anticipation;
        self.jump.stretch_per_speed = stretch_per_speed;
        Ok(())
    }

    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// The loop's length, seconds.
    pub fn duration(&self) -> f32 {
        self.jump.duration() + Self::PAUSE
    }

    /// `(t, plain height, principled height, principled stretch)` over the loop.
    pub fn sample_heights(&self, samples: usize) -> Result<Vec<[f32; 4]>, String> {
        check_samples(samples)?;
        Ok((0..samples)
            .map(|k| {
                let t = self.duration() * k as f32 / (samples - 1) as f32;
                let p = self.jump.principled(t);
                [t, self.jump.plain(t).height, p.height, p.stretch]
            })
            .collect())
    }

    /// Draws both balls at `time_sec`; returns the note.
    pub fn draw(&self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let t = in_range("time", time_sec, 0.0, self.duration())?;
        frame.grid(12, 0.5);
        // Both balls from the ground to above the apex, whatever the time.
        frame.keep_box_in_view(
            Vec3::new(-1.7, -0.3, -0.4),
            Vec3::new(1.7, self.jump.apex + 2.0 * RADIUS + 0.5, 0.4),
        );
        let plain = self.jump.plain(t);
        frame.mesh(
            MeshId::SPHERE,
            ball(
                Vec3::new(-1.2, plain.height + RADIUS, 0.0),
                Vec3::Y,
                Vec3::ONE,
            ),
            PLAIN,
        );
        let p = self.jump.principled(t);
        let scale = stretch_scale(self.runner, self.use_exercise, p.stretch);
        let centre = Vec3::new(1.2, p.height + RADIUS * scale.x, 0.0);
        frame.mesh(MeshId::SPHERE, ball(centre, Vec3::Y, scale), PRINCIPLED);
        // Shadows on the ground under both: how high each is, and when it lands, read from one
        // view.
        frame.contact_shadow(Vec3::new(-1.2, plain.height, 0.0), RADIUS);
        frame.contact_shadow(Vec3::new(1.2, p.height, 0.0), RADIUS * scale.y);
        // Each name under its ball's lowest point, so it follows the ball up from any view, a
        // gap below it (as if under a dot 16 px across). Seen from above, a squashed ball's
        // outline reaches below that point by up to about its half-width less its half-height:
        // the name starts lower by 0.6 of that, so it does not touch the ball it names.
        let squashed = RADIUS * (scale.y - scale.x).max(0.0) * 0.6;
        for (bottom, text, color) in [
            (Vec3::new(-1.2, plain.height, 0.0), "plain", PLAIN),
            (Vec3::new(1.2, p.height - squashed, 0.0), "principles", PRINCIPLED),
        ] {
            frame.label_off_dot(bottom, 16.0, glam::Vec2::Y, text, color, 0);
        }
        // The apex both reach.
        let apex = self.jump.apex + 2.0 * RADIUS;
        frame.line(
            Vec3::new(-2.0, apex, 0.0),
            Vec3::new(2.0, apex, 0.0),
            palette::GRID_AXIS,
        );
        let push_off = self.jump.wind_up * 0.5;
        let phase = if t < push_off {
            "anticipation: crouching before take-off"
        } else if t < self.jump.wind_up {
            "push-off: stretching up to the take-off stretch"
        } else if t < self.jump.wind_up + self.jump.flight {
            "flight: a parabola, slow at the apex, stretched when fast"
        } else if t < self.jump.duration() {
            "landing: the stretch relaxes, a squash springs back"
        } else {
            "at rest"
        };
        let in_flight = (self.jump.wind_up..self.jump.wind_up + self.jump.flight).contains(&t);
        // The push-off stretches towards the take-off stretch, so when that is capped the note
        // says so there too, with the take-off speed.
        let pushing_off = (push_off..self.jump.wind_up).contains(&t);
        let speed = if in_flight {
            p.vertical_velocity.abs()
        } else {
            self.jump.take_off_speed()
        };
        let capped = if (in_flight || pushing_off) && p.stretch >= MAX_STRETCH - 1e-4 {
            format!(
                ", capped at {} (1 + {} × {} m/s would be {})",
                format_number(MAX_STRETCH),
                format_number(self.jump.stretch_per_speed),
                format_number(speed),
                format_number(1.0 + self.jump.stretch_per_speed * speed),
            )
        } else {
            String::new()
        };
        let mut note = format!(
            "t = {} s, {phase}. Right ball: stretch s = {}{capped} (volume kept: {}); take-off \
             at {} m/s.",
            format_number(t),
            format_number(p.stretch),
            format_number(scale.x * scale.y * scale.z),
            format_number(self.jump.take_off_speed()),
        );
        if self.use_exercise {
            note += " ";
            note += &scale_note(self.runner, p.stretch);
        }
        Ok(note)
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 3: follow-through on an antenna.

/// What one joint's damped spring of stiffness `k` and damping `c` does on its own, in words:
/// under-damped below `2√k`, critically damped at it (within 0.1 %), over-damped above. A chain
/// of such joints need not do the same (Figure 3's note says what its tip does).
pub fn damping_regime(c: f32, k: f32) -> &'static str {
    let critical = 2.0 * k.sqrt();
    if (c - critical).abs() <= 1e-3 * critical {
        "critically damped (one joint alone would not swing past)"
    } else if c < critical {
        "under-damped (one joint alone would swing past)"
    } else {
        "over-damped (one joint alone would creep back)"
    }
}

/// Colours of Figure 3.
pub const BODY: Vec3 = palette::TEAL;
pub const ANTENNA: Vec3 = palette::PURPLE;

/// Simulation step of Figure 3, seconds.
pub const DT: f32 = 1.0 / 120.0;

/// The reference antenna drawn beside the student's.
pub const GHOST_REFERENCE: Vec3 = palette::GREY;
/// How far (m) the student's antenna tip may drift from the reference's over a whole loop of
/// steps and still match: float rounding of a different but correct formula accumulates.
const TIP_TOLERANCE: f32 = 2e-3;

/// Figure 3: a body slides from side to side and stops at each end; an antenna on top, a chain
/// of joints each pulled by a damped spring towards its rest place above the joint below, lags
/// behind, swings past when the body stops, and settles. The motion is simulated from time 0 to
/// the timeline's time (deterministic: scrubbing gives the same picture), starting from the
/// antenna's state at the start of a loop once the body has looped for a while, so the end of
/// the loop runs on into its start without a jump; while time moves forward the simulation
/// continues from where it was instead of starting again.
///
/// With "use my exercise" every joint of the shown antenna is stepped by the student's
/// `spring_step` (exercise 2b.2) and the reference antenna is drawn beside it as a ghost.
pub struct FollowThrough {
    stiffness: f32,
    damping: f32,
    joints: usize,
    use_exercise: bool,
    runner: Runner,
    /// Stepped by the reference `spring_step`.
    reference: Antenna,
    /// Stepped by the student's `spring_step` (only with `use_exercise`).
    yours: Antenna,
    /// Steps of [`DT`] both antennas have taken; `None` when they must start again.
    steps_done: Option<usize>,
    /// Both antennas at time 0: the reference's state at the start of a loop once it repeats.
    start: Antenna,
    /// The furthest (m) the tip swings past the base after a stop, over a loop from `start`.
    swing_past: f32,
    /// The furthest (m) the tip is to the side of the base in the last [`Self::LATE`] s of each
    /// hold, over a loop from `start`: what is left of the wobble (or the lag) when the body
    /// moves again.
    late: f32,
    /// Why the student's antenna stopped (a failure note), if it did.
    problem: Option<String>,
}

impl Default for FollowThrough {
    fn default() -> Self {
        Self::new()
    }
}

impl FollowThrough {
    /// One loop: move right (1 s), hold (1 s), move left (1 s), hold (1 s).
    pub const DURATION: f32 = 4.0;
    /// Length of the antenna, metres: more joints cut it into shorter segments.
    pub const LENGTH: f32 = 1.1;
    /// The highest view of the figure, radians above the horizon (about 34°; the page's camera
    /// looks from 20°): from up to here the antenna still stands tall on screen.
    pub const MAX_PITCH_RAD: f32 = 0.6;
    /// The most joints. Each joint is pulled by the one below and never pulls it back, so a
    /// wobble grows from joint to joint: with more joints (or less damping than
    /// [`Self::MIN_DAMPING`], or a softer spring than [`Self::MIN_STIFFNESS`]) the antenna whips
    /// round and folds over. Inside these limits no joint bends by more than 110°
    /// (tests/figures_expressive.rs checks a grid of them).
    pub const MAX_JOINTS: usize = 6;
    /// The least damping the figure takes, 1/s.
    pub const MIN_DAMPING: f32 = 8.0;
    /// The softest spring the figure takes, 1/s².
    pub const MIN_STIFFNESS: f32 = 50.0;
    /// The end of each hold (s) over which the note says how far the tip still is from above the
    /// base. Within 1 cm counts as settled.
    pub const LATE: f32 = 0.25;

    fn segment(joints: usize) -> f32 {
        Self::LENGTH / (joints - 1) as f32
    }

    pub fn new() -> Self {
        let antenna = Antenna::new(Self::base(0.0), 6, Self::segment(6));
        let mut scene = FollowThrough {
            stiffness: 150.0,
            damping: 10.0,
            joints: 6,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            reference: antenna.clone(),
            yours: antenna.clone(),
            steps_done: None,
            start: antenna,
            swing_past: 0.0,
            late: 0.0,
            problem: None,
        };
        scene.settle();
        scene
    }

    /// How far (m) the tip is past the base in the direction of the body's last move while the
    /// body holds still (1 to 2 s at the right end, 3 to 4 s at the left); 0 while it moves.
    fn past(time_sec: f32, antenna: &Antenna) -> f32 {
        let side = match time_sec {
            t if (1.0..=2.0).contains(&t) => 1.0,
            t if t >= 3.0 => -1.0,
            _ => 0.0,
        };
        side * (antenna.tip().x - antenna.positions[0].x)
    }

    /// Loops the body under a straight antenna until the antenna's state at the start of a loop
    /// repeats (three loops settle every slider setting to float rounding; four are run), keeps
    /// that state as `start`, the furthest the tip swings past the base in the last loop and how
    /// far it is to the side of the base at the end of each hold.
    fn settle(&mut self) {
        let mut antenna = Antenna::new(Self::base(0.0), self.joints, Self::segment(self.joints));
        // The holds end at 2 s and 4 s: counted in steps, as the times are rounded.
        let half = (2.0 / DT).round() as usize;
        let late = (Self::LATE / DT).round() as usize;
        for _ in 0..4 {
            self.start = antenna.clone();
            (self.swing_past, self.late) = (0.0, 0.0);
            for step in 1..=(Self::DURATION / DT).round() as usize {
                let t = step as f32 * DT;
                antenna.step(Self::base(t), self.stiffness, self.damping, DT);
                self.swing_past = self.swing_past.max(Self::past(t, &antenna));
                if (step + late) % half <= late {
                    let side = (antenna.tip().x - antenna.positions[0].x).abs();
                    self.late = self.late.max(side);
                }
            }
        }
    }

    /// Stiffness k (1/s², [`Self::MIN_STIFFNESS`] to 600), damping c (1/s,
    /// [`Self::MIN_DAMPING`] to 60), joints (2 to [`Self::MAX_JOINTS`]).
    pub fn set(&mut self, stiffness: f32, damping: f32, joints: f32) -> Result<(), String> {
        let stiffness = in_range("stiffness", stiffness, Self::MIN_STIFFNESS, 600.0)?;
        let damping = in_range("damping", damping, Self::MIN_DAMPING, 60.0)?;
        let joints = in_range("joints", joints, 2.0, Self::MAX_JOINTS as f32)?;
        if joints.fract() != 0.0 {
            return Err(format!("joints must be a whole number, got {joints}"));
        }
        let joints = joints as usize;
        if (stiffness, damping, joints) != (self.stiffness, self.damping, self.joints) {
            (self.stiffness, self.damping, self.joints) = (stiffness, damping, joints);
            self.steps_done = None;
            self.settle();
        }
        Ok(())
    }

    pub fn set_use_exercise(&mut self, on: bool) {
        if on != self.use_exercise {
            self.use_exercise = on;
            self.steps_done = None;
        }
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.steps_done = None;
    }

    /// The base of the antenna (top of the body) at `time_sec`: eased moves with holds.
    pub fn base(time_sec: f32) -> Vec3 {
        let t = time_sec.rem_euclid(Self::DURATION);
        let ease = |s: f32| Ease::Smoothstep.apply(s);
        let x = match t {
            t if t < 1.0 => -1.5 + 3.0 * ease(t),
            t if t < 2.0 => 1.5,
            t if t < 3.0 => 1.5 - 3.0 * ease(t - 2.0),
            _ => -1.5,
        };
        Vec3::new(x, 0.8, 0.0)
    }

    /// The antenna the figure shows: the student's while it runs, else the reference.
    pub fn shown(&self) -> &Antenna {
        if self.use_exercise && self.problem.is_none() {
            &self.yours
        } else {
            &self.reference
        }
    }

    /// Simulates from the start of a loop (`start`) to `time_sec` in steps of [`DT`],
    /// continuing from the last call when time moved forward.
    fn simulate(&mut self, time_sec: f32) {
        let steps = (time_sec / DT).round() as usize;
        if self.steps_done.is_none_or(|done| done > steps) {
            self.reference = self.start.clone();
            self.yours = self.start.clone();
            self.problem = None;
            self.steps_done = Some(0);
        }
        let (k, c, runner) = (self.stiffness, self.damping, self.runner);
        for step in self.steps_done.unwrap_or(0) + 1..=steps {
            let base = Self::base(step as f32 * DT);
            self.reference.step(base, k, c, DT);
            if self.use_exercise && self.problem.is_none() {
                let student = |x, v, target, k, c, dt| {
                    let (x, v) = run::spring_step(runner, x, v, target, k, c, dt)
                        .map_err(|f| failure_note("exercise 2b.2 spring_step", FILE, &f))?;
                    if x.is_finite() && v.is_finite() {
                        Ok((x, v))
                    } else {
                        Err(format!(
                            "Your spring_step returned a non-finite value at t = {} s: x = {x}, \
                             v = {v}. The figure shows the reference.",
                            format_number(step as f32 * DT)
                        ))
                    }
                };
                if let Err(note) = self.yours.step_with(base, k, c, DT, student) {
                    self.problem = Some(note);
                }
            }
        }
        self.steps_done = Some(steps);
    }

    /// `(t, base x, tip x)` over one loop from `start`, metres.
    pub fn sample_tip(&mut self, samples: usize) -> Result<Vec<[f32; 3]>, String> {
        check_samples(samples)?;
        let mut antenna = self.start.clone();
        let total = (Self::DURATION / DT).round() as usize;
        let mut out = Vec::with_capacity(samples);
        let mut next = 0;
        for k in 0..=total {
            let t = k as f32 * DT;
            if k > 0 {
                antenna.step(Self::base(t), self.stiffness, self.damping, DT);
            }
            while next < samples
                && (next as f32 / (samples - 1) as f32) * Self::DURATION <= t + 1e-6
            {
                out.push([t, antenna.positions[0].x, antenna.tip().x]);
                next += 1;
            }
        }
        while out.len() < samples {
            out.push([Self::DURATION, antenna.positions[0].x, antenna.tip().x]);
        }
        Ok(out)
    }

    /// Draws the body and the antenna at `time_sec`; returns the note.
    pub fn draw(&mut self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let t = in_range("time", time_sec, 0.0, Self::DURATION)?;
        self.simulate(t);
        frame.grid(12, 0.5);
        // From the body's bottom to the antenna's top along the body's whole slide (its sides at
        // ±1.82 m), no wider: the camera fits this at every size and, at the page's sliders, does
        // not move as the antenna swings (its joints swing out to 1.98 m only at the sliders'
        // corners, where the tip's name pulls the fit). Seen from the front left and above
        // (lessons/02b-expressive-animation/lesson.js), it fills the canvas both ways.
        frame.keep_box_in_view(
            Vec3::new(-1.85, Self::base(0.0).y - 0.5, -0.25),
            Vec3::new(1.85, Self::base(0.0).y + Self::LENGTH, 0.25),
        );
        // From higher up the joints stack on one another and the sideways lag the figure is
        // about shrinks to nothing: the orbit stops at [`Self::MAX_PITCH_RAD`].
        frame.max_pitch_rad = Some(Self::MAX_PITCH_RAD);
        let antenna = self.shown();
        let base = antenna.positions[0];
        // A small body, so the antenna (the subject) is not dwarfed by it.
        let body = Mat4::from_translation(base - Vec3::Y * 0.25)
            * Mat4::from_scale(Vec3::new(0.32, 0.25, 0.25));
        frame.mesh(MeshId::CUBE, body, BODY);
        // The antenna as a curve and its joints as outlined dots, the same size at any distance.
        frame.wide_polyline(&antenna.positions, ANTENNA, crate::draw::CURVE_PX);
        for p in &antenna.positions[1..] {
            frame.marker(*p, crate::draw::DOT_PX, ANTENNA);
        }
        frame.marker(antenna.tip(), 16.0, palette::PINK);
        // Above the tip's dot by a gap on screen: anchored at the tip, inside the box above.
        frame.label_off_dot(antenna.tip(), 16.0, glam::Vec2::NEG_Y, "tip", palette::PINK, 0);
        let running_yours = self.use_exercise && self.problem.is_none();
        if running_yours {
            // The reference as a ghost beside the student's antenna.
            let reference = &self.reference.positions;
            frame.wide_polyline(reference, GHOST_REFERENCE, crate::draw::CURVE_PX);
            frame.label_off_dot(
                self.reference.tip(),
                0.0,
                glam::Vec2::NEG_Y,
                "reference",
                GHOST_REFERENCE,
                0,
            );
        }
        let critical = 2.0 * self.stiffness.sqrt();
        // What the chain does, from its simulated loop: each joint chases a moving target, so
        // the tip can stay behind while one joint alone would swing past, or the reverse.
        let chain = if self.swing_past >= 1e-3 {
            format!("swings up to {} m", format_number(self.swing_past))
        } else {
            "never gets 1 mm".into()
        };
        // The joints' wobbles pass up the chain, so the tip's outlasts one joint's.
        let late = if self.late < 0.01 {
            "it is within 1 cm of the base".into()
        } else {
            format!("it is still up to {} m to the side of the base", format_number(self.late))
        };
        let offset = antenna.tip().x - base.x;
        let mut note = format!(
            "Damping c = {} (critical: 2√k = {}): {}. After each stop the tip {chain} past the \
             base; in the last 0.25 s of each hold {late}. The tip is {} m {} of the base.",
            format_number(self.damping),
            format_number(critical),
            damping_regime(self.damping, self.stiffness),
            format_number(offset.abs()),
            if offset < 0.0 { "left" } else { "right" },
        );
        if self.use_exercise {
            note += " ";
            note += &self.exercise_note();
        }
        Ok(note)
    }

    /// What the student's `spring_step` (exercise 2b.2) did: why it stopped, or how far its
    /// antenna's tip is from the reference's after every joint was stepped by it since time 0.
    pub fn exercise_note(&self) -> String {
        if let Some(problem) = &self.problem {
            return problem.clone();
        }
        let time = format!(
            "the tip at t = {} s, every joint stepped by your code since t = 0",
            format_number(self.steps_done.unwrap_or(0) as f32 * DT)
        );
        let (ok, note) = compare_note(
            "spring_step",
            &time,
            &self.yours.tip().to_array(),
            &self.reference.tip().to_array(),
            TIP_TOLERANCE,
        );
        if !ok {
            return note;
        }
        // The tip can match while a term the figure barely uses is wrong: one step on inputs
        // chosen so that each term shows.
        let one_step = |x: Vec3, v: Vec3, target: Vec3, k: f32, c: f32, dt: f32| {
            let (yx, yv) = run::spring_step(self.runner, x, v, target, k, c, dt)?;
            let (rx, rv) = expressive::spring_step(x, v, target, k, c, dt);
            Ok(Probe {
                at: format!(
                    "one step from x = (0, 0, 0), v = ({}, 0, 0) to target (1, 0, 0) with k = {}, \
                     c = {}, dt = {}",
                    format_number(v.x),
                    format_number(k),
                    format_number(c),
                    format_number(dt)
                ),
                yours: [yx.to_array(), yv.to_array()].concat(),
                reference: [rx.to_array(), rv.to_array()].concat(),
            })
        };
        let steps: Result<Vec<Probe>, Failure> =
            [(0.0, 100.0, 0.0), (2.0, 100.0, 10.0), (2.0, 0.0, 10.0)]
                .into_iter()
                .map(|(v, k, c)| one_step(Vec3::ZERO, Vec3::X * v, Vec3::X, k, c, 0.1))
                .collect();
        match steps {
            Err(f) => failure_note("exercise 2b.2 spring_step", FILE, &f),
            Ok(steps) => {
                let shown = Probe {
                    at: time,
                    yours: Vec::new(),
                    reference: Vec::new(),
                };
                let probes: Vec<Probe> = std::iter::once(shown).chain(steps).collect();
                probe_note("spring_step", &probes, TOLERANCE).1
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The stretch figure: volume kept or not, side by side.

/// Colours of the stretch figure: the ball that keeps its volume, the one that does not, and
/// the direction of motion.
pub const KEPT: Vec3 = palette::ORANGE;
pub const GROWN: Vec3 = palette::GREY;
/// The right ball's surface: a pale grey, on which the dark dashed outline at rest shows (the
/// name keeps [`GROWN`], the caption's grey).
const GROWN_SURFACE: Vec3 = palette::GRID;
pub const DIRECTION: Vec3 = palette::BLUE;
/// Radius of the stretch figure's balls at rest, metres.
pub const STRETCH_RADIUS: f32 = 0.5;
/// Where the two balls of the stretch figure sit.
const KEPT_CENTRE: Vec3 = Vec3::new(-1.5, 1.3, 0.0);
const GROWN_CENTRE: Vec3 = Vec3::new(1.5, 1.3, 0.0);
/// The stretch figure's slider range for `s`.
pub const STRETCH_FIGURE_RANGE: (f32, f32) = (0.4, 2.5);

/// The stretch figure: two balls stretched by `s` along a direction `a` at an angle in the
/// picture's plane. Left, `R · diag(s, 1/√s, 1/√s) · Rᵀ` (the lesson's squash and stretch, volume
/// kept); right, `R · diag(s, 1, 1) · Rᵀ` (stretched along `a` only, the volume grows by `s`).
pub struct StretchComparison {
    stretch: f32,
    angle_deg: f32,
}

impl Default for StretchComparison {
    fn default() -> Self {
        Self::new()
    }
}

impl StretchComparison {
    /// `s` = 1.6 (the lesson's cap) along a direction 30° above the x axis.
    pub fn new() -> Self {
        Self {
            stretch: MAX_STRETCH,
            angle_deg: 30.0,
        }
    }

    /// Sets the stretch `s` (0.4 to 2.5) and the direction's angle from the x axis (−90° to 90°).
    /// Both are checked before either changes.
    pub fn set(&mut self, stretch: f32, angle_deg: f32) -> Result<(), String> {
        let (lo, hi) = STRETCH_FIGURE_RANGE;
        let stretch = in_range("stretch", stretch, lo, hi)?;
        let angle_deg = in_range("angle", angle_deg, -90.0, 90.0)?;
        self.stretch = stretch;
        self.angle_deg = angle_deg;
        Ok(())
    }

    /// The unit direction of motion `a`.
    pub fn axis(&self) -> Vec3 {
        let a = self.angle_deg.to_radians();
        Vec3::new(a.cos(), a.sin(), 0.0)
    }

    /// The left ball's linear map, the core's [`expressive::squash_stretch_matrix`].
    pub fn kept(&self) -> Mat3 {
        expressive::squash_stretch_matrix(self.axis(), self.stretch)
    }

    /// The right ball's linear map: `s` along `a`, nothing across.
    pub fn grown(&self) -> Mat3 {
        let r = Mat3::from_quat(glam::Quat::from_rotation_arc(Vec3::X, self.axis()));
        r * Mat3::from_diagonal(Vec3::new(self.stretch, 1.0, 1.0)) * r.transpose()
    }

    /// How much longer than wide the left ball is: `s / (1/√s) = s^1.5`.
    pub fn kept_aspect(&self) -> f32 {
        self.stretch.powf(1.5)
    }

    /// Draws both balls, their outlines at rest and the direction `a`; returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        frame.grid(12, 0.5);
        let a = self.axis();
        let across = Vec3::new(-a.y, a.x, 0.0);
        let (kept, grown) = (self.kept(), self.grown());
        for (centre, m, color, title) in [
            (KEPT_CENTRE, kept, KEPT, "volume kept"),
            (GROWN_CENTRE, grown, GROWN, "stretched only"),
        ] {
            let model = Mat4::from_translation(centre)
                * Mat4::from_mat3(m)
                * Mat4::from_scale(Vec3::splat(STRETCH_RADIUS));
            let surface = if color == GROWN { GROWN_SURFACE } else { color };
            frame.mesh(MeshId::SPHERE, model, surface);
            // The ball at rest, as a dashed outline in the picture's plane, over the ball.
            let circle: Vec<Vec3> = (0..=64)
                .map(|k| {
                    let phi = k as f32 / 64.0 * std::f32::consts::TAU;
                    centre + Vec3::new(phi.cos(), phi.sin(), 0.0) * STRETCH_RADIUS
                })
                .collect();
            let mut rest = crate::draw::StrokeStyle::dashed(2.0, 0.07, 0.05);
            rest.on_top = true;
            frame.stroke(&circle, palette::DARK, rest);
            // The name 0.3 m under the ball's lowest point (its half-height is the length of the
            // map's second row times the radius), at any stretch and direction.
            let below = STRETCH_RADIUS * m.row(1).length() + 0.3;
            frame.label_off_dot(
                centre - Vec3::Y * below,
                0.0,
                glam::Vec2::Y,
                title,
                color,
                0,
            );
            // Longer than the ball at every stretch, so both ends show.
            let reach = STRETCH_RADIUS * self.stretch.max(1.0) + 0.35;
            frame.arrow(centre - a * reach, centre + a * reach, DIRECTION, 0.12);
            // The half-widths across the motion, along and across.
            let half_across = (m * across).length() * STRETCH_RADIUS;
            frame.wide_line_on_top(
                centre,
                centre + across * half_across,
                palette::DARK,
                crate::draw::CURVE_PX,
            );
        }
        // The name just past the left arrow's head, along it, placed after the balls' names
        // (which keep their places under the balls where it points down towards them); the
        // figure is a picture in the x-y plane, so a drag pans it instead of turning the balls
        // and circles edge-on.
        let tip = KEPT_CENTRE + a * (STRETCH_RADIUS * self.stretch.max(1.0) + 0.35);
        frame.label_off_dot(tip, 0.0, glam::Vec2::new(a.x, -a.y), "a", DIRECTION, 0);
        frame.flat = true;
        frame.keep_box_in_view(Vec3::new(-3.2, -0.35, -0.3), Vec3::new(3.2, 2.95, 0.3));
        let across_kept = 1.0 / self.stretch.sqrt();
        format!(
            "s = {} along a. Left: scale (s, 1/√s, 1/√s) = ({}, {}, {}), volume × {}, {} times as \
             long as wide. Right: scale (s, 1, 1), volume × {}, {} times as long as wide.",
            format_number(self.stretch),
            format_number(self.stretch),
            format_number(across_kept),
            format_number(across_kept),
            format_number(kept.determinant()),
            format_number(self.kept_aspect()),
            format_number(grown.determinant()),
            format_number(self.stretch),
        )
    }
}
