//! The figures of lesson 14, rigid bodies: the tennis racket, the throw, the impulse at a contact,
//! the stack and the dominoes, the quaternion drift.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec3;
use inbetween::draw::{palette, Frame, MeshId};
use inbetween::figures::rigid_body::{
    DriftFigure, ImpulseFigure, RacketFigure, StackFigure, StackPreset, ThrowFigure, DOMINOES,
    DOMINO_HALF, DRIFT_DRAWN_MAX_NORM, DRIFT_STEPS, FALLEN_DEG, INTEGRATORS, RACKET_PLOT_TOP,
    THROW_START, THROW_VELOCITY,
};

#[test]
fn the_figure_draws_three_rackets_with_their_momentum_and_names() {
    let f = RacketFigure::new();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame);
    let cubes = frame
        .meshes
        .iter()
        .filter(|m| m.mesh == MeshId::CUBE)
        .count();
    assert_eq!(cubes, 3);
    for (_, name) in INTEGRATORS {
        assert!(frame.labels.iter().any(|l| l.text == name), "{name}");
        assert!(
            note.contains(&format!("{name}: energy 100 %, |L| 100.0 %")),
            "{note}"
        );
    }
    assert!(frame.segments_of(palette::Y_AXIS).count() >= 3);
    assert!(!frame.keep_in_view.is_empty());
    // Each racket's L is a dark arrow drawn over everything: it starts at the racket's centre,
    // inside the box, and after a racket loses |L| it ends inside the box too.
    let dark: Vec<_> = frame
        .strokes
        .iter()
        .filter(|s| Vec3::from_slice(&s.color[..3]) == palette::DARK)
        .collect();
    for k in 0..3 {
        let at = RacketFigure::place(k);
        let from_centre = dark.iter().filter(|s| Vec3::from(s.a) == at).count();
        assert_eq!(from_centre, 1, "racket {k}");
    }
    assert!(dark.iter().all(|s| s.depth_bias == inbetween::draw::ON_TOP));
}

#[test]
fn over_ten_seconds_each_integrator_shows_its_character() {
    let mut f = RacketFigure::new();
    let start_axis = Vec3::Y;
    let mut lowest = [1.0f32; 3];
    for k in 1..=600 {
        f.advance_to(k as f32 / 60.0).unwrap();
        for (i, b) in f.bodies().iter().enumerate() {
            lowest[i] = lowest[i].min((b.orientation * Vec3::Y).dot(start_axis));
        }
    }
    let last = *f.samples().last().unwrap();
    assert_eq!(
        f.samples().len(),
        601,
        "one sample per step, the start included"
    );
    // L held: |L| kept to float rounding, the energy within 0.1 % all along (the splitting's
    // bounded error); the racket turns over.
    assert!((last[4] - 1.0).abs() < 1e-4, "{last:?}");
    let held_error = f
        .samples()
        .iter()
        .map(|r| (r[1] - 1.0).abs())
        .fold(0.0, f32::max);
    assert!(held_error < 1e-3, "held-L energy off by {held_error}");
    assert!(lowest[0] < -0.9, "the held-L racket flips: {lowest:?}");
    // Explicit: the energy grows; implicit: it never grows and falls.
    let explicit_most = f.samples().iter().map(|r| r[2]).fold(0.0, f32::max);
    let implicit_most = f.samples().iter().map(|r| r[3]).fold(0.0, f32::max);
    assert!(
        explicit_most > 1.2,
        "explicit energy at most {explicit_most}"
    );
    assert!(
        implicit_most <= 1.0 + 1e-5 && last[3] < 0.99,
        "implicit: {implicit_most}, {}",
        last[3]
    );
}

#[test]
fn the_run_starts_again_when_time_goes_back_or_the_spin_changes() {
    let mut f = RacketFigure::new();
    f.advance_to(2.0).unwrap();
    let at_two = f.bodies()[0];
    f.advance_to(1.0).unwrap();
    f.advance_to(2.0).unwrap();
    assert_eq!(f.bodies()[0], at_two, "the replay is the same run");
    assert!(f.set_spin(f32::NAN, 0.1).is_err());
    assert!(f.set_spin(6.0, 2.0).unwrap_err().contains("wobble"));
    assert_eq!(f.bodies()[0], at_two, "a rejected setting changes nothing");
    f.set_spin(10.0, 0.0).unwrap();
    assert_eq!(f.samples().len(), 1);
    assert!(f.advance_to(61.0).is_err());
    // Without a wobble the spin about the middle axis stays (an unstable balance, held exactly).
    f.advance_to(5.0).unwrap();
    assert!((f.bodies()[0].orientation * Vec3::Y).dot(Vec3::Y) > 0.999);
}

/// The notes of the throw, the rackets and the stack name the time as the page's clock shows it
/// (`time.toFixed(2)`), not the time of the last whole step, up to 1/60 s earlier: at 0.1653 s
/// the clock reads 0.17 s while the last step is at 0.15 s.
#[test]
fn the_notes_name_the_time_the_timeline_shows() {
    let mut throw = ThrowFigure::new();
    let mut racket = RacketFigure::new();
    let mut stack = StackFigure::new(StackPreset::Stack);
    // Times through the throw, each at least 0.03 ms off the rounding boundaries of two decimals.
    for k in 0..300 {
        let t = 0.0037 * k as f64 + 0.00013;
        let clock = format!("t = {t:.2} s");
        throw.advance_to(t as f32).unwrap();
        racket.advance_to(t as f32).unwrap();
        stack.advance_to(t as f32).unwrap();
        for note in [
            throw.draw(&mut Frame::default()),
            racket.draw(&mut Frame::default()),
            stack.draw(&mut Frame::default()),
        ] {
            assert!(note.contains(&clock), "at {t} s: {note}");
        }
    }
    // A change of setting starts the run again, at t = 0.
    racket.set_spin(8.0, 0.05).unwrap();
    assert!(racket.draw(&mut Frame::default()).contains("t = 0.00 s"));
}

// ---- Figure 1: a box thrown with spin ----

/// The throw at `spin` and `tilt`, flown to the end, checked at every step.
fn fly(spin: f32, tilt: f32, mut check: impl FnMut(&ThrowFigure)) -> ThrowFigure {
    let mut f = ThrowFigure::new();
    f.set_throw(spin, tilt).unwrap();
    let steps = (f.duration_sec() * 60.0).floor() as usize;
    for k in 0..=steps {
        f.advance_to(k as f32 / 60.0).unwrap();
        check(&f);
    }
    assert_eq!(f.samples().len(), steps + 1, "one sample per step");
    f
}

#[test]
fn the_thrown_box_keeps_its_angular_momentum_to_float_precision() {
    for spin in [5.0, 15.0] {
        for tilt in [0.0, 20.0, 45.0, 80.0] {
            let mut l0 = None;
            let f = fly(spin, tilt, |f| {
                let l = f.body().angular_momentum();
                let l0 = *l0.get_or_insert(l);
                // Direction and size: L is one fixed vector in the world.
                assert!(
                    (l - l0).length() < 2e-6 * l0.length(),
                    "spin {spin}, tilt {tilt}: L went from {l0} to {l}"
                );
            });
            let l = f.samples().iter().map(|r| r[2]);
            let (lo, hi) = (l.clone().fold(f32::MAX, f32::min), l.fold(0.0, f32::max));
            assert!(hi - lo <= 2e-6 * hi, "|L| from {lo} to {hi}");
        }
    }
}

#[test]
fn omega_wobbles_around_l_unless_the_box_spins_about_a_principal_axis() {
    let most_turn = |tilt: f32| {
        let f = fly(10.0, tilt, |_| {});
        let w0 = f.omegas()[0];
        f.omegas()
            .iter()
            .map(|w| w.angle_between(w0).to_degrees())
            .fold(0.0, f32::max)
    };
    // About the shortest axis (a principal axis) ω stays along L.
    assert!(most_turn(0.0) < 0.1, "{}", most_turn(0.0));
    for (tilt, at_least) in [(10.0, 10.0), (20.0, 25.0), (40.0, 45.0)] {
        let turned = most_turn(tilt);
        assert!(turned > at_least, "tilt {tilt}: ω turned {turned}°");
    }
    // The angle between ω and L comes and goes, and at tilt 0 it is 0.
    let f = fly(10.0, 20.0, |_| {});
    let angles: Vec<f32> = f.samples().iter().map(|r| r[3]).collect();
    let (lo, hi) = (
        angles.iter().copied().fold(f32::MAX, f32::min),
        angles.iter().copied().fold(0.0, f32::max),
    );
    assert!(lo < 5.0 && hi > 12.0, "ω–L angle from {lo}° to {hi}°");
    assert!(fly(10.0, 0.0, |_| {}).samples().iter().all(|r| r[3] < 0.05));
}

#[test]
fn omegas_tip_stays_on_the_plane_across_l_and_the_energy_holds_to_3_percent() {
    // Torque-free motion keeps E = ½ ω · L, so ω · L̂ = 2E / |L| is constant: ω's tip moves on
    // a plane across L (the invariable plane). The first-order step keeps it to a few per cent.
    for tilt in [20.0, 60.0] {
        let f = fly(15.0, tilt, |_| {});
        let e0 = f.samples()[0][4];
        let l = f.body().angular_momentum().normalize();
        let along0 = f.omegas()[0].dot(l);
        for (row, w) in f.samples().iter().zip(f.omegas()) {
            assert!((row[4] / e0 - 1.0).abs() < 0.03, "tilt {tilt}: {row:?}");
            assert!((w.dot(l) / along0 - 1.0).abs() < 0.03, "tilt {tilt}: {w}");
        }
    }
}

#[test]
fn the_centre_of_mass_flies_the_parabola_and_lands_at_its_start_height() {
    let f = fly(12.0, 30.0, |f| {
        let t = f.samples().last().unwrap()[0];
        let at = f.body().position;
        assert!(
            (at - ThrowFigure::parabola(t)).length() < 5e-4,
            "at t = {t}: {at}, parabola {}",
            ThrowFigure::parabola(t)
        );
    });
    // The parabola's closed form: x₀ + v₀ t + ½ g t², back at the start height at 2 v₀ᵧ / g.
    let t = f.duration_sec();
    assert!((t - 2.0 * THROW_VELOCITY.y / 9.81).abs() < 1e-6);
    assert!((ThrowFigure::parabola(t).y - THROW_START.y).abs() < 1e-4);
    let apex = ThrowFigure::parabola(0.5 * t);
    assert!((apex.y - THROW_START.y - THROW_VELOCITY.y.powi(2) / (2.0 * 9.81)).abs() < 1e-4);
    // Past the flight the box holds where it ended.
    let mut g = f.clone();
    g.advance_to(30.0).unwrap();
    assert_eq!(g.body(), f.body());
}

#[test]
fn the_throw_refuses_bad_settings_and_replays_the_same_run() {
    let mut f = ThrowFigure::new();
    f.advance_to(1.0).unwrap();
    let at_one = *f.body();
    for (spin, tilt, name) in [
        (-1.0, 20.0, "spin"),
        (15.5, 20.0, "spin"),
        (f32::NAN, 20.0, "spin"),
        (10.0, 81.0, "tilt"),
        (10.0, -0.5, "tilt"),
        (10.0, f32::INFINITY, "tilt"),
    ] {
        let err = f.set_throw(spin, tilt).unwrap_err();
        assert!(err.contains(name), "{err}");
    }
    assert!(f.advance_to(-0.1).is_err() && f.advance_to(f32::NAN).is_err());
    assert!(f.advance_to(61.0).is_err());
    assert_eq!(*f.body(), at_one, "a rejected call changes nothing");
    f.advance_to(0.5).unwrap();
    f.advance_to(1.0).unwrap();
    assert_eq!(*f.body(), at_one, "the replay is the same run");
    f.set_throw(10.0, 20.0).unwrap();
    assert_eq!(f.samples().len(), 1, "a new setting starts again");
}

#[test]
fn the_throw_draws_the_box_l_omega_and_the_trail_and_says_l_stays_fixed() {
    let mut f = ThrowFigure::new();
    f.advance_to(0.8).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame);
    assert_eq!(
        frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::CUBE)
            .count(),
        1
    );
    // Two arrows (their heads are cones), labelled.
    assert_eq!(
        frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::CONE)
            .count(),
        2
    );
    for name in ["L (angular momentum)", "ω (angular velocity)"] {
        assert!(frame.labels.iter().any(|l| l.text == name), "{name}");
    }
    assert!(frame.segments_of(palette::PURPLE).count() >= 1);
    // The trail: one segment per step flown.
    assert!(frame.strokes.len() >= 48, "{}", frame.strokes.len());
    assert!(!frame.keep_in_view.is_empty());
    assert!(
        note.contains("L stays fixed") && note.contains("|L| = "),
        "{note}"
    );
    // No spin: no arrows, and the note says why.
    f.set_throw(0.0, 30.0).unwrap();
    f.advance_to(0.5).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame);
    assert!(note.contains("No spin"), "{note}");
    assert!(frame.labels.is_empty());
}

// ---- Figure 3: an impulse at a contact ----

fn dropped(tilt: f32, e: f32, height: f32) -> ImpulseFigure {
    let mut f = ImpulseFigure::new();
    f.set_drop(tilt, e, height).unwrap();
    f.advance_to(f.duration_sec()).unwrap();
    f
}

/// Figure 4 from the hit on, on the 760 x 420 canvas of an 800 x 600 page, at the page's camera
/// fitted to what the frame keeps in view: near the ground the box spans at least 120 px on
/// screen (framed with the whole fall it spans 70 to 105 px, under the empty height it fell
/// from), and every line, the arrows' included, ends on the canvas.
#[test]
fn after_the_hit_the_drop_frames_the_box_and_its_arrows() {
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::figures::rigid_body::DROP_HALF;
    use inbetween::rigid_body::contact::corners;
    let size = Vec2::new(760.0, 420.0);
    for (tilt, e, height) in [(20.0, 0.5, 1.0), (30.0, 0.2, 1.6), (45.0, 1.0, 2.0), (0.0, 0.5, 2.0)] {
        let mut f = dropped(tilt, e, height);
        let hit = f.impact_details().copied().expect("a hit");
        for t in [hit.time_sec + 0.02, hit.time_sec + 0.16, f.duration_sec()] {
            f.advance_to(t).unwrap();
            let mut frame = Frame::default();
            f.draw(&mut frame);
            let mut camera = OrbitCamera::from_view([0.0, 1.0, 0.0, 4.0, 0.5, 0.3]);
            camera.fit(&frame.fit_points(), size, FIT_PAD_PX);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let on_screen = |p: Vec3| project_to_canvas(view_proj, size, p);
            let c: Vec<Vec2> = corners(f.body(), DROP_HALF).iter().map(|&c| on_screen(c).unwrap()).collect();
            let lo = c.iter().fold(Vec2::MAX, |a, &b| a.min(b));
            let hi = c.iter().fold(Vec2::MIN, |a, &b| a.max(b));
            let span = (hi - lo).max_element();
            let at = format!("tilt {tilt}, e {e}, {height} m, t {t:.2} s");
            if f.body().position.y < 0.6 {
                assert!(span >= 120.0, "{at}: the box spans {span} px");
            }
            for s in frame.strokes.iter() {
                let head = on_screen(Vec3::from(s.b)).expect("in front of the camera");
                assert!(head.cmpge(Vec2::ZERO).all() && head.cmple(size).all(), "{at}: a stroke ends at {head}");
            }
        }
    }
}

#[test]
fn the_impulse_turns_the_contact_points_normal_velocity_into_minus_e_times_itself() {
    for tilt in [0.0, 10.0, 30.0, 45.0] {
        for e in [0.0, 0.3, 0.5, 1.0] {
            let f = dropped(tilt, e, 1.0);
            let hit = *f.impact_details().expect("the box lands");
            assert!(hit.normal_before < -4.0, "{hit:?}");
            assert!(
                (hit.normal_after + e * hit.normal_before).abs() < 1e-4 * -hit.normal_before,
                "tilt {tilt}, e {e}: {} → {}",
                hit.normal_before,
                hit.normal_after
            );
            assert_eq!(f.impact(), Some((hit.time_sec, hit.j)));
            // Energy: kept at e = 1, lost below.
            if e == 1.0 {
                assert!(
                    (hit.energy_after - hit.energy_before).abs() < 1e-5 * hit.energy_before,
                    "{hit:?}"
                );
            } else {
                assert!(hit.energy_after < hit.energy_before, "{hit:?}");
            }
        }
    }
}

#[test]
fn the_box_meets_the_ground_after_the_free_fall_time_at_the_free_fall_speed() {
    for h in [0.2, 1.0, 2.0] {
        let hit = *dropped(20.0, 0.5, h).impact_details().unwrap();
        let (t, v): (f32, f32) = ((2.0 * h / 9.81).sqrt(), (2.0 * 9.81 * h).sqrt());
        assert!(
            (hit.time_sec - t).abs() < 1e-3,
            "h {h}: {} s, √(2h/g) = {t}",
            hit.time_sec
        );
        assert!(
            (hit.normal_before + v).abs() < 5e-3 * v,
            "h {h}: {}",
            hit.normal_before
        );
        // The contact point is on the ground, and it is the lowest corner.
        assert!(hit.point.y.abs() < 1e-4, "{}", hit.point);
    }
}

#[test]
fn a_level_drop_gets_no_spin_and_a_tilted_one_does_by_the_inverse_inertia_of_r_cross_j() {
    for e in [0.0, 0.5, 1.0] {
        // Level: four corners land together, the impulse acts under the centre of mass, and the
        // box bounces as a particle would, j = (1 + e) m |v|.
        let hit = *dropped(0.0, e, 1.0).impact_details().unwrap();
        assert!(hit.omega_after.length() < 1e-4, "{}", hit.omega_after);
        let v = -hit.velocity_before.y;
        assert!(
            (hit.j - (1.0 + e) * v).abs() < 1e-4 * v,
            "{} vs {}",
            hit.j,
            (1.0 + e) * v
        );
        assert!((hit.point - (hit.centre - 0.1 * Vec3::Y)).length() < 1e-4);
    }
    for tilt in [1.0, 10.0, 45.0] {
        let f = dropped(tilt, 0.5, 1.0);
        let hit = *f.impact_details().unwrap();
        assert!(
            hit.omega_after.length() > 1.0,
            "tilt {tilt}: {}",
            hit.omega_after
        );
        // Δω = I⁻¹ (r × j n), Δv = j n / m, from rest.
        let mut then = *f.body();
        then.orientation = hit.orientation;
        let r = hit.point - hit.centre;
        let expected = then.world_inverse_inertia() * r.cross(hit.j * Vec3::Y);
        assert!((hit.omega_after - expected).length() < 1e-4 * expected.length());
        let dv = hit.velocity_after - hit.velocity_before;
        assert!((dv - hit.j * Vec3::Y).length() < 1e-5);
    }
}

#[test]
fn the_frictionless_box_never_moves_sideways_and_comes_to_rest_on_a_face() {
    for (tilt, e) in [(20.0, 0.5), (45.0, 0.0), (5.0, 0.3)] {
        let mut f = ImpulseFigure::new();
        f.set_drop(tilt, e, 1.0).unwrap();
        for k in 0..=120 {
            f.advance_to(k as f32 / 60.0).unwrap();
            let p = f.body().position;
            assert!(
                p.x.abs() < 1e-5 && p.z.abs() < 1e-5,
                "t = {}: {p}",
                k as f32 / 60.0
            );
        }
        assert!(f.stopped().is_none());
        let last = *f.samples().last().unwrap();
        assert!((last[1] - 0.1).abs() < 2e-3 && last[3] < 1e-2, "{last:?}");
        assert_eq!(
            f.samples().len(),
            121 + 2,
            "a row per step and two at the hit"
        );
    }
}

#[test]
fn the_drop_refuses_bad_settings_and_replays_the_same_run() {
    let mut f = ImpulseFigure::new();
    f.advance_to(1.0).unwrap();
    let at_one = *f.body();
    for (tilt, e, h, name) in [
        (-1.0, 0.5, 1.0, "tilt"),
        (46.0, 0.5, 1.0, "tilt"),
        (10.0, 1.1, 1.0, "restitution"),
        (10.0, f32::NAN, 1.0, "restitution"),
        (10.0, 0.5, 0.1, "height"),
        (10.0, 0.5, 2.5, "height"),
    ] {
        let err = f.set_drop(tilt, e, h).unwrap_err();
        assert!(err.contains(name), "{err}");
    }
    assert!(f.advance_to(-1.0).is_err() && f.advance_to(61.0).is_err());
    assert_eq!(*f.body(), at_one, "a rejected call changes nothing");
    f.advance_to(0.2).unwrap();
    assert!(f.impact().is_none(), "scrubbing back forgets the impact");
    f.advance_to(1.0).unwrap();
    assert_eq!(*f.body(), at_one, "the replay is the same run");
}

#[test]
fn the_drop_draws_the_impulse_and_the_velocities_before_and_after() {
    let mut f = ImpulseFigure::new();
    f.advance_to(0.2).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame);
    assert!(note.starts_with("Falling"), "{note}");
    assert!(!frame.markers.is_empty(), "the lowest corner is marked");
    f.advance_to(0.6).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame);
    for name in ["j n", "v before", "v after", "ω after"] {
        assert!(frame.labels.iter().any(|l| l.text == name), "{name}");
    }
    // Dropped without spin: no ω before to draw.
    assert!(!frame.labels.iter().any(|l| l.text == "ω before"));
    // The names read: "v before" in the full blue (its arrow is faded), and ω after, whose
    // arrow points to −x, reads leftwards from its head instead of back over it.
    let label = |name: &str| frame.labels.iter().find(|l| l.text == name).unwrap();
    assert_eq!(label("v before").color, palette::BLUE);
    let omega = f.impact_details().unwrap().omega_after;
    assert!(omega.x < 0.0, "{omega}");
    assert!(
        label("ω after").left,
        "ω after reads back over its arrow's head"
    );
    assert!(!label("v after").left);
    let hit = *f.impact_details().unwrap();
    assert!(
        frame
            .markers
            .iter()
            .any(|m| Vec3::from(m.center) == hit.point),
        "the contact point is a dot"
    );
    assert!(frame.segments_of(palette::RED).count() >= 1, "the impulse");
    // The impulse's arrow comes up to the contact point from below (outside the box), at least
    // 30 cm long: the 1.41 N s of a corner hit drawn as its 14 cm velocity change was a stub
    // under the contact's dot.
    assert!(
        frame
            .segments_of(palette::RED)
            .all(|(a, b)| a.y <= hit.point.y + 1e-4 && b.y <= hit.point.y + 1e-4),
        "the impulse ends at the contact"
    );
    let lowest = frame
        .segments_of(palette::RED)
        .map(|(a, b)| a.y.min(b.y))
        .fold(f32::MAX, f32::min);
    assert!(hit.j < 2.0, "a corner hit's small impulse: {}", hit.j);
    assert!(hit.point.y - lowest >= 0.3 - 1e-4, "the impulse's arrow is {} m", hit.point.y - lowest);
    // v before arrives at the centre of mass at the hit and v after leaves it: both point
    // straight down, so from one point they would lie one over the other; end to end, before
    // is above the centre and after below it.
    let y = hit.centre.y;
    let faded = palette::BLUE.lerp(Vec3::ONE, 0.55);
    assert!(frame.segments_of(faded).count() >= 1 && frame.segments_of(palette::BLUE).count() >= 1);
    assert!(
        frame.segments_of(faded).all(|(a, b)| a.y >= y - 1e-4 && b.y >= y - 1e-4),
        "v before ends at the centre"
    );
    assert!(
        frame.segments_of(palette::BLUE).all(|(a, b)| a.y <= y + 1e-4 && b.y <= y + 1e-4),
        "v after starts at the centre"
    );
    assert!(
        note.contains("−e times it") && note.contains("j = "),
        "{note}"
    );
}

// ---- Figure 4: a stack and a row of dominoes ----

/// The stack or the dominoes at `passes`, run to the end; the top box's largest travel (m).
fn settle(preset: StackPreset, passes: f32) -> (StackFigure, f32) {
    let mut f = StackFigure::new(preset);
    f.set_solver(passes, 0.5, 0.0).unwrap();
    f.advance_to(f.duration_sec()).unwrap();
    let most = f.samples().iter().map(|r| r[2]).fold(0.0, f32::max);
    (f, most)
}

#[test]
fn the_stack_stands_for_ten_seconds_at_twenty_passes() {
    let (f, most) = settle(StackPreset::Stack, 20.0);
    assert_eq!(f.samples().len(), 601, "one row per step");
    assert!(most < 0.015, "the top box moved {most} m");
    for k in 0..3 {
        assert!(f.tilt_deg(k) < 1.0, "box {k} tilted {}°", f.tilt_deg(k));
    }
    assert!(f.samples().last().unwrap()[1] < 1e-4, "still moving");
    assert!(f.exploded().is_none());
}

#[test]
fn the_fewer_the_passes_the_more_the_stack_creeps() {
    // The page: in 10 s the top box creeps about half a metre at 1 pass, a quarter at 2, 4 cm
    // at 10, 1 cm at 20 and a few millimetres at 50.
    let creep: Vec<f32> = [1.0, 2.0, 10.0, 20.0, 50.0]
        .into_iter()
        .map(|n| settle(StackPreset::Stack, n).1)
        .collect();
    assert!(creep.windows(2).all(|w| w[0] > w[1]), "{creep:?}");
    assert!((0.4..0.7).contains(&creep[0]), "1 pass: {creep:?}");
    assert!((0.2..0.35).contains(&creep[1]), "2 passes: {creep:?}");
    assert!((0.03..0.05).contains(&creep[2]), "10 passes: {creep:?}");
    assert!(creep[4] < 0.005, "50 passes: {creep:?}");
}

#[test]
fn a_resting_stack_keeps_a_little_kinetic_energy_the_fewer_the_passes_the_more() {
    // The page plots the total kinetic energy on a log axis: at rest the stack keeps what the
    // passes leave unresolved each step, about 2.5 µJ at 20 passes, about 1 mJ at 2 and under
    // 1 µJ at 50 (from 1 s on, once the start has settled); a push gives joules. Every sample
    // but the first (the still start, a gap on the log axis) is positive.
    let energies = |passes: f32| -> Vec<f32> {
        let (f, _) = settle(StackPreset::Stack, passes);
        assert_eq!(f.samples()[0][1], 0.0);
        assert!(f.samples()[1..].iter().all(|r| r[1] > 0.0), "{passes} passes");
        f.samples().iter().filter(|r| r[0] >= 1.0).map(|r| r[1]).collect()
    };
    let median = |mut e: Vec<f32>| {
        e.sort_by(f32::total_cmp);
        e[e.len() / 2]
    };
    let m: Vec<f32> = [2.0, 10.0, 20.0, 50.0].map(|n| median(energies(n))).to_vec();
    assert!(m.windows(2).all(|w| w[0] > w[1]), "{m:?}");
    assert!((0.7e-3..1.5e-3).contains(&m[0]), "2 passes: {m:?}");
    assert!((2.0e-6..3.0e-6).contains(&m[2]), "20 passes: {m:?}");
    let most_at_50 = energies(50.0).into_iter().fold(0.0, f32::max);
    assert!(most_at_50 < 1e-6, "50 passes: {most_at_50}");
    let mut pushed = StackFigure::new(StackPreset::Stack);
    pushed.advance_to(2.0).unwrap();
    pushed.push().unwrap();
    pushed.advance_to(pushed.duration_sec()).unwrap();
    let peak = pushed.samples().iter().map(|r| r[1]).fold(0.0, f32::max);
    assert!((1.0..10.0).contains(&peak), "{peak}");
    let end = pushed.samples().last().unwrap()[1];
    assert!(end < 1e-6, "at rest again: {end}");
}

#[test]
fn every_domino_falls_in_turn_within_the_run() {
    let mut f = StackFigure::new(StackPreset::Dominoes);
    let mut fell_at = [None; DOMINOES];
    let steps = (f.duration_sec() * 60.0) as usize;
    for s in 0..=steps {
        f.advance_to(s as f32 / 60.0).unwrap();
        for (k, at) in fell_at.iter_mut().enumerate() {
            if at.is_none() && f.tilt_deg(k) > FALLEN_DEG {
                *at = Some(s);
            }
        }
    }
    let fell: Vec<usize> = fell_at
        .iter()
        .map(|s| s.expect("every domino falls"))
        .collect();
    assert!(fell.windows(2).all(|w| w[0] < w[1]), "in turn: {fell:?}");
    assert!(fell[DOMINOES - 1] < 2 * 60, "all down within 2 s: {fell:?}");
    assert_eq!(f.fallen(), DOMINOES);
    assert!(
        f.samples().last().unwrap()[2] > DOMINO_HALF.y,
        "the last one moved"
    );
    // Even one pass topples them all: a falling domino only needs its push passed on.
    let (f, _) = settle(StackPreset::Dominoes, 1.0);
    assert_eq!(f.fallen(), DOMINOES);
}

#[test]
fn a_push_is_replayed_and_reset_forgets_it() {
    let mut f = StackFigure::new(StackPreset::Stack);
    f.advance_to(1.0).unwrap();
    f.push().unwrap();
    f.advance_to(4.0).unwrap();
    let pushed = f.bodies()[2].0;
    // The shove slides the top box off the stack.
    assert!(f.samples().last().unwrap()[2] > 0.3, "{pushed:?}");
    f.advance_to(0.5).unwrap();
    f.advance_to(4.0).unwrap();
    assert_eq!(
        f.bodies()[2].0,
        pushed,
        "the replay pushes at the same frame"
    );
    f.reset();
    f.advance_to(4.0).unwrap();
    assert!(f.samples().last().unwrap()[2] < 0.01);
    // The dominoes' push reaches the first domino.
    let mut d = StackFigure::new(StackPreset::Dominoes);
    let before = d.bodies()[0].0.velocity;
    d.push().unwrap();
    assert!(d.bodies()[0].0.velocity.x > before.x + 0.2);
}

#[test]
fn the_note_names_a_push_once_it_shows() {
    // The note's state and plots are those recorded before a push's step: at a push's own time
    // (or earlier, replayed) the note says it comes; from the next step on, that it happened.
    let mut d = StackFigure::new(StackPreset::Dominoes);
    d.advance_to(0.5).unwrap();
    d.push().unwrap();
    let note = |d: &mut StackFigure, t: f32| {
        d.advance_to(t).unwrap();
        d.draw(&mut Frame::default())
    };
    for t in [0.0, 0.5] {
        let n = note(&mut d, t);
        assert!(!n.contains("Pushed") && n.contains("A push comes at t = 0.50 s."), "{n}");
    }
    let n = note(&mut d, 0.6);
    assert!(n.contains("Pushed once.") && !n.contains("A push comes"), "{n}");
}

#[test]
fn the_solver_settings_are_checked_before_any_is_changed() {
    let mut f = StackFigure::new(StackPreset::Stack);
    f.advance_to(1.0).unwrap();
    let at_one = f.bodies()[2].0;
    for (passes, mu, e, name) in [
        (2.5, 0.5, 0.0, "iterations"),
        (0.0, 0.5, 0.0, "iterations"),
        (51.0, 0.5, 0.0, "iterations"),
        (f32::NAN, 0.5, 0.0, "iterations"),
        (20.0, 1.5, 0.0, "friction"),
        (20.0, -0.1, 0.0, "friction"),
        (20.0, 0.5, 1.01, "restitution"),
        (20.0, 0.5, f32::INFINITY, "restitution"),
    ] {
        let err = f.set_solver(passes, mu, e).unwrap_err();
        assert!(err.contains(name), "{err}");
    }
    assert!(f.advance_to(-1.0).is_err() && f.advance_to(61.0).is_err());
    assert_eq!(f.bodies()[2].0, at_one, "a rejected call changes nothing");
    f.set_solver(50.0, 0.0, 1.0).unwrap();
    assert_eq!(f.samples().len(), 1, "a new setting starts again");
}

#[test]
fn the_stack_draws_its_boxes_and_contact_points() {
    // Dominoes bouncing with e = 1: several contacts of a body restored at once add energy.
    let mut f = StackFigure::new(StackPreset::Dominoes);
    f.set_solver(20.0, 0.5, 1.0).unwrap();
    f.advance_to(f.duration_sec()).unwrap();
    assert!(f.exploded().is_some_and(|t| t < 2.0), "{:?}", f.exploded());
    for preset in [StackPreset::Stack, StackPreset::Dominoes] {
        let mut f = StackFigure::new(preset);
        f.advance_to(0.5).unwrap();
        let mut frame = Frame::default();
        let note = f.draw(&mut frame);
        let cubes = frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::CUBE)
            .count();
        assert_eq!(cubes, f.bodies().len());
        assert!(!f.contact_points().is_empty());
        let dots = frame
            .markers
            .iter()
            .filter(|m| m.color == palette::RED.extend(1.0).to_array())
            .count();
        assert_eq!(dots, f.contact_points().len());
        assert!(note.contains("20 solver passes per step"), "{note}");
        assert!(f.exploded().is_none() && !note.contains("failed"));
    }
}

// ---- Figure 5: quaternion drift ----

#[test]
fn each_additive_step_multiplies_q_by_the_closed_form_and_normalising_keeps_it_1() {
    for (spin, ms) in [(5.0, 20.0), (10.0, 20.0), (30.0, 50.0), (3.0, 17.0)] {
        let mut f = DriftFigure::new();
        f.set_drift(spin, ms).unwrap();
        f.advance_to(2.0).unwrap();
        let dt: f32 = ms / 1000.0;
        let growth = (1.0 + (0.5 * spin * dt).powi(2)).sqrt();
        assert!((f.growth_per_step() - growth).abs() < 1e-7);
        let rows = f.samples();
        assert_eq!(rows.len(), f.steps_done() + 1, "a row per step");
        for pair in rows.windows(2) {
            let ratio = pair[1][2] / pair[0][2];
            assert!(
                (ratio - growth).abs() < 1e-5 * growth,
                "spin {spin}, {ms} ms: ×{ratio}, expected ×{growth}"
            );
            assert!(pair[1][2] > pair[0][2], "grows every step");
        }
        for row in rows {
            assert!((row[1] - 1.0).abs() < 1e-5, "normalised: {row:?}");
            assert!((row[3] - 1.0).abs() < 1e-5, "exponential: {row:?}");
        }
        let n = f.steps_done() as i32;
        let expected = (growth as f64).powi(n) as f32;
        let last = rows.last().unwrap()[2];
        assert!((last / expected - 1.0).abs() < 1e-4, "{last} vs {expected}");
    }
}

#[test]
fn at_short_steps_the_drift_is_slow_and_a_row_comes_each_frame() {
    let mut f = DriftFigure::new();
    f.set_drift(30.0, 1.0).unwrap();
    // Reached in uneven jumps: the rows are the same as in one go.
    for t in [0.7, 3.3, 10.0] {
        f.advance_to(t).unwrap();
    }
    let mut g = DriftFigure::new();
    g.set_drift(30.0, 1.0).unwrap();
    g.advance_to(10.0).unwrap();
    assert_eq!(f.samples(), g.samples());
    assert_eq!(f.samples().len(), 601, "a row per frame");
    let growth = (1.0f64 + (0.5 * 30.0 * 0.001f64).powi(2)).sqrt();
    let expected = growth.powi(10_000) as f32;
    let last = f.samples().last().unwrap();
    assert!(
        (last[2] / expected - 1.0).abs() < 1e-3,
        "{last:?} vs {expected}"
    );
    assert!(
        // The exponential step's |q| drifts by rounding alone (each step multiplies by a unit
        // quaternion rounded to float): about 2.4e-4 over these 10,000 steps.
        (last[1] - 1.0).abs() < 1e-5 && (last[3] - 1.0).abs() < 1e-3,
        "{last:?}"
    );
}

#[test]
fn the_normalised_additive_box_lags_by_the_closed_form_and_the_raw_matrix_stretches() {
    let mut f = DriftFigure::new();
    f.set_drift(10.0, 20.0).unwrap();
    f.advance_to(5.0).unwrap();
    // Each additive step turns by 2 atan(|ω| Δt / 2) instead of |ω| Δt.
    let (w, dt) = (10.0f64, 0.02f64);
    let lag = 250.0 * (w * dt - 2.0 * (0.5 * w * dt).atan());
    assert!(
        (f.lag_deg() as f64 - lag.to_degrees()).abs() < 0.1,
        "{} vs {}",
        f.lag_deg(),
        lag.to_degrees()
    );
    // The unnormalised box's matrix is (1 − s²) E + s² R(q/|q|), exactly: every entry of the
    // rotation formula but the 1s on the diagonal is quadratic in q.
    let b = f.bodies()[1];
    let s = b.orientation.length();
    let r = glam::Mat3::from_quat(b.orientation.normalize());
    let m = b.rotation();
    let expected = glam::Mat3::IDENTITY * (1.0 - s * s) + r * (s * s);
    for (x, y) in m.to_cols_array().iter().zip(expected.to_cols_array()) {
        assert!((x - y).abs() < 1e-3 * s * s, "{m} vs {expected}");
    }
    // About an axis that is no axis of the world, the box's edges are no longer perpendicular
    // (it shears) and no longer unit (it stretches).
    let cols = [m.x_axis, m.y_axis, m.z_axis];
    let shear = (0..3)
        .flat_map(|i| (i + 1..3).map(move |j| (i, j)))
        .map(|(i, j)| cols[i].normalize().dot(cols[j].normalize()).abs())
        .fold(0.0f32, f32::max);
    assert!(shear > 0.2, "largest cosine between edges {shear}");
    assert!(cols.iter().any(|c| (c.length() - 1.0).abs() > 0.5), "{m}");
    assert!(s > 3.0, "{s}");
}

#[test]
fn the_drift_refuses_bad_settings_and_stops_the_raw_quaternion_before_it_overflows() {
    let mut f = DriftFigure::new();
    f.advance_to(1.0).unwrap();
    let at_one = *f.bodies();
    for (spin, ms, name) in [
        (0.5, 10.0, "spin"),
        (31.0, 10.0, "spin"),
        (f32::NAN, 10.0, "spin"),
        (5.0, 0.5, "step"),
        (5.0, 51.0, "step"),
        (5.0, f32::INFINITY, "step"),
    ] {
        let err = f.set_drift(spin, ms).unwrap_err();
        assert!(err.contains(name), "{err}");
    }
    assert!(f.advance_to(-1.0).is_err() && f.advance_to(61.0).is_err());
    assert_eq!(*f.bodies(), at_one, "a rejected call changes nothing");
    // ×1.25 a step: past 10⁶ in 62 steps; stopped there, every number finite.
    f.set_drift(30.0, 50.0).unwrap();
    f.advance_to(10.0).unwrap();
    let stopped = f.overflowed_at().expect("stopped");
    assert!((stopped - 62.0 * 0.05).abs() < 1e-3, "{stopped}");
    assert!(f.samples().iter().flatten().all(|x| x.is_finite()));
    let mut frame = Frame::default();
    let note = f.draw(&mut frame);
    assert!(note.contains("stopped there"), "{note}");
    // The undrawn box's name keeps its box's teal, the colour the caption gives the
    // unnormalised step.
    let hidden: Vec<_> = frame
        .labels
        .iter()
        .filter(|l| l.text.contains("(not drawn)"))
        .collect();
    assert_eq!(hidden.len(), 1);
    assert!(hidden[0].text.starts_with("unnormalised"), "{}", hidden[0].text);
    assert_eq!(hidden[0].color, palette::TEAL);
    assert_eq!(
        frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::CUBE)
            .count(),
        2
    );
}

#[test]
fn the_drift_draws_three_labelled_boxes_with_their_raw_matrices() {
    let mut f = DriftFigure::new();
    f.advance_to(8.0).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame);
    let cubes: Vec<_> = frame
        .meshes
        .iter()
        .filter(|m| m.mesh == MeshId::CUBE)
        .collect();
    assert_eq!(cubes.len(), 3);
    // The unnormalised box's model matrix is its raw rotation: not a rotation any more.
    let raw = cubes[1].model;
    let unit = cubes[0].model;
    assert!((raw.determinant() - unit.determinant()).abs() > 0.05 * unit.determinant());
    for (_, name) in DRIFT_STEPS {
        assert!(
            frame.labels.iter().any(|l| l.text.starts_with(name)),
            "{name}"
        );
    }
    // The box it should have been, outlined.
    assert!(frame.segments_of(palette::GREY).count() >= 12);
    assert!(
        note.contains("unnormalised |q| = ") && note.contains("behind the exponential one"),
        "{note}"
    );
}

// ---- every figure at the ends of its ranges ----

/// Everything a frame holds is finite.
fn finite_frame(frame: &Frame) -> bool {
    frame.meshes.iter().all(|m| m.model.is_finite())
        && frame
            .strokes
            .iter()
            .all(|s| s.a.iter().chain(&s.b).all(|x| x.is_finite()))
        && frame
            .markers
            .iter()
            .all(|m| m.center.iter().all(|x| x.is_finite()))
        && frame.labels.iter().all(|l| l.anchor.is_finite())
        && frame.keep_in_view.iter().all(|p| p.is_finite())
}

#[test]
fn at_the_ends_of_their_ranges_the_figures_stay_finite_and_draw() {
    let check = |samples: Vec<f32>, frame: &Frame, what: &str| {
        assert!(samples.iter().all(|x| x.is_finite()), "{what}: samples");
        assert!(finite_frame(frame), "{what}: frame");
    };
    for spin in [0.0, 15.0] {
        for tilt in [0.0, 80.0] {
            let mut f = ThrowFigure::new();
            f.set_throw(spin, tilt).unwrap();
            f.advance_to(60.0).unwrap();
            let mut frame = Frame::default();
            f.draw(&mut frame);
            check(f.samples().concat(), &frame, "throw");
        }
    }
    for tilt in [0.0, 45.0] {
        for e in [0.0, 1.0] {
            for h in [0.2, 2.0] {
                let mut f = ImpulseFigure::new();
                f.set_drop(tilt, e, h).unwrap();
                f.advance_to(60.0).unwrap();
                let mut frame = Frame::default();
                f.draw(&mut frame);
                check(f.samples().concat(), &frame, "drop");
                assert!(f.impact().is_some());
            }
        }
    }
    for preset in [StackPreset::Stack, StackPreset::Dominoes] {
        for (passes, mu, e) in [(1.0, 0.0, 1.0), (1.0, 1.0, 0.0), (50.0, 0.0, 1.0)] {
            let mut f = StackFigure::new(preset);
            f.set_solver(passes, mu, e).unwrap();
            f.push().unwrap();
            f.advance_to(60.0).unwrap();
            let mut frame = Frame::default();
            f.draw(&mut frame);
            check(f.samples().concat(), &frame, "stack");
        }
    }
    for (spin, ms) in [(1.0, 1.0), (30.0, 1.0), (1.0, 50.0), (30.0, 50.0)] {
        let mut f = DriftFigure::new();
        f.set_drift(spin, ms).unwrap();
        f.advance_to(60.0).unwrap();
        let mut frame = Frame::default();
        f.draw(&mut frame);
        check(f.samples().concat(), &frame, "drift");
    }
}

#[test]
fn the_throw_plots_l_flat_at_one_and_omega_moving() {
    let mut f = ThrowFigure::new();
    f.advance_to(f.duration_sec()).unwrap();
    let rows = f.plot_rows();
    assert_eq!(rows.len(), f.samples().len());
    assert_eq!(rows[0][1..3], [1.0, 1.0]);
    let l_off = rows.iter().map(|r| (r[2] - 1.0).abs()).fold(0.0, f32::max);
    let w_lo = rows.iter().map(|r| r[1]).fold(f32::INFINITY, f32::min);
    assert!(l_off < 1e-5, "|L| share off by {l_off}");
    assert!(w_lo < 0.99, "|ω| share at least {w_lo}");
    for (row, sample) in rows.iter().zip(f.samples()) {
        assert_eq!((row[0], row[3]), (sample[0], sample[3]));
    }
}

#[test]
fn the_throw_is_framed_round_its_flight_so_the_box_reads() {
    // Figure 1 at the viewer's default camera, fitted to what the figure declares, on the two
    // canvases the page gives it: the frame holds the flight, not a floor much larger than it
    // (a box 40 px long with short stubs of L and ω), so the box spans an eighth of the
    // canvas's height or more; and every line the figure draws (path, L, ω and its trail) and
    // the box stay inside the canvas, for spins and tilts across the sliders, through the flight.
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use glam::Vec2;
    for size in crate::label_clearance::CANVASES {
        for (spin, tilt) in [(10.0, 20.0), (15.0, 80.0), (5.0, 50.0), (15.0, 40.0), (10.0, 0.0)] {
            let mut f = ThrowFigure::new();
            f.set_throw(spin, tilt).unwrap();
            for k in 0..=12 {
                f.advance_to(f.duration_sec() * k as f32 / 12.0).unwrap();
                let mut frame = Frame::default();
                f.draw(&mut frame);
                // As the viewer: with an inset, the figure fits left of its square.
                let mut camera = OrbitCamera::default();
                let left = inbetween::draw::inset::inset_rect(size).min.x;
                let beside = frame.inset.is_some()
                    && camera.fit_left_of(&frame.fit_points(), size, left, FIT_PAD_PX);
                if !beside {
                    camera.fit(&frame.fit_points(), size, FIT_PAD_PX);
                }
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
                let model = frame.meshes[0].model;
                let corners: Vec<Vec2> = (0..8)
                    .map(|c| {
                        let s = |bit: u32| if c & bit == 0 { -1.0 } else { 1.0 };
                        at(model.transform_point3(Vec3::new(s(1), s(2), s(4))))
                    })
                    .collect();
                let lo = corners.iter().fold(Vec2::MAX, |m, c| m.min(*c));
                let hi = corners.iter().fold(Vec2::MIN, |m, c| m.max(*c));
                let what = format!("spin {spin}, tilt {tilt}, step {k}/12 on {size}");
                // An eighth of the canvas's height: 48 to 77 px across the sweep; 38 to 62 px when
                // the frame held the floor 1.7 m round the flight.
                let long = (hi - lo).max_element();
                assert!(long > 0.125 * size.y, "{what}: box {lo} to {hi}");
                let ends = frame.strokes.iter().flat_map(|s| [s.a, s.b]);
                for p in corners.into_iter().chain(ends.map(|p| at(Vec3::from(p)))) {
                    assert!(
                        p.cmpge(Vec2::ZERO).all() && p.cmple(size).all(),
                        "{what}: {p} off the canvas"
                    );
                }
            }
        }
    }
}

// ---- "use my exercise" ----

use inbetween::exercises::run::Failure;
use inbetween::rigid_body::{self as rb, OrientationStep};

/// A student whose four exercises are right (the reference cores; the stubs of a plain build
/// answer "not done").
fn correct(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let v3 = |i: usize| Vec3::from_slice(&args[i..i + 3]);
    let q = |i: usize| glam::Quat::from_slice(&args[i..i + 4]);
    Ok(match name {
        "box_inertia" => {
            let m = inbetween::rigid_body::inertia::solid_box(args[0], v3(1));
            vec![m.x_axis.x, m.y_axis.y, m.z_axis.z]
        }
        "orientation_step" => rb::orientation_step(q(0), v3(4), args[7], OrientationStep::Additive)
            .to_array()
            .to_vec(),
        "world_inverse_inertia" => rb::world_inverse_inertia(q(0), v3(4))
            .to_cols_array()
            .to_vec(),
        "normal_impulse" => {
            let inv = glam::Mat3::from_cols_slice(&args[10..19]);
            vec![rb::normal_impulse(
                v3(0),
                v3(3),
                v3(6),
                args[9],
                inv,
                args[19],
            )]
        }
        _ => return Err(Failure::Call(format!("no exercise {name}"))),
    })
}

/// A student whose 14.1 swaps the y and z moments, whose 14.2 forgets to normalise, whose 14.4
/// doubles the impulse and whose 14.3 is not done.
fn mistaken(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    match name {
        "box_inertia" => correct(name, args).map(|m| vec![m[0], m[2], m[1]]),
        "orientation_step" => {
            let (q, omega) = (
                glam::Quat::from_slice(&args[0..4]),
                Vec3::from_slice(&args[4..7]),
            );
            let w = glam::Quat::from_xyzw(omega.x, omega.y, omega.z, 0.0);
            Ok((q + (w * q) * (0.5 * args[7])).to_array().to_vec())
        }
        "world_inverse_inertia" => Err(Failure::NotDone),
        "normal_impulse" => correct(name, args).map(|j| vec![2.0 * j[0]]),
        _ => correct(name, args),
    }
}

#[test]
fn the_rackets_spin_with_the_students_moments() {
    let mut f = RacketFigure::new();
    f.set_runner(mistaken);
    f.set_use_exercise(true);
    f.advance_to(10.0).unwrap();
    // With y the largest moment the spin about y is stable: the held-L racket never turns over.
    let up = f.bodies()[0].orientation * Vec3::Y;
    assert!(up.y > 0.9, "{up}");
    let note = f.draw(&mut Frame::default());
    assert!(note.contains("Your box_inertia differs"), "{note}");
    assert!(note.contains("spin with your moments"), "{note}");
    // Off again: the reference's moments, and the racket flips within the 10 s.
    f.set_use_exercise(false);
    let mut lowest = 1.0f32;
    for k in 1..=600 {
        f.advance_to(k as f32 / 60.0).unwrap();
        lowest = lowest.min((f.bodies()[0].orientation * Vec3::Y).y);
    }
    assert!(lowest < -0.9, "{lowest}");
}

#[test]
fn the_drift_steps_the_normalised_box_with_the_students_step() {
    let mut f = DriftFigure::new();
    f.set_runner(mistaken);
    f.set_use_exercise(true);
    f.advance_to(5.0).unwrap();
    // The student forgot to normalise: the "normalised" box grows as the unnormalised one.
    let b = f.bodies();
    assert!((b[0].orientation.length() - b[1].orientation.length()).abs() < 1e-4);
    assert!(b[0].orientation.length() > 1.1);
    let note = f.draw(&mut Frame::default());
    assert!(note.contains("Your orientation_step differs"), "{note}");
    // A correct student: the same run as the reference.
    let mut g = DriftFigure::new();
    g.set_runner(correct);
    g.set_use_exercise(true);
    g.advance_to(5.0).unwrap();
    let mut h = DriftFigure::new();
    h.advance_to(5.0).unwrap();
    assert_eq!(g.samples(), h.samples());
    assert!(g
        .draw(&mut Frame::default())
        .contains("matches the reference"));
}

#[test]
fn the_impact_uses_the_students_impulse_and_says_what_is_not_done() {
    let mut f = ImpulseFigure::new();
    f.set_runner(mistaken);
    f.set_use_exercise(true);
    f.advance_to(1.0).unwrap();
    let hit = *f.impact_details().expect("hit");
    let mut r = ImpulseFigure::new();
    r.advance_to(1.0).unwrap();
    let reference = *r.impact_details().unwrap();
    // 14.3 not done: the reference tensor; 14.4 doubled: twice the impulse, so the corner
    // leaves faster than −e times its approach.
    assert!((hit.j - 2.0 * reference.j).abs() < 1e-4 * reference.j);
    assert!(hit.normal_after > reference.normal_after + 0.1);
    let note = f.draw(&mut Frame::default());
    // One line an exercise, under the impact's numbers.
    let lines: Vec<&str> = note.lines().collect();
    assert_eq!(lines.len(), 3, "{note}");
    assert!(lines[0].starts_with("Impact at t = "), "{note}");
    assert!(lines[1].starts_with("Not done yet: exercise 14.3"), "{note}");
    assert!(lines[2].starts_with("Your normal_impulse differs"), "{note}");
    // The wrong impulse does not bounce the corner at −e times its approach: the note says so
    // instead of calling it that.
    assert!(!note.contains("(−e times it"), "{note}");
    assert!(note.contains("e = 0.500 asks for −e times it, 2.214 m/s"), "{note}");
    let reference_note = r.draw(&mut Frame::default());
    assert!(reference_note.contains("(−e times it, e = 0.500)"), "{reference_note}");
}

#[test]
fn the_omega_arrows_are_tied_to_the_centre_whatever_the_signs_of_omega() {
    use inbetween::figures::rigid_body::{ties_omega_arrows, OMEGA_SIDE_M};
    // At the default drop: the grey line runs from the centre at the hit to the start of the ω
    // arrows, OMEGA_SIDE_M to the side.
    let f = dropped(20.0, 0.5, 1.0);
    let hit = *f.impact_details().expect("hit");
    let mut frame = Frame::default();
    f.draw(&mut frame);
    let tie = frame
        .segments_of(palette::GREY)
        .find(|(a, b)| *a == hit.centre || *b == hit.centre);
    let (a, b) = tie.expect("a grey line from the centre at the hit");
    assert!((a.distance(b) - OMEGA_SIDE_M).abs() < 1e-4);
    // A level drop gets no spin: no ω arrow, nothing to tie.
    let level = dropped(0.0, 0.5, 1.0);
    let centre = level.impact_details().expect("hit").centre;
    let mut frame = Frame::default();
    level.draw(&mut frame);
    assert!(!frame.segments_of(palette::GREY).any(|(a, b)| a == centre || b == centre));
    // The drop's ω after always has a positive z (the tilt is about −z), so the signs are tried
    // on the rule itself: ω before zero and every component of ω after negative still ties the
    // arrow (the two ω's component-wise largest values are zero there).
    assert!(ties_omega_arrows(Vec3::ZERO, Vec3::new(-3.0, -1.0, -2.0)));
    assert!(ties_omega_arrows(Vec3::new(-3.0, -1.0, -2.0), Vec3::ZERO));
    assert!(!ties_omega_arrows(Vec3::ZERO, Vec3::ZERO));
    assert!(!ties_omega_arrows(Vec3::ZERO, Vec3::splat(1e-6)));
}

/// The times (s) at which the held-L racket's middle axis turns past horizontal, over 12 s.
fn flip_times(spin: f32, wobble: f32) -> (Vec<f32>, RacketFigure) {
    let mut f = RacketFigure::new();
    f.set_spin(spin, wobble).unwrap();
    let (mut flips, mut prev) = (Vec::new(), 1.0f32);
    for k in 1..=720 {
        f.advance_to(k as f32 / 60.0).unwrap();
        let y = (f.bodies()[0].orientation * Vec3::Y).y;
        if (y < 0.0) != (prev < 0.0) {
            flips.push(k as f32 / 60.0);
        }
        prev = y;
    }
    (flips, f)
}

#[test]
fn the_racket_flips_sooner_with_more_wobble_or_spin_and_never_without_wobble() {
    // The page: at 6 rad/s and a wobble of 0.05 rad/s the first turn-over near 1.9 s and then
    // every 3.2 s or so; at 0.01 rad/s first near 2.3 s and every 5 s; at 0 never; at 12 rad/s
    // twice as often.
    let (default, f) = flip_times(6.0, 0.05);
    assert!((default[0] - 1.9).abs() < 0.1, "{default:?}");
    assert!(
        default.len() == 4 && (default[1] - default[0] - 3.2).abs() < 0.2,
        "{default:?}"
    );
    assert!(
        f.exploded_at(1).is_none(),
        "the explicit racket holds at 6 rad/s"
    );
    let (small, _) = flip_times(6.0, 0.01);
    assert!(
        (small[0] - 2.3).abs() < 0.1 && (small[1] - small[0] - 5.0).abs() < 0.3,
        "{small:?}"
    );
    let (none, _) = flip_times(6.0, 0.0);
    assert!(none.is_empty(), "{none:?}");
    let (fast, f) = flip_times(12.0, 0.05);
    assert!((fast[0] - 1.05).abs() < 0.1 && fast.len() >= 6, "{fast:?}");
    // At 12 rad/s the explicit racket's energy runs away: stopped, said, a gap in the plots.
    let t = f
        .exploded_at(1)
        .expect("the explicit racket explodes at 12 rad/s");
    assert!(t < 12.0 && f.exploded_at(0).is_none() && f.exploded_at(2).is_none());
    let last = f.samples().last().unwrap();
    assert!(last[2].is_nan() && last[5].is_nan() && last[1].is_finite());
    let mut frame = Frame::default();
    let note = f.draw(&mut frame);
    assert!(note.contains("explicit: exploded at t ="), "{note}");
    assert!(frame
        .meshes
        .iter()
        .any(|m| m.color.truncate() == palette::RED));
    assert!(frame.meshes.iter().all(|m| m.model.is_finite()));
}

#[test]
fn at_20_rad_s_and_50_ms_the_drift_is_fast_and_the_lag_large() {
    // The page's "Try this": each step multiplies |q| by √1.25 ≈ 1.118, so the unnormalised box
    // is too large to draw (|q| past √2.5) after 5 steps, 0.25 s; the normalised box falls
    // 4.2° behind the exponential one a step, 83° in one second.
    let mut f = DriftFigure::new();
    f.set_drift(20.0, 50.0).unwrap();
    assert!((f.growth_per_step() - 1.25f32.sqrt()).abs() < 1e-6);
    f.advance_to(0.2).unwrap();
    assert!(f.bodies()[1].orientation.length() < DRIFT_DRAWN_MAX_NORM);
    f.advance_to(0.25).unwrap();
    assert!(f.bodies()[1].orientation.length() > DRIFT_DRAWN_MAX_NORM);
    f.advance_to(1.0).unwrap();
    assert!((f.lag_deg() - 83.3).abs() < 0.5, "{}", f.lag_deg());
}

#[test]
fn the_default_drop_gives_the_numbers_the_page_quotes() {
    // 20°, e = 0.5, 1 m: the corner arrives at 4.43 m/s (√(2 g h)) and leaves at 2.21 m/s, the
    // centre only slows to 3.02 m/s, the box leaves spinning at 18 rad/s, with j = 1.41 N s;
    // landing flat (tilt 0) takes j = (1 + e) m v = 6.64 N s.
    let mut f = ImpulseFigure::new();
    f.advance_to(1.0).unwrap();
    let hit = *f.impact_details().unwrap();
    assert!((hit.normal_before + 4.43).abs() < 0.01, "{hit:?}");
    assert!((hit.normal_after - 2.21).abs() < 0.01, "{hit:?}");
    assert!((hit.velocity_after.y + 3.02).abs() < 0.01, "{hit:?}");
    assert!((hit.omega_after.length() - 18.2).abs() < 0.1, "{hit:?}");
    assert!((hit.j - 1.41).abs() < 0.01, "{hit:?}");
    f.set_drop(0.0, 0.5, 1.0).unwrap();
    f.advance_to(1.0).unwrap();
    let flat = f.impact_details().unwrap();
    assert!(
        (flat.j - 6.64).abs() < 0.01 && flat.omega_after.length() < 1e-3,
        "{flat:?}"
    );
}

#[test]
fn the_impulse_plot_follows_the_point_that_hit() {
    // Two rows at the moment of the hit: the corner arriving at 4.43 m/s, then leaving at e
    // times that, 2.21 m/s; the plot draws the jump.
    let mut f = ImpulseFigure::new();
    f.advance_to(1.0).unwrap();
    let hit = *f.impact_details().unwrap();
    let at: Vec<&[f32; 4]> = f
        .samples()
        .iter()
        .filter(|r| r[0] == hit.time_sec)
        .collect();
    assert_eq!(at.len(), 2, "{:?}", f.samples());
    assert_eq!((at[0][2], at[1][2]), (hit.normal_before, hit.normal_after));
    assert_eq!((at[0][3], at[1][3]), (hit.energy_before, hit.energy_after));
    assert!(
        f.samples().windows(2).all(|w| w[0][0] <= w[1][0]),
        "time never goes back"
    );
}

#[test]
fn without_friction_the_stack_blows_up_and_the_figure_says_so() {
    // At μ = 0 nothing stops the boxes sliding on each other: the stack shears, the boxes pass
    // into each other near 1.8 s and the solver pushes them out with more energy than the stack
    // ever had; the figure stops there and says why. With friction nothing of the kind, pushed
    // or not.
    let mut f = StackFigure::new(StackPreset::Stack);
    f.set_solver(20.0, 0.0, 0.0).unwrap();
    f.advance_to(10.0).unwrap();
    let t = f.exploded().expect("the frictionless stack blows up");
    assert!((1.6..2.0).contains(&t), "{t}");
    let note = f.draw(&mut Frame::default());
    assert!(note.contains("more energy than the run ever had"), "{note}");
    assert!(f.samples().iter().flatten().all(|x| x.is_finite()));
    // Dominoes bouncing with e = 1: several contacts of a body restored at once add energy.
    let mut f = StackFigure::new(StackPreset::Dominoes);
    f.set_solver(20.0, 0.5, 1.0).unwrap();
    f.advance_to(f.duration_sec()).unwrap();
    assert!(f.exploded().is_some_and(|t| t < 2.0), "{:?}", f.exploded());
    for preset in [StackPreset::Stack, StackPreset::Dominoes] {
        let mut f = StackFigure::new(preset);
        f.advance_to(0.5).unwrap();
        f.push().unwrap();
        f.push().unwrap();
        f.advance_to(f.duration_sec()).unwrap();
        assert!(f.exploded().is_none(), "{preset:?} at {:?}", f.exploded());
    }
}

#[test]
fn a_level_drop_reads_no_spin_in_the_note() {
    let mut f = ImpulseFigure::new();
    f.set_drop(0.0, 0.5, 1.0).unwrap();
    f.advance_to(0.6).unwrap();
    let note = f.draw(&mut Frame::default());
    assert!(note.contains("(|ω| = 0.000)"), "{note}");
    assert!(
        !note.contains("e-"),
        "no rounding leftovers in scientific notation: {note}"
    );
}

#[test]
fn the_throws_l_and_omega_are_wider_than_the_other_arrows() {
    // L and ω are what Figure 1 shows, often a few degrees apart on screen: each has a shaft
    // wider than a plain arrow's, from the centre of mass.
    use inbetween::draw::ARROW_PX;
    let mut f = ThrowFigure::new();
    f.advance_to(0.3).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame);
    let at = f.body().position;
    for color in [palette::PURPLE, palette::TEAL] {
        assert!(
            frame.strokes.iter().any(|s| {
                Vec3::from_slice(&s.color) == color
                    && s.width_px >= ARROW_PX + 1.5
                    && Vec3::from(s.a).distance(at) < 1e-4
            }),
            "a wide shaft of colour {color}"
        );
    }
}

#[test]
fn after_the_hit_the_plotted_corner_swings_down_with_the_boxs_turn_and_bounces_again() {
    // Figure 4's caption, at the page's defaults (tilt 20°, e = 0.5, 1 m): the corner that hit
    // leaves at −e times its approach; within 0.05 s a neighbouring corner lands and turns the
    // box the other way, so the corner that hit swings down at about 5 m/s while the centre
    // falls at under 0.2 m/s (the plot's velocity is mostly the turn's, ω × r); a step or two
    // later it lands again and bounces up.
    let mut f = ImpulseFigure::new();
    f.advance_to(1.0).unwrap();
    let hit = *f.impact_details().unwrap();
    assert!((hit.normal_after + 0.5 * hit.normal_before).abs() < 1e-3);
    let rows: Vec<[f32; 4]> = f.samples().to_vec();
    let (k, dip) = rows
        .iter()
        .enumerate()
        .filter(|(_, r)| r[0] > hit.time_sec && r[0] < hit.time_sec + 0.05)
        .min_by(|a, b| a.1[2].total_cmp(&b.1[2]))
        .unwrap();
    assert!((-5.5..-4.5).contains(&dip[2]), "the corner swings down at {} m/s", dip[2]);
    let mut at_dip = ImpulseFigure::new();
    at_dip.advance_to(dip[0]).unwrap();
    let centre = at_dip.body().velocity.y;
    assert!(centre.abs() < 0.2, "the centre moves at {centre} m/s");
    let bounce = rows[k..].iter().find(|r| r[2] > 0.0).unwrap();
    assert!(bounce[0] - dip[0] < 0.035, "bounces at {} s", bounce[0]);
}

#[test]
fn the_throws_l_reaches_past_omegas_tip() {
    // ω lies a few degrees off L (5° at the page's default 0.3 s): L is drawn longer than ω's
    // reach along it, so its last part and head stand clear past ω's tip at every step, for
    // spins and tilts across the sliders. The names sit at the tips.
    use inbetween::figures::rigid_body::THROW_ARROW_M;
    for (spin, tilt) in [(10.0, 20.0), (15.0, 5.0), (5.0, 60.0), (15.0, 80.0)] {
        let mut f = ThrowFigure::new();
        f.set_throw(spin, tilt).unwrap();
        for k in 0..=12 {
            f.advance_to(f.duration_sec() * k as f32 / 12.0).unwrap();
            let mut frame = Frame::default();
            f.draw(&mut frame);
            let tip = |name: &str| {
                let l = frame.labels.iter().find(|l| l.text.starts_with(name)).unwrap();
                l.anchor - f.body().position
            };
            let (l, w) = (tip("L "), tip("ω "));
            let past = l.length() - w.dot(l.normalize());
            assert!(
                (past - 0.5 * THROW_ARROW_M).abs() < 1e-3,
                "spin {spin}, tilt {tilt}, step {k}: L ends {past} m past ω's tip"
            );
        }
    }
}

#[test]
fn the_drops_arrows_show_over_the_boxes_and_the_ground() {
    // The impulse, v and ω of the hit start inside the box at the hit and run through the box
    // now and below the ground: all of them are drawn over everything.
    use inbetween::draw::ON_TOP;
    for (tilt, e, height) in [(20.0, 0.5, 1.0), (36.0, 0.2, 1.6)] {
        let mut f = dropped(tilt, e, height);
        f.advance_to(1.0).unwrap();
        let mut frame = Frame::default();
        f.draw(&mut frame);
        let arrows: Vec<_> = frame
            .strokes
            .iter()
            .filter(|s| Vec3::from_slice(&s.color) != palette::GREY)
            .collect();
        assert!(arrows.len() >= 4, "j n, v before and after, ω after");
        assert!(arrows.iter().all(|s| s.depth_bias == ON_TOP));
        // v is drawn after ω: where they lie on one line on screen, v shows.
        let last_teal = arrows.iter().rposition(|s| Vec3::from_slice(&s.color) == palette::TEAL);
        let first_blue = arrows.iter().position(|s| {
            let c = Vec3::from_slice(&s.color);
            c == palette::BLUE || c == palette::BLUE.lerp(Vec3::ONE, 0.55)
        });
        assert!(last_teal < first_blue, "{last_teal:?} {first_blue:?}");
    }
}

#[test]
fn at_a_small_wobble_the_energy_steps_come_about_4_s_apart_and_the_held_racket_5() {
    // The page's Try this at a wobble of 0.01 rad/s: all three rackets first turn over near
    // 2.3 s; the explicit and implicit ones (whose energy steps the plot shows) next about 4 s
    // later, the L-held one about 5 s later.
    let mut f = RacketFigure::new();
    f.set_spin(6.0, 0.01).unwrap();
    let mut prev = [1.0f32; 3];
    let mut flips = vec![Vec::new(), Vec::new(), Vec::new()];
    for k in 1..=720 {
        f.advance_to(k as f32 / 60.0).unwrap();
        for (b, flips) in flips.iter_mut().enumerate() {
            let y = (f.bodies()[b].orientation * Vec3::Y).y;
            if (y < 0.0) != (prev[b] < 0.0) {
                flips.push(k as f32 / 60.0);
            }
            prev[b] = y;
        }
    }
    for (b, gap) in [(0, 5.0), (1, 4.0), (2, 4.0)] {
        let t = &flips[b];
        assert!(
            (t[0] - 2.3).abs() < 0.15 && (t[1] - t[0] - gap).abs() < 0.35,
            "racket {b}: {t:?}"
        );
    }
}

/// At e = 0 the corner's normal velocity after the hit is zero up to rounding (a few 1e-7 m/s):
/// the note gives it, and every other number, as a plain decimal, never as "-4.768e-7".
#[test]
fn the_impact_note_reads_rounding_leftovers_as_zero() {
    for tilt in [0.0, 10.0, 20.0, 45.0] {
        for height in [0.5, 1.0, 2.0] {
            let f = dropped(tilt, 0.0, height);
            let note = f.draw(&mut Frame::default());
            assert!(!note.contains("e-"), "tilt {tilt}, height {height}: {note}");
        }
    }
}

#[test]
fn the_throws_omega_tip_reach_bounds_its_trail_and_is_reached() {
    // The reach the view and the inset are framed with: ω's drawn tip stays within it through
    // the flight and comes close to it (a flight is a wobble or more), for spins and tilts
    // across the sliders.
    use inbetween::figures::rigid_body::{THROW_ARROW_M, THROW_L_M};
    for (spin, tilt) in [(10.0, 20.0), (3.0, 63.0), (15.0, 80.0), (5.0, 50.0), (10.0, 0.5)] {
        let mut f = ThrowFigure::new();
        f.set_throw(spin, tilt).unwrap();
        let reach = f.omega_tip_reach();
        f.advance_to(f.duration_sec()).unwrap();
        let l = f.body().angular_momentum().normalize();
        let far = f
            .omegas()
            .iter()
            .map(|w| THROW_ARROW_M * w.reject_from(l).length() / w.dot(l))
            .fold(0.0, f32::max);
        let what = format!("spin {spin}, tilt {tilt}: reach {reach} m, trail out to {far} m");
        assert!(far <= reach * 1.01 + 1e-3, "{what}");
        assert!(far >= 0.9 * reach, "{what}");
        // The inset from above holds the whole trail and L's tip, round the box now.
        let mut frame = Frame::default();
        f.draw(&mut frame);
        let at = f.body().position;
        let scale = THROW_ARROW_M / f.omegas()[0].dot(l);
        let inset = frame.inset.as_ref().unwrap();
        let tips = f.omegas().iter().map(|w| at + scale * *w);
        for p in tips.chain([at, at + THROW_L_M * l]) {
            let inside = p.cmpge(inset.min - 1e-3).all() && p.cmple(inset.max + 1e-3).all();
            assert!(inside, "{what}: {p} outside the inset's {inset:?}");
        }
    }
}

#[test]
fn the_racket_plots_stop_at_three_times_the_start_and_each_name_has_its_rackets_colour() {
    // At the defaults no curve reaches 3 times its start: each axis spans the samples. At
    // 12 rad/s the explicit racket climbs towards 100 times its start energy and explodes; the
    // axes stop at 3 (the caption's number), and the held and implicit curves, which the text
    // compares, lie inside them, the implicit racket's fall to about a quarter included.
    let span = |f: &RacketFigure, first: usize, k: usize| {
        f.samples()
            .iter()
            .map(|r| r[first + k])
            .filter(|x| x.is_finite())
            .fold((f32::MAX, f32::MIN), |(lo, hi), x| (lo.min(x), hi.max(x)))
    };
    assert_eq!(RACKET_PLOT_TOP, 3.0);
    let mut f = RacketFigure::new();
    f.advance_to(f.duration_sec()).unwrap();
    let r = f.plot_ranges();
    for (first, range) in [(1, [r[0], r[1]]), (4, [r[2], r[3]])] {
        let (lo, hi) = (0..3).map(|k| span(&f, first, k)).fold((f32::MAX, f32::MIN), |a, b| {
            (a.0.min(b.0), a.1.max(b.1))
        });
        assert!(hi < RACKET_PLOT_TOP && range == [lo, hi], "{range:?} for {lo}..{hi}");
    }
    f.set_spin(12.0, 0.05).unwrap();
    f.advance_to(f.duration_sec()).unwrap();
    assert!(f.exploded_at(1).is_some(), "the explicit racket explodes at 12 rad/s");
    let r = f.plot_ranges();
    assert_eq!((r[1], r[3]), (RACKET_PLOT_TOP, RACKET_PLOT_TOP), "{r:?}");
    assert!(span(&f, 1, 1).1 > 10.0, "the explicit energy runs off the top");
    for (first, lo) in [(1, r[0]), (4, r[2])] {
        for k in [0, 2] {
            let (a, b) = span(&f, first, k);
            assert!(a >= lo && b <= RACKET_PLOT_TOP, "column {}: {a}..{b} in {r:?}", first + k);
        }
    }
    assert!(span(&f, 1, 2).0 < 0.3 && r[0] < 0.3, "the implicit energy's fall: {r:?}");
    // Each racket's name in its colour (red once it has exploded), as the caption colours it.
    let mut frame = Frame::default();
    f.draw(&mut frame);
    for (k, color) in [palette::PURPLE, palette::RED, palette::TEAL].into_iter().enumerate() {
        let name = INTEGRATORS[k].1;
        let label = frame.labels.iter().find(|l| l.text == name).expect(name);
        assert_eq!(label.color, color, "{name}");
    }
    let mut frame = Frame::default();
    RacketFigure::new().draw(&mut frame);
    for (k, color) in [palette::PURPLE, palette::ORANGE, palette::TEAL].into_iter().enumerate() {
        let label = frame.labels.iter().find(|l| l.text == INTEGRATORS[k].1).unwrap();
        assert_eq!(label.color, color, "{}", INTEGRATORS[k].1);
    }
}
