//! The lessons' quizzes (`lessons/*/quiz.json`) as data, natively: every file parses and has 4 to
//! 8 questions; every choice question has exactly one right choice and explains every choice;
//! every numeric answer names a core of `quiz_answer` that computes a finite number, with a
//! tolerance that tells a right answer from a near miss; every "show me" names a figure of its
//! page and controls its script adds. Then each quiz core against values derived by hand (the
//! derivation in a comment) or a property, independently of the core. The page renders them in
//! tests/e2e/course.test.mjs.

use inbetween::exercises::run::{quiz_answer, QUIZ_ANSWERS};
use serde_json::Value;
use std::fs;
use std::path::{Path, PathBuf};

fn q(name: &str, args: &[f32]) -> f32 {
    quiz_answer(name, args).unwrap_or_else(|e| panic!("{name}{args:?}: {e}"))
}

macro_rules! assert_close {
    ($a:expr, $b:expr, $eps:expr) => {{
        let (a, b, eps): (f32, f32, f32) = ($a, $b, $eps);
        assert!((a - b).abs() <= eps, "{} = {a}, expected {b} (±{eps})", stringify!($a));
    }};
}

/// Every lesson folder that has a quiz.json, with the parsed quiz.
fn quizzes() -> Vec<(PathBuf, Value)> {
    let mut out: Vec<(PathBuf, Value)> = fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons"))
        .expect("lessons/")
        .map(|e| e.expect("a lesson folder").path())
        .filter(|p| p.join("quiz.json").is_file())
        .map(|p| {
            let text = fs::read_to_string(p.join("quiz.json")).unwrap();
            let quiz = serde_json::from_str(&text)
                .unwrap_or_else(|e| panic!("{}: quiz.json does not parse: {e}", p.display()));
            (p, quiz)
        })
        .collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

fn text<'a>(v: &'a Value, key: &str, at: &str) -> &'a str {
    v[key].as_str().unwrap_or_else(|| panic!("{at}: \"{key}\" must be a string"))
}

#[test]
fn every_lesson_but_none_has_a_quiz() {
    let folders: Vec<String> = quizzes()
        .iter()
        .map(|(p, _)| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    for lesson in [
        "00-triangles-to-pixels", "01-transforms", "02-keyframes", "02b-expressive-animation",
        "03-rotations", "04-rigid-motions", "05-noise", "06-skeletons", "07-inverse-kinematics",
        "08-blending", "09-skinning", "10-blend-shapes", "11-particles", "12-boids", "13-cloth",
        "14-rigid-bodies", "15-fluids",
    ] {
        assert!(folders.iter().any(|f| f == lesson), "lessons/{lesson} has no quiz.json");
    }
}

#[test]
fn every_quiz_has_what_the_page_needs() {
    let mut used = Vec::new();
    for (folder, quiz) in quizzes() {
        let name = folder.file_name().unwrap().to_string_lossy().into_owned();
        let page = fs::read_to_string(folder.join("index.html")).unwrap();
        let script = fs::read_to_string(folder.join("lesson.js")).unwrap();
        let questions = quiz["questions"].as_array().unwrap_or_else(|| panic!("{name}: no questions"));
        assert!((4..=8).contains(&questions.len()), "{name}: {} questions, not 4 to 8", questions.len());
        let mut ids = Vec::new();
        for question in questions {
            let id = text(question, "id", &name);
            let at = format!("{name} {id}");
            assert!(!ids.contains(&id), "{at}: the id is used twice");
            ids.push(id);
            assert!(text(question, "prompt", &at).len() > 20, "{at}: a prompt that asks something");
            match text(question, "type", &at) {
                "choice" => {
                    let choices = question["choices"].as_array().expect("choices");
                    assert!(choices.len() >= 2, "{at}: at least two choices");
                    let right = choices.iter().filter(|c| c["correct"] == Value::Bool(true)).count();
                    assert_eq!(right, 1, "{at}: exactly one right choice");
                    for c in choices {
                        assert!(!text(c, "text", &at).is_empty(), "{at}: a choice without text");
                        // Every choice teaches: the right one why, the wrong ones what they mistake.
                        assert!(text(c, "why", &at).len() > 20, "{at}: {:?} does not explain itself", c["text"]);
                    }
                }
                "number" => {
                    let core = text(&question["answer"], "core", &at);
                    let args: Vec<f32> = question["answer"]["args"]
                        .as_array()
                        .unwrap_or_else(|| panic!("{at}: answer.args"))
                        .iter()
                        .map(|a| a.as_f64().unwrap_or_else(|| panic!("{at}: args must be numbers")) as f32)
                        .collect();
                    assert!(QUIZ_ANSWERS.contains(&core), "{at}: no quiz core named {core:?}");
                    let value = quiz_answer(core, &args).unwrap_or_else(|e| panic!("{at}: {e}"));
                    assert!(value.is_finite(), "{at}: {value}");
                    let tolerance = question["tolerance"].as_f64().expect("tolerance") as f32;
                    // The tolerance must tell a right answer from a near miss a student could make.
                    assert!(
                        tolerance > 0.0 && tolerance < (value.abs() * 0.2).max(0.05),
                        "{at}: tolerance {tolerance} for {value}"
                    );
                    assert!(question.get("unit").is_none_or(Value::is_string), "{at}: the unit must be text");
                    assert!(text(question, "why", &at).len() > 20, "{at}: why");
                    assert!(text(question, "hint", &at).len() > 10, "{at}: hint");
                    used.push(core.to_string());
                }
                other => panic!("{at}: unknown type {other:?}"),
            }
            if let Some(show) = question.get("show") {
                let figure = text(show, "figure", &at);
                assert!(page.contains(&format!("id=\"{figure}\"")), "{at}: no figure #{figure} on the page");
                assert!(script.contains(&format!("'#{figure}'")) || script.contains(&format!("'{figure}'")), "{at}: lesson.js never sets up #{figure}");
                for key in show["set"].as_object().expect("show.set").keys() {
                    // Lesson 10's weight sliders are named after the face's targets (from Rust).
                    let from_rust = name == "10-blend-shapes"
                        && inbetween::blend_shapes::FACE_TARGETS.contains(&key.as_str());
                    assert!(
                        from_rust || script.contains(&format!("'{key}'")),
                        "{at}: lesson.js has no control {key:?}"
                    );
                }
            }
        }
    }
    // Every quiz core is asked for by some quiz.
    for core in QUIZ_ANSWERS {
        assert!(used.iter().any(|u| u == core), "no quiz uses the core {core:?}");
    }
}

#[test]
fn quiz_cores_check_their_arguments() {
    assert!(quiz_answer("nope", &[]).unwrap_err().contains("no quiz answer named \"nope\""));
    for &name in QUIZ_ANSWERS {
        assert!(quiz_answer(name, &[0.5; 9]).is_err(), "{name} takes 9 numbers?");
        assert!(quiz_answer(name, &[f32::NAN; 9]).unwrap_err().contains("finite"));
    }
    for (name, args) in [
        ("wgpu_depth", &[2.0, 8.0, 1.0][..]), // far before near
        ("wgpu_depth", &[0.0, 1.0, 8.0]),
        ("soup_over_indexed", &[8.5, 12.0]),
        ("soup_over_indexed", &[0.0, 12.0]),
        ("depth_fighting_distance", &[0.1, 1000.0, 0.01, 20.0]),
        ("depth_fighting_distance", &[10.0, 5.0, 0.01, 16.0]),
        ("squash_stretch_across", &[0.0]),
        ("jump_take_off_stretch", &[-0.1]),
        ("screw_slide", &[90.0, 0.0, 0.0, 0.0, 1.0, 2.0, 0.0]),
        ("polar_step_scale", &[0.0]),
        ("nlerp_angle_deg", &[200.0, 0.5]),
        ("nlerp_angle_deg", &[120.0, 1.5]),
        ("two_joint_root_angle_deg", &[0.0, 0.5, 0.8]),
        ("two_joint_error", &[0.5, -0.5, 0.8]),
        ("weight_for_speed", &[1.4, 0.0, 2.8, 0.7, 2.0]),
        ("lbs_elbow_area_percent", &[200.0, 0.0]),
        ("lbs_elbow_area_percent", &[0.0, 270.0]),
    ] {
        assert!(quiz_answer(name, args).is_err(), "{name}{args:?} should be refused");
    }
}

#[test]
fn wgpu_depth_is_the_hyperbola() {
    // depth(d) = f (d − n) / (d (f − n)): 8 × 1 / (2 × 7) = 4/7 at d = 2, n = 1, f = 8.
    assert_close!(q("wgpu_depth", &[2.0, 1.0, 8.0]), 4.0 / 7.0, 1e-6);
    // The planes go to 0 and 1, and depth 0.5 is at d = 2nf/(n + f) (the lesson's 1.78 m).
    assert_close!(q("wgpu_depth", &[1.0, 1.0, 8.0]), 0.0, 1e-6);
    assert_close!(q("wgpu_depth", &[8.0, 1.0, 8.0]), 1.0, 1e-6);
    assert_close!(q("wgpu_depth", &[16.0 / 9.0, 1.0, 8.0]), 0.5, 1e-6);
}

#[test]
fn soup_over_indexed_counts_bytes() {
    // A cube: soup 36 corners × 12 B = 432 B; indexed 8 × 12 B + 36 × 4 B = 240 B; 432/240 = 1.8.
    assert_close!(q("soup_over_indexed", &[8.0, 12.0]), 1.8, 1e-6);
    // The lesson's tetrahedron: 144 B against 96 B.
    assert_close!(q("soup_over_indexed", &[4.0, 4.0]), 1.5, 1e-6);
}

#[test]
fn depth_fighting_distance_is_where_the_step_outgrows_the_separation() {
    // d = gap f n (2ᵇ − 1) / (h (f − n)) with h = 3 m: 0.01 × 1000 × 0.1 × 65535 / (3 × 999.9).
    let by_hand = 0.01 * 1000.0 * 0.1 * 65535.0 / (3.0 * 999.9);
    assert_close!(q("depth_fighting_distance", &[0.1, 1000.0, 0.01, 16.0]), by_hand, 0.01);
    assert_close!(by_hand, 21.8, 0.05); // the lesson's text
    // Proportional to the gap; z_near 1 m moves it ten times farther (the text's 219 m); z_far
    // 5000 m hardly moves it.
    let base = q("depth_fighting_distance", &[0.1, 1000.0, 0.01, 16.0]);
    assert_close!(q("depth_fighting_distance", &[0.1, 1000.0, 0.04, 16.0]), 4.0 * base, 0.01);
    assert_close!(q("depth_fighting_distance", &[1.0, 1000.0, 0.01, 16.0]), 219.0, 0.5);
    assert_close!(q("depth_fighting_distance", &[0.1, 5000.0, 0.01, 16.0]), base, 0.05);
    // 24 bits: 2²⁴ − 1 steps instead of 2¹⁶ − 1, 256 times farther (the text's 5.6 km).
    assert_close!(q("depth_fighting_distance", &[0.1, 1000.0, 0.01, 24.0]) / base, 16_777_215.0 / 65535.0, 0.01);
}

#[test]
fn squash_stretch_keeps_the_volume() {
    // 1/√0.64 = 1/0.8 = 1.25.
    assert_close!(q("squash_stretch_across", &[0.64]), 1.25, 1e-6);
    for s in [0.3, 0.8, 1.0, 1.38, 1.6, 2.5] {
        let across = q("squash_stretch_across", &[s]);
        assert_close!(s * across * across, 1.0, 1e-5);
    }
}

#[test]
fn jump_take_off_stretch_is_capped() {
    // Apex 1.6 m over 1 s of flight: take-off at 4 × 1.6 / 1 = 6.4 m/s; 1 + 0.06 × 6.4 = 1.384.
    assert_close!(q("jump_take_off_stretch", &[0.06]), 1.384, 1e-5);
    // 1 + 0.1 × 6.4 = 1.64, over the cap of 1.6.
    assert_close!(q("jump_take_off_stretch", &[0.1]), 1.6, 1e-6);
    assert_close!(q("jump_take_off_stretch", &[0.0]), 1.0, 1e-6);
}

#[test]
fn screw_slide_is_the_translation_along_the_axis() {
    // 90° about y, t = (1, 2, 0): the slide is t · y = 2 (the x part comes from the axis' offset).
    assert_close!(q("screw_slide", &[90.0, 0.0, 1.0, 0.0, 1.0, 2.0, 0.0]), 2.0, 1e-5);
    // A turn with t perpendicular to the axis is a pure turn about a shifted line: no slide.
    assert_close!(q("screw_slide", &[60.0, 0.0, 0.0, 1.0, 0.7, -0.4, 0.0]), 0.0, 1e-5);
    // No turn: a pure slide by |t| = |(3, 4, 0)| = 5.
    assert_close!(q("screw_slide", &[0.0, 0.0, 1.0, 0.0, 3.0, 4.0, 0.0]), 5.0, 1e-5);
    // The axis need not be unit length, nor along a coordinate: t · n with n = (1, 1, 0)/√2.
    assert_close!(q("screw_slide", &[45.0, 2.0, 2.0, 0.0, 1.0, 0.0, 0.0]), 1.0 / 2f32.sqrt(), 1e-5);
}

#[test]
fn polar_step_averages_with_the_inverse_transpose() {
    // ½ (σ + 1/σ): ½ (4 + ¼) = 2.125.
    assert_close!(q("polar_step_scale", &[4.0]), 2.125, 1e-6);
    // A rotation (σ = 1) is a fixed point; σ and 1/σ land on the same value.
    assert_close!(q("polar_step_scale", &[1.0]), 1.0, 1e-6);
    assert_close!(q("polar_step_scale", &[0.25]), q("polar_step_scale", &[4.0]), 1e-6);
    // A mirror stays a mirror: −σ goes to −½ (σ + 1/σ).
    assert_close!(q("polar_step_scale", &[-4.0]), -2.125, 1e-6);
}

#[test]
fn nlerp_lags_slerp_near_the_keys() {
    // Keys 120° apart are quaternions 60° apart: 0.75 (1, 0) + 0.25 (cos 60°, sin 60°)
    // = (0.875, 0.2165), half-angle atan(0.2165 / 0.875) = 13.898°, so 27.796°.
    let by_hand = 2.0 * (0.25 * 60f32.to_radians().sin()).atan2(0.75 + 0.25 * 60f32.to_radians().cos());
    assert_close!(q("nlerp_angle_deg", &[120.0, 0.25]), by_hand.to_degrees(), 1e-3);
    assert_close!(q("nlerp_angle_deg", &[120.0, 0.25]), 27.8, 0.01);
    // The ends are the keys, and halfway nlerp meets slerp (by symmetry).
    assert_close!(q("nlerp_angle_deg", &[120.0, 0.0]), 0.0, 1e-3);
    assert_close!(q("nlerp_angle_deg", &[120.0, 1.0]), 120.0, 1e-2);
    assert_close!(q("nlerp_angle_deg", &[120.0, 0.5]), 60.0, 1e-2);
    // Slower than slerp in the first half, for every angle.
    for angle in [30.0, 90.0, 150.0] {
        assert!(q("nlerp_angle_deg", &[angle, 0.25]) < angle * 0.25);
    }
}

#[test]
fn two_joint_follows_the_law_of_cosines() {
    // a = b = 0.5, d = 0.8: cos α = (0.25 + 0.64 − 0.25) / (2 × 0.5 × 0.8) = 0.8, α = 36.87°.
    assert_close!(q("two_joint_root_angle_deg", &[0.5, 0.5, 0.8]), 0.8f32.acos().to_degrees(), 0.01);
    // a = 3, b = 4, d = 5: a right angle at the middle joint, cos α = 3/5.
    assert_close!(q("two_joint_root_angle_deg", &[3.0, 4.0, 5.0]), 0.6f32.acos().to_degrees(), 0.05);
    // Reachable: reached; too close: |a − b| away from the root at best; too far: a + b.
    assert_close!(q("two_joint_error", &[0.5, 0.5, 0.8]), 0.0, 1e-4);
    assert_close!(q("two_joint_error", &[0.7, 0.3, 0.1]), 0.4 - 0.1, 1e-4);
    assert_close!(q("two_joint_error", &[0.5, 0.5, 1.3]), 1.3 - 1.0, 1e-4);
}

#[test]
fn weight_for_speed_solves_travel_over_duration() {
    // (1.4 + 1.4 w) / (1 − 0.3 w) = 2 → 1.4 + 1.4 w = 2 − 0.6 w → w = 0.3.
    assert_close!(q("weight_for_speed", &[1.4, 1.0, 2.8, 0.7, 2.0]), 0.3, 1e-5);
    // The two clips' own speeds give weights 0 and 1; the blend's speed T(w)/d(w) at the
    // answer is the speed asked for.
    assert_close!(q("weight_for_speed", &[1.4, 1.0, 2.8, 0.7, 1.4]), 0.0, 1e-5);
    assert_close!(q("weight_for_speed", &[1.4, 1.0, 2.8, 0.7, 4.0]), 1.0, 1e-5);
    for v in [1.6, 2.5, 3.3] {
        let w = q("weight_for_speed", &[1.4, 1.0, 2.8, 0.7, v]);
        let (travel, duration) = (1.4 + (2.8 - 1.4) * w, 1.0 + (0.7 - 1.0) * w);
        assert_close!(travel / duration, v, 1e-4);
    }
}

#[test]
fn lbs_elbow_ring_shrinks_by_half_angle_cosines() {
    // The elbow ring's weights are ½ and ½, and ½ (I + R(θ)) shrinks the plane of the turn by
    // cos(θ/2). A twist turns the ring in its own plane: both directions, cos²(θ/2).
    for twist in [0.0f32, 60.0, 90.0, 120.0, 180.0] {
        let c = (twist / 2.0).to_radians().cos();
        assert_close!(q("lbs_elbow_area_percent", &[0.0, twist]), 100.0 * c * c, 0.1);
    }
    // A bend turns it out of its plane: one direction, cos(θ/2) (the lesson's 71% at 90°).
    for bend in [0.0f32, 90.0, 120.0, 150.0] {
        assert_close!(q("lbs_elbow_area_percent", &[bend, 0.0]), 100.0 * (bend / 2.0).to_radians().cos(), 0.1);
    }
}

#[test]
fn blend_full_scales_the_base_by_the_total() {
    // 0.5 × 0.5 + 0.5 × 0.5 + 0.5 × 0.62 = 0.81 = 1.5 × 0.5 + 0.5 × 0.12.
    assert_close!(q("blend_full_vertex", &[0.5, 0.5, 0.62, 0.5, 0.5, 0.5]), 0.81, 1e-6);
    // Weights that sum to 1 give the differential form.
    for w in [[0.2f32, 0.3], [1.0, 0.0], [-0.3, 0.8]] {
        let full = q("blend_full_vertex", &[0.5, 0.7, 0.62, 1.0 - w[0] - w[1], w[0], w[1]]);
        let differential = inbetween::blend_shapes::differential_vertex(
            glam::Vec3::new(0.0, 0.5, 0.0),
            &[glam::Vec3::new(0.0, 0.7, 0.0), glam::Vec3::new(0.0, 0.62, 0.0)],
            &w,
        );
        assert_close!(full, differential.y, 1e-6);
    }
}
