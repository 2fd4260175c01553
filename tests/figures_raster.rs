//! Native tests of lesson 00's figures (src/figures/raster.rs): what they draw, what they reject,
//! and what their notes say about the student's exercises.

use glam::{Vec2, Vec3};
use inbetween::draw::{Frame, MeshId};
use inbetween::exercises::run::{direct, Failure, Flat};
use inbetween::figures::raster::{
    frustum_colors as fc, DepthPrecision, Frustum, MeshStorage, Normals, Shading, INDEXED_COLOR,
    SOUP_COLOR, TRUE_NORMAL, WRONG_NORMAL,
};
use inbetween::raster::{self, Material};

/// A correct student: the reference for every exercise of this lesson.
fn reference(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let mut rest = args;
    let mut out = Vec::new();
    match name {
        "perspective_matrix" => raster::perspective_wgpu(args[0], args[1], args[2], args[3])
            .unwrap()
            .put(&mut out),
        "vertex_normals" => {
            let p = Vec::<Vec3>::take(&mut rest).unwrap();
            let i: Vec<u32> = Vec::<f32>::take(&mut rest)
                .unwrap()
                .iter()
                .map(|&x| x as u32)
                .collect();
            let mut n = vec![Vec3::ZERO; p.len()];
            raster::vertex_normals(&p, &i, &mut n).unwrap();
            n.put(&mut out)
        }
        "blinn_phong" => {
            let v = |k: usize| Vec3::from_slice(&args[k..k + 3]);
            let m = inbetween::exercises::raster::material(
                v(9),
                [args[12], args[13], args[14]],
                args[15],
            );
            raster::blinn_phong(v(0), v(3), v(6), &m).put(&mut out)
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

/// Typical mistakes: OpenGL's matrix instead of wgpu's; normals not normalised; Phong instead
/// of Blinn-Phong.
fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let mut rest = args;
    let mut out = Vec::new();
    match name {
        "perspective_matrix" => raster::perspective_gl(args[0], args[1], args[2], args[3])
            .unwrap()
            .put(&mut out),
        "vertex_normals" => {
            let p = Vec::<Vec3>::take(&mut rest).unwrap();
            let i: Vec<u32> = Vec::<f32>::take(&mut rest)
                .unwrap()
                .iter()
                .map(|&x| x as u32)
                .collect();
            let mut n = vec![Vec3::ZERO; p.len()];
            raster::vertex_normals(&p, &i, &mut n).unwrap();
            n.iter().map(|x| *x * 2.0).collect::<Vec<_>>().put(&mut out)
        }
        "blinn_phong" => {
            let v = |k: usize| Vec3::from_slice(&args[k..k + 3]);
            let m = inbetween::exercises::raster::material(
                v(9),
                [args[12], args[13], args[14]],
                args[15],
            );
            raster::phong(v(0), v(3), v(6), &m).put(&mut out)
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(
        "attempt to divide by zero (src/exercises/raster.rs:30:5)".into(),
    ))
}

fn stub(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::NotDone)
}

#[test]
fn mesh_figure_draws_both_storages_with_their_sizes() {
    let mut scene = MeshStorage::new();
    scene.set_shape("tetrahedron").unwrap();
    let mut f = Frame::default();
    let note = scene.draw(&mut f);
    let soup_points = f
        .markers
        .iter()
        .filter(|p| Vec3::from_slice(&p.color[..3]) == SOUP_COLOR)
        .count();
    let indexed_points = f
        .markers
        .iter()
        .filter(|p| Vec3::from_slice(&p.color[..3]) == INDEXED_COLOR)
        .count();
    assert_eq!(
        (soup_points, indexed_points),
        (12, 4),
        "12 corners in the soup, 4 positions indexed"
    );
    assert_eq!(
        f.segments_of(INDEXED_COLOR).count(),
        6,
        "a tetrahedron has 6 edges"
    );
    assert!(note.contains("144 B") && note.contains("96 B"), "{note}");
    scene.set_shape("sphere").unwrap();
    scene.set_segments(64.0).unwrap();
    let s = scene.sizes();
    assert!(s.soup_bytes > s.indexed_bytes * 19 / 10);
    assert!(scene.set_shape("cube").unwrap_err().contains("shape"));
    assert!(scene.set_segments(1000.0).unwrap_err().contains("segments"));
    assert!(scene.set_segments(f32::NAN).is_err());
}

#[test]
fn frustum_point_is_clipped_outside_and_its_ndc_is_read_out() {
    let mut scene = Frustum::new();
    scene.set_offset(0.0, 0.0).unwrap();
    // s = 0: half of z_near, clipped; in the middle: inside; s = 1: past z_far.
    let color_of_p = |scene: &Frustum, s: f32| {
        let mut f = Frame::default();
        scene.draw(&mut f, s).unwrap();
        let l = f.labels.iter().find(|l| l.text == "p").unwrap().color;
        (l, f)
    };
    assert_eq!(color_of_p(&scene, 0.0).0, fc::OUTSIDE);
    assert_eq!(color_of_p(&scene, 0.5).0, fc::POINT);
    assert_eq!(color_of_p(&scene, 1.0).0, fc::OUTSIDE);
    // Where the point crosses z_near and z_far, the depth is 0 and 1.
    let (near, far) = (1.0, 8.0);
    let s_at = |d: f32| (d - 0.5 * near) / (1.15 * far - 0.5 * near);
    let r = scene.readout(s_at(near)).unwrap();
    assert!(r[6].abs() < 1e-4 && (r[13] + 1.0).abs() < 1e-4, "{r:?}");
    let r = scene.readout(s_at(far)).unwrap();
    assert!((r[6] - 1.0).abs() < 1e-4 && (r[13] - 1.0).abs() < 1e-4);
    assert!((r[3] - far).abs() < 1e-3, "w is the distance");
    let depth = scene.sample_depth(50).unwrap();
    assert!(
        depth.windows(2).all(|w| w[1][1] > w[0][1]),
        "depth grows with distance"
    );
    assert!(scene
        .set_frustum(60.0, 5.0, 4.0)
        .unwrap_err()
        .contains("z_far"));
    assert!(scene
        .set_frustum(0.0, 1.0, 4.0)
        .unwrap_err()
        .contains("field of view"));
    assert!(scene.draw(&mut Frame::default(), 2.0).is_err());
}

#[test]
fn frustum_reports_the_students_matrix() {
    let mut scene = Frustum::new();
    scene.set_use_exercise(true);
    scene.set_runner(reference);
    let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
    assert!(note.contains("matches the reference"), "{note}");
    scene.set_runner(wrong);
    let note = scene.exercise_note();
    assert!(
        note.contains("differs") && note.contains("z_near to depth -1.000"),
        "{note}"
    );
    scene.set_runner(panics);
    assert!(scene
        .exercise_note()
        .contains("panicked: attempt to divide by zero (src/exercises/raster.rs:30:5)"));
    scene.set_runner(stub);
    assert!(scene
        .exercise_note()
        .starts_with("Not done yet: exercise 0.1"));
}

#[test]
fn depth_buffer_fights_only_beyond_the_predicted_distance() {
    let mut scene = DepthPrecision::new();
    scene.set(0.1, 1000.0, 0.01, 16.0).unwrap();
    let from = scene.fighting_from();
    let h = inbetween::figures::raster::EYE_HEIGHT;
    // Well inside: the upper plane always wins whatever the rounding noise; far beyond: it
    // often loses.
    let noise: Vec<Vec2> = (0..64)
        .map(|k| Vec2::new((k % 8) as f32 / 7.0 - 0.5, (k / 8) as f32 / 7.0 - 0.5))
        .collect();
    let wins = |d: f32| {
        noise
            .iter()
            .filter(|&&j| scene.upper_wins(d, d * (h + 0.01) / h, j))
            .count()
    };
    assert_eq!(wins(from * 0.3), 64);
    assert!(wins(from * 4.0) < 40, "{}", wins(from * 4.0));
    // 24 bits push the fighting 256 times farther; a 10 times larger z_near, 10 times.
    scene.set(0.1, 1000.0, 0.01, 24.0).unwrap();
    assert!((scene.fighting_from() / from - 256.0).abs() < 0.5);
    scene.set(1.0, 1000.0, 0.01, 16.0).unwrap();
    assert!((scene.fighting_from() / from - 10.0).abs() < 0.1);
    let img = scene.image(64, 48).unwrap();
    assert_eq!(img.len(), 64 * 48 * 4);
    assert!(scene.image(10_000, 10).is_err());
    assert!(scene
        .set(0.1, 1000.0, 0.05, 8.0)
        .unwrap_err()
        .contains("bits"));
    assert!(scene
        .set(2.0, 1.0, 0.05, 16.0)
        .unwrap_err()
        .contains("z_far"));
    let mut f = Frame::default();
    assert!(
        scene.draw(&mut f).contains("z_far / z_near = 1000. "),
        "the ratio in the note"
    );
}

/// Figure 3's note: the ratio as a whole number when it is one (to a tenth otherwise), and the
/// three steps in one notation, so their decades can be compared at a glance.
#[test]
fn the_depth_note_writes_the_ratio_and_the_steps_in_one_notation() {
    for (near, far, bits, ratio) in [(0.1, 1000.0, 16, "10000"), (0.03, 10.001, 24, "333.4")] {
        let note = scene_at(near, far, bits as f32).draw(&mut Frame::default());
        let start = format!("z_far / z_near = {ratio}. With {bits} bits, one depth step is worth ");
        assert!(note.starts_with(&start), "{note}");
        // "M.MMe±N m at 1 m, M.MMe±N m at 10 m and M.MMe±N m at z_far": each the core's step.
        let words: Vec<&str> = note[start.len()..].split(' ').collect();
        for (k, d) in [(0, 1.0), (5, 10.0), (11, far)] {
            let printed = words[k];
            let (mantissa, _) = printed.split_once('e').unwrap_or_else(|| panic!("{printed}"));
            assert_eq!(mantissa.len(), 4, "three digits: {printed}");
            let value: f32 = printed.parse().unwrap();
            let step = raster::depth_step(d, near, far, bits);
            assert!((value / step - 1.0).abs() < 0.005, "{printed} against {step} at {d} m");
        }
    }
}

/// Figure 2's plot: the distances run over the point's whole trip, from half of z_near to 15 %
/// past z_far, so the playhead (`distance_at`) is on the plot all the way.
#[test]
fn the_depth_plot_spans_the_points_whole_trip() {
    let mut scene = Frustum::new();
    for (near, far) in [(1.0, 8.0), (0.1, 20.0), (2.0, 3.0)] {
        scene.set_frustum(50.0, near, far).unwrap();
        let samples = scene.sample_depth(201).unwrap();
        let (first, last) = (samples[0][0], samples[200][0]);
        assert!((first - scene.distance_at(0.0)).abs() < 1e-6, "{first}");
        assert!((last - scene.distance_at(1.0)).abs() < 1e-4, "{last}");
        assert!((first - 0.5 * near).abs() < 1e-6 && (last - 1.15 * far).abs() < 1e-4);
        // Depths in [0, 1] (wgpu) exactly between the planes.
        for [d, wgpu, _] in samples {
            let inside = (near..=far).contains(&d);
            assert_eq!((-1e-6..=1.0 + 1e-6).contains(&wgpu), inside, "{wgpu} at {d} m");
        }
    }
}

#[test]
fn z_fighting_shows_blue_pixels_only_with_the_short_buffer() {
    let blue = |scene: &DepthPrecision| {
        let img = scene.image(160, 120).unwrap();
        img.chunks_exact(4)
            .filter(|p| p[2] > 120 && p[0] < 90)
            .count()
    };
    let mut scene = DepthPrecision::new();
    scene.set(0.1, 1000.0, 0.01, 16.0).unwrap();
    let sixteen = blue(&scene);
    scene.set(0.1, 1000.0, 0.01, 24.0).unwrap();
    let twenty_four = blue(&scene);
    assert!(sixteen > 200, "{sixteen}");
    assert!(twenty_four < sixteen / 5, "{twenty_four} vs {sixteen}");
}

#[test]
fn normals_figure_draws_true_and_wrong_normals() {
    let mut scene = Normals::new();
    let mut f = Frame::default();
    scene.set_scale_x(1.0).unwrap();
    scene.draw(&mut f, MeshId(3), MeshId(4));
    let count = |f: &Frame, c: Vec3| f.segments_of(c).count();
    let vertices = scene.smooth_mesh().positions.len();
    assert_eq!(count(&f, TRUE_NORMAL), vertices);
    assert_eq!(count(&f, WRONG_NORMAL), 0, "no scale: M n is right");
    assert!(scene.worst_wrong_angle_deg() < 1e-3);
    scene.set_scale_x(3.0).unwrap();
    f.clear();
    scene.draw(&mut f, MeshId(3), MeshId(4));
    assert_eq!(count(&f, WRONG_NORMAL), vertices);
    assert!(scene.worst_wrong_angle_deg() > 20.0);
    assert_eq!(
        f.meshes.iter().filter(|m| m.mesh == MeshId(4)).count(),
        1,
        "the smooth mesh"
    );
    scene.set_flat(true);
    f.clear();
    scene.draw(&mut f, MeshId(3), MeshId(4));
    assert_eq!(
        count(&f, TRUE_NORMAL),
        scene.flat_mesh().positions.len() / 3,
        "one per face"
    );
    assert!(scene.set_scale_x(0.0).is_err());
    // Smooth normals are unit; flat ones repeat per corner.
    assert!(scene
        .smooth_mesh()
        .normals
        .iter()
        .all(|n| (n.length() - 1.0).abs() < 1e-5));
}

#[test]
fn normals_figure_reports_the_students_normals() {
    let mut scene = Normals::new();
    scene.set_runner(reference);
    scene.set_use_exercise(true);
    assert!(scene
        .draw(&mut Frame::default(), MeshId(3), MeshId(4))
        .contains("matches the reference"));
    scene.set_runner(wrong);
    scene.set_use_exercise(true);
    let note = scene.draw(&mut Frame::default(), MeshId(3), MeshId(4));
    assert!(
        note.contains("differs on this sphere") && note.contains("at vertex"),
        "{note}"
    );
    // The vertex the note names is marked in the view, over the mesh (its normal may point
    // into the sphere), where the stretched sphere puts it.
    let named: usize = note
        .split("at vertex ")
        .nth(1)
        .and_then(|rest| rest.split(|c: char| !c.is_ascii_digit()).next()?.parse().ok())
        .unwrap_or_else(|| panic!("{note}"));
    scene.set_scale_x(2.0).unwrap();
    let mut frame = Frame::default();
    scene.draw(&mut frame, MeshId(3), MeshId(4));
    let positions = scene.smooth_mesh().positions;
    let model = glam::Mat4::from_translation(Vec3::new(0.0, 1.3, 0.0))
        * glam::Mat4::from_scale(Vec3::new(2.0, 1.0, 1.0));
    let at = model.transform_point3(positions[named]);
    assert!(
        frame.markers.iter().any(|m| m.size_px < 0.0
            && (Vec3::from_array(m.center) - at).length() < 1e-5
            && m.color[..3] == inbetween::draw::palette::ORANGE.to_array()),
        "no marker over vertex {named} at {at}"
    );
    assert!(note.contains("(the orange dot)"), "{note}");
    scene.set_runner(stub);
    scene.set_use_exercise(true);
    assert!(scene
        .draw(&mut Frame::default(), MeshId(3), MeshId(4))
        .contains("Not done yet: exercise 0.2"));
    scene.set_use_exercise(false);
    let mut frame = Frame::default();
    assert!(!scene.draw(&mut frame, MeshId(3), MeshId(4)).contains("exercise"));
    assert!(frame.markers.is_empty(), "no vertex marked without the exercise");
}

#[test]
fn shading_figure_draws_the_vectors_and_checks_blinn_phong() {
    let mut scene = Shading::new();
    let mut f = Frame::default();
    let note = scene.draw(&mut f, MeshId(7));
    assert!(f.meshes[0].unlit && f.meshes[0].vertex_colors && f.meshes[0].mesh == MeshId(7));
    let names: Vec<&str> = f.labels.iter().map(|l| l.text.as_str()).collect();
    assert!(names.contains(&"h") && !names.contains(&"r"), "{names:?}");
    assert!(note.contains("n·l"));
    scene.set_model("phong").unwrap();
    f.clear();
    scene.draw(&mut f, MeshId(7));
    assert!(f.labels.iter().any(|l| l.text == "r"));
    scene.set_use_exercise(true);
    scene.set_runner(reference);
    assert!(scene.exercise_note().contains("matches the reference"));
    scene.set_runner(wrong);
    assert!(scene.exercise_note().contains("differs"));
    scene.set_runner(panics);
    assert!(scene.exercise_note().contains("panicked"));
    // Dragging to the image's right edge puts the light on the right.
    scene.set_light_from_image(1.0, 0.5).unwrap();
    assert!(scene.light().x > 0.9);
    let (az, el) = scene.light_deg();
    assert!((az - 90.0).abs() < 3.0 && el.abs() < 1.0, "{az} {el}");
    let img = scene.image("specular", 32).unwrap();
    assert_eq!(img.len(), 32 * 32 * 4);
    assert!(scene.image("glow", 32).is_err());
    assert!(scene.image("ambient", 4).is_err());
    assert!(scene
        .set_material(2.0, 0.5, 0.5, 8.0)
        .unwrap_err()
        .contains("k_a"));
    assert!(scene.set_model("gouraud").is_err());
    assert!(scene.set_light_deg(f32::NAN, 0.0).is_err());
}

/// The 3D sphere is shaded by the page's formula for the eye along +z: the brightest vertex is
/// where the highlight must be (n along h), the vertices facing away get the ambient term only,
/// and the student's code shades it when asked.
#[test]
fn shading_figure_shades_the_sphere_on_the_cpu() {
    let mut scene = Shading::new();
    scene.set_light_deg(40.0, 35.0).unwrap();
    scene.set_material(0.1, 0.6, 0.8, 64.0).unwrap();
    let (sphere, colors) = scene.shade_sphere().expect("first call shades");
    let (normals, colors) = (sphere.normals.clone(), colors.to_vec());
    assert_eq!(colors.len(), normals.len());
    let l = scene.light();
    let h = (l + Vec3::Z).normalize();
    let brightest = (0..colors.len())
        .max_by(|&a, &b| colors[a].x.total_cmp(&colors[b].x))
        .unwrap();
    assert!(
        normals[brightest].dot(h) > 0.99,
        "highlight at n = h: {}",
        normals[brightest]
    );
    for (n, c) in normals.iter().zip(&colors) {
        if n.dot(l) < -0.1 {
            let ambient = 0.1 * Material::default().color;
            assert!(
                (c.truncate() - ambient).abs().max_element() < 1e-5,
                "ambient only: {c}"
            );
        }
    }
    assert!(
        scene.shade_sphere().is_none(),
        "nothing changed, nothing to upload"
    );
    // The student's blinn_phong shades it (a wrong one visibly), a panicking one falls back.
    scene.set_use_exercise(true);
    scene.set_runner(wrong);
    let wrong_colors = scene.shade_sphere().unwrap().1.to_vec();
    assert!(wrong_colors
        .iter()
        .zip(&colors)
        .any(|(a, b)| (*a - *b).abs().max_element() > 0.05));
    scene.set_runner(reference);
    let same = scene.shade_sphere().unwrap().1.to_vec();
    assert!(same
        .iter()
        .zip(&colors)
        .all(|(a, b)| (*a - *b).abs().max_element() < 1e-4));
    assert!(scene
        .draw(&mut Frame::default(), MeshId(7))
        .contains("shaded by your blinn_phong"));
    scene.set_runner(panics);
    let fallback = scene.shade_sphere().unwrap().1.to_vec();
    assert_eq!(fallback, colors);
    assert!(scene
        .draw(&mut Frame::default(), MeshId(7))
        .contains("panicked"));
}

/// The numbers Figure 1's caption and note give.
#[test]
fn mesh_sizes_match_the_caption() {
    let mut scene = MeshStorage::new();
    let ratio = |scene: &MeshStorage| {
        let s = scene.sizes();
        s.soup_bytes as f32 / s.indexed_bytes as f32
    };
    scene.set_segments(8.0).unwrap();
    let mut f = Frame::default();
    let note = scene.draw(&mut f);
    assert!(note.contains("The soup is 1.95× larger"), "{note}");
    assert_eq!(format!("{:.2}", ratio(&scene)), "1.95");
    scene.set_segments(64.0).unwrap();
    assert_eq!(format!("{:.2}", ratio(&scene)), "2.00");
    assert!(scene.listing().is_empty(), "no listing for a big mesh");
    scene.set_shape("tetrahedron").unwrap();
    assert_eq!(ratio(&scene), 1.5);
    let listing = scene.listing();
    // Position 0 is a corner of t0, t1 and t2, and t3 does not use it.
    for t in ["t0: 0 ", "t1: 0 ", "t2: 0 "] {
        assert!(listing.contains(t), "{listing}");
    }
    assert!(!listing.contains("t3: 0 "), "{listing}");
    assert_eq!(
        listing.matches("t3:").count(),
        2,
        "t3 in the soup and in the index list"
    );
    let mut f = Frame::default();
    scene.draw(&mut f);
    for t in ["t0", "t1", "t2", "t3", "0", "1", "2", "3"] {
        assert!(f.labels.iter().any(|l| l.text == t), "label {t}");
    }
    assert!(!f.keep_in_view.is_empty());
}

/// Figure 2's caption: where the wgpu depth passes 0.5, 2nf/(n + f).
#[test]
fn depth_passes_one_half_where_the_caption_says() {
    let mut scene = Frustum::new();
    let half_at = |scene: &Frustum| {
        let samples = scene.sample_depth(10_000).unwrap();
        samples.iter().find(|s| s[1] >= 0.5).unwrap()[0]
    };
    let d = half_at(&scene);
    assert!((d - 1.78).abs() < 0.005, "{d}");
    assert!((d - 1.0) / (8.0 - 1.0) < 0.25, "not a quarter of the way");
    scene.set_frustum(50.0, 0.1, 8.0).unwrap();
    let d = half_at(&scene);
    assert!((d - 0.2).abs() < 0.005, "{d}");
    // Point x = 3 m: clipped near the eye, inside once the frustum is wide enough.
    scene.set_frustum(50.0, 1.0, 8.0).unwrap();
    scene.set_offset(3.0, 0.3).unwrap();
    let inside = |s: f32| scene.readout(s).unwrap()[4].abs() <= 1.0;
    assert!(!inside(0.1) && inside(0.9));
    // Labels and the whole frustum are declared to stay in view.
    let mut f = Frame::default();
    scene.draw(&mut f, 0.0).unwrap();
    assert!(f.keep_in_view.len() >= 10);
    let priority = |text: &str| f.labels.iter().find(|l| l.text == text).unwrap().priority;
    assert!(priority("p") > priority("eye") && priority("eye") > priority("image"));
}

/// Figure 3's caption: 21.8 m at 16 bits and z_near 0.1 m, 219 m at 1 m, 5.6 km at 24 bits,
/// hardly any change with z_far 5000 m; the plot's samples span z_near to z_far on a log scale.
#[test]
fn fighting_distances_match_the_caption() {
    let mut scene = DepthPrecision::new();
    assert_eq!(format!("{:.1}", scene.fighting_from()), "21.8");
    scene.set(1.0, 1000.0, 0.01, 16.0).unwrap();
    assert_eq!(format!("{:.0}", scene.fighting_from()), "219");
    let steps = |s: &DepthPrecision| s.sample_step(50).unwrap();
    let (a, b) = (DepthPrecision::new(), scene_at(1.0, 1000.0, 16.0));
    // The step drops by a decade at the same distance; the separation does not move.
    let (sa, sb) = (steps(&a), steps(&b));
    let at = |s: &[[f32; 4]], d: f32| {
        s.iter()
            .min_by(|x, y| (x[0] - d).abs().total_cmp(&(y[0] - d).abs()))
            .copied()
            .unwrap()
    };
    let (x, y) = (at(&sa, 10.0), at(&sb, 10.0));
    let per_d2 = |s: [f32; 4]| s[1] / (s[0] * s[0]);
    assert!((per_d2(x) / per_d2(y) - 10.0).abs() < 0.1, "{x:?} {y:?}");
    assert!(
        (x[3] / x[0] - y[3] / y[0]).abs() < 1e-6,
        "the separation line stays"
    );
    let c = scene_at(0.1, 1000.0, 24.0);
    assert_eq!(format!("{:.1}", c.fighting_from() / 1000.0), "5.6");
    assert!(c.fighting_from() > 1000.0);
    let d = scene_at(0.1, 5000.0, 16.0);
    assert!((d.fighting_from() / a.fighting_from() - 1.0).abs() < 0.001);
    // Log spacing: the first sample at z_near, the last at z_far, equal ratios between.
    assert!((sa[0][0] - 0.1).abs() < 1e-6 && (sa[49][0] - 1000.0).abs() < 0.1);
    let r = sa[1][0] / sa[0][0];
    assert!((sa[30][0] / sa[29][0] - r).abs() < 1e-3);
    assert!((b.fighting_from_bits(24) / b.fighting_from_bits(16) - 256.0).abs() < 0.1);
    // 24 bits at the defaults: red everywhere in the image, no blue.
    let blue = |s: &DepthPrecision| {
        s.image(160, 120)
            .unwrap()
            .chunks_exact(4)
            .filter(|p| p[2] > 120 && p[0] < 90)
            .count()
    };
    assert_eq!(blue(&c), 0);
    // z_near 1 m: blue only in a thin band just under the horizon.
    let img = b.image(160, 120).unwrap();
    let rows: Vec<usize> = img
        .chunks_exact(4)
        .enumerate()
        .filter(|(_, p)| p[2] > 120 && p[0] < 90)
        .map(|(k, _)| k / 160)
        .collect();
    assert!(!rows.is_empty());
    let (lo, hi) = (rows.iter().min().unwrap(), rows.iter().max().unwrap());
    assert!(hi - lo <= 4, "rows {lo}..{hi}");
}

/// Figure 3's Try this, z_near from 0.1 m to 1 m: "the bars shrink, the near ones tenfold, and
/// the orange ones turn green" in the side view.
#[test]
fn figure_3s_bars_shrink_tenfold_and_turn_green_with_z_near_1_m() {
    use inbetween::draw::palette;
    // Each bar: (distance, height, orange?), a wide line up from the floor at x = 1.1 m every 2 m.
    let bars = |near: f32| {
        let mut f = Frame::default();
        scene_at(near, 1000.0, 16.0).draw(&mut f);
        let mut out: Vec<(f32, f32, bool)> = f
            .segments()
            .filter(|(a, b, c)| {
                a.x == 1.1 && a.y == 0.0 && b.y > 0.0 && -a.z % 2.0 == 0.0
                    && (*c == palette::ORANGE || *c == palette::GREEN)
            })
            .map(|(a, b, c)| (-a.z, b.y, c == palette::ORANGE))
            .collect();
        out.sort_by(|p, q| p.0.total_cmp(&q.0));
        out
    };
    let (before, after) = (bars(0.1), bars(1.0));
    assert_eq!(before.len(), 20, "a bar every 2 m to 40 m");
    assert_eq!(
        before.iter().map(|b| b.0).collect::<Vec<_>>(),
        after.iter().map(|b| b.0).collect::<Vec<_>>()
    );
    assert!(before.iter().any(|b| b.2) && !after.iter().any(|b| b.2), "orange turns green");
    // A bar is drawn at most 6 m tall: one at the cap shrinks by less than its step does.
    const CAP_M: f32 = 6.0;
    let mut tenfold = 0;
    for (b, a) in before.iter().zip(&after) {
        assert!(a.1 < b.1, "every bar shrinks: {b:?} {a:?}");
        if b.1 < CAP_M {
            assert!((b.1 / a.1 - 10.0).abs() < 0.1, "tenfold: {b:?} {a:?}");
            tenfold += 1;
        }
    }
    assert!(tenfold >= 10, "the near ones: {tenfold}");
    // The caption says so, of the side view (where it shows) rather than of the plot's lines,
    // whose axes rescale with z_near.
    let page = include_str!("../lessons/00-triangles-to-pixels/index.html");
    let page = page.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(page.contains(
        "in the side view the bars shrink, the near ones tenfold, and the orange ones turn green"
    ));
}

/// Figure 3's side view names its bars in the colour of the bar it sits by: a green name over
/// orange bars would call them one depth step within the separation. At the page's settings
/// (orange beyond 21.8 m) the name goes by a green bar; with 24 bits all are green; with a
/// z_near of 0.01 m, 16 bits and floors 0.1 mm apart every bar is orange and so is the name.
/// And the view is a diagram: a drag slides it rather than turning it end-on.
#[test]
fn figure_3s_bar_name_takes_the_colour_of_its_bar_and_the_view_slides() {
    use inbetween::draw::palette;
    for (near, gap, bits, color) in [
        (0.1, 0.01, 16.0, palette::GREEN),
        (0.1, 0.01, 24.0, palette::GREEN),
        (0.01, 1e-4, 16.0, palette::ORANGE),
    ] {
        let mut scene = DepthPrecision::new();
        scene.set(near, 1000.0, gap, bits).unwrap();
        let mut f = Frame::default();
        scene.draw(&mut f);
        assert!(f.flat, "the side view slides");
        let name = f.labels.iter().find(|l| l.text.starts_with("one depth step")).unwrap();
        let bar = f.markers.iter().find(|m| Vec3::from(m.center) == name.anchor);
        let bar = bar.expect("the name sits by a bar's top");
        assert_eq!(Vec3::from_slice(&bar.color[..3]), name.color, "z_near {near}, {bits} bits");
        assert_eq!(name.color, color, "z_near {near}, {bits} bits");
    }
}

fn scene_at(near: f32, far: f32, bits: f32) -> DepthPrecision {
    let mut s = DepthPrecision::new();
    s.set(near, far, 0.01, bits).unwrap();
    s
}

/// Figure 4's caption: no lean at scale 1, up to 61° at scale 4, 10 facets around.
#[test]
fn normals_lean_as_the_caption_says() {
    let mut scene = Normals::new();
    scene.set_scale_x(1.0).unwrap();
    assert!(scene.worst_wrong_angle_deg() < 0.01);
    scene.set_scale_x(4.0).unwrap();
    let worst = scene.worst_wrong_angle_deg();
    assert_eq!(format!("{worst:.0}"), "61");
    scene.set_flat(true);
    // Faces whose centres lie just above the equator: one band of 20 triangles, two to each
    // flat quad, so 10 different normals: 10 facets.
    let band: Vec<Vec3> = scene
        .normals()
        .iter()
        .filter(|(c, _)| c.y > 0.0 && c.y < 0.5)
        .map(|(_, n)| *n)
        .collect();
    assert_eq!(band.len(), 20);
    let mut facets: Vec<Vec3> = Vec::new();
    for n in band {
        if !facets.iter().any(|f| f.abs_diff_eq(n, 1e-4)) {
            facets.push(n);
        }
    }
    assert_eq!(facets.len(), 10);
    // The stretched sphere and its arrows fit, flat or smooth: every arrow's ends lie in the box
    // of the points the figure keeps in view (within a centimetre).
    for flat in [true, false] {
        scene.set_flat(flat);
        let mut f = Frame::default();
        scene.draw(&mut f, MeshId(3), MeshId(4));
        let (lo, hi) = f.keep_in_view.iter().fold(
            (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        assert!(hi.x > 4.0, "{hi}");
        for (a, b) in f.segments_of(TRUE_NORMAL).chain(f.segments_of(WRONG_NORMAL)) {
            for p in [a, b] {
                assert!(p.cmpge(lo - 0.01).all() && p.cmple(hi + 0.01).all(), "flat {flat}: {p} outside {lo}..{hi}");
            }
        }
    }
}

/// Figure 5's caption and text: Blinn-Phong's highlight is wider at the same exponent and about
/// matches Phong's at four times it; per-vertex shading agrees with per-pixel shading at
/// shininess 8 but not at 128.
#[test]
fn shading_claims_hold() {
    let mut scene = Shading::new();
    let lit = |img: &[u8]| img.chunks_exact(4).filter(|p| p[0] > 200).count();
    let diff = |a: &[u8], b: &[u8]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (*x as i32 - *y as i32).abs())
            .max()
            .unwrap()
    };
    scene.set_material(0.15, 0.7, 0.5, 8.0).unwrap();
    let (p8, b8) = (
        scene.image("phong", 128).unwrap(),
        scene.image("blinn-phong", 128).unwrap(),
    );
    assert!(lit(&b8) > lit(&p8), "{} {}", lit(&b8), lit(&p8));
    let g8 = scene.image("gouraud", 128).unwrap();
    let small = diff(&g8, &b8);
    scene.set_material(0.15, 0.7, 0.5, 32.0).unwrap();
    let p32 = scene.image("phong", 128).unwrap();
    scene.set_material(0.15, 0.7, 0.5, 128.0).unwrap();
    let (b128, g128) = (
        scene.image("blinn-phong", 128).unwrap(),
        scene.image("gouraud", 128).unwrap(),
    );
    let spot = |img: &[u8]| img.chunks_exact(4).filter(|p| p[2] > 150).count() as f32;
    assert!((spot(&p32) / spot(&b128) - 1.0).abs() < 0.35);
    let large = diff(&g128, &b128);
    assert!(large > 3 * small && large > 60, "{small} {large}");
    // The 3D view: the sphere, the vectors and the light are declared to stay in view.
    let mut f = Frame::default();
    scene.draw(&mut f, MeshId(3));
    assert!(f.keep_in_view.len() >= 8 + 5);
    assert!(scene.image("nonsense", 64).is_err());
}

/// A student's function that is right at the figure's input but wrong elsewhere is caught by the
/// probes, which the note names.
#[test]
fn probes_catch_what_the_shown_input_cannot() {
    // Blinn-Phong with a highlight even when the light is behind the surface.
    fn no_clamp(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        if name != "blinn_phong" {
            return reference(name, args);
        }
        let v = |k: usize| Vec3::from_slice(&args[k..k + 3]);
        let (n, l, eye, color) = (v(0), v(3), v(6), v(9));
        let (ka, kd, ks, s) = (args[12], args[13], args[14], args[15]);
        let h = (l + eye).normalize();
        let c = ka * color
            + kd * n.dot(l).max(0.0) * color
            + Vec3::splat(ks * n.dot(h).max(0.0).powf(s));
        Ok(c.to_array().to_vec())
    }
    let mut scene = Shading::new();
    scene.set_runner(no_clamp);
    let note = scene.exercise_note();
    assert!(
        note.contains("matches the reference at the marked fragment (the figure's input), but differs at a light just behind the surface"),
        "{note}"
    );
    scene.set_runner(reference);
    let note = scene.exercise_note();
    assert!(note.contains("and at 4 more inputs"), "{note}");

    // A perspective matrix that always uses the figure's aspect ratio, 1.5.
    fn fixed_aspect(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        let mut a = args.to_vec();
        if name == "perspective_matrix" {
            a[1] = 1.5;
        }
        reference(name, &a)
    }
    let mut frustum = Frustum::new();
    frustum.set_runner(fixed_aspect);
    let note = frustum.exercise_note();
    assert!(
        note.contains("(the figure's input), but differs at field of view 90.000°, aspect 1.000"),
        "{note}"
    );
    assert!(
        !note.contains("maps z_near"),
        "right at the figure's frustum: {note}"
    );
    frustum.set_runner(wrong);
    let note = frustum.exercise_note();
    assert!(note.contains("maps z_near to depth -1.000"), "{note}");

    // Vertex normals weighted by area: the ridge probe tells.
    fn by_area(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        if name != "vertex_normals" {
            return reference(name, args);
        }
        let mut rest = args;
        let p = Vec::<Vec3>::take(&mut rest).unwrap();
        let i = Vec::<f32>::take(&mut rest).unwrap();
        let mut n = vec![Vec3::ZERO; p.len()];
        for t in i.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|k| k as usize);
            let face = (p[b] - p[a]).cross(p[c] - p[a]);
            for k in [a, b, c] {
                n[k] += face;
            }
        }
        let n: Vec<Vec3> = n.iter().map(|v| v.normalize_or_zero()).collect();
        let mut out = Vec::new();
        n.put(&mut out);
        Ok(out)
    }
    let mut normals = Normals::new();
    normals.set_runner(by_area);
    normals.set_use_exercise(true);
    let mut f = Frame::default();
    let note = normals.draw(&mut f, MeshId(3), MeshId(4));
    assert!(
        note.contains("It differs on a ridge of one large and one small triangle"),
        "{note}"
    );
    normals.set_runner(reference);
    normals.set_use_exercise(true);
    let note = normals.draw(&mut f, MeshId(3), MeshId(4));
    assert!(note.contains("It also matches on a tetrahedron"), "{note}");
}

/// Figure 2's Try this: the wgpu depth passes 0.5 at d = 2nf/(n + f), about 1.78 m for z_near 1 m
/// and z_far 8 m and about 0.2 m for z_near 0.1 m; the note prints that crossing, and the depth
/// core gives 0.5 there.
#[test]
fn frustum_note_gives_where_the_depth_passes_one_half() {
    let mut scene = Frustum::new();
    for (near, printed) in [(1.0, "1.778"), (0.1, "0.198")] {
        scene.set_frustum(60.0, near, 8.0).unwrap();
        let half = scene.half_depth_distance();
        assert!((raster::ndc_depth_wgpu(half, near, 8.0) - 0.5).abs() < 1e-5);
        let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
        assert!(
            note.contains(&format!("passes 0.5 at d = {printed} m")),
            "{note}"
        );
    }
}

/// Figure 1 at many segments: dots only on the patch facing the camera, about six corners of the
/// soup for each indexed position there, and few enough to stay apart.
#[test]
fn a_dense_sphere_marks_a_patch_only() {
    let count = |scene: &MeshStorage| {
        let mut f = Frame::default();
        let note = scene.draw(&mut f);
        let of = |c: Vec3| dot_centres(&f, c).len();
        (of(SOUP_COLOR), of(INDEXED_COLOR), note)
    };
    let mut scene = MeshStorage::new();
    scene.set_segments(16.0).unwrap();
    let s = scene.sizes();
    let (soup, indexed, note) = count(&scene);
    assert_eq!(
        (soup, indexed),
        (s.soup_positions, s.vertices),
        "every dot at 16"
    );
    assert!(!note.contains("patch"), "{note}");
    scene.set_segments(64.0).unwrap();
    let (soup, indexed, note) = count(&scene);
    assert!(
        indexed > 30 && soup + indexed < 600,
        "{soup} + {indexed} dots"
    );
    let ratio = soup as f32 / indexed as f32;
    assert!((5.0..7.0).contains(&ratio), "{ratio} corners per position");
    assert!(
        note.contains(&format!(
            "Dots only on the patch facing you: {soup} corners of the soup, {indexed} positions indexed."
        )),
        "{note}"
    );
    assert!(f32_dot_sizes_at_most(&scene, 5.0));
    // Outside the patch the edges are pale and 1 px wide: far fewer full-colour wide edges.
    let mut f = Frame::default();
    scene.draw(&mut f);
    let wide = |c: Vec3| {
        f.strokes
            .iter()
            .filter(|st| Vec3::from_slice(&st.color[..3]) == c)
            .count()
    };
    assert!(
        wide(SOUP_COLOR) < soup + 10,
        "{} wide soup edges",
        wide(SOUP_COLOR)
    );
    assert!(
        wide(INDEXED_COLOR) < 4 * indexed,
        "{} wide indexed edges",
        wide(INDEXED_COLOR)
    );
    // The pale edges follow every few rings and meridians only (about a tenth of the ~6000
    // edges): all of them fill the sphere's disc with a pale wash where no line shows. Enough
    // remain to draw the sphere round the patch.
    let pale = |c: Vec3| {
        let c = c.lerp(Vec3::ONE, 0.65);
        f.lines.iter().filter(|v| Vec3::from_slice(&v.color[..3]).distance(c) < 1e-4).count() / 2
    };
    let (soup_pale, indexed_pale) = (pale(SOUP_COLOR), pale(INDEXED_COLOR));
    assert!((300..1000).contains(&indexed_pale), "{indexed_pale} pale indexed edges");
    // The soup's: a dash for each of the two triangles on either side of such an edge.
    assert!(
        (indexed_pale..3 * indexed_pale).contains(&soup_pale),
        "{soup_pale} pale soup edges"
    );
}

/// The dots of Figure 1's two spheres, markers or shaded discs, in colour `c`.
fn dot_centres(f: &Frame, c: Vec3) -> Vec<Vec3> {
    let markers = (f.markers.iter()).filter(|m| Vec3::from_slice(&m.color[..3]) == c).map(|m| m.center);
    let points = (f.points.iter()).filter(|p| Vec3::from_slice(&p.color[..3]) == c).map(|p| p.center);
    markers.chain(points).map(Vec3::from).collect()
}

/// Figure 1's dense soup still reads as a sphere: every pale ring and meridian edge of the indexed
/// sphere has, on the soup, a pale dash along it (parallel, within a third of an edge of it: the
/// copy of that edge in a triangle on either side, shrunk towards its centre), so the soup's
/// rings run round the whole sphere as the indexed one's do; and its dots are shaded discs, not
/// markers, whose dark-and-white rim fills a dot under 8 px and makes hundreds of them one grey mat.
#[test]
fn a_dense_soup_draws_its_rings_as_dashes_and_dots_without_rims() {
    let (left, right) = (Vec3::new(-1.4, 1.2, 0.0), Vec3::new(1.4, 1.2, 0.0));
    for segments in [17.0, 24.0, 51.0, 64.0] {
        let mut scene = MeshStorage::new();
        scene.set_segments(segments).unwrap();
        let mut f = Frame::default();
        scene.draw(&mut f);
        let pale = |c: Vec3, centre: Vec3| -> Vec<(Vec3, Vec3)> {
            let c = c.lerp(Vec3::ONE, 0.65);
            (f.lines.chunks_exact(2))
                .filter(|v| Vec3::from_slice(&v[0].color[..3]).distance(c) < 1e-4)
                .map(|v| (Vec3::from(v[0].position) - centre, Vec3::from(v[1].position) - centre))
                .collect()
        };
        let (soup, indexed) = (pale(SOUP_COLOR, left), pale(INDEXED_COLOR, right));
        let edge = std::f32::consts::TAU / segments;
        let missing = (indexed.iter())
            .filter(|(a, b)| {
                let (mid, along) = ((*a + *b) * 0.5, (*b - *a).normalize());
                !soup.iter().any(|(c, d)| {
                    (*d - *c).normalize().dot(along).abs() > 0.99
                        && ((*c + *d) * 0.5).distance(mid) < edge / 3.0
                })
            })
            .count();
        assert_eq!(missing, 0, "{segments} segments: {missing} of {} ring and meridian edges have no soup dash", indexed.len());
        for c in [SOUP_COLOR, INDEXED_COLOR] {
            assert!(
                !f.markers.iter().any(|m| Vec3::from_slice(&m.color[..3]) == c),
                "{segments} segments: rimmed markers on the dense patch"
            );
            let n = dot_centres(&f, c).len();
            assert!(n >= 3, "{segments} segments: {n} dots");
        }
    }
}

/// Figure 1's patch of dots on a dense sphere turns with the camera: from any eye round the
/// figure, every dot on each sphere lies on the side facing the eye (within the patch's 25° of
/// the direction from between the spheres), and the counts keep about six corners per position.
#[test]
fn a_dense_sphere_patch_faces_the_eye_after_an_orbit() {
    let (left, right) = (Vec3::new(-1.4, 1.2, 0.0), Vec3::new(1.4, 1.2, 0.0));
    let middle = Vec3::new(0.0, 1.2, 0.0);
    let mut scene = MeshStorage::new();
    scene.set_segments(51.0).unwrap();
    for eye in [
        Vec3::new(6.0, 2.0, 1.0),
        Vec3::new(-3.0, 4.0, -5.0),
        Vec3::new(0.5, -2.0, 6.0),
        Vec3::new(0.0, 8.0, 0.5),
    ] {
        scene.set_eye(eye);
        let facing = (eye - middle).normalize();
        let mut f = Frame::default();
        let note = scene.draw(&mut f);
        let dots = |c: Vec3, centre: Vec3| -> Vec<Vec3> {
            dot_centres(&f, c).into_iter().map(|p| p - centre).collect()
        };
        let (soup, indexed) = (dots(SOUP_COLOR, left), dots(INDEXED_COLOR, right));
        assert!(indexed.len() > 30, "eye {eye}: {} positions marked", indexed.len());
        for p in soup.iter().chain(&indexed) {
            // The soup's corners are pulled towards their triangle's centre: a few degrees more.
            let cos = p.normalize().dot(facing);
            assert!(cos > 0.85, "eye {eye}: a dot at {p} is {:.0}° from the eye's side", cos.acos().to_degrees());
        }
        let ratio = soup.len() as f32 / indexed.len() as f32;
        assert!((5.0..7.0).contains(&ratio), "eye {eye}: {ratio} corners per position");
        assert!(note.contains(&format!("{} corners of the soup, {} positions indexed", soup.len(), indexed.len())), "{note}");
    }
    // An eye at the point between the spheres, or not a number, keeps the last direction.
    let mut f = Frame::default();
    let before = scene.draw(&mut f);
    scene.set_eye(middle);
    scene.set_eye(Vec3::NAN);
    assert_eq!(scene.draw(&mut Frame::default()), before);
}

/// Figure 1's soup corners at up to 10 segments show their orange inside the outline (a marker's
/// white-and-dark rim takes 2.5 px of its radius: at 6 px across a dot reads as a grey ring), and
/// at the page's camera (target (0, 1.2, 0), distance 5.6, pitch 0.3) on a 650 × 420 canvas the
/// corners of neighbouring triangles stay apart (but round the poles), so the dots read as a ring
/// round each position.
#[test]
fn soup_corners_show_their_colour_and_stay_apart() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    for segments in [4.0, 6.0, 8.0, 10.0] {
        let mut scene = MeshStorage::new();
        scene.set_segments(segments).unwrap();
        let mut f = Frame::default();
        scene.draw(&mut f);
        let soup: Vec<_> = f
            .markers
            .iter()
            .filter(|m| Vec3::from_slice(&m.color[..3]) == SOUP_COLOR)
            .collect();
        assert!(
            soup.iter().all(|m| m.size_px >= 8.0),
            "{segments} segments: dots under 8 px"
        );
        let size = Vec2::new(650.0, 420.0);
        let mut camera = OrbitCamera::from_view([0.0, 1.2, 0.0, 5.6, 0.0, 0.3]);
        camera.fit(&f.fit_points(), size, FIT_PAD_PX);
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let eye = camera.eye();
        // The corners on the half facing the eye, where none hides behind the sphere.
        let centre = Vec3::new(-1.4, 1.2, 0.0);
        let front: Vec<(Vec2, f32)> = soup
            .iter()
            .filter(|m| (Vec3::from(m.center) - centre).dot(eye - centre) > 0.5)
            .map(|m| {
                (
                    project_to_canvas(view_proj, size, Vec3::from(m.center)).unwrap(),
                    m.size_px,
                )
            })
            .collect();
        // Round the poles, where every triangle of a ring meets, the corners crowd whatever
        // the dots' size; elsewhere each keeps at least half a dot from its nearest.
        let crowded = front
            .iter()
            .filter(|a| {
                front
                    .iter()
                    .any(|b| b.0 != a.0 && a.0.distance(b.0) < 0.5 * a.1)
            })
            .count();
        assert!(
            crowded * 5 <= front.len(),
            "{segments} segments: {crowded} of {} corners crowd a neighbour",
            front.len()
        );
    }
}

fn f32_dot_sizes_at_most(scene: &MeshStorage, px: f32) -> bool {
    let mut f = Frame::default();
    scene.draw(&mut f);
    f.markers.iter().all(|m| m.size_px.abs() <= px)
}

/// Figure 2's labels at the apex (eye, z_near, p, image) keep their places beside their anchors
/// and clear of the eye's, the point's and the image's dots, at the page's camera fitted to a
/// 760 × 420 or 760 × 760 canvas (the 800 × 600 page) and a 650 × 420 one (1600 × 1000), all along the
/// point's path.
#[test]
fn frustum_labels_at_the_apex_stay_apart_and_off_the_dots() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::draw::layout::{place, LabelBox, Rect};
    let scene = Frustum::new();
    for size in [
        Vec2::new(760.0, 420.0),
        Vec2::new(760.0, 760.0),
        Vec2::new(650.0, 420.0),
    ] {
        for k in 0..=20 {
            let s = k as f32 / 20.0;
            let mut f = Frame::default();
            scene.draw(&mut f, s).unwrap();
            let mut camera = OrbitCamera::from_view([4.5, 1.2, -4.0, 17.0, 0.45, 0.45]);
            let fit: Vec<Vec3> = f.fit_points();
            camera.fit(&fit, size, FIT_PAD_PX);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let on = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
            // The labels' boxes as the page measures them: about 7.7 px a character, 17 px high.
            let boxes: Vec<LabelBox> = f
                .labels
                .iter()
                .map(|l| LabelBox {
                    anchor: on(l.anchor) + l.offset_px,
                    size: Vec2::new(7.7 * l.text.chars().count() as f32, 17.0),
                    left: l.left,
                    visible: true,
                    priority: l.priority,
                })
                .collect();
            let placed = place(&boxes, size);
            let dots: Vec<Vec2> = f.markers.iter().map(|m| on(Vec3::from(m.center))).collect();
            // The frustum's p (the NDC box's p comes later).
            let first_p = f.labels.iter().position(|l| l.text == "p").unwrap();
            for (i, (label, p)) in f.labels.iter().zip(&placed).enumerate() {
                if !["eye", "z_near", "image"].contains(&label.text.as_str()) && i != first_p {
                    continue;
                }
                let at = format!("{} at s = {s} on {size}", label.text);
                assert!(p.shown, "{at}: hidden");
                assert!(p.leader_to.is_none(), "{at}: moved off its anchor");
                let rect = Rect {
                    min: p.top_left,
                    size: Vec2::new(7.7 * label.text.chars().count() as f32, 17.0),
                };
                // A dot on the label's own dot (the point on the near plane is its own image)
                // does not count.
                let own = boxes[i].anchor;
                for d in dots[..3].iter().filter(|d| d.distance(own) > 16.0) {
                    assert!(
                        !rect.overlaps(
                            &Rect {
                                min: *d - 4.0,
                                size: Vec2::splat(8.0)
                            },
                            0.0
                        ),
                        "{at}: over a dot at {d}"
                    );
                }
            }
        }
    }
}

/// The text under Figure 5: the 3D sphere has 11.25° between vertices (32 segments, 16 rings),
/// and at shininess 128 Blinn-Phong's highlight is about 12° across where (n·h)^128 is half.
#[test]
fn the_highlight_is_narrower_than_the_spacing_of_the_spheres_vertices() {
    let scene = Shading::new();
    let sphere = scene.sphere();
    // Around the equator: 32 vertices, 11.25° apart.
    let mut around: Vec<f32> = sphere
        .positions
        .iter()
        .filter(|p| p.y.abs() < 1e-4)
        .map(|p| p.z.atan2(p.x).to_degrees())
        .collect();
    around.sort_by(f32::total_cmp);
    around.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
    assert_eq!(around.len(), 32, "{around:?}");
    assert!((around[1] - around[0] - 11.25).abs() < 1e-3);
    // From pole to pole: 16 rings of 11.25°.
    let mut up: Vec<f32> = sphere
        .positions
        .iter()
        .map(|p| p.y.clamp(-1.0, 1.0).acos().to_degrees())
        .collect();
    up.sort_by(f32::total_cmp);
    up.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
    assert_eq!(up.len(), 17, "{up:?}");
    // The highlight's full width at half height: tilt n away from h until the specular halves.
    let m = Material {
        ambient: 0.0,
        diffuse: 0.0,
        specular: 1.0,
        shininess: 128.0,
        color: Vec3::ONE,
    };
    let (l, v) = (Vec3::Z, Vec3::Z);
    let specular = |deg: f32| {
        let a = deg.to_radians();
        raster::blinn_phong(Vec3::new(a.sin(), 0.0, a.cos()), l, v, &m).x
    };
    let half = (0..2000)
        .map(|k| k as f32 * 0.01)
        .find(|&d| specular(d) <= 0.5)
        .unwrap();
    assert!(
        (2.0 * half - 12.0).abs() < 0.5,
        "{} degrees across",
        2.0 * half
    );
    assert!(2.0 * half > 11.25 && 2.0 * half < 2.0 * 11.25);
}

/// Figure 4 at its page camera (lessons/00-triangles-to-pixels/lesson.js, fitted to what the
/// figure keeps in view) on the canvases the page gives it at 1600 × 1000 (650 × 420) and
/// 800 × 600 (760 × 340): the stretched sphere sits in the middle of the canvas's height and, at
/// the scales of 3 (the default) and 4 (the Try this), spans three quarters of the canvas's width
/// or more at 1600 × 1000 and 65 % at 800 × 600 (where the arrows' height limits it).
#[test]
fn the_stretched_sphere_fills_the_normals_canvas() {
    use glam::{Mat4, Vec2};
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let view = crate::page_camera(
        include_str!("../lessons/00-triangles-to-pixels/lesson.js"),
        "normalsViewer",
    );
    for scale in [1.0, 3.0, 4.0] {
        for size in [Vec2::new(650.0, 420.0), Vec2::new(760.0, 340.0)] {
            let mut scene = Normals::new();
            scene.set_scale_x(scale).unwrap();
            let mut frame = Frame::default();
            scene.draw(&mut frame, MeshId(3), MeshId(4));
            let mut camera = OrbitCamera::from_view(view);
            assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let sphere = &frame.meshes[0].model;
            // The sphere's outline: points all over the unit sphere, placed by its model matrix.
            let on_canvas: Vec<Vec2> = (0..=32)
                .flat_map(|i| (0..64).map(move |j| (i, j)))
                .map(|(i, j)| {
                    let (lat, lon) = (i as f32 / 32.0 * std::f32::consts::PI, j as f32 / 64.0 * std::f32::consts::TAU);
                    Vec3::new(lat.sin() * lon.cos(), lat.cos(), lat.sin() * lon.sin())
                })
                .map(|p| project_to_canvas(view_proj, size, sphere.transform_point3(p)).unwrap())
                .collect();
            let (lo, hi) = on_canvas.iter().fold((Vec2::MAX, Vec2::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
            let at = format!("scale {scale} on {size}: the sphere spans {lo} to {hi}");
            assert!(((lo.y + hi.y) / 2.0 - size.y / 2.0).abs() < 0.05 * size.y, "{at}");
            let least = if size.x == 650.0 { 0.75 } else { 0.65 };
            if scale >= 3.0 {
                assert!(hi.x - lo.x >= least * size.x, "{at}");
            }
            assert_eq!(*sphere, Mat4::from_translation(Vec3::Y * 1.3) * Mat4::from_scale(Vec3::new(scale, 1.0, 1.0)));
        }
    }
}
