//! Hostile input to the figures' logic, natively: what a page, a student's console or a dropped
//! file could pass through a binding. Each rule is checked where it is decided (the figure or the
//! core), so that the wasm boundary only converts types. A rejected call leaves the scene as it
//! was; an accepted one never produces NaN or ±Infinity later.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec2;
use inbetween::curves::{ArcLengthTable, Interpolation, Track};
use inbetween::figures::curves::{KeyframesScene, LagrangeScene};

// ---- one rule for every count: a whole number in range, never rounded ----

#[test]
fn counts_passed_as_numbers_must_be_whole() {
    let mut lagrange = LagrangeScene::new();
    let before = lagrange.key_count();
    let e = lagrange.set_key_count(4.5).unwrap_err();
    assert!(e.contains("whole number from 3 to 16"), "{e}");
    assert_eq!(
        lagrange.key_count(),
        before,
        "a rejected count changes nothing"
    );
    lagrange.set_key_count(5.0).unwrap();
    assert_eq!(lagrange.key_count(), 5);

    let e = inbetween::figures::boids::law_plot_samples(2.5).unwrap_err();
    assert!(e.contains("whole number from 2 to 1000"), "{e}");
    assert_eq!(
        inbetween::figures::boids::law_plot_samples(3.0)
            .unwrap()
            .len(),
        9
    );

    let mut flock = inbetween::figures::boids::FlockFigure::new();
    assert!(flock.set_count(20.5).unwrap_err().contains("whole number"));
    let mut emitter = inbetween::figures::particles::EmitterFigure::new();
    assert!(emitter
        .set_burst(10.5)
        .unwrap_err()
        .contains("whole number"));
    let mut skeleton = inbetween::figures::skeleton::SkeletonFigure::new();
    assert!(skeleton
        .set_keys_per_cycle(4.5)
        .unwrap_err()
        .contains("whole number"));
    let mut cloth =
        inbetween::figures::cloth::ClothFigure::new(inbetween::figures::cloth::Preset::Flag);
    assert!(cloth
        .set_resolution(10.5)
        .unwrap_err()
        .contains("whole number"));
    for v in [f32::NAN, f32::INFINITY, -1.0, 4_294_967_299.0] {
        assert!(lagrange.set_key_count(v).is_err(), "{v}");
    }
}

// ---- arc length on degenerate keys ----

#[test]
fn arc_length_lookup_never_panics_on_a_nan_length() {
    // Keys 1e-30 s apart: the natural spline's tangents overflow, and with them the length.
    let keys = vec![Vec2::ZERO, Vec2::new(1.0, 1.0), Vec2::new(2.0, 0.0)];
    let track = Track::new(vec![0.0, 1e-30, 2e-30], keys)
        .and_then(|t| t.with_interpolation(Interpolation::Natural))
        .unwrap();
    let table = ArcLengthTable::new(&track, 24);
    for s in [0.0, 0.5, 1.0, f32::NAN, f32::INFINITY, -1.0] {
        let _ = table.time_at_length(&track, s); // must return, not panic
    }
}

#[test]
fn the_key_editor_rejects_keys_closer_than_its_minimum_spacing() {
    let mut scene = KeyframesScene::new();
    scene.set_scheme("natural").unwrap();
    let before = scene.track().clone();
    let keys = vec![Vec2::ZERO, Vec2::new(1.0, 1.0), Vec2::new(2.0, 0.0)];
    let e = scene
        .set_keys(vec![0.0, 1e-30, 2e-30], keys.clone())
        .unwrap_err();
    assert!(e.contains("at least 0.001 s apart"), "{e}");
    assert_eq!(scene.track(), &before, "a rejected edit changes nothing");
    // What the page then asks for still works and is finite.
    for row in scene.sample_motion(50).unwrap() {
        assert!(row.iter().all(|v| v.is_finite()), "{row:?}");
    }
    scene.set_keys(vec![0.0, 0.001, 0.002], keys).unwrap();
    scene.set_arc_length(true);
    let p = scene.position(0.0015).unwrap();
    assert!(p.is_finite());
}

#[test]
fn the_key_editor_rejects_values_outside_its_range() {
    let mut scene = KeyframesScene::new();
    let before = scene.track().clone();
    let far = vec![Vec2::ZERO, Vec2::new(1e38, 0.0), Vec2::new(2.0, 0.0)];
    let e = scene.set_keys(vec![0.0, 1.0, 2.0], far).unwrap_err();
    assert!(e.contains("[-10000, 10000] m"), "{e}");
    let near = vec![Vec2::ZERO, Vec2::new(1.0, 0.0), Vec2::new(2.0, 0.0)];
    let e = scene.set_keys(vec![-3e38, 1.0, 3e38], near).unwrap_err();
    assert!(e.contains("key times must lie in"), "{e}");
    let e = scene
        .set_key_tangent(0, Vec2::new(1e38, 0.0), Vec2::ZERO)
        .unwrap_err();
    assert!(e.contains("tangents must lie in"), "{e}");
    assert_eq!(scene.track(), &before);
    assert!(scene.loop_sec().is_finite());
    // Centripetal keys at the limit stay finite.
    scene.set_scheme("centripetal").unwrap();
    let edge = vec![Vec2::splat(-1e4), Vec2::ZERO, Vec2::splat(1e4)];
    scene.set_keys(vec![0.0, 1.0, 2.0], edge).unwrap();
    scene.set_arc_length(true);
    let mut ghosts = Vec::new();
    scene.ghosts(&mut ghosts);
    assert!(ghosts.iter().all(|g| g.is_finite()));
}

#[test]
fn a_rejected_tension_keeps_the_previous_tension() {
    let mut scene = KeyframesScene::new();
    assert!(scene.set_tension(f32::NAN).is_err());
    assert!(scene.set_tension(3.0).is_err());
    scene.set_tension(0.5).unwrap();
}

// ---- a rejected setter changes nothing ----

#[test]
fn rejected_setters_leave_every_field_as_it_was() {
    use glam::Vec3;
    use inbetween::figures::transforms::{Order, SingleShape};
    let mut shape = SingleShape::new();
    let before = shape.matrix(Order::RotateFirst);
    let e = shape
        .set_transform(Vec3::new(5.0, 6.0, 7.0), Vec3::new(f32::NAN, 0.0, 0.0))
        .unwrap_err();
    assert!(e.contains("rx"), "{e}");
    assert_eq!(
        shape.matrix(Order::RotateFirst),
        before,
        "the translation was kept"
    );

    let mut jump = inbetween::figures::expressive::JumpComparison::new();
    let duration = jump.duration();
    assert!(jump.set_principles(0.55, f32::NAN).is_err());
    assert_eq!(jump.duration(), duration, "the anticipation was kept");

    let mut skeleton = inbetween::figures::skeleton::SkeletonFigure::new();
    let e = skeleton.set_blend("none-of-these", 1.0).unwrap_err();
    assert!(e.contains("no clip named"), "{e}");
    skeleton.set_blend("none", 1.0).unwrap();
}

// ---- huge finite values: rejected with their range, never NaN later ----

#[test]
fn rigid_keys_outside_their_range_are_rejected() {
    use glam::{Quat, Vec3};
    use inbetween::figures::rigid::{AffineKeys, RigidMotion};
    let mut rigid = RigidMotion::new();
    let axis = rigid.screw_axis();
    let h = std::f32::consts::FRAC_1_SQRT_2;
    let q = Quat::from_xyzw(1e38, h, 0.0, h);
    let e = rigid.set_end_quat(q, Vec3::X).unwrap_err();
    assert!(e.contains("[-10000, 10000]"), "{e}");
    let e = rigid
        .set_end(Vec3::Y, 90.0, Vec3::new(1e38, 0.0, 0.0))
        .unwrap_err();
    assert!(e.contains("tx must lie in [-100, 100]"), "{e}");
    assert_eq!(rigid.screw_axis(), axis, "a rejected key changes nothing");
    // At the edge of the range every speed is finite.
    let q = Quat::from_xyzw(1e4, 1e4, -1e4, 1e4);
    rigid.set_end_quat(q, Vec3::splat(100.0)).unwrap();
    for row in rigid.sample_speed(20).unwrap() {
        assert!(row.iter().all(|v| v.is_finite()), "{row:?}");
    }

    let mut affine = AffineKeys::new();
    let e = affine
        .set_key_b(30.0, Vec3::new(1e38, 2.0, 1.0), 0.3)
        .unwrap_err();
    assert!(e.contains("sx must lie in"), "{e}");
    affine
        .set_key_b(30.0, Vec3::new(1e4, 2.0, 1.0), 0.3)
        .unwrap();
    for row in affine.sample_determinant(20).unwrap() {
        assert!(row.iter().all(|v| v.is_finite()), "{row:?}");
    }
}

// ---- setters: every argument checked before any field changes ----
//
// Each test sets a known state, calls the setter with good arguments and one bad one, and
// checks that what the figure shows (its getters, its note, its pose) is exactly as before.

#[test]
fn a_rejected_additive_weight_keeps_the_additive_layer() {
    use inbetween::figures::blending::BlendFigure;
    let mut f = BlendFigure::new();
    f.set_additive("lean forward (a pose)", 0.5).unwrap();
    let note = f.pose(0.3).unwrap();
    let model = f.model().to_vec();
    for bad in [f32::NAN, -0.1, 1.5, 1e38] {
        let e = f.set_additive("wave (a clip)", bad).unwrap_err();
        assert!(e.contains("layer weight"), "{e}");
        assert_eq!(
            f.pose(0.3).unwrap(),
            note,
            "a rejected call changes nothing"
        );
        assert_eq!(f.model(), model.as_slice());
    }
    let e = f.set_additive("no such layer", 0.2).unwrap_err();
    assert!(e.contains("additive layer"), "{e}");
    assert_eq!(f.pose(0.3).unwrap(), note);
    // A good call still applies both.
    f.set_additive("wave (a clip)", 0.25).unwrap();
    assert!(f
        .pose(0.3)
        .unwrap()
        .contains("wave (a clip), layer weight 0.25"));
}

#[test]
fn a_rejected_key_count_keeps_the_clips() {
    use inbetween::figures::skeleton::SkeletonFigure;
    let mut f = SkeletonFigure::new();
    f.set_keys_per_cycle(7.0).unwrap();
    let keys = f.key_times();
    let note = f.pose(0.4).unwrap();
    for bad in [f32::NAN, 3.0, 26.0, 7.5, 1e38] {
        assert!(f.set_keys_per_cycle(bad).is_err(), "{bad}");
        assert_eq!(
            f.key_times(),
            keys,
            "a rejected count keeps the clips ({bad})"
        );
        assert_eq!(f.pose(0.4).unwrap(), note);
    }
    f.set_keys_per_cycle(9.0).unwrap();
    assert_ne!(f.key_times(), keys);
}

// A fractional count is an error, never rounded or truncated, and the figure is left as it was.

#[test]
fn a_fractional_substep_count_is_rejected_not_rounded() {
    use inbetween::figures::cloth::{ClothFigure, Preset};
    // Cloth: 4.5 substeps is refused, not rounded to 5 (which would replay the run).
    let mut cloth = ClothFigure::new(Preset::Flag);
    cloth.set_substeps(4.0).unwrap();
    let mut untouched = cloth.clone();
    let e = cloth.set_substeps(4.5).unwrap_err();
    assert!(
        e.contains("substeps must be a whole number from 1 to 40"),
        "{e}"
    );
    cloth.advance_to(0.3).unwrap();
    untouched.advance_to(0.3).unwrap();
    // The same run, bit for bit (the exploded cloths' samples are NaN, which is not == NaN).
    let bits = |f: &ClothFigure| f.samples().iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&cloth), bits(&untouched));
}

#[test]
fn fractional_segment_and_iteration_counts_are_rejected_not_rounded() {
    use inbetween::figures::ik::IkFigure;
    use inbetween::figures::raster::MeshStorage;
    // IK: 2.5 segments and 10.5 iterations are refused, not rounded to 3 (a chain the analytic
    // solver cannot show) and 11.
    let mut ik = IkFigure::new();
    ik.set_segments(2.0).unwrap();
    let results = ik.results().unwrap();
    let e = ik.set_segments(2.5).unwrap_err();
    assert!(
        e.contains("segments must be a whole number from 2 to 8"),
        "{e}"
    );
    assert_eq!(ik.segments(), 2);
    let e = ik.set_iterations(10.5).unwrap_err();
    assert!(
        e.contains("iterations must be a whole number from 1 to 50"),
        "{e}"
    );
    assert_eq!(ik.results().unwrap(), results);

    // The mesh storage figure: 8.5 segments is refused, not rounded to 9.
    let mut mesh = MeshStorage::new();
    mesh.set_shape("sphere").unwrap();
    mesh.set_segments(8.0).unwrap();
    let sizes = mesh.sizes();
    let e = mesh.set_segments(8.5).unwrap_err();
    assert!(
        e.contains("segments must be a whole number from 3 to 64"),
        "{e}"
    );
    assert_eq!(mesh.sizes(), sizes);
}

#[test]
fn a_fractional_timing_flock_is_rejected_not_truncated() {
    use inbetween::figures::boids::FlockFigure;
    // The boids' timing flock: 500.5 boids is refused, not truncated to 500.
    let mut flock = FlockFigure::new();
    let e = flock.prepare_timing(500.5).unwrap_err();
    assert!(
        e.contains("boids to time must be a whole number from 2 to 20000"),
        "{e}"
    );
    assert!(
        flock.timing_step("grid").is_err(),
        "no timing flock was built"
    );
    flock.prepare_timing(500.0).unwrap();
    flock.timing_step("grid").unwrap();
}

#[test]
fn a_rejected_value_never_leaves_one_copy_of_the_comparison_changed() {
    use glam::Vec3;
    use inbetween::figures::transforms::ScaleComparison;
    let mut c = ScaleComparison::new();
    c.set_upper_arm_scale(Vec3::new(1.0, 1.5, 1.0)).unwrap();
    c.set_forearm_angles_deg(Vec3::new(-40.0, 10.0, 0.0))
        .unwrap();
    // What the figure shows: its note and both forearms, as drawn (the setters pose nothing).
    let shown = |c: &mut ScaleComparison| {
        let note = c.draw(&mut inbetween::draw::Frame::default()).unwrap();
        let shapes = [c.forearm_shape(0), c.forearm_shape(1)];
        let outlines = [c.forearm_outline(0), c.forearm_outline(1)];
        (note, shapes, outlines)
    };
    let before = shown(&mut c);
    let e = c
        .set_upper_arm_scale(Vec3::new(2.0, 2.0, f32::NAN))
        .unwrap_err();
    assert!(e.contains("sz"), "{e}");
    let e = c
        .set_forearm_angles_deg(Vec3::new(10.0, f32::INFINITY, 0.0))
        .unwrap_err();
    assert!(e.contains("y"), "{e}");
    assert_eq!(shown(&mut c), before, "both copies as they were");
    // A good value still reaches both copies.
    c.set_upper_arm_scale(Vec3::new(1.0, 2.5, 1.0)).unwrap();
    let after = shown(&mut c);
    // (Only the copy that inherits scale passes the arm's stretch on to its forearm.)
    assert_ne!(after.1[1], before.1[1]);
}
