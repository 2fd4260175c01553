#![allow(clippy::needless_range_loop)]
//! Native tests of lesson 05's figures (src/figures/noise.rs): what they draw and say.

use glam::Vec3;
use inbetween::draw::{palette, Frame, MeshId, TextureId};
use inbetween::exercises::run::{direct, Failure};
use inbetween::figures::noise::*;

fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    match name {
        "fade" => Ok(vec![0.5, 0.0]),
        "perlin_cell" | "fractal_sum" => Ok(vec![0.123]),
        "terrain_normal" => Ok(vec![0.0, 0.0, 1.0]),
        _ => direct(name, args),
    }
}

fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(
        "panicked at src/exercises/noise.rs:30:5:\nboom".into(),
    ))
}

#[test]
fn noise1d_blends_the_two_ramps_at_the_probe() {
    let mut s = Noise1d::new();
    s.set_probe(3.5).unwrap();
    let mut f = Frame::default();
    let note = s.draw(&mut f);
    assert!(
        note.contains("cell [3, 4]") && note.contains("t = 0.500"),
        "{note}"
    );
    // The pink probe sits on the blue curve.
    let probe = f
        .points
        .iter()
        .find(|p| p.color[..3] == palette::PINK.to_array())
        .unwrap();
    let curve: Vec<(Vec3, Vec3)> = f.segments_of(palette::BLUE).collect();
    let c = Vec3::from(probe.center);
    let near = curve
        .iter()
        .map(|(a, _)| (*a - c).length())
        .fold(f32::INFINITY, f32::min);
    assert!(near < 0.05, "probe {c} is {near} from the curve");
    assert!(s.set_probe(9.0).unwrap_err().contains("x"));
    assert!(s.set_seed(1.5).unwrap_err().contains("seed"));
    let fade = s.sample_fade(11).unwrap();
    assert_eq!(fade[0], [0.0, 0.0, 0.0, 0.0]);
    assert_eq!(fade[10][1], 1.0);
    assert!(s.sample_fade(1).is_err());
}

#[test]
fn noise1d_reports_the_students_fade() {
    let mut s = Noise1d::new();
    s.set_use_exercise(true);
    let mut f = Frame::default();
    if cfg!(feature = "solutions") {
        assert!(s.draw(&mut f).contains("matches the reference"));
    } else {
        assert!(s.draw(&mut f).contains("Not done yet: exercise 5.1 fade"));
    }
    s.set_runner(wrong);
    assert!(s.draw(&mut f).contains("differs at t = "));
    s.set_runner(panics);
    let n = s.draw(&mut f);
    assert!(
        n.contains("panicked at src/exercises/noise.rs:30:5: boom"),
        "{n}"
    );
}

#[test]
fn noise2d_is_zero_at_the_dots_only_on_the_z0_slice() {
    let mut s = Noise2d::new();
    s.take_dirty();
    let t = &s.terrains()[0];
    // Vertex (64, 64) is u = v = 0, noise coordinates (0, 0): a lattice point.
    let r = t.resolution();
    assert_eq!(t.positions[64 * r + 64].y, 0.0);
    s.set_z(0.37).unwrap();
    assert!(s.take_dirty(), "changing z regenerates");
    assert_ne!(s.terrains()[0].positions[64 * r + 64].y, 0.0);
    assert!(!s.take_dirty(), "once");
    let mut f = Frame::default();
    let note = s.draw(&mut f, MeshId(3));
    assert!(note.contains("slice z = 0.370"));
    // 25 lattice gradients as arrows (cones).
    assert_eq!(
        f.meshes.iter().filter(|m| m.mesh == MeshId::CONE).count(),
        25
    );
    s.set_use_exercise(true);
    s.set_runner(wrong);
    assert!(s.draw(&mut f, MeshId(3)).contains("differs"));
    assert!(s.set_probe(2.5, 0.0).unwrap_err().contains("probe x"));
}

#[test]
fn octaves_plot_each_octave_and_their_sum() {
    let mut s = Octaves::new();
    s.set_params(4.0, 0.5, 2.0).unwrap();
    s.take_dirty();
    let rows = s.sample_octaves(50).unwrap();
    for row in &rows {
        let sum: f32 = row[1..=5].iter().sum();
        assert!((sum - row[11]).abs() < 1e-5);
        assert!(
            row[6..=10].iter().all(|x| x.is_nan()),
            "octaves above N are left out"
        );
    }
    assert!(s.set_params(10.0, 0.5, 2.0).unwrap_err().contains("N"));
    assert!(s
        .set_params(3.0, f32::NAN, 2.0)
        .unwrap_err()
        .contains("alpha"));
    s.set_use_exercise(true);
    s.set_runner(wrong);
    let mut f = Frame::default();
    assert!(s
        .draw(&mut f, MeshId(3))
        .contains("fractal_sum (5.3) differs"));
    s.set_runner(direct);
    let n = s.draw(&mut f, MeshId(3));
    if cfg!(feature = "solutions") {
        assert!(n.contains("matches"), "{n}");
    } else {
        assert!(n.contains("Not done yet"), "{n}");
    }
}

#[test]
fn terrain_scene_regenerates_lazily_and_in_place() {
    let mut s = TerrainScene::new();
    s.take_dirty();
    let before = s.terrains()[0].positions.as_ptr();
    s.set_params(9.0, 0.4, 2.0, 0.6, 1.0, 0.0).unwrap();
    s.set_variant(1).unwrap();
    assert!(s.is_stale());
    assert!(s.take_dirty());
    assert_eq!(s.terrains()[0].positions.as_ptr(), before, "same buffers");
    assert!(
        s.terrains()[0].positions.iter().all(|p| p.y >= -1e-6),
        "a ridge sum is never negative"
    );
    assert!(s
        .set_params(9.0, 0.4, 2.0, 5.0, 1.0, 0.0)
        .unwrap_err()
        .contains("h"));
    assert!(s.set_variant(6).is_err());
    assert!(s.set_resolution(2000).unwrap_err().contains("resolution"));
    s.set_resolution(64).unwrap();
    s.take_dirty();
    assert_eq!(s.terrains()[0].resolution(), 64);
    // Animated variants change with time; the others do not.
    s.advance(0.5).unwrap();
    assert!(!s.take_dirty());
    s.set_variant(5).unwrap();
    s.take_dirty();
    let y0 = s.terrains()[0].positions[100].y;
    s.advance(0.5).unwrap();
    s.take_dirty();
    assert_ne!(s.terrains()[0].positions[100].y, y0);
}

#[test]
fn terrain_scene_draws_the_students_normal_beside_the_reference() {
    let mut s = TerrainScene::new();
    s.take_dirty();
    s.set_use_exercise(true);
    s.set_runner(wrong);
    let mut f = Frame::default();
    let n = s.draw(&mut f, MeshId(3));
    assert!(n.contains("terrain_normal (5.4) differs"), "{n}");
    assert!(f.labels.iter().any(|l| l.text == "yours"));
}

#[test]
fn quiz_marks_answers_and_says_why() {
    let mut q = Quiz::new();
    let mut f = Frame::default();
    assert!(q
        .draw(&mut f, &[MeshId(3); 6])
        .starts_with("0 of 6 answered"));
    assert!(q.set_answer(6, 1).is_err());
    assert!(q.set_answer(0, 7).is_err());
    // Find the right set for each terrain by comparing with the sets' own terrains.
    let sets = quiz_sets();
    let perm = inbetween::noise::Permutation::perlin();
    let mut right = [0usize; 6];
    for i in 0..6 {
        let t = &q.terrains()[i];
        for (k, set) in sets.iter().enumerate() {
            let mut probe = inbetween::terrain::Terrain::new(QUIZ_RESOLUTION).unwrap();
            probe.regenerate(&perm, &set.params).unwrap();
            if probe.positions == t.positions {
                right[i] = k + 1;
            }
        }
        assert!(right[i] > 0, "terrain {i} comes from one of the sets");
    }
    for (i, &set) in right.iter().enumerate() {
        q.set_answer(i, if i == 0 { set % 6 + 1 } else { set })
            .unwrap();
    }
    q.check();
    assert_eq!(q.score(), 5);
    f.clear();
    let note = q.draw(&mut f, &[MeshId(3); 6]);
    assert!(note.starts_with("5 of 6 right."), "{note}");
    assert!(note.contains(&format!(
        "a: not set {}; it is set {}",
        right[0] % 6 + 1,
        right[0]
    )));
    assert!(f.labels.iter().any(|l| l.text.ends_with('✗')));
    assert_eq!(f.labels.iter().filter(|l| l.text.ends_with('✓')).count(), 5);
    let old = q.terrains()[0].positions.clone();
    q.new_round();
    assert_eq!(q.score(), 0, "a new round clears the answers");
    let _ = old;
}

#[test]
fn textures_fill_rgba_and_show_them_on_quads() {
    let mut t = Textures::new();
    assert!(t.take_dirty());
    assert!(!t.take_dirty(), "nothing changed since");
    let before = t.images()[0].to_vec();
    assert_eq!(before.len(), 4 * TEXTURE_SIZE * TEXTURE_SIZE);
    t.set_params(4.0, 0.0, 4.0).unwrap();
    assert!(t.take_dirty());
    assert_ne!(t.images()[0], &before[..], "turbulence changes the marble");
    assert!(t.set_params(100.0, 0.0, 4.0).unwrap_err().contains("scale"));
    let mut f = Frame::default();
    let ids = [TextureId(0), TextureId(1), TextureId(2)];
    let note = t.draw(&mut f, &ids);
    assert!(note.contains("RGBA"));
    assert!(f.meshes.is_empty());
    assert_eq!(f.quads.iter().map(|q| q.texture).collect::<Vec<_>>(), ids);
}

#[test]
fn fractals_count_segments_and_triangles() {
    let mut s = Fractals::new();
    let mut f = Frame::default();
    s.set_depth(2.0).unwrap();
    s.draw(&mut f);
    assert_eq!(f.segments_of(palette::BLUE).count(), 3 * 16);
    assert_eq!(f.segments_of(palette::ORANGE).count(), 9 * 3);
    assert!(s.set_depth(8.0).unwrap_err().contains("depth"));
    s.set_show_previous(true);
    f.clear();
    s.draw(&mut f);
    assert_eq!(f.segments_of(palette::GRID).count(), 3 * 4 + 3 * 3);
}
