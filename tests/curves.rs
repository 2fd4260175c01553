//! Tests of the keyframe curves core (`inbetween::curves`): validation, every scheme through
//! its keys, continuity at keys, end behaviours, cursor against binary search, arc length,
//! timing, and reference values from scipy (`tests/data/curves_scipy.csv`, written by
//! `scripts/reference/curves_scipy.py`).
//!
//! Run with `cargo test --test native curves:: -- --nocapture` to see the measured errors.
// Native only (proptest); the browser runs tests/transform.rs and tests/web*.rs.
#![cfg(not(target_arch = "wasm32"))]
// Loops over key indices read like the formulas (`i − 1`, `i`, `i + 1`).
#![allow(clippy::needless_range_loop)]

use glam::{Vec2, Vec3, Vec4};
use inbetween::curves::*;
use proptest::prelude::*;

// ---------------------------------------------------------------------------------------------
// Helpers

/// `|a − b| ≤ eps · (1 + |b|)`: absolute near zero, relative for large values.
fn close<T: Value>(a: T, b: T, eps: f32) -> bool {
    (a - b).length() <= eps * (1.0 + b.length())
}

macro_rules! assert_close {
    ($a:expr, $b:expr, $eps:expr) => {
        assert_close!($a, $b, $eps, "")
    };
    ($a:expr, $b:expr, $eps:expr, $($context:tt)+) => {{
        let (a, b, eps) = ($a, $b, $eps);
        assert!(close(a, b, eps), "{:?} is not within {} of {:?}: {}", a, eps, b, format!($($context)+));
    }};
}

const ALL_SCHEMES: [Interpolation; 8] = [
    Interpolation::Step,
    Interpolation::Linear,
    Interpolation::Lagrange,
    Interpolation::Hermite,
    Interpolation::Cardinal { tension: 0.5 },
    Interpolation::CATMULL_ROM,
    Interpolation::Natural,
    Interpolation::Centripetal,
];

/// Five keys at non-uniform times, a 3D path with a sharp turn.
fn keys_3d() -> (Vec<f32>, Vec<Vec3>) {
    (
        vec![0.0, 0.4, 1.5, 1.9, 3.2],
        vec![
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 2.0, 0.0),
            Vec3::new(3.0, 2.5, -1.0),
            Vec3::new(3.2, 0.0, -1.5),
            Vec3::new(5.0, 1.0, 0.5),
        ],
    )
}

fn track_3d(interpolation: Interpolation) -> Track<Vec3> {
    let (times, values) = keys_3d();
    let track = Track::new(times, values).unwrap();
    if interpolation == Interpolation::Hermite {
        // A Hermite track with broken tangents at key 2.
        let mut track = track
            .with_interpolation(Interpolation::CATMULL_ROM)
            .unwrap();
        track
            .set_tangents(2, Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, -2.0, 1.0))
            .unwrap();
        track
    } else {
        track.with_interpolation(interpolation).unwrap()
    }
}

/// One-sided second-order derivative estimates `(left, right)` of a track's position at `t`.
fn one_sided_derivatives<T: Value>(track: &Track<T>, t: f32, delta: f32) -> (T, T) {
    let p = |t: f32| track.position(t);
    let left = (p(t) * 3.0 - p(t - delta) * 4.0 + p(t - 2.0 * delta)) * (1.0 / (2.0 * delta));
    let right = (p(t + delta) * 4.0 - p(t) * 3.0 - p(t + 2.0 * delta)) * (1.0 / (2.0 * delta));
    (left, right)
}

// ---------------------------------------------------------------------------------------------
// Validation: one failing input per rule

#[test]
fn empty_track_is_rejected() {
    let error = Track::<f32>::new(vec![], vec![]).unwrap_err();
    assert_eq!(error, TrackError::Empty);
    assert!(error.to_string().contains("at least one key"));
}

#[test]
fn mismatched_lengths_are_rejected() {
    let error = Track::new(vec![0.0, 1.0, 2.0], vec![1.0_f32, 2.0]).unwrap_err();
    assert_eq!(
        error,
        TrackError::LengthMismatch {
            times: 3,
            values: 2
        }
    );
    assert!(error.to_string().contains("3 key times but 2 key values"));
    // Times without values is a mismatch, not an empty track.
    assert!(matches!(
        Track::<f32>::new(vec![0.0], vec![]),
        Err(TrackError::LengthMismatch { .. })
    ));
}

#[test]
fn non_finite_times_are_rejected_with_their_index() {
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let error = Track::new(vec![0.0, 1.0, bad], vec![0.0_f32; 3]).unwrap_err();
        assert!(
            matches!(error, TrackError::NonFiniteTime { index: 2, .. }),
            "{error:?}"
        );
        assert!(error.to_string().starts_with("key 2 has time"), "{error}");
    }
}

#[test]
fn non_finite_values_are_rejected_with_their_index() {
    let values = vec![Vec3::ZERO, Vec3::new(1.0, f32::NAN, 0.0), Vec3::ONE];
    let error = Track::new(vec![0.0, 1.0, 2.0], values).unwrap_err();
    assert_eq!(error, TrackError::NonFiniteValue { index: 1 });
    assert_eq!(
        error.to_string(),
        "key 1 has a value that is NaN or infinite"
    );
    let error = Track::new(vec![0.0], vec![f32::INFINITY]).unwrap_err();
    assert_eq!(error, TrackError::NonFiniteValue { index: 0 });
}

#[test]
fn times_not_strictly_increasing_are_rejected_with_their_index() {
    // Equal times.
    let error = Track::new(vec![0.0, 1.0, 1.0], vec![0.0_f32; 3]).unwrap_err();
    assert_eq!(
        error,
        TrackError::TimesNotIncreasing {
            index: 2,
            previous_sec: 1.0,
            time_sec: 1.0
        }
    );
    // Decreasing times.
    let error = Track::new(vec![0.0, 2.0, 1.0, 3.0], vec![0.0_f32; 4]).unwrap_err();
    assert_eq!(
        error,
        TrackError::TimesNotIncreasing {
            index: 2,
            previous_sec: 2.0,
            time_sec: 1.0
        }
    );
    assert_eq!(
        error.to_string(),
        "key times must strictly increase, but key 2 is at 1 s, not after key 1 at 2 s"
    );
}

#[test]
fn hermite_tangent_counts_must_match_keys() {
    let error = Track::new_hermite(
        vec![0.0, 1.0],
        vec![0.0_f32, 1.0],
        vec![0.0],
        vec![0.0, 0.0],
    )
    .unwrap_err();
    assert_eq!(
        error,
        TrackError::TangentCountMismatch {
            keys: 2,
            tangents_in: 1,
            tangents_out: 2
        }
    );
    assert!(error
        .to_string()
        .contains("2 keys but 1 in tangents and 2 out tangents"));
}

#[test]
fn non_finite_tangents_are_rejected_with_their_index() {
    let error = Track::new_hermite(
        vec![0.0, 1.0],
        vec![0.0_f32, 1.0],
        vec![0.0, 0.0],
        vec![0.0, f32::NAN],
    )
    .unwrap_err();
    assert_eq!(error, TrackError::NonFiniteTangent { index: 1 });
    let mut track = Track::new(vec![0.0, 1.0], vec![0.0_f32, 1.0]).unwrap();
    let before = track.clone();
    assert_eq!(
        track.set_tangents(0, f32::INFINITY, 0.0),
        Err(TrackError::NonFiniteTangent { index: 0 })
    );
    assert_eq!(track, before, "a rejected edit leaves the track unchanged");
}

#[test]
fn tension_outside_zero_two_is_rejected() {
    let track = Track::new(vec![0.0, 1.0], vec![0.0_f32, 1.0]).unwrap();
    for tension in [-0.1, 2.1, f32::NAN] {
        let error = track
            .clone()
            .with_interpolation(Interpolation::Cardinal { tension })
            .unwrap_err();
        assert!(
            matches!(error, TrackError::TensionOutOfRange { .. }),
            "{error:?}"
        );
        assert!(error
            .to_string()
            .starts_with("the tension must be between 0 and 2"));
    }
    for tension in [0.0, 1.0, 2.0] {
        assert!(track
            .clone()
            .with_interpolation(Interpolation::Cardinal { tension })
            .is_ok());
    }
}

#[test]
fn editing_a_missing_key_is_rejected() {
    let mut track = Track::new(vec![0.0, 1.0], vec![0.0_f32, 1.0]).unwrap();
    let error = track.set_tangents(2, 0.0, 0.0).unwrap_err();
    assert_eq!(error, TrackError::KeyOutOfRange { index: 2, keys: 2 });
    assert_eq!(
        error.to_string(),
        "there is no key 2: the track has 2 keys, numbered from 0 to 1"
    );
}

#[test]
fn errors_are_std_errors() {
    let error: Box<dyn std::error::Error> = Box::new(TrackError::Empty);
    assert!(!error.to_string().is_empty());
}

// ---------------------------------------------------------------------------------------------
// Every scheme passes through its keys

#[test]
fn every_scheme_passes_through_its_keys() {
    let (times, values) = keys_3d();
    for scheme in ALL_SCHEMES {
        let track = track_3d(scheme);
        for (i, (&t, &p)) in times.iter().zip(&values).enumerate() {
            assert_close!(track.position(t), p, 1e-5, "{scheme:?} at key {i}");
        }
    }
}

#[test]
fn scalar_vec2_and_vec4_tracks_pass_through_their_keys() {
    let times = vec![0.0, 0.3, 1.0, 1.2];
    let scalars = vec![0.0_f32, 1.0, -1.0, 2.0];
    let track = Track::new(times.clone(), scalars.clone()).unwrap();
    let vec2 = Track::new(
        times.clone(),
        scalars.iter().map(|&x| Vec2::new(x, -x)).collect(),
    )
    .unwrap();
    let vec4 = Track::new(
        times.clone(),
        scalars.iter().map(|&x| Vec4::splat(x)).collect(),
    )
    .unwrap();
    for scheme in ALL_SCHEMES
        .into_iter()
        .filter(|s| *s != Interpolation::Hermite)
    {
        let (track, vec2, vec4) = (
            track.clone().with_interpolation(scheme).unwrap(),
            vec2.clone().with_interpolation(scheme).unwrap(),
            vec4.clone().with_interpolation(scheme).unwrap(),
        );
        for (&t, &x) in times.iter().zip(&scalars) {
            assert_close!(track.position(t), x, 1e-5, "{scheme:?}");
            assert_close!(vec2.position(t), Vec2::new(x, -x), 1e-5, "{scheme:?}");
            assert_close!(vec4.position(t), Vec4::splat(x), 1e-5, "{scheme:?}");
        }
    }
}

#[test]
fn single_key_track_is_constant() {
    for scheme in ALL_SCHEMES {
        let track = Track::new(vec![1.0], vec![Vec3::ONE])
            .unwrap()
            .with_interpolation(scheme)
            .unwrap();
        for behaviour in [
            EndBehaviour::Clamp,
            EndBehaviour::Extrapolate,
            EndBehaviour::Loop,
            EndBehaviour::PingPong,
        ] {
            let track = track.clone().with_end_behaviour(behaviour);
            for t in [-5.0, 1.0, 7.0] {
                assert_eq!(
                    track.evaluate(t),
                    Sample::at_rest(Vec3::ONE),
                    "{scheme:?} {behaviour:?}"
                );
            }
        }
    }
}

#[test]
fn linear_is_exact_at_start_midpoint_and_end() {
    let track = Track::new(
        vec![1.0, 3.0],
        vec![Vec2::new(0.0, 4.0), Vec2::new(2.0, 0.0)],
    )
    .unwrap();
    assert_eq!(track.position(1.0), Vec2::new(0.0, 4.0));
    assert_eq!(track.position(2.0), Vec2::new(1.0, 2.0));
    assert_eq!(track.position(3.0), Vec2::new(2.0, 0.0));
    assert_eq!(track.velocity(1.7), Vec2::new(1.0, -2.0));
    assert_eq!(track.acceleration(1.7), Vec2::ZERO);
}

#[test]
fn step_holds_each_value_until_the_next_key() {
    let track = Track::new(vec![0.0, 1.0, 2.0], vec![5.0_f32, 6.0, 7.0])
        .unwrap()
        .with_interpolation(Interpolation::Step)
        .unwrap();
    assert_eq!(track.position(0.999), 5.0);
    assert_eq!(track.position(1.0), 6.0);
    assert_eq!(track.position(1.999), 6.0);
    assert_eq!(track.position(2.0), 7.0);
    assert_eq!(track.velocity(0.5), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Hermite basis and tangents

#[test]
fn hermite_basis_endpoints_and_partition_of_unity() {
    assert_eq!(hermite_basis(0.0), [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(hermite_basis(1.0), [0.0, 0.0, 1.0, 0.0]);
    assert_eq!(hermite_basis_derivative(0.0), [0.0, 1.0, 0.0, 0.0]);
    assert_eq!(hermite_basis_derivative(1.0), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(hermite_basis(0.5), [0.5, 0.125, 0.5, -0.125]);
    for k in 0..=20 {
        let s = k as f32 / 20.0;
        let [h00, _, h01, _] = hermite_basis(s);
        assert!((h00 + h01 - 1.0).abs() < 1e-6);
        // Derivatives against central differences.
        let delta = 1e-3;
        let (a, b) = (hermite_basis(s - delta), hermite_basis(s + delta));
        let d = hermite_basis_derivative(s);
        let (da, db) = (
            hermite_basis_derivative(s - delta),
            hermite_basis_derivative(s + delta),
        );
        let dd = hermite_basis_second_derivative(s);
        for j in 0..4 {
            assert!(
                ((b[j] - a[j]) / (2.0 * delta) - d[j]).abs() < 1e-3,
                "h' {j} at {s}"
            );
            assert!(
                ((db[j] - da[j]) / (2.0 * delta) - dd[j]).abs() < 1e-3,
                "h'' {j} at {s}"
            );
        }
    }
}

#[test]
fn cardinal_tangents_follow_the_non_uniform_formula() {
    let times = [0.0, 1.0, 1.5, 4.0];
    let values = [0.0_f32, 2.0, 1.0, 3.0];
    let mut out = [f32::NAN; 4];
    cardinal_tangents(&times, &values, 1.0, &mut out);
    assert_eq!(out, [2.0, 1.0 / 1.5, 1.0 / 3.0, 2.0 / 2.5]);
    cardinal_tangents(&times, &values, 2.0, &mut out);
    assert_eq!(out, [4.0, 2.0 / 1.5, 2.0 / 3.0, 4.0 / 2.5]);
    // Uniform times, tension 1: the Catmull-Rom tangent (p_{i+1} − p_{i−1}) / 2Δt.
    let mut out = [0.0; 3];
    cardinal_tangents(&[0.0, 0.5, 1.0], &[0.0_f32, 1.0, 4.0], 1.0, &mut out);
    assert_eq!(out[1], 4.0 / 1.0);
    // One key: zero tangent.
    let mut one = [1.0_f32];
    cardinal_tangents(&[3.0], &[5.0_f32], 1.0, &mut one);
    assert_eq!(one, [0.0]);
}

#[test]
fn tension_zero_gives_zero_tangents() {
    let (times, values) = keys_3d();
    let mut out = vec![Vec3::ONE; times.len()];
    cardinal_tangents(&times, &values, 0.0, &mut out);
    assert!(out.iter().all(|&d| d == Vec3::ZERO));
    let track = track_3d(Interpolation::Cardinal { tension: 0.0 });
    for &t in &times {
        assert_eq!(track.velocity(t), Vec3::ZERO);
    }
}

#[test]
fn cubic_schemes_are_c1_at_keys() {
    let (times, _) = keys_3d();
    for scheme in [
        Interpolation::Cardinal { tension: 0.5 },
        Interpolation::CATMULL_ROM,
        Interpolation::Natural,
    ] {
        let track = track_3d(scheme);
        for i in 1..times.len() - 1 {
            let (left, right) = one_sided_derivatives(&track, times[i], 1e-3);
            assert_close!(left, right, 5e-3, "{scheme:?} at key {i}");
            assert_close!(
                right,
                track.tangents_out()[i],
                5e-3,
                "{scheme:?} at key {i}"
            );
        }
    }
}

#[test]
fn hermite_follows_broken_tangents() {
    let track = track_3d(Interpolation::Hermite);
    let (times, _) = keys_3d();
    for i in 1..times.len() - 1 {
        let (left, right) = one_sided_derivatives(&track, times[i], 1e-3);
        assert_close!(left, track.tangents_in()[i], 5e-3, "in tangent at key {i}");
        assert_close!(
            right,
            track.tangents_out()[i],
            5e-3,
            "out tangent at key {i}"
        );
    }
    assert_eq!(track.tangents_in()[2], Vec3::new(1.0, 0.0, 0.0));
    assert_eq!(track.tangents_out()[2], Vec3::new(0.0, -2.0, 1.0));
}

#[test]
fn switching_to_hermite_keeps_the_curve() {
    for scheme in [
        Interpolation::Linear,
        Interpolation::CATMULL_ROM,
        Interpolation::Natural,
        Interpolation::Centripetal,
    ] {
        let track = track_3d(scheme);
        let hermite = track
            .clone()
            .with_interpolation(Interpolation::Hermite)
            .unwrap();
        for k in 0..=64 {
            let t = 3.2 * k as f32 / 64.0;
            assert_close!(
                hermite.position(t),
                track.position(t),
                1e-5,
                "{scheme:?} at {t}"
            );
        }
    }
}

#[test]
fn natural_spline_is_c2_with_zero_end_curvature() {
    let track = track_3d(Interpolation::Natural);
    let (times, values) = keys_3d();
    let (d_in, d_out) = (track.tangents_in(), track.tangents_out());
    for i in 1..times.len() - 1 {
        // Acceleration at t_i from the segment on the left, and from the segment on the right.
        let [_, _, left] = hermite_segment(
            times[i - 1],
            times[i],
            values[i - 1],
            d_out[i - 1],
            values[i],
            d_in[i],
            times[i],
        );
        let right = track.acceleration(times[i]);
        assert_close!(left, right, 1e-4, "second derivative at key {i}");
    }
    assert_close!(track.acceleration(times[0]), Vec3::ZERO, 1e-4);
    assert_close!(track.acceleration(times[times.len() - 1]), Vec3::ZERO, 1e-4);
    // The cardinal spline is not C2: it shows that the test above can fail.
    let cardinal = track_3d(Interpolation::CATMULL_ROM);
    let i = 2;
    let [_, _, left] = hermite_segment(
        times[i - 1],
        times[i],
        values[i - 1],
        cardinal.tangents_out()[i - 1],
        values[i],
        cardinal.tangents_in()[i],
        times[i],
    );
    assert!(!close(left, cardinal.acceleration(times[i]), 1e-2));
}

#[test]
fn centripetal_track_equals_the_barry_goldman_pyramid() {
    let track = track_3d(Interpolation::Centripetal);
    let (times, values) = keys_3d();
    for i in 0..times.len() - 1 {
        let (points, knots) = centripetal_segment_points(&values, i);
        for k in 0..=10 {
            let s = k as f32 / 10.0;
            let t = times[i] + s * (times[i + 1] - times[i]);
            let tau = knots[1] + s * (knots[2] - knots[1]);
            assert_close!(
                track.position(t),
                barry_goldman(points, knots, tau),
                1e-5,
                "segment {i}, s = {s}"
            );
        }
    }
}

#[test]
fn centripetal_direction_is_continuous_at_keys() {
    let track = track_3d(Interpolation::Centripetal);
    for i in 1..4 {
        let (d_in, d_out) = (track.tangents_in()[i], track.tangents_out()[i]);
        assert_close!(d_in.normalize(), d_out.normalize(), 1e-5, "key {i}");
    }
}

#[test]
fn centripetal_has_no_loop_where_catmull_rom_has_one() {
    // Two close keys between distant ones: uniform Catmull-Rom makes a loop (the x coordinate
    // goes backwards), centripetal does not.
    let times = vec![0.0, 1.0, 2.0, 3.0];
    let values = vec![
        Vec2::new(0.0, 0.0),
        Vec2::new(4.0, 0.0),
        Vec2::new(4.2, 0.1),
        Vec2::new(8.0, 0.0),
    ];
    let uniform = Track::new(times.clone(), values.clone())
        .unwrap()
        .with_interpolation(Interpolation::CATMULL_ROM)
        .unwrap();
    let centripetal = Track::new(times, values)
        .unwrap()
        .with_interpolation(Interpolation::Centripetal)
        .unwrap();
    let backwards =
        |track: &Track<Vec2>| (0..=300).any(|k| track.velocity(1.0 + k as f32 / 300.0).x < 0.0);
    assert!(backwards(&uniform));
    assert!(!backwards(&centripetal));
}

// ---------------------------------------------------------------------------------------------
// Lagrange

#[test]
fn lagrange_reproduces_a_polynomial_of_degree_n_minus_one() {
    // q(t) = 0.5 t⁴ − t³ + 2t − 1 through 5 keys at non-uniform times.
    let q = |t: f32| 0.5 * t.powi(4) - t.powi(3) + 2.0 * t - 1.0;
    let dq = |t: f32| 2.0 * t.powi(3) - 3.0 * t * t + 2.0;
    let ddq = |t: f32| 6.0 * t * t - 6.0 * t;
    let times = vec![-1.0, -0.2, 0.5, 1.1, 2.0];
    let values = times.iter().map(|&t| q(t)).collect();
    let track = Track::new(times, values)
        .unwrap()
        .with_interpolation(Interpolation::Lagrange)
        .unwrap();
    for k in 0..=60 {
        let t = -1.0 + 3.0 * k as f32 / 60.0;
        let sample = track.evaluate(t);
        assert_close!(sample.position, q(t), 1e-5, "p at {t}");
        assert_close!(sample.velocity, dq(t), 1e-4, "p' at {t}");
        assert_close!(sample.acceleration, ddq(t), 1e-4, "p'' at {t}");
    }
}

#[test]
fn lagrange_refuses_more_keys_than_its_cap_at_once() {
    let keys = |n: usize| {
        let times: Vec<f32> = (0..n).map(|i| i as f32).collect();
        Track::new(times, vec![0.0_f32; n]).unwrap()
    };
    assert!(keys(MAX_LAGRANGE_KEYS)
        .with_interpolation(Interpolation::Lagrange)
        .is_ok());
    let start = std::time::Instant::now();
    let mut track = keys(10_000);
    let err = track
        .set_interpolation(Interpolation::Lagrange)
        .unwrap_err();
    assert_eq!(err, TrackError::TooManyKeysForLagrange { keys: 10_000 });
    assert!(err.to_string().contains("at most 64 keys"), "{err}");
    assert_eq!(
        track.interpolation(),
        Interpolation::Linear,
        "a refused scheme leaves the track unchanged"
    );
    assert!(
        start.elapsed().as_secs_f32() < 1.0,
        "refused without sampling"
    );
}

#[test]
fn lagrange_oscillates_more_with_more_keys() {
    // Runge's function f(x) = 1 / (1 + 25x²) on [−1, 1] at evenly spaced keys: adding two keys
    // to ten makes the Lagrange polynomial *worse* near the ends, while the natural spline gets
    // better.
    let runge = |x: f32| 1.0 / (1.0 + 25.0 * x * x);
    let max_error = |n: usize, scheme: Interpolation| {
        let times: Vec<f32> = (0..n)
            .map(|i| -1.0 + 2.0 * i as f32 / (n - 1) as f32)
            .collect();
        let values = times.iter().map(|&x| runge(x)).collect();
        let track = Track::new(times, values)
            .unwrap()
            .with_interpolation(scheme)
            .unwrap();
        (0..=1000)
            .map(|k| -1.0 + k as f32 / 500.0)
            .map(|x| (track.position(x) - runge(x)).abs())
            .fold(0.0, f32::max)
    };
    let lagrange = (
        max_error(10, Interpolation::Lagrange),
        max_error(12, Interpolation::Lagrange),
    );
    let natural = (
        max_error(10, Interpolation::Natural),
        max_error(12, Interpolation::Natural),
    );
    eprintln!(
        "Runge function, max error with 10 / 12 keys: Lagrange {:.3} / {:.3}, natural spline {:.3} / {:.3}",
        lagrange.0, lagrange.1, natural.0, natural.1
    );
    assert!(lagrange.1 > lagrange.0 && lagrange.0 > 0.25);
    assert!(natural.1 < natural.0 && natural.1 < 0.1);
}

// ---------------------------------------------------------------------------------------------
// Reference values from scipy

struct Reference {
    sections: Vec<(String, Vec<Vec<f32>>)>,
}

impl Reference {
    fn load() -> Self {
        let text = include_str!("data/curves_scipy.csv");
        let mut sections: Vec<(String, Vec<Vec<f32>>)> = Vec::new();
        for line in text
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty() && !l.starts_with('#'))
        {
            if let Some(name) = line.strip_prefix("section ") {
                sections.push((name.to_string(), Vec::new()));
            } else {
                let row = line.split(',').map(|x| x.parse::<f32>().unwrap()).collect();
                sections
                    .last_mut()
                    .expect("a row before any section")
                    .1
                    .push(row);
            }
        }
        Self { sections }
    }

    fn section(&self, name: &str) -> &[Vec<f32>] {
        &self
            .sections
            .iter()
            .find(|(n, _)| n == name)
            .unwrap_or_else(|| panic!("no section {name}"))
            .1
    }

    fn column(&self, name: &str, column: usize) -> Vec<f32> {
        self.section(name).iter().map(|row| row[column]).collect()
    }
}

/// Compares a track with reference rows `t, p, p′, p″`; returns the largest error of each,
/// relative to the largest reference magnitude of that column.
fn compare_with_reference(track: &Track<f32>, rows: &[Vec<f32>]) -> [f32; 3] {
    let mut worst = [0.0_f32; 3];
    let mut cursor = Cursor::new();
    for column in 0..3 {
        let scale = rows.iter().map(|r| r[column + 1].abs()).fold(1.0, f32::max);
        for row in rows {
            let sample = track.evaluate_with(&mut cursor, row[0]);
            let ours = [sample.position, sample.velocity, sample.acceleration][column];
            worst[column] = worst[column].max((ours - row[column + 1]).abs() / scale);
        }
    }
    worst
}

#[test]
fn hermite_matches_scipy_cubic_hermite_spline() {
    let reference = Reference::load();
    let tangents = reference.column("hermite_keys", 2);
    let track = Track::new_hermite(
        reference.column("hermite_keys", 0),
        reference.column("hermite_keys", 1),
        tangents.clone(),
        tangents,
    )
    .unwrap();
    let [p, v, a] = compare_with_reference(&track, reference.section("hermite_samples"));
    eprintln!(
        "Hermite vs scipy CubicHermiteSpline, relative error: p {p:.2e}, p' {v:.2e}, p'' {a:.2e}"
    );
    assert!(
        p < 1e-5 && v < 1e-5 && a < 1e-5,
        "p {p:e}, p' {v:e}, p'' {a:e}"
    );
}

#[test]
fn natural_spline_matches_scipy_cubic_spline_natural() {
    let reference = Reference::load();
    let track = Track::new(
        reference.column("natural_keys", 0),
        reference.column("natural_keys", 1),
    )
    .unwrap()
    .with_interpolation(Interpolation::Natural)
    .unwrap();
    let [p, v, a] = compare_with_reference(&track, reference.section("natural_samples"));
    eprintln!(
        "Natural vs scipy CubicSpline(natural), relative error: p {p:.2e}, p' {v:.2e}, p'' {a:.2e}"
    );
    assert!(
        p < 1e-5 && v < 1e-5 && a < 1e-5,
        "p {p:e}, p' {v:e}, p'' {a:e}"
    );
}

// ---------------------------------------------------------------------------------------------
// Segment search and cursor

#[test]
fn find_segment_edge_cases() {
    let times = [0.0, 1.0, 2.5, 4.0];
    assert_eq!(find_segment(&times, -3.0), 0);
    assert_eq!(find_segment(&times, 0.0), 0);
    assert_eq!(find_segment(&times, 0.99), 0);
    assert_eq!(
        find_segment(&times, 1.0),
        1,
        "a key time starts its segment"
    );
    assert_eq!(find_segment(&times, 3.0), 2);
    assert_eq!(
        find_segment(&times, 4.0),
        2,
        "the last key belongs to the last segment"
    );
    assert_eq!(find_segment(&times, 9.0), 2);
    assert_eq!(find_segment(&times, f32::NAN), 0);
    assert_eq!(find_segment(&[1.0], 5.0), 0);
    assert_eq!(find_segment(&[], 5.0), 0);
}

#[test]
fn cursor_agrees_with_binary_search_in_every_order() {
    let times: Vec<f32> = (0..50).map(|i| (i as f32).powf(1.3) * 0.1).collect();
    let end = times[times.len() - 1];
    let mut queries: Vec<f32> = (0..=2000)
        .map(|k| -0.5 + (end + 1.0) * k as f32 / 2000.0)
        .collect();
    queries.extend(times.iter().copied());
    queries.extend((0..500).rev().map(|k| k as f32 * 0.01)); // decreasing
    queries.extend([f32::NAN, 3.0, f32::INFINITY, f32::NEG_INFINITY, 1.0]);
    let mut state = 12345_u32;
    queries.extend((0..500).map(|_| {
        state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        (state >> 8) as f32 / (1 << 24) as f32 * end
    }));
    let mut cursor = Cursor::new();
    for &t in &queries {
        assert_eq!(
            cursor.find(&times, t),
            find_segment(&times, t),
            "at t = {t}"
        );
    }
}

#[test]
fn cursor_sampling_equals_binary_search_sampling() {
    for scheme in ALL_SCHEMES {
        for behaviour in [
            EndBehaviour::Clamp,
            EndBehaviour::Extrapolate,
            EndBehaviour::Loop,
            EndBehaviour::PingPong,
        ] {
            let track = track_3d(scheme).with_end_behaviour(behaviour);
            let times: Vec<f32> = (0..=700).map(|k| -1.0 + k as f32 / 100.0).collect();
            let mut out = vec![Vec3::NAN; times.len()];
            track.positions(&times, &mut out);
            let mut samples = vec![Sample::default(); times.len()];
            track.evaluate_many(&times, &mut samples);
            for ((&t, &p), sample) in times.iter().zip(&out).zip(&samples) {
                assert_eq!(p, track.position(t), "{scheme:?} {behaviour:?} at {t}");
                assert_eq!(
                    *sample,
                    track.evaluate(t),
                    "{scheme:?} {behaviour:?} at {t}"
                );
                assert_eq!(
                    p, sample.position,
                    "position-only path: {scheme:?} {behaviour:?} at {t}"
                );
            }
        }
    }
}

#[test]
fn positions_evenly_includes_both_ends() {
    let track = Track::new(vec![0.0, 2.0], vec![0.0_f32, 4.0]).unwrap();
    let mut out = [0.0; 5];
    track.positions_evenly(0.0, 2.0, &mut out);
    assert_eq!(out, [0.0, 1.0, 2.0, 3.0, 4.0]);
    let mut one = [9.0];
    track.positions_evenly(0.5, 2.0, &mut one);
    assert_eq!(one, [1.0]);
}

// ---------------------------------------------------------------------------------------------
// End behaviours

#[test]
fn clamp_holds_the_end_values_at_rest() {
    let track = track_3d(Interpolation::CATMULL_ROM);
    let (_, values) = keys_3d();
    assert_eq!(track.evaluate(-1.0), Sample::at_rest(values[0]));
    assert_eq!(track.evaluate(10.0), Sample::at_rest(values[4]));
}

#[test]
fn extrapolate_continues_in_a_straight_line() {
    let track = track_3d(Interpolation::CATMULL_ROM).with_end_behaviour(EndBehaviour::Extrapolate);
    let (times, values) = keys_3d();
    let end_velocity = track.velocity(times[4]);
    assert_eq!(end_velocity, track.tangents_in()[4]);
    let after = track.evaluate(times[4] + 2.0);
    assert_close!(after.position, values[4] + end_velocity * 2.0, 1e-6);
    assert_eq!(
        (after.velocity, after.acceleration),
        (end_velocity, Vec3::ZERO)
    );
    let start_velocity = track.velocity(times[0]);
    assert_close!(track.position(-0.5), values[0] - start_velocity * 0.5, 1e-6);
    // A linear track extrapolates its end segments.
    let linear = Track::new(vec![0.0, 1.0, 2.0], vec![0.0_f32, 1.0, 3.0])
        .unwrap()
        .with_end_behaviour(EndBehaviour::Extrapolate);
    assert_eq!(linear.position(3.0), 5.0);
    assert_eq!(linear.position(-1.0), -1.0);
}

#[test]
fn loop_repeats_with_the_duration_as_period() {
    let track = track_3d(Interpolation::Natural).with_end_behaviour(EndBehaviour::Loop);
    let duration = track.duration_sec();
    for k in 0..100 {
        let t = k as f32 * 0.031;
        let sample = track.evaluate(t);
        for cycles in [-2.0, 1.0, 3.0] {
            let other = track.evaluate(t + cycles * duration);
            assert_close!(
                other.position,
                sample.position,
                1e-4,
                "t = {t}, {cycles} cycles"
            );
            assert_close!(
                other.velocity,
                sample.velocity,
                1e-3,
                "t = {t}, {cycles} cycles"
            );
        }
    }
}

#[test]
fn ping_pong_plays_backwards_with_reversed_velocity() {
    let track = track_3d(Interpolation::CATMULL_ROM).with_end_behaviour(EndBehaviour::PingPong);
    let (t0, duration) = (track.start_sec(), track.duration_sec());
    for k in 1..50 {
        let x = duration * k as f32 / 50.0;
        let forward = track.evaluate(t0 + x);
        let backward = track.evaluate(t0 + 2.0 * duration - x);
        assert_close!(backward.position, forward.position, 1e-5);
        assert_close!(backward.velocity, -forward.velocity, 1e-4);
        assert_close!(backward.acceleration, forward.acceleration, 1e-3);
        assert_close!(
            track.position(t0 + 2.0 * duration + x),
            forward.position,
            1e-4,
            "period 2D"
        );
        assert_close!(
            track.position(t0 - x),
            track.position(t0 + x),
            1e-4,
            "before the start"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Arc length

/// Largest relative deviation of the speed from `L / (M − 1)` per step, measured by finite
/// differences between consecutive points of `points`.
fn speed_error(points: &[Vec3], total_length: f32) -> f32 {
    let target = total_length / (points.len() - 1) as f32;
    points
        .windows(2)
        .map(|w| ((w[1] - w[0]).length() - target).abs() / target)
        .fold(0.0, f32::max)
}

#[test]
fn arc_length_sampling_has_constant_speed() {
    // Catmull-Rom through keys at uneven times and distances: the speed along the original
    // track varies a lot.
    let track = track_3d(Interpolation::CATMULL_ROM);
    let table = ArcLengthTable::new(&track, 16);
    let total = table.total_length();
    let mut points = vec![Vec3::ZERO; 2001];
    table.positions_at_constant_speed(&track, &mut points);
    let refined = speed_error(&points, total);

    let table_only: Vec<Vec3> = (0..points.len())
        .map(|k| {
            let s = total * k as f32 / (points.len() - 1) as f32;
            track.position(arc_length_invert(table.times_sec(), table.lengths(), s))
        })
        .collect();
    let unrefined = speed_error(&table_only, total);

    let mut even_in_time = vec![Vec3::ZERO; points.len()];
    track.positions_evenly(track.start_sec(), track.end_sec(), &mut even_in_time);
    let original = speed_error(&even_in_time, total);

    eprintln!(
        "arc length: speed error {:.3}% with Newton refinement, {:.3}% table only, {:.1}% without \
         reparametrisation (path length {total:.4}, {} table entries)",
        refined * 100.0,
        unrefined * 100.0,
        original * 100.0,
        table.lengths().len()
    );
    assert!(
        refined < 0.005,
        "speed error {:.3}% exceeds 0.5%",
        refined * 100.0
    );
    assert!(
        original > 0.5,
        "the test curve should have uneven speed to begin with"
    );
    assert_eq!(points[0], keys_3d().1[0]);
    assert_close!(points[2000], keys_3d().1[4], 1e-5);
}

#[test]
fn arc_length_of_a_polyline_is_the_sum_of_its_sides() {
    let track = Track::new(
        vec![0.0, 1.0, 3.0],
        vec![Vec2::ZERO, Vec2::new(3.0, 4.0), Vec2::new(3.0, -2.0)],
    )
    .unwrap();
    let table = ArcLengthTable::new(&track, 4);
    assert_close!(table.total_length(), 11.0, 1e-6);
    assert_eq!(table.lengths().len(), 9);
    assert_close!(
        table.position_at_length(&track, 5.0),
        Vec2::new(3.0, 4.0),
        1e-5
    );
    assert_close!(
        table.position_at_length(&track, 8.0),
        Vec2::new(3.0, 1.0),
        1e-5
    );
    // Clamped outside [0, L].
    assert_eq!(table.position_at_length(&track, -1.0), Vec2::ZERO);
    assert_close!(
        table.position_at_length(&track, 20.0),
        Vec2::new(3.0, -2.0),
        1e-6
    );
}

#[test]
fn arc_length_invert_reads_the_table() {
    let params = [0.0, 1.0, 2.0, 4.0];
    let lengths = [0.0, 2.0, 2.0, 6.0];
    assert_eq!(arc_length_invert(&params, &lengths, 0.0), 0.0);
    assert_eq!(arc_length_invert(&params, &lengths, 1.0), 0.5);
    assert_eq!(
        arc_length_invert(&params, &lengths, 2.0),
        1.0,
        "first parameter reaching s"
    );
    assert_eq!(arc_length_invert(&params, &lengths, 4.0), 3.0);
    assert_eq!(arc_length_invert(&params, &lengths, 6.0), 4.0);
    assert_eq!(arc_length_invert(&params, &lengths, -1.0), 0.0);
    assert_eq!(arc_length_invert(&params, &lengths, 7.0), 4.0);
}

#[test]
fn step_track_has_zero_length() {
    let track = Track::new(vec![0.0, 1.0], vec![0.0_f32, 5.0])
        .unwrap()
        .with_interpolation(Interpolation::Step)
        .unwrap();
    let table = ArcLengthTable::new(&track, 8);
    assert_eq!(table.total_length(), 0.0);
    assert_eq!(table.time_at_length(&track, 0.0), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Timing

const EASES: [Ease; 10] = [
    Ease::Linear,
    Ease::Smoothstep,
    Ease::Smootherstep,
    Ease::Sine,
    Ease::In { power: 2.0 },
    Ease::In { power: 3.5 },
    Ease::Out { power: 2.0 },
    Ease::Out { power: 3.0 },
    Ease::InOut { power: 2.0 },
    Ease::InOut { power: 4.0 },
];

#[test]
fn eases_go_from_zero_to_one_with_the_right_derivatives() {
    for ease in EASES {
        assert!(ease.apply(0.0).abs() < 1e-6, "{ease:?}");
        assert!((ease.apply(1.0) - 1.0).abs() < 1e-6, "{ease:?}");
        assert_eq!(ease.apply(-1.0), ease.apply(0.0));
        assert_eq!(ease.apply(2.0), ease.apply(1.0));
        let delta = 1e-3;
        for k in 1..100 {
            let s = k as f32 / 100.0;
            let [_, d, dd] = ease.apply_with_derivatives(s);
            let [_, d_low, _] = ease.apply_with_derivatives(s - delta);
            let [_, d_high, _] = ease.apply_with_derivatives(s + delta);
            assert!(ease.apply(s) >= ease.apply(s - 0.01), "{ease:?} increasing");
            // InOut joins two curves at ½, where e″ jumps: skip the finite differences there.
            if matches!(ease, Ease::InOut { .. }) && (s - 0.5).abs() < 2.0 * delta {
                continue;
            }
            let numeric = (ease.apply(s + delta) - ease.apply(s - delta)) / (2.0 * delta);
            assert!(
                (numeric - d).abs() < 2e-3 * (1.0 + d.abs()),
                "{ease:?} e' at {s}"
            );
            let numeric = (d_high - d_low) / (2.0 * delta);
            assert!(
                (numeric - dd).abs() < 1e-2 * (1.0 + dd.abs()),
                "{ease:?} e'' at {s}"
            );
        }
    }
    // Slow-in and slow-out: zero slope at the ends.
    for ease in [
        Ease::Smoothstep,
        Ease::Smootherstep,
        Ease::Sine,
        Ease::InOut { power: 3.0 },
    ] {
        assert!(ease.apply_with_derivatives(0.0)[1].abs() < 1e-6, "{ease:?}");
        assert!(ease.apply_with_derivatives(1.0)[1].abs() < 1e-6, "{ease:?}");
    }
    assert_eq!(
        Ease::In { power: 0.2 }.apply(0.5),
        0.5,
        "powers below 1 are clamped to 1"
    );
}

#[test]
fn time_warp_keeps_the_ends_and_slows_in_and_out() {
    let track = Track::new(vec![1.0, 3.0], vec![Vec2::ZERO, Vec2::new(4.0, 2.0)]).unwrap();
    let warp = TimeWarp::over(&track, Ease::Smoothstep);
    assert_eq!(warp.warp(1.0)[0], 1.0);
    assert_eq!(warp.warp(3.0)[0], 3.0);
    assert_eq!(
        warp.warp(5.0),
        [5.0, 1.0, 0.0],
        "identity outside the interval"
    );
    let start = track.evaluate_warped(&warp, 1.0);
    assert_eq!(start.position, Vec2::ZERO);
    assert_eq!(start.velocity, Vec2::ZERO, "slow-in: starts at rest");
    assert_close!(
        track.evaluate_warped(&warp, 2.0).position,
        Vec2::new(2.0, 1.0),
        1e-6,
        "symmetric ease"
    );
    assert_close!(
        track.evaluate_warped(&warp, 3.0).velocity,
        Vec2::ZERO,
        1e-6,
        "slow-out"
    );
    // Chain rule against finite differences.
    let curve = track_3d(Interpolation::CATMULL_ROM);
    let warp = TimeWarp::new(0.2, 2.9, Ease::Sine);
    let delta = 1e-3;
    for k in 1..40 {
        let t = 0.25 + k as f32 * 0.065;
        let sample = curve.evaluate_warped(&warp, t);
        let (before, after) = (
            curve.evaluate_warped(&warp, t - delta),
            curve.evaluate_warped(&warp, t + delta),
        );
        let velocity = (after.position - before.position) / (2.0 * delta);
        let acceleration = (after.velocity - before.velocity) / (2.0 * delta);
        assert_close!(sample.velocity, velocity, 1e-2, "velocity at {t}");
        if curve
            .times()
            .iter()
            .all(|&key| (warp.warp(t)[0] - key).abs() > 0.05)
        {
            assert_close!(
                sample.acceleration,
                acceleration,
                2e-2,
                "acceleration at {t}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Properties that hold for every input

/// Valid keys: 2 to 12 keys, time steps in [0.05, 2] s, values in [−10, 10]³.
fn arbitrary_keys() -> impl Strategy<Value = (Vec<f32>, Vec<Vec3>)> {
    (2_usize..12).prop_flat_map(|n| {
        (
            -5.0_f32..5.0,
            prop::collection::vec(0.05_f32..2.0, n - 1),
            prop::collection::vec(prop::array::uniform3(-10.0_f32..10.0), n),
        )
            .prop_map(|(start, steps, values)| {
                let mut times = vec![start];
                for step in steps {
                    times.push(times[times.len() - 1] + step);
                }
                (times, values.into_iter().map(Vec3::from_array).collect())
            })
    })
}

fn arbitrary_scheme() -> impl Strategy<Value = Interpolation> {
    prop_oneof![
        Just(Interpolation::Step),
        Just(Interpolation::Linear),
        (0.0_f32..=2.0).prop_map(|tension| Interpolation::Cardinal { tension }),
        Just(Interpolation::Natural),
        Just(Interpolation::Centripetal),
    ]
}

proptest! {
    // Failures are reported in the test output; no regression file is written.
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn any_track_passes_through_its_keys((times, values) in arbitrary_keys(), scheme in arbitrary_scheme()) {
        let track = Track::new(times.clone(), values.clone()).unwrap().with_interpolation(scheme).unwrap();
        for (&t, &p) in times.iter().zip(&values) {
            prop_assert!(close(track.position(t), p, 1e-5), "{:?} at {}: {} vs {}", scheme, t, track.position(t), p);
        }
    }

    #[test]
    fn cursor_always_agrees_with_binary_search(
        (times, _) in arbitrary_keys(),
        queries in prop::collection::vec(-8.0_f32..30.0, 1..200),
        sort in any::<bool>(),
    ) {
        let mut queries = queries;
        if sort {
            queries.sort_by(f32::total_cmp);
        }
        let mut cursor = Cursor::new();
        for &t in &queries {
            let i = find_segment(&times, t);
            prop_assert_eq!(cursor.find(&times, t), i);
            // The segment brackets t when t is inside the keyed range.
            if t >= times[0] && t <= times[times.len() - 1] {
                prop_assert!(times[i] <= t && t <= times[i + 1]);
            }
        }
    }

    #[test]
    fn loop_is_periodic((times, values) in arbitrary_keys(), x in 0.0_f32..1.0, cycles in -3_i32..3) {
        let track = Track::new(times, values).unwrap()
            .with_interpolation(Interpolation::CATMULL_ROM).unwrap()
            .with_end_behaviour(EndBehaviour::Loop);
        let t = track.start_sec() + x * track.duration_sec();
        let shifted = t + cycles as f32 * track.duration_sec();
        // Rounding of the shifted time moves the sample by at most |p′| · ulp-scale time error.
        let speed = track.tangents_out().iter().map(|d| d.length()).fold(1.0, f32::max);
        let tolerance = 1e-5 * speed * (1.0 + shifted.abs() + track.duration_sec());
        prop_assert!((track.position(shifted) - track.position(t)).length() <= tolerance * 20.0);
    }

    #[test]
    fn arc_length_inversion_is_monotone_and_exact_at_entries(
        steps in prop::collection::vec((0.01_f32..1.0, 0.0_f32..3.0), 1..30),
        fractions in prop::collection::vec(0.0_f32..=1.0, 2..50),
    ) {
        let mut params = vec![0.0];
        let mut lengths = vec![0.0];
        for (dp, dl) in steps {
            params.push(params[params.len() - 1] + dp);
            lengths.push(lengths[lengths.len() - 1] + dl);
        }
        let total = lengths[lengths.len() - 1];
        for (j, &length) in lengths.iter().enumerate() {
            let u = arc_length_invert(&params, &lengths, length);
            // Equal lengths (a stop) give the first parameter that reaches them.
            let first = lengths.partition_point(|&l| l < length);
            prop_assert!((u - params[first]).abs() <= 1e-5 * (1.0 + params[j]));
        }
        let mut fractions = fractions;
        fractions.sort_by(f32::total_cmp);
        let us: Vec<f32> = fractions.iter().map(|f| arc_length_invert(&params, &lengths, f * total)).collect();
        prop_assert!(us.windows(2).all(|w| w[0] <= w[1] + 1e-6));
    }

    #[test]
    fn eases_stay_in_the_unit_interval(s in -1.0_f32..2.0, power in 1.0_f32..6.0) {
        for ease in [Ease::Smoothstep, Ease::Smootherstep, Ease::Sine, Ease::In { power }, Ease::Out { power }, Ease::InOut { power }] {
            let e = ease.apply(s);
            prop_assert!((-1e-6..=1.0 + 1e-6).contains(&e), "{:?}({}) = {}", ease, s, e);
        }
    }
}

/// A case the property test above finds: f32 rounding can take smootherstep just past 1 near
/// s = 1.
#[test]
fn smootherstep_does_not_overshoot_near_one() {
    let e = Ease::Smootherstep.apply(0.998_832_3);
    assert!((0.0..=1.0).contains(&e), "{e}");
}

/// The tangents a track keeps for each scheme, computed with the generic functions on the value
/// type itself: a track computes them on `Vec4`s (`Value::to_vec4`), which must give the same
/// numbers to the bit (a lane mixed into another, or a value type's length used in a scheme
/// that has none).
fn expected_tangents<T: Value>(
    scheme: Interpolation,
    times: &[f32],
    values: &[T],
) -> (Vec<T>, Vec<T>) {
    let n = times.len();
    let (mut tin, mut tout) = (vec![T::ZERO; n], vec![T::ZERO; n]);
    match scheme {
        Interpolation::Linear => {
            for i in 0..n {
                let slope =
                    |a: usize, b: usize| (values[b] - values[a]) * (1.0 / (times[b] - times[a]));
                let before = if i > 0 { slope(i - 1, i) } else { T::ZERO };
                let after = if i + 1 < n { slope(i, i + 1) } else { before };
                tin[i] = if i > 0 { before } else { after };
                tout[i] = after;
            }
        }
        Interpolation::Lagrange => {
            for i in 0..n {
                let [_, velocity, _] = lagrange(times, values, times[i]);
                (tin[i], tout[i]) = (velocity, velocity);
            }
        }
        Interpolation::Cardinal { tension } => {
            cardinal_tangents(times, values, tension, &mut tout);
            tin.copy_from_slice(&tout);
        }
        Interpolation::Natural => {
            natural_spline_tangents(
                times,
                values,
                &mut tout,
                &mut vec![0.0; n],
                &mut vec![T::ZERO; n],
            );
            tin.copy_from_slice(&tout);
        }
        Interpolation::Centripetal => centripetal_tangents(times, values, &mut tin, &mut tout),
        _ => {}
    }
    (tin, tout)
}

fn check_track_tangents<T: Value>(times: &[f32], values: Vec<T>) {
    for scheme in [
        Interpolation::Step,
        Interpolation::Linear,
        Interpolation::Lagrange,
        Interpolation::CATMULL_ROM,
        Interpolation::Cardinal { tension: 0.3 },
        Interpolation::Natural,
        Interpolation::Centripetal,
    ] {
        let track = Track::new(times.to_vec(), values.clone())
            .unwrap()
            .with_interpolation(scheme)
            .unwrap();
        let (tin, tout) = expected_tangents(scheme, times, &values);
        let bits = |v: &[T]| v.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>();
        assert_eq!(
            bits(track.tangents_in()),
            bits(&tin),
            "{scheme:?} in tangents of {values:?}"
        );
        assert_eq!(
            bits(track.tangents_out()),
            bits(&tout),
            "{scheme:?} out tangents of {values:?}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn track_tangents_are_the_schemes_on_each_value_type(
        gaps in prop::collection::vec(0.05_f32..2.0, 1..9),
        raw in prop::collection::vec(prop::array::uniform4(-50.0_f32..50.0), 9),
    ) {
        let times: Vec<f32> = std::iter::once(0.0).chain(gaps.iter().scan(0.0, |t, g| { *t += g; Some(*t) })).collect();
        let keys = &raw[..times.len()];
        check_track_tangents(&times, keys.iter().map(|c| c[0]).collect::<Vec<f32>>());
        check_track_tangents(&times, keys.iter().map(|c| Vec2::new(c[0], c[1])).collect());
        check_track_tangents(&times, keys.iter().map(|c| Vec3::new(c[0], c[1], c[2])).collect());
        check_track_tangents(&times, keys.iter().map(|&c| Vec4::from(c)).collect());
    }
}
