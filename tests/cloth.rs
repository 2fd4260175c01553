//! Lesson 13 core: cloth. Rest, dt = 0, collisions, XPBD edge lengths, energy, bad input, the
//! explosion past the stability limit.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec3;
use inbetween::cloth::{
    project_distance, spring_force, Cloth, ClothError, ClothParams, ClothSpec, Colliders, Method,
    SpringKind, MAX_SIDE,
};
use proptest::prelude::*;

fn hanging(side: i64) -> Cloth {
    let spec = ClothSpec {
        columns: side,
        rows: side,
        width_m: 1.0,
        height_m: 1.0,
        mass_kg: 0.25,
        origin: Vec3::new(-0.5, 2.0, 0.0),
        across: Vec3::X,
        down: Vec3::NEG_Y,
    };
    Cloth::new(&spec).unwrap()
}

fn no_ground() -> Colliders {
    Colliders {
        ground_y: None,
        ..Default::default()
    }
}

#[test]
fn grid_counts() {
    let c = hanging(5);
    assert_eq!(c.len(), 25);
    let count = |k| c.springs.iter().filter(|s| s.kind == k).count();
    assert_eq!(count(SpringKind::Structural), 2 * 5 * 4);
    assert_eq!(count(SpringKind::Shear), 2 * 4 * 4);
    assert_eq!(count(SpringKind::Bending), 2 * 5 * 3);
    assert_eq!(c.triangles.len(), 2 * 4 * 4);
    // Normals of a flat cloth: all along across × down = X × −Y = −Z.
    for n in &c.normals {
        assert!((*n - Vec3::NEG_Z).length() < 1e-6, "{n}");
    }
}

#[test]
fn at_rest_with_pinned_corners_and_no_gravity_stays_at_rest() {
    for method in [Method::MassSpring, Method::Xpbd] {
        let mut c = hanging(12);
        let (a, b) = (c.index(0, 0), c.index(11, 0));
        c.set_pinned(a, true);
        c.set_pinned(b, true);
        let start = c.positions.clone();
        let params = ClothParams {
            gravity: Vec3::ZERO,
            method,
            ..Default::default()
        };
        for _ in 0..120 {
            c.step(&params, &no_ground(), 1.0 / 60.0).unwrap();
        }
        let moved = c
            .positions
            .iter()
            .zip(&start)
            .map(|(p, q)| (*p - *q).length())
            .fold(0.0f32, f32::max);
        assert!(moved < 1e-6, "{method:?} moved {moved}");
        assert!(c.energy(&params).abs() < 1e-6);
    }
}

#[test]
fn dt_zero_changes_nothing() {
    for method in [Method::MassSpring, Method::Xpbd] {
        let mut c = hanging(8);
        c.set_pinned(0, true);
        let params = ClothParams {
            method,
            wind: Vec3::new(5.0, 0.0, 3.0),
            ..Default::default()
        };
        for _ in 0..10 {
            c.step(&params, &Colliders::default(), 1.0 / 60.0).unwrap();
        }
        let (p, v, n, t) = (
            c.positions.clone(),
            c.velocities.clone(),
            c.normals.clone(),
            c.time_sec,
        );
        c.step(&params, &Colliders::default(), 0.0).unwrap();
        assert_eq!(c.positions, p);
        assert_eq!(c.velocities, v);
        assert_eq!(c.normals, n);
        assert_eq!(c.time_sec, t);
    }
}

#[test]
fn no_particle_ends_inside_the_sphere_or_under_the_ground() {
    for method in [Method::MassSpring, Method::Xpbd] {
        let mut c = Cloth::new(&ClothSpec::level(20, 1.5)).unwrap();
        let colliders = Colliders {
            ground_y: Some(0.0),
            sphere: Some((Vec3::new(0.1, 0.6, 0.0), 0.5)),
            cuboid: Some((Vec3::new(-0.7, 0.2, 0.5), Vec3::new(0.2, 0.2, 0.2))),
            friction: 0.4,
            thickness: 0.01,
        };
        let params = ClothParams {
            method,
            ..Default::default()
        };
        let mut touched = false;
        for frame in 0..240 {
            c.step(&params, &colliders, 1.0 / 60.0).unwrap();
            assert!(
                c.exploded().is_none(),
                "{method:?} exploded at frame {frame}"
            );
            for p in &c.positions {
                assert!(p.y >= 0.01 - 1e-5, "{method:?}: {p} under the ground");
                let d = (*p - Vec3::new(0.1, 0.6, 0.0)).length();
                assert!(d >= 0.51 - 1e-4, "{method:?}: {p} inside the sphere ({d})");
                touched |= d < 0.52;
                let q = (*p - Vec3::new(-0.7, 0.2, 0.5)).abs();
                assert!(
                    q.max_element() >= 0.21 - 1e-4
                        || q.x >= 0.21 - 1e-4
                        || q.y >= 0.21 - 1e-4
                        || q.z >= 0.21 - 1e-4,
                    "{method:?}: {p} inside the box"
                );
            }
        }
        assert!(touched, "{method:?}: the cloth never reached the sphere");
        // It came to drape: it went down around the sphere (some particles near the ground).
        assert!(
            c.positions.iter().any(|p| p.y < 0.2),
            "{method:?} did not drape"
        );
    }
}

#[test]
fn friction_holds_the_cloth_on_the_sphere() {
    // With friction the draped cloth slides off the sphere more slowly: its centre stays higher.
    let run = |mu: f32| {
        let mut c = Cloth::new(&ClothSpec::level(16, 1.3)).unwrap();
        let colliders = Colliders {
            sphere: Some((Vec3::new(0.3, 0.6, 0.0), 0.5)),
            friction: mu,
            ..Default::default()
        };
        let params = ClothParams {
            method: Method::Xpbd,
            ..Default::default()
        };
        for _ in 0..150 {
            c.step(&params, &colliders, 1.0 / 60.0).unwrap();
        }
        c.positions.iter().map(|p| p.x).sum::<f32>() / c.len() as f32
    };
    // The sphere is off-centre: without friction the cloth slides towards −x off its top.
    let (slippery, grippy) = (run(0.0), run(2.0));
    assert!(
        (grippy - 0.3).abs() < (slippery - 0.3).abs(),
        "mean x: μ = 0 → {slippery}, μ = 2 → {grippy}"
    );
}

#[test]
fn xpbd_with_zero_compliance_keeps_edge_lengths() {
    let mut c = hanging(16);
    let (a, b) = (c.index(0, 0), c.index(15, 0));
    c.set_pinned(a, true);
    c.set_pinned(b, true);
    let params = ClothParams {
        method: Method::Xpbd,
        compliance: [0.0, 0.0, 0.0],
        substeps: 20,
        wind: Vec3::new(3.0, 0.0, 4.0),
        ..Default::default()
    };
    for _ in 0..120 {
        c.step(&params, &no_ground(), 1.0 / 60.0).unwrap();
    }
    let worst = c.max_stretch();
    assert!(worst < 0.02, "XPBD α = 0: max stretch {worst}");
    // It did move (the corners hold it, gravity and wind pull it).
    assert!(c.positions[c.index(8, 15)].z > 0.05);
    // The same cloth as springs of the same order of stiffness stretches far more.
    let mut soft = hanging(16);
    soft.set_pinned(a, true);
    soft.set_pinned(b, true);
    let p = ClothParams {
        method: Method::MassSpring,
        ..params
    };
    for _ in 0..120 {
        soft.step(&p, &no_ground(), 1.0 / 60.0).unwrap();
    }
    assert!(soft.max_stretch() > 2.0 * worst);
}

#[test]
fn energy_does_not_grow_without_external_forces() {
    for method in [Method::MassSpring, Method::Xpbd] {
        let mut c = hanging(10);
        // Disturb it: stretch it sideways by 20 % and give one row a kick.
        for p in &mut c.positions {
            p.x *= 1.2;
        }
        for i in 0..10 {
            c.velocities[i] = Vec3::new(0.0, 0.0, 1.0);
        }
        let mut params = ClothParams {
            method,
            gravity: Vec3::ZERO,
            wind: Vec3::ZERO,
            ..Default::default()
        };
        params.compliance_from_stiffness();
        let e0 = c.energy(&params);
        let mut last = e0;
        let mut highest = e0;
        for _ in 0..300 {
            c.step(&params, &no_ground(), 1.0 / 60.0).unwrap();
            let e = c.energy(&params);
            highest = highest.max(e);
            last = e;
        }
        assert!(c.exploded().is_none());
        assert!(
            highest <= e0 * 1.02,
            "{method:?}: energy rose to {highest} from {e0}"
        );
        assert!(
            last < e0,
            "{method:?}: damping took no energy ({last} vs {e0})"
        );
    }
}

#[test]
fn momentum_is_conserved_by_the_springs() {
    let mut c = hanging(6);
    for (i, p) in c.positions.iter_mut().enumerate() {
        *p += Vec3::new(0.01 * (i % 3) as f32, 0.0, -0.02 * (i % 2) as f32);
    }
    let params = ClothParams {
        gravity: Vec3::ZERO,
        drag: 0.0,
        ..Default::default()
    };
    for _ in 0..20 {
        c.step(&params, &no_ground(), 1.0 / 60.0).unwrap();
    }
    let momentum: Vec3 = c.velocities.iter().sum::<Vec3>() * c.particle_mass;
    assert!(momentum.length() < 1e-5, "{momentum}");
}

#[test]
fn past_the_stability_limit_it_explodes_and_is_detected_and_resettable() {
    let mut c = hanging(12);
    c.set_pinned(0, true);
    c.set_pinned(11, true);
    let stiff = ClothParams {
        stiffness: [4000.0, 2000.0, 1000.0],
        substeps: 2,
        ..Default::default()
    };
    let limit = c.stable_substep_estimate(&stiff);
    assert!(
        1.0 / 120.0 > 2.0 * limit,
        "the step is past the limit {limit}"
    );
    for _ in 0..60 {
        c.step(&stiff, &no_ground(), 1.0 / 60.0).unwrap();
    }
    let when = c.exploded().expect("exploded");
    assert!(when < 1.0);
    let frozen = c.positions.clone();
    c.step(&stiff, &no_ground(), 1.0 / 60.0).unwrap();
    assert_eq!(c.positions, frozen, "an exploded cloth no longer moves");
    // Below the limit the same cloth is fine.
    c.reset();
    assert!(c.exploded().is_none() && c.time_sec == 0.0);
    let fine = ClothParams::default();
    assert!(1.0 / 60.0 / fine.substeps as f32 <= c.stable_substep_estimate(&fine));
    for _ in 0..120 {
        c.step(&fine, &no_ground(), 1.0 / 60.0).unwrap();
    }
    assert!(c.exploded().is_none());
    assert!(c.max_stretch() < 0.3);
    // XPBD with the same stiffness (α = 1/k) and step stays put together.
    c.reset();
    let mut xpbd = ClothParams {
        method: Method::Xpbd,
        ..stiff
    };
    xpbd.compliance_from_stiffness();
    for _ in 0..120 {
        c.step(&xpbd, &no_ground(), 1.0 / 60.0).unwrap();
    }
    assert!(c.exploded().is_none());
}

#[test]
fn wind_pushes_along_the_normal() {
    // A level cloth, held at its four corners, in an updraft bulges up.
    let mut c = Cloth::new(&ClothSpec::level(10, 1.0)).unwrap();
    for (col, row) in [(0, 0), (9, 0), (0, 9), (9, 9)] {
        let i = c.index(col, row);
        c.set_pinned(i, true);
    }
    let params = ClothParams {
        gravity: Vec3::ZERO,
        wind: Vec3::new(0.0, 5.0, 0.0),
        ..Default::default()
    };
    for _ in 0..30 {
        c.step(&params, &no_ground(), 1.0 / 60.0).unwrap();
    }
    assert!(c.positions[c.index(5, 5)].y > 1.01);
    // Wind in the cloth's plane does nothing to a flat cloth.
    let mut flat = Cloth::new(&ClothSpec::level(6, 1.0)).unwrap();
    let side = ClothParams {
        gravity: Vec3::ZERO,
        wind: Vec3::new(5.0, 0.0, 0.0),
        ..Default::default()
    };
    flat.step(&side, &no_ground(), 1.0 / 60.0).unwrap();
    assert!(flat.velocities.iter().all(|v| v.length() < 1e-6));
}

#[test]
fn a_grabbed_particle_follows_the_pointer() {
    for method in [Method::MassSpring, Method::Xpbd] {
        let mut c = hanging(8);
        let target = Vec3::new(0.2, 1.8, 0.4);
        c.grab = Some((c.index(4, 4), target));
        let params = ClothParams {
            method,
            gravity: Vec3::ZERO,
            ..Default::default()
        };
        for _ in 0..30 {
            c.step(&params, &no_ground(), 1.0 / 60.0).unwrap();
        }
        assert!((c.positions[c.index(4, 4)] - target).length() < 1e-5);
        // Its neighbours were dragged along.
        assert!(c.exploded().is_none(), "{method:?}");
        assert!(
            c.positions[c.index(4, 5)].z > 0.1,
            "{method:?} {} {:?}",
            c.positions[c.index(4, 5)],
            c.exploded()
        );
    }
}

#[test]
fn bad_input_is_an_error() {
    for (columns, rows) in [(0, 5), (5, 0), (-3, 5), (1, 5), (MAX_SIDE as i64 + 1, 2)] {
        let spec = ClothSpec {
            columns,
            rows,
            ..ClothSpec::level(4, 1.0)
        };
        let e = Cloth::new(&spec).unwrap_err();
        assert_eq!(e, ClothError::Resolution { columns, rows });
        assert!(e.to_string().contains("between 2 and 256"), "{e}");
    }
    assert!(Cloth::new(&ClothSpec::level(MAX_SIDE as i64, 1.0)).is_ok());
    let bad_mass = ClothSpec {
        mass_kg: f32::NAN,
        ..ClothSpec::level(4, 1.0)
    };
    assert!(Cloth::new(&bad_mass)
        .unwrap_err()
        .to_string()
        .contains("mass"));
    let mut c = hanging(4);
    let nan_k = ClothParams {
        stiffness: [f32::NAN, 1.0, 1.0],
        ..Default::default()
    };
    let e = c.step(&nan_k, &no_ground(), 0.01).unwrap_err();
    assert!(e.to_string().contains("structural stiffness"), "{e}");
    let e = c
        .step(&ClothParams::default(), &no_ground(), f32::NAN)
        .unwrap_err();
    assert!(e.to_string().contains("dt"), "{e}");
    let zero_substeps = ClothParams {
        substeps: 0,
        ..Default::default()
    };
    assert!(c.step(&zero_substeps, &no_ground(), 0.01).is_err());
    let nan_wind = ClothParams {
        wind: Vec3::new(f32::INFINITY, 0.0, 0.0),
        ..Default::default()
    };
    assert!(c.step(&nan_wind, &no_ground(), 0.01).is_err());
    let bad_sphere = Colliders {
        sphere: Some((Vec3::ZERO, -1.0)),
        ..Default::default()
    };
    assert!(c.step(&ClothParams::default(), &bad_sphere, 0.01).is_err());
    c.grab = Some((999, Vec3::ZERO));
    assert!(c.step(&ClothParams::default(), &no_ground(), 0.01).is_err());
    // Nothing moved through all of that.
    assert!(c.exploded().is_none() && c.time_sec == 0.0);
}

proptest! {
    #[test]
    fn spring_force_is_equal_and_opposite_and_along_the_spring(
        a in prop::array::uniform3(-2.0f32..2.0), b in prop::array::uniform3(-2.0f32..2.0),
        va in prop::array::uniform3(-3.0f32..3.0), vb in prop::array::uniform3(-3.0f32..3.0),
        k in 0.0f32..500.0, c in 0.0f32..5.0, rest in 0.1f32..2.0,
    ) {
        let (a, b, va, vb) = (Vec3::from(a), Vec3::from(b), Vec3::from(va), Vec3::from(vb));
        prop_assume!((b - a).length() > 1e-3);
        let fa = spring_force(a, b, va, vb, k, c, rest);
        let fb = spring_force(b, a, vb, va, k, c, rest);
        prop_assert!((fa + fb).length() <= 1e-3 * (1.0 + fa.length()));
        prop_assert!(fa.cross((b - a).normalize()).length() <= 1e-3 * (1.0 + fa.length()));
    }

    #[test]
    fn rigid_projection_restores_the_length_and_keeps_the_centre_of_mass(
        a in prop::array::uniform3(-2.0f32..2.0), b in prop::array::uniform3(-2.0f32..2.0),
        wa in 0.0f32..10.0, wb in 0.1f32..10.0, rest in 0.1f32..2.0, alpha in 0.0f32..1e-3,
    ) {
        let (mut pa, mut pb) = (Vec3::from(a), Vec3::from(b));
        prop_assume!((pb - pa).length() > 1e-2);
        let before = wb * pa + wa * pb; // mass-weighted centre times (wa wb)(1/wa + 1/wb)
        let (mut sa, mut sb) = (pa, pb);
        project_distance(&mut pa, &mut pb, wa, wb, rest, 0.0, 0.01);
        prop_assert!(((pb - pa).length() - rest).abs() < 1e-4);
        prop_assert!((wb * pa + wa * pb - before).length() < 1e-3);
        // With compliance the ends move less, but the centre of mass still stays put (exercise
        // 13.3's hint: wb·Δpa + wa·Δpb = 0).
        project_distance(&mut sa, &mut sb, wa, wb, rest, alpha, 0.01);
        prop_assert!((wb * sa + wa * sb - before).length() < 1e-3);
    }
}

#[test]
fn the_benchmark_cloth_stays_stable() {
    for method in [Method::MassSpring, Method::Xpbd] {
        // Fewer frames at 100 × 100: the tests run unoptimised.
        for (side, frames) in [(32, 60), (100, 12)] {
            let (mut c, p, col) = inbetween::cloth::benchmark_cloth(side, method).unwrap();
            for _ in 0..frames {
                c.step(&p, &col, 1.0 / 60.0).unwrap();
            }
            assert!(
                c.exploded().is_none(),
                "{method:?} {side}: {}",
                c.max_stretch()
            );
        }
    }
}
