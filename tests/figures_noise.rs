#![allow(clippy::needless_range_loop)]
//! Native tests of lesson 05's figures (src/figures/noise.rs): what they draw and say.

use glam::Vec3;
use inbetween::draw::{palette, Frame, MeshId, TextureId};
use inbetween::exercises::run::{direct, Failure};
use inbetween::figures::noise::*;
#[path = "support/flat.rs"]
mod flat;

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
        .markers
        .iter()
        .find(|p| p.color[..3] == palette::PINK.to_array())
        .unwrap();
    // A dot of a fixed size on screen, drawn over the lines (negative size): visible at any
    // zoom of the eight-cell view.
    assert!(probe.size_px <= -12.0, "{}", probe.size_px);
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
    // [t, fade, fade′, 3t² − 2t³, fade″, (3t² − 2t³)″]: the curvature plot's ends.
    assert_eq!(fade[0], [0.0, 0.0, 0.0, 0.0, 0.0, 6.0]);
    assert_eq!(fade[10][1], 1.0);
    assert_eq!((fade[10][4], fade[10][5]), (0.0, -6.0));
    assert!(s.sample_fade(1).is_err());
}

#[test]
fn noise1d_probe_follows_one_ramp_next_to_an_integer() {
    // The caption's Try this: just right of 3 the pink dot sits on the orange ramp g₀·t of
    // integer 3, just left of it on the teal ramp g₁·(t − 1) of the same integer.
    let mut s = Noise1d::new();
    let pink_and = |s: &Noise1d, ramp: Vec3| {
        let mut f = Frame::default();
        s.draw(&mut f);
        let at = |c: Vec3| {
            f.markers
                .iter()
                .find(|p| p.color[..3] == c.to_array())
                .map(|p| Vec3::from(p.center))
                .unwrap()
        };
        (at(palette::PINK), at(ramp))
    };
    s.set_probe(3.02).unwrap();
    let (pink, orange) = pink_and(&s, palette::ORANGE);
    assert!((pink - orange).length() < 1e-3, "{pink} vs {orange}");
    s.set_probe(2.98).unwrap();
    let (pink, teal) = pink_and(&s, palette::TEAL);
    assert!((pink - teal).length() < 1e-3, "{pink} vs {teal}");
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
    // A fade that is right except for its slope at the ends: the probe (t = 0.35) cannot tell,
    // the other inputs tried can.
    fn slope_wrong_at_ends(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        let mut v = direct(name, args)?;
        if name == "fade" && (args[0] == 0.0 || args[0] == 1.0) {
            v[1] = 1.0;
        }
        Ok(v)
    }
    s.set_runner(slope_wrong_at_ends);
    let n = s.draw(&mut f);
    if cfg!(feature = "solutions") {
        assert!(
            n.contains("differs at t = 0.000")
                && n.contains("2 of the 6 inputs")
                && n.contains("Also at t = 1.000"),
            "{n}"
        );
    }
    s.set_runner(panics);
    let n = s.draw(&mut f);
    assert!(
        n.contains("panicked at src/exercises/noise.rs:30:5: boom"),
        "{n}"
    );
}

#[test]
fn noise2d_is_zero_at_the_dots_only_on_integer_slices() {
    let mut s = Noise2d::new();
    s.take_dirty();
    // Vertex 32 (x + 2) of each row and column lies over lattice point x (s = 2, 129 vertices).
    let dot_heights = |s: &Noise2d| -> Vec<f32> {
        let t = &s.terrains()[0];
        let r = t.resolution();
        let mut h = Vec::new();
        for j in -2..=2 {
            for i in -2..=2 {
                h.push(t.positions[(32 * (j + 2)) as usize * r + (32 * (i + 2)) as usize].y);
            }
        }
        h
    };
    assert!(dot_heights(&s).iter().all(|&y| y == 0.0));
    let mut f = Frame::default();
    assert!(s.draw(&mut f, MeshId(3)).contains("0 at every dot"));
    // Between layers the dots lift off, by the value the note's formula gives.
    s.set_z(0.37).unwrap();
    assert!(s.take_dirty(), "changing z regenerates");
    assert!(!s.take_dirty(), "once");
    let perm = inbetween::noise::Permutation::perlin();
    let heights = dot_heights(&s);
    assert!(
        heights.iter().filter(|&&y| y.abs() > 1e-3).count() >= 10,
        "{heights:?}"
    );
    for j in -2..=2 {
        for i in -2..=2 {
            let (value, slope) = s.dot_value_and_slope(i, j);
            let (x, y) = (i as f32, j as f32);
            assert!((value - perm.noise3(x, y, 0.37)).abs() < 1e-6);
            // The arrow is the surface's slope at the dot (central differences of the slice).
            let e = 1e-3;
            let dx = (perm.noise3(x + e, y, 0.37) - perm.noise3(x - e, y, 0.37)) / (2.0 * e);
            let dy = (perm.noise3(x, y + e, 0.37) - perm.noise3(x, y - e, 0.37)) / (2.0 * e);
            assert!(
                (slope - glam::Vec2::new(dx, dy)).length() < 2e-3,
                "{slope} vs ({dx}, {dy})"
            );
        }
    }
    f.clear();
    let note = s.draw(&mut f, MeshId(3));
    assert!(
        note.contains("slice z = 0.370") && note.contains("no longer 0 at the dots"),
        "{note}"
    );
    // One arrow (cone) per lattice point; black sticks from the plane up to the lifted dots.
    assert_eq!(
        f.meshes.iter().filter(|m| m.mesh == MeshId::CONE).count(),
        25
    );
    assert!(f.segments_of(palette::KEY).count() >= 10);
    // At z = 1 and z = 2 the slice holds a layer of lattice points: 0 at every dot again, with
    // that layer's gradients, which differ from layer 0's.
    for z in [1.0, 2.0] {
        s.set_z(z).unwrap();
        s.take_dirty();
        assert!(dot_heights(&s).iter().all(|&y| y.abs() < 1e-6), "z = {z}");
        f.clear();
        let note = s.draw(&mut f, MeshId(3));
        assert!(note.contains("0 at every dot again"), "{note}");
        assert!(!note.contains("no longer"), "{note}");
        assert_eq!(f.segments_of(palette::KEY).count(), 0, "no sticks");
    }
    s.set_z(1.0).unwrap();
    let layer1: Vec<_> = (-2..=2).map(|i| s.dot_value_and_slope(i, 0).1).collect();
    s.set_z(0.0).unwrap();
    let layer0: Vec<_> = (-2..=2).map(|i| s.dot_value_and_slope(i, 0).1).collect();
    assert_ne!(layer0, layer1);
    assert!(s.set_probe(2.5, 0.0).unwrap_err().contains("probe x"));
}

#[test]
fn noise2d_probe_stick_is_drawn_through_the_surface() {
    // The stick from height 0 up (or down) to the probe's value runs inside the hill or hollow
    // round the probe: depth-tested, the surface hides part of it.
    let mut s = Noise2d::new();
    s.set_probe(0.4, -0.3).unwrap();
    let mut f = Frame::default();
    s.draw(&mut f, MeshId(3));
    let pink: Vec<_> = f
        .strokes
        .iter()
        .filter(|st| Vec3::new(st.color[0], st.color[1], st.color[2]) == palette::PINK)
        .collect();
    assert!(!pink.is_empty(), "the probe's stick is drawn");
    assert!(
        pink.iter().all(|st| st.depth_bias == inbetween::draw::ON_TOP),
        "the probe's stick is drawn over the surface"
    );
}

#[test]
fn noise2d_colours_show_the_sign() {
    let mut s = Noise2d::new();
    s.take_dirty();
    let t = &s.terrains()[0];
    let (mut up, mut down) = (0, 0);
    for (p, c) in t.positions.iter().zip(&t.colors) {
        if p.y > 0.1 {
            assert!(c.x > c.z, "red above 0: {c}");
            up += 1;
        } else if p.y < -0.1 {
            assert!(c.z > c.x, "blue below 0: {c}");
            down += 1;
        }
    }
    assert!(up > 100 && down > 100);
}

#[test]
fn noise2d_draws_the_students_cell_and_checks_it_across_the_cell() {
    let mut s = Noise2d::new();
    s.take_dirty();
    s.set_use_exercise(true);
    s.set_runner(wrong);
    let mut f = Frame::default();
    let n = s.draw(&mut f, MeshId(3));
    assert!(n.contains("perlin_cell (5.2) differs"), "{n}");
    assert!(
        n.contains(&format!(
            "of the {} inputs",
            1 + STUDENT_GRID * STUDENT_GRID
        )),
        "{n}"
    );
    // The student's values as a pink grid over the probe's cell, at the height they give.
    assert_eq!(
        f.segments_of(palette::STUDENT).count() - 1,
        2 * STUDENT_GRID * (STUDENT_GRID - 1)
    );
    assert!(f.labels.iter().any(|l| l.text == "yours"));
    // Right at the probe, wrong near the cell's far edge: still reported.
    fn wrong_near_the_far_edge(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        let v = direct(name, args)?;
        if name == "perlin_cell" && args[0] > 0.9 {
            return Ok(vec![v[0] + 0.5]);
        }
        Ok(v)
    }
    s.set_runner(wrong_near_the_far_edge);
    let n = s.draw(&mut f, MeshId(3));
    if cfg!(feature = "solutions") {
        assert!(n.contains("differs at p = (1.000"), "{n}");
        assert!(n.contains(&format!("{} of the", STUDENT_GRID)), "{n}");
        s.set_runner(direct);
        assert!(s
            .draw(&mut f, MeshId(3))
            .contains("matches the reference at all"));
    }
    s.set_runner(panics);
    f.clear();
    let n = s.draw(&mut f, MeshId(3));
    assert!(
        n.contains("panicked at src/exercises/noise.rs:30:5: boom"),
        "{n}"
    );
    assert_eq!(
        f.segments_of(palette::STUDENT).count(),
        1,
        "only the probe's stick"
    );
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
fn terrain_normal_is_drawn_over_the_peaks() {
    // At the page test's rough ridge (s 4.76, h 1.19, ω 3.37) the peaks round the vertex are
    // taller than the arrow: depth-tested, its shaft is hidden among them.
    let mut s = TerrainScene::new();
    s.set_params(2.0, 0.79, 3.37, 1.19, 4.76, -3.02).unwrap();
    s.set_variant(1).unwrap();
    s.take_dirty();
    let mut f = Frame::default();
    s.draw(&mut f, MeshId(3));
    let grey: Vec<_> = f
        .strokes
        .iter()
        .filter(|st| Vec3::new(st.color[0], st.color[1], st.color[2]) == palette::REFERENCE)
        .collect();
    assert!(!grey.is_empty(), "the normal is drawn");
    assert!(grey.iter().all(|st| st.depth_bias == inbetween::draw::ON_TOP));
    // A thin grey line on the terrain is hard to find: the shaft is wide, over a wider dark
    // outline drawn before it, and its name is large.
    let wide = inbetween::figures::noise::NORMAL_PX;
    let shaft = f
        .strokes
        .iter()
        .position(|st| st.color[..3] == palette::REFERENCE.to_array() && st.width_px >= wide)
        .expect("a wide grey shaft");
    let outline = f
        .strokes
        .iter()
        .position(|st| st.color[..3] == palette::DARK.to_array())
        .expect("a dark outline");
    assert!(outline < shaft && f.strokes[outline].width_px >= f.strokes[shaft].width_px + 2.0);
    assert!(f.labels.iter().any(|l| l.text == "n" && l.large));
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
            probe.regenerate(&perm, &set.shown_params()).unwrap();
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
    q.new_round();
    assert_eq!(q.score(), 0, "a new round clears the answers");
    // The quiz's 97-vertex meshes show octaves up to 4 (up to 2 at s = 3, where octave 3's cells
    // are exactly two spacings wide), as the page says;
    // the sets' own N stays what the table lists.
    let shown: Vec<u32> = sets.iter().map(|s| s.shown_params().fractal.n).collect();
    assert_eq!(shown, [4, 1, 4, 4, 2, 4]);
    let listed: Vec<u32> = sets.iter().map(|s| s.params.fractal.n).collect();
    assert_eq!(listed, [9, 1, 9, 9, 9, 9]);
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
    // The outlines are wide strokes, not 1 px lines.
    assert!(f.lines.is_empty());
    assert!(f.strokes.iter().all(|s| s.width_px == FRACTAL_PX && FRACTAL_PX >= 2.0));
    assert!(s.set_depth(8.0).unwrap_err().contains("depth"));
    s.set_show_previous(true);
    f.clear();
    let note = s.draw(&mut f);
    assert_eq!(f.segments_of(palette::GREY).count(), 3 * 4 + 3 * 3);
    // The note counts what the step adds: 2 bump sides per segment of depth 1, and 3 triangles
    // of depth 1 cut.
    assert!(
        note.contains("each of the snowflake's 12 segments into 4 and adds the 24 coloured sides")
            && note.contains("every triangle of depth 1 in the Sierpinski triangle (3 of them)"),
        "{note}"
    );
    // Every segment of the depth before lies on the Sierpinski triangle of this depth: grey covers
    // its outer edges and the orange left over is the new inner triangles.
    let orange: Vec<(Vec3, Vec3)> = f.segments_of(palette::ORANGE).collect();
    let on_orange = |p: Vec3| {
        orange.iter().any(|(a, b)| {
            let (a, b, p) = (a.truncate(), b.truncate(), p.truncate());
            let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
            (a + t * (b - a) - p).length() < 1e-4
        })
    };
    let grey_on_right: Vec<(Vec3, Vec3)> = f
        .segments_of(palette::GREY)
        .filter(|(a, _)| a.x > 0.0)
        .collect();
    assert_eq!(grey_on_right.len(), 9);
    assert!(grey_on_right
        .iter()
        .all(|(a, b)| on_orange(*a) && on_orange(*b) && on_orange((*a + *b) / 2.0)));
    // What the step adds is drawn again over the grey (nearer the camera), so it shows even where
    // the step is finer than a pixel: the 24 bump sides and the 3 middle triangles' 9 sides, none
    // of them on a grey segment.
    let grey: Vec<(Vec3, Vec3)> = f.segments_of(palette::GREY).collect();
    for (color, count) in [(palette::BLUE, 24), (palette::ORANGE, 9)] {
        let over: Vec<(Vec3, Vec3)> = f.segments_of(color).filter(|(a, _)| a.z > 0.01).collect();
        assert_eq!(over.len(), count);
        assert!(over.iter().all(|(a, b)| !grey.iter().any(|(c, d)| {
            let (m, c, d) = (((*a + *b) / 2.0).truncate(), c.truncate(), d.truncate());
            let t = ((m - c).dot(d - c) / (d - c).length_squared()).clamp(0.0, 1.0);
            (c + t * (d - c) - m).length() < 1e-4
        })));
    }
}

#[test]
fn where_the_newest_octave_adds_nothing_both_profiles_show() {
    // At N = 7, α = 0.2 the newest octave is about 1e-5 high: the profile without it lies on
    // the orange one. The dark one is drawn after it, dashed and narrower, so the orange shows
    // between the dashes and either side of them.
    let mut s = Octaves::new();
    s.set_params(7.0, 0.2, 3.37).unwrap();
    let mut f = Frame::default();
    s.draw(&mut f, MeshId(3));
    let of = |c: Vec3| -> Vec<usize> {
        (0..f.strokes.len())
            .filter(|&i| f.strokes[i].color[..3] == c.to_array())
            .collect()
    };
    let (orange, dark) = (of(palette::ORANGE), of(palette::DARK));
    assert!(!orange.is_empty() && !dark.is_empty());
    assert!(orange.iter().max() < dark.iter().min(), "the dark profile over the orange");
    assert!(dark.iter().all(|&i| f.strokes[i].dash[3] > 0.0), "dashed");
    let width = |i: &[usize]| f.strokes[i[0]].width_px;
    assert!(width(&orange) >= width(&dark) + 2.0, "{} {}", width(&orange), width(&dark));
}

#[test]
fn octaves_name_the_octaves_finer_than_the_mesh_and_can_leave_them_out() {
    let mut s = Octaves::new();
    // 193 vertices, 0.0104 m apart: octave 5 (cells of 1/32 m) fits, octave 6 does not.
    assert_eq!(s.last_resolved_octave(), Some(5));
    s.set_params(5.0, 0.8, 2.0).unwrap();
    let mut f = Frame::default();
    assert!(!s.draw(&mut f, MeshId(3)).contains("finer than the mesh"));
    s.set_params(7.0, 0.8, 2.0).unwrap();
    let n = s.draw(&mut f, MeshId(3));
    assert!(
        n.contains("Octaves 6 and 7 are finer than the mesh")
            && n.contains("0.010 m apart")
            && n.contains("(0.021 m)"),
        "{n}"
    );
    s.set_params(6.0, 0.8, 2.0).unwrap();
    assert!(s.draw(&mut f, MeshId(3)).contains("Octave 6 is finer"));
    // Left out: the surface is the sum up to octave 5, and the plot's sum column too, while the
    // plot still shows octave 6 itself (grey on the page).
    s.set_band_limit(true);
    s.take_dirty();
    let n = s.draw(&mut f, MeshId(3));
    assert!(
        n.contains("left out of the surface: what stays rough there is octave 5, whose cells are \
             3.000 vertex spacings wide."),
        "{n}"
    );
    let perm = inbetween::noise::Permutation::perlin();
    let t = &s.terrains()[0];
    let five = inbetween::noise::Fractal {
        n: 5,
        alpha: 0.8,
        omega: 2.0,
    };
    let k = 77 * OCTAVES_RESOLUTION + 101;
    let q = t.positions[k];
    assert!((q.y - 0.5 * five.sum2(&perm, q.x, q.z)).abs() < 1e-5);
    let rows = s.sample_octaves(3).unwrap();
    let sum5: f32 = rows[1][1..=6].iter().sum();
    assert!((rows[1][11] - sum5).abs() < 1e-6 && rows[1][7].is_finite());
    // At ω = 3.37 the finest octave kept, 3, is a bed of spikes 2.5 spacings wide: the note
    // names it, so the spikes left are not taken for the octaves left out.
    // Both profiles (orange, dark) are drawn over the surface, whose spikes stand in front of
    // the line v = 0.25 at these settings.
    let mut g = Frame::default();
    s.draw(&mut g, MeshId(3));
    let on_top = g.strokes.iter().filter(|st| st.depth_bias == inbetween::draw::ON_TOP).count();
    assert!(on_top >= 2 * 400, "{on_top} segments on top, of {}", g.strokes.len());
    s.set_params(7.0, 0.8, 3.37).unwrap();
    let n = s.draw(&mut f, MeshId(3));
    assert!(n.contains("Octaves 4 to 7 are finer") && n.contains("octave 3, whose cells are 2.508 vertex"), "{n}");
    s.set_params(7.0, 0.8, 2.0).unwrap();
    s.set_band_limit(false);
    assert!(s.take_dirty(), "the toggle regenerates");
    // With nothing past the limit, the ticked box says so instead of changing nothing silently.
    s.set_params(3.0, 0.5, 2.0).unwrap();
    s.set_band_limit(true);
    let n = s.draw(&mut f, MeshId(3));
    assert!(
        n.contains("shows octaves up to 5, so none of these is left out: raise N"),
        "{n}"
    );
}

#[test]
fn octaves_draw_the_students_profile_and_check_it_along_the_line() {
    let mut s = Octaves::new();
    s.take_dirty();
    s.set_use_exercise(true);
    s.set_runner(wrong);
    let mut f = Frame::default();
    let n = s.draw(&mut f, MeshId(3));
    assert!(
        n.contains("fractal_sum (5.3) differs at p = (-1.000, 0.250)"),
        "{n}"
    );
    assert!(
        n.contains(&format!("of the {PROFILE_POINTS} inputs")),
        "{n}"
    );
    assert_eq!(f.segments_of(palette::STUDENT).count(), PROFILE_POINTS - 1);
    // Right everywhere but past u = 0.9: the verdict finds it on the drawn line.
    fn wrong_at_the_right_end(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        let v = direct(name, args)?;
        if name == "fractal_sum" && args[0] > 0.9 {
            return Ok(vec![v[0] + 0.2]);
        }
        Ok(v)
    }
    s.set_runner(wrong_at_the_right_end);
    let n = s.draw(&mut f, MeshId(3));
    if cfg!(feature = "solutions") {
        assert!(
            n.contains("differs at p = (0.905, 0.250)")
                && n.contains("20 of the 401")
                && n.contains("and 16 more"),
            "{n}"
        );
        s.set_runner(direct);
        let n = s.draw(&mut f, MeshId(3));
        assert!(n.contains("matches the reference at all 401 inputs"), "{n}");
    } else {
        assert!(n.contains("Not done yet"), "{n}");
    }
}

#[test]
fn terrain_scene_names_the_octaves_finer_than_the_mesh() {
    let mut s = TerrainScene::new();
    s.take_dirty();
    let mut f = Frame::default();
    // 128 vertices, 0.0157 m apart: octaves 5 to 9 of the course's N = 9 are wasted.
    let n = s.draw(&mut f, MeshId(3));
    assert!(
        n.contains("0.016 m apart, so octaves 5 to 9 are finer than the mesh"),
        "{n}"
    );
    s.set_resolution(512).unwrap();
    s.take_dirty();
    let n = s.draw(&mut f, MeshId(3));
    assert!(n.contains("octaves 7 to 9 are finer"), "{n}");
    // One octave past the mesh: the sentence speaks of it in the singular.
    s.set_params(7.0, 0.4, 2.0, 0.3, 1.0, 0.0).unwrap();
    s.take_dirty();
    let n = s.draw(&mut f, MeshId(3));
    assert!(
        n.contains(
            "so octave 7 is finer than the mesh (cells no wider than two spacings, 0.008 m): it \
             falls between vertices and only adds aliasing; “leave out octaves finer than the \
             mesh” drops it."
        ),
        "{n}"
    );
    s.set_params(6.0, 0.4, 2.0, 0.3, 1.0, 0.0).unwrap();
    s.take_dirty();
    assert!(!s.draw(&mut f, MeshId(3)).contains("finer than the mesh"));
    // Leaving them out builds the surface from octaves 0 to 4 at 128 × 128.
    s.set_resolution(128).unwrap();
    s.set_params(9.0, 0.4, 2.0, 0.3, 1.0, 0.0).unwrap();
    s.set_band_limit(true);
    s.take_dirty();
    assert_eq!(s.shown_params().fractal.n, 4);
    let mut expected = inbetween::terrain::Terrain::new(128).unwrap();
    expected
        .regenerate(&inbetween::noise::Permutation::perlin(), &s.shown_params())
        .unwrap();
    assert_eq!(s.terrains()[0].positions, expected.positions);
}

#[test]
fn terrain_scene_checks_the_students_normal_beyond_the_sliders() {
    let mut s = TerrainScene::new();
    s.take_dirty();
    s.set_use_exercise(true);
    // A normal that forgets s: at the default s = 1 every vertex agrees, so only the inputs at
    // other s can tell.
    fn forgets_s(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        match name {
            "terrain_normal" => direct(name, &[args[0], 1.0, args[2], args[3]]),
            _ => direct(name, args),
        }
    }
    s.set_runner(forgets_s);
    let mut f = Frame::default();
    let n = s.draw(&mut f, MeshId(3));
    if cfg!(feature = "solutions") {
        assert!(
            n.contains("differs at the probe's ∇g with h = 0.5, s = 2")
                && n.contains("2 of the 8 inputs"),
            "{n}"
        );
        s.set_runner(direct);
        assert!(s
            .draw(&mut f, MeshId(3))
            .contains("matches the reference at all 8 inputs"));
    }
}

const FOUR: [MeshId; 4] = [MeshId(3), MeshId(4), MeshId(5), MeshId(6)];

/// The mean steepness `1 − n_y` over a terrain's vertices.
fn mean_steepness(t: &inbetween::terrain::Terrain) -> f32 {
    t.normals.iter().map(|n| 1.0 - n.y).sum::<f32>() / t.normals.len() as f32
}

#[test]
fn variants_stand_side_by_side_from_the_same_noise() {
    let mut f = Variants::new();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, &FOUR);
    // Four terrains at their own places, each labelled with its variant.
    let drawn: Vec<(MeshId, Vec3)> = frame
        .meshes
        .iter()
        .filter(|m| FOUR.contains(&m.mesh))
        .map(|m| (m.mesh, m.model.w_axis.truncate()))
        .collect();
    assert_eq!(drawn.len(), 4);
    for (i, (id, at)) in drawn.iter().enumerate() {
        assert_eq!(*id, FOUR[i]);
        assert!(at.distance(Variants::placement(i)) < 1e-6);
    }
    for i in 0..4 {
        for j in 0..i {
            let d = Variants::placement(i) - Variants::placement(j);
            assert!(
                d.x.abs() > 2.1 || d.z.abs() > 2.1,
                "terrains {i} and {j} overlap"
            );
        }
    }
    let labels: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    assert_eq!(labels, SIDE_BY_SIDE_VARIANTS.map(|v| v.1));
    assert!(!frame.keep_in_view.is_empty());
    // The page: 129 × 129 vertices each, 1/64 m apart, so octave 5's cells (1/32 m, exactly two
    // spacings: the Nyquist limit) and the finer ones are left out.
    assert_eq!(VARIANTS_RESOLUTION, 129);
    assert!(
        note.contains("Octaves 5 to 9 are finer than these meshes and left out"),
        "{note}"
    );
    for i in 0..4 {
        assert_eq!(f.shown_params(i).fractal.n, 4);
    }
    // The same noise: the sum's terrain is Figure 4's shape at N = 4.
    let sum = &f.terrains()[0].positions;
    let perm = inbetween::noise::Permutation::perlin();
    let p = f.shown_params(0);
    for &k in &[0, 1000, 8000] {
        let q = sum[k];
        assert!((q.y - p.h * p.g(&perm, q.x, q.z).0).abs() < 1e-5);
    }
}

/// What the text and the Try this say: the ridge never goes below 0, the inverted ridge lies
/// around 0 with water in its lowest parts, marble stays within ±h/2; from α = 0.4 to 0.8 the
/// ridge grows by about 70 %, the sum gets taller and rougher, marble still spans ±0.15 m; at h = 0
/// all four are flat.
#[test]
fn variants_do_what_the_page_says() {
    let mut f = Variants::new();
    let mut frame = Frame::default();
    f.draw(&mut frame, &FOUR);
    let water = inbetween::terrain::terrain_color(-1.0, Vec3::Y, 1.0);
    let (ridge_lo, ridge_04) = f.height_range(1);
    assert!(ridge_lo >= 0.0);
    let (inv_lo, inv_hi) = f.height_range(2);
    assert!(inv_lo < -0.05 && inv_hi > 0.05, "{inv_lo} {inv_hi}");
    assert!(f.terrains()[2]
        .colors
        .iter()
        .any(|c| (*c - water).length() < 1e-3));
    let (m_lo, m_hi) = f.height_range(3);
    assert!(m_lo >= -0.15 - 1e-6 && m_hi <= 0.15 + 1e-6);
    assert!(
        m_lo < -0.149 && m_hi > 0.149,
        "marble spans ±h/2: {m_lo} {m_hi}"
    );
    let (sum_lo, sum_hi) = f.height_range(0);
    let rough_04 = mean_steepness(f.terrains()[0]);

    f.set_params(9.0, 0.8, 0.3).unwrap();
    let note = f.draw(&mut frame, &FOUR);
    let (ridge_lo, ridge_08) = f.height_range(1);
    assert!(ridge_lo >= 0.0);
    assert!(
        ridge_08 / ridge_04 > 1.65 && ridge_08 / ridge_04 < 1.75,
        "{ridge_04} -> {ridge_08}"
    );
    let (lo, hi) = f.height_range(0);
    assert!(hi - lo > 1.5 * (sum_hi - sum_lo));
    assert!(mean_steepness(f.terrains()[0]) > 1.5 * rough_04);
    let (m_lo, m_hi) = f.height_range(3);
    assert!(m_lo < -0.149 && m_hi > 0.149 && m_lo >= -0.1500001 && m_hi <= 0.1500001);
    assert!(note.contains("marble from -0.150 to 0.150 m"), "{note}");

    f.set_params(9.0, 0.8, 0.0).unwrap();
    f.draw(&mut frame, &FOUR);
    for i in 0..4 {
        assert_eq!(
            f.height_range(i),
            (0.0, 0.0),
            "variant {i} is flat at h = 0"
        );
    }
}

#[test]
fn variants_reject_bad_parameters_and_keep_the_last_good_ones() {
    let mut f = Variants::new();
    assert!(f
        .set_params(2.5, 0.4, 0.3)
        .unwrap_err()
        .contains("N must be a whole number"));
    assert!(f.set_params(10.0, 0.4, 0.3).unwrap_err().contains("N"));
    assert!(f
        .set_params(9.0, f32::NAN, 0.3)
        .unwrap_err()
        .contains("alpha"));
    assert!(f.set_params(9.0, 0.4, 3.0).unwrap_err().contains("h"));
    assert!(f.set_params(9.0, 0.4, -0.1).unwrap_err().contains("h"));
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, &FOUR);
    assert!(note.contains("N = 9, α = 0.400, h = 0.300"), "{note}");
}

/// Figure 2's Try this: between two layers (z = 0.5) the arrows turn and, on the whole, shrink
/// (each is the fade-weighted mix of the two layers' gradients).
#[test]
fn noise2d_arrows_turn_and_shrink_between_layers() {
    let mut s = Noise2d::new();
    let slopes = |s: &Noise2d| -> Vec<glam::Vec2> {
        let mut v = Vec::new();
        for j in -2..=2 {
            for i in -2..=2 {
                v.push(s.dot_value_and_slope(i, j).1);
            }
        }
        v
    };
    let at0 = slopes(&s);
    s.set_z(0.5).unwrap();
    let half = slopes(&s);
    let mean = |v: &[glam::Vec2]| v.iter().map(|g| g.length()).sum::<f32>() / v.len() as f32;
    assert!(
        mean(&half) < 0.8 * mean(&at0),
        "{} vs {}",
        mean(&half),
        mean(&at0)
    );
    let turned = at0
        .iter()
        .zip(&half)
        .filter(|(a, b)| b.length() > 1e-3 && a.angle_to(**b).abs() > 10f32.to_radians())
        .count();
    assert!(turned >= 10, "{turned} of 25 arrows turn");
}

/// Figures 2, 3 and 4 declare their whole terrain as what must stay in view, so the camera fits
/// it at any canvas size (no corner cut at 800 × 600).
#[test]
fn single_terrain_figures_keep_their_whole_surface_in_view() {
    fn check(frame: &Frame, t: &inbetween::terrain::Terrain) {
        let (lo, hi) = frame.keep_in_view.iter().fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        assert!(!frame.keep_in_view.is_empty());
        for p in &t.positions {
            assert!(
                p.cmpge(lo - 1e-6).all() && p.cmple(hi + 1e-6).all(),
                "{p} outside"
            );
        }
    }
    let mut n2 = Noise2d::new();
    n2.take_dirty();
    let mut f = Frame::default();
    n2.draw(&mut f, MeshId(3));
    check(&f, n2.terrains()[0]);
    let mut oct = Octaves::new();
    oct.set_params(7.0, 0.8, 2.0).unwrap();
    oct.take_dirty();
    let mut f = Frame::default();
    oct.draw(&mut f, MeshId(3));
    check(&f, oct.terrains()[0]);
    let mut ter = TerrainScene::new();
    ter.set_params(9.0, 0.4, 2.0, 1.5, 1.0, 0.0).unwrap();
    ter.take_dirty();
    let mut f = Frame::default();
    ter.draw(&mut f, MeshId(3));
    check(&f, ter.terrains()[0]);
}

/// The page: about 11° apart on average at 17 × 17, under 1° at 129 × 129; the Try this: 15.6° at
/// 9 × 9 down to 0.6° at 129 × 129, always closer on a finer mesh; flat ground at h = 0.
#[test]
fn averaged_normals_close_in_on_the_exact_ones_as_the_mesh_gets_finer() {
    let mut f = Normals::new();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, MeshId(3));
    assert!(note.starts_with("17 × 17 vertices"), "{note}");
    let mut last = f32::INFINITY;
    let mut means = Vec::new();
    for r in NORMALS_RESOLUTIONS {
        f.set_params(r as f32, 0.3).unwrap();
        let mut frame = Frame::default();
        let note = f.draw(&mut frame, MeshId(3));
        let (mean, largest) = f.angle_stats();
        assert!(mean < last && mean <= largest, "{r}: {mean} after {last}");
        last = mean;
        means.push(mean);
        assert!(
            note.contains(&format!("by {mean:.1}° on average")),
            "{note}"
        );
        // Two arrows (cones) at each of 9 × 9 vertices, the whole terrain in view.
        assert_eq!(
            frame
                .meshes
                .iter()
                .filter(|m| m.mesh == MeshId::CONE)
                .count(),
            2 * 81
        );
        assert!(!frame.keep_in_view.is_empty());
        // The exact normals are the terrain's own (what lights it).
        let (exact, averaged) = f.normals();
        assert_eq!(exact, &f.terrains()[0].normals[..]);
        assert_eq!(exact.len(), averaged.len());
    }
    assert!((means[0] - 15.6).abs() < 0.05, "{}", means[0]);
    assert!((means[1] - 11.0).abs() < 0.5, "{}", means[1]);
    assert!(
        (means[4] - 0.6).abs() < 0.05 && means[4] < 1.0,
        "{}",
        means[4]
    );
    f.set_params(33.0, 0.0).unwrap();
    f.draw(&mut Frame::default(), MeshId(3));
    let (exact, averaged) = f.normals();
    assert!(exact
        .iter()
        .chain(averaged)
        .all(|n| (*n - Vec3::Y).length() < 1e-6));
    assert_eq!(f.angle_stats(), (0.0, 0.0));
}

#[test]
fn normals_figure_rejects_bad_parameters_and_keeps_the_last_good_ones() {
    let mut f = Normals::new();
    assert!(f
        .set_params(20.0, 0.3)
        .unwrap_err()
        .contains("resolution must be one of"));
    assert!(f
        .set_params(f32::NAN, 0.3)
        .unwrap_err()
        .contains("resolution"));
    assert!(f.set_params(17.0, 1.5).unwrap_err().contains("h"));
    assert!(f.set_params(65.0, f32::INFINITY).unwrap_err().contains("h"));
    let note = f.draw(&mut Frame::default(), MeshId(3));
    assert!(
        note.starts_with("17 × 17 vertices") && note.contains("h = 0.300"),
        "{note}"
    );
}

/// Figure 5's plot: one row per resolution offered, the same numbers as the note at each.
#[test]
fn the_normals_plot_gives_the_angle_at_every_resolution() {
    let mut f = Normals::new();
    f.set_params(17.0, 0.5).unwrap();
    f.draw(&mut Frame::default(), MeshId(3));
    let rows = f.angles_by_resolution();
    assert_eq!(rows.len(), NORMALS_RESOLUTIONS.len());
    for (row, r) in rows.iter().zip(NORMALS_RESOLUTIONS) {
        assert_eq!(row[0], r as f32);
        assert!(row[1] <= row[2]);
    }
    assert!(rows.windows(2).all(|w| w[1][1] < w[0][1]), "{rows:?}");
    assert_eq!(rows[1][1..], <[f32; 2]>::from(f.angle_stats())[..]);
}

#[test]
fn the_1d_noise_curve_and_its_guides_are_wide_strokes() {
    let mut s = Noise1d::new();
    s.set_probe(3.5).unwrap();
    let mut f = Frame::default();
    s.draw(&mut f);
    // The only 1-pixel line is the baseline, in the grid's axis colour.
    assert!(f
        .lines
        .iter()
        .all(|v| v.color[..3] == palette::GRID_AXIS.to_array()));
    let curve: Vec<_> = f
        .strokes
        .iter()
        .filter(|st| st.color[..3] == palette::BLUE.to_array())
        .collect();
    assert!(curve.len() > 50, "the curve is many segments");
    assert!(curve.iter().all(|st| st.width_px == inbetween::draw::CURVE_PX));
    // The gradients, ramps and the gap between them: GUIDE_PX.
    assert!(
        f.strokes.iter().filter(|st| st.width_px == GUIDE_PX).count() >= 9 + 2 + 1,
        "nine gradients, two ramps, the gap"
    );
}

#[test]
fn the_1d_figure_declares_a_view_that_holds_everything_it_draws() {
    // The camera fits the declared box at every canvas size and "frame all" returns to it: the
    // box must hold the curve, the ticks, what is drawn of both ramps and every dot, wherever
    // the probe is.
    for seed in [0.0, 1.0, 7.0, 42.0] {
        let mut s = Noise1d::new();
        s.set_seed(seed).unwrap();
        for k in 0..32 {
            s.set_probe(0.05 + 7.9 * k as f32 / 31.0).unwrap();
            let (lo, hi) = s.view_box();
            let mut f = Frame::default();
            s.draw(&mut f);
            let (flo, fhi) = f.keep_in_view.iter().fold(
                (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
                |(a, b), p| (a.min(*p), b.max(*p)),
            );
            assert_eq!((flo, fhi), (lo, hi), "the frame declares view_box()");
            let drawn = f
                .segments()
                .flat_map(|(a, b, _)| [a, b])
                .chain(f.markers.iter().map(|m| Vec3::from(m.center)))
                .chain(f.points.iter().map(|p| Vec3::from(p.center)));
            for p in drawn {
                assert!(
                    p.x >= lo.x - 1e-4 && p.x <= hi.x + 1e-4 && p.y >= lo.y - 1e-4 && p.y <= hi.y + 1e-4,
                    "seed {seed}: {p} outside {lo} – {hi}"
                );
            }
        }
    }
}

/// The ramps are drawn as far as the curve's own height (and the probe's dots) reach, not
/// to a steep gradient's full rise: at the defaults the curve spans at least 60 % of the
/// declared height (41 % in a box fitted to the steepest ramp), each ramp still
/// runs from its lattice point past the probe's dot on it, and with the camera fitted on the
/// page's 760 × 420 canvas from its orbit the curve is at least 200 px tall.
#[test]
fn the_1d_figure_frames_the_curve_and_cuts_the_ramps_at_its_height() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let s = Noise1d::new();
    let mut f = Frame::default();
    s.draw(&mut f);
    let (lo, hi) = s.view_box();
    let curve: Vec<Vec3> = f
        .segments_of(palette::BLUE)
        .flat_map(|(a, b)| [a, b])
        .collect();
    let (c_lo, c_hi) = curve
        .iter()
        .fold((f32::MAX, f32::MIN), |(l, h), p| (l.min(p.y), h.max(p.y)));
    let share = (c_hi - c_lo) / (hi.y - lo.y);
    assert!(share >= 0.6, "the curve spans {share} of the view's height");
    let ramps: Vec<(Vec3, Vec3)> = f
        .strokes
        .iter()
        .filter(|st| {
            st.color[..3] == palette::ORANGE.to_array() || st.color[..3] == palette::TEAL.to_array()
        })
        // A ramp ends on the axis at its lattice point; a gradient tick crosses it mid-way.
        .filter(|st| st.a[1] == 0.0 || st.b[1] == 0.0)
        .map(|st| (Vec3::from(st.a), Vec3::from(st.b)))
        .collect();
    assert_eq!(ramps.len(), 2, "two ramps");
    for color in [palette::ORANGE, palette::TEAL] {
        let dot = f
            .markers
            .iter()
            .find(|m| m.color[..3] == color.to_array())
            .map(|m| Vec3::from(m.center))
            .unwrap();
        let on_ramp = ramps.iter().any(|(a, b)| {
            let (l, r) = (a.x.min(b.x), a.x.max(b.x));
            dot.x >= l - 1e-4 && dot.x <= r + 1e-4
        });
        assert!(
            on_ramp,
            "the {color} dot at {dot} lies on what is drawn of its ramp"
        );
    }
    let size = glam::Vec2::new(760.0, 420.0);
    let mut camera = OrbitCamera::from_view([0.0, 0.0, 0.0, 7.5, 0.0, 0.0]);
    assert!(camera.fit(&f.fit_points(), size, FIT_PAD_PX));
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let px: Vec<glam::Vec2> = curve
        .iter()
        .map(|p| project_to_canvas(view_proj, size, *p).unwrap())
        .collect();
    let (y_lo, y_hi) = px
        .iter()
        .fold((f32::MAX, f32::MIN), |(l, h), p| (l.min(p.y), h.max(p.y)));
    assert!(y_hi - y_lo >= 200.0, "the curve is {} px tall", y_hi - y_lo);
}

#[test]
fn a_new_quiz_round_regenerates_its_terrains_once() {
    let mut q = Quiz::new();
    assert!(q.take_dirty(), "the first terrains are uploaded");
    assert!(!q.take_dirty());
    let before: Vec<Vec<Vec3>> = q.terrains().iter().map(|t| t.positions.clone()).collect();
    q.new_round();
    assert!(q.take_dirty(), "a new round reshuffles the terrains");
    assert!(!q.take_dirty(), "once");
    let after: Vec<Vec<Vec3>> = q.terrains().iter().map(|t| t.positions.clone()).collect();
    assert_ne!(before, after);
}

#[test]
fn each_quiz_letter_is_nearest_its_own_terrain() {
    // Between the rows a letter reads as the tile beside it in the other row: at the page's
    // camera and orbited as the page test does, each letter's box is nearer its own terrain's
    // middle, on the canvas, than any other terrain's.
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let mut q = Quiz::new();
    q.set_answer(4, 3).unwrap();
    let mut f = Frame::default();
    let meshes: Vec<MeshId> = (0..6).map(MeshId).collect();
    q.draw(&mut f, &meshes);
    for size in crate::label_clearance::CANVASES {
        for (yaw, pitch) in [(0.0, 0.8), (-1.216, 1.104), (1.216, 1.104), (-0.6, 0.5)] {
            let mut camera = OrbitCamera::from_view([0.0, -0.2, 0.2, 8.2, yaw, pitch]);
            camera.fit(&f.fit_points(), size, FIT_PAD_PX);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let middle = |i: usize| project_to_canvas(view_proj, size, Quiz::placement(i)).unwrap();
            for (i, label) in f.labels.iter().enumerate() {
                let r = label.first_place(view_proj, size).unwrap();
                let c = r.min + 0.5 * r.size;
                let nearest = (0..6)
                    .min_by(|&a, &b| c.distance(middle(a)).total_cmp(&c.distance(middle(b))))
                    .unwrap();
                assert_eq!(nearest, i, "{:?} at ({yaw}, {pitch}) on {size}", label.text);
                // At the page's camera, nor over its own tile (the back row's peaks rise past
                // their far edge). Orbited, "above" and "below" on the canvas need not lead
                // off the tile.
                if yaw != 0.0 {
                    continue;
                }
                let own = q.terrains()[i].positions.iter().step_by(7);
                for p in own.filter_map(|&p| {
                    project_to_canvas(view_proj, size, p + Quiz::placement(i))
                }) {
                    assert!(
                        !(p.cmpgt(r.min).all() && p.cmplt(r.max()).all()),
                        "{:?} covers its tile at {p}, ({yaw}, {pitch}) on {size}",
                        label.text
                    );
                }
            }
        }
    }
}

#[test]
fn the_fractals_figure_declares_a_view_that_holds_both_shapes() {
    // Without a declared view a narrow canvas would cut the snowflake's left and the triangle's right.
    let (lo, hi) = Fractals::view_box();
    let mut s = Fractals::new();
    s.set_show_previous(true);
    for depth in 0..=6 {
        s.set_depth(depth as f32).unwrap();
        let mut f = Frame::default();
        s.draw(&mut f);
        assert!(!f.keep_in_view.is_empty());
        let drawn = f
            .segments()
            .flat_map(|(a, b, _)| [a, b])
            .chain(f.labels.iter().map(|l| l.anchor));
        for p in drawn {
            assert!(
                p.x >= lo.x - 1e-4 && p.x <= hi.x + 1e-4 && p.y >= lo.y - 1e-4 && p.y <= hi.y + 1e-4,
                "depth {depth}: {p} outside {lo} – {hi}"
            );
        }
    }
}

#[test]
fn the_fractals_names_are_centred_under_their_shapes() {
    // A name that starts at the shape's middle reads as belonging to whatever lies to its right.
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let mut s = Fractals::new();
    let mut f = Frame::default();
    s.draw(&mut f);
    for size in crate::label_clearance::CANVASES {
        // The page's camera (lessons/05-noise/lesson.js), fitted to the declared view.
        let mut camera = OrbitCamera::from_view([0.0, -0.1, 0.0, 5.6, 0.0, 0.0]);
        camera.fit(&f.fit_points(), size, FIT_PAD_PX);
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        // Each shape's middle on the canvas: the extremes of its lines in its colour.
        for (name, color) in [
            ("Koch snowflake", palette::BLUE),
            ("Sierpinski triangle", palette::ORANGE),
        ] {
            let xs: Vec<f32> = f
                .segments()
                .filter(|(_, _, c)| *c == color)
                .flat_map(|(a, b, _)| [a, b])
                .map(|p| project_to_canvas(view_proj, size, p).unwrap().x)
                .collect();
            let lo = xs.iter().copied().fold(f32::MAX, f32::min);
            let hi = xs.iter().copied().fold(f32::MIN, f32::max);
            let label = f.labels.iter().find(|l| l.text == name).unwrap();
            let rect = label.first_place(view_proj, size).unwrap();
            let middle = rect.min.x + 0.5 * rect.size.x;
            assert!(
                (middle - 0.5 * (lo + hi)).abs() < 2.0,
                "{name} on {size}: box middle at {middle}, the shape from {lo} to {hi}"
            );
        }
    }
}

/// 5.1 right below t = 0.9 and panicking from there (an `assert!` on `t`).
fn fade_panics_near_1(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name == "fade" && args[0] >= 0.9 {
        return Err(Failure::Panicked(format!(
            "panicked at src/exercises/noise.rs:24:5:\nt is too close to the cell's end: {}",
            args[0]
        )));
    }
    match name {
        "fade" => {
            let t = args[0];
            Ok(vec![
                inbetween::noise::fade(t),
                inbetween::noise::fade_derivative(t),
            ])
        }
        _ => direct(name, args),
    }
}

thread_local! {
    /// The first panic of the page-like runner below.
    static STUCK: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

/// [`fade_panics_near_1`] as the page runs it: after a panic, every later call gets it back.
fn fade_stuck_after_a_panic(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if let Some(message) = STUCK.with(|s| s.borrow().clone()) {
        return Err(Failure::Panicked(message));
    }
    let answer = fade_panics_near_1(name, args);
    if let Err(Failure::Panicked(message)) = &answer {
        STUCK.with(|s| *s.borrow_mut() = Some(message.clone()));
    }
    answer
}

#[test]
fn a_panic_of_5_1_is_named_once_against_the_t_that_caused_it() {
    for runner in [
        fade_panics_near_1 as fn(&str, &[f32]) -> Result<Vec<f32>, Failure>,
        fade_stuck_after_a_panic,
    ] {
        STUCK.with(|s| *s.borrow_mut() = None);
        let mut s = Noise1d::new();
        s.set_runner(runner);
        s.set_use_exercise(true);
        // The page samples the fade plot first: its first t at or past 0.9 panics.
        s.sample_fade(101).unwrap();
        let n = s.draw(&mut Frame::default());
        assert!(
            n.contains(
                "Your exercise 5.1 fade, called with t = 0.900, panicked at \
                 src/exercises/noise.rs:24:5: t is too close to the cell's end: 0.9."
            ),
            "{n}"
        );
        assert_eq!(n.matches("panicked").count(), 1, "{n}");
        // Without the plot, the verdict's probes meet it first, at t = 1.
        let mut s = Noise1d::new();
        STUCK.with(|s| *s.borrow_mut() = None);
        s.set_runner(runner);
        s.set_use_exercise(true);
        let n = s.draw(&mut Frame::default());
        assert!(
            n.contains("fade, called with t = 1.000, panicked at") && n.contains("end: 1."),
            "{n}"
        );
    }
}

/// Figure 7 keeps all six quiz terrains in view from any orbit the student can reach: at the
/// page's camera (lessons/05-noise/lesson.js) turned to every 30° of yaw and pitches from below
/// the ground to straight down, fitted as the viewer does on the canvases the page gives it at
/// 800 × 600 and 1600 × 1000, every vertex of every terrain lands on the canvas. Without a
/// declared view the page's fixed camera cut the back and front rows once orbited.
#[test]
fn the_quiz_terrains_stay_in_view_from_every_orbit() {
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let q = Quiz::new();
    let mut f = Frame::default();
    let meshes: Vec<MeshId> = (0..6).map(MeshId).collect();
    q.draw(&mut f, &meshes);
    let points: Vec<Vec3> = q
        .terrains()
        .iter()
        .enumerate()
        .flat_map(|(i, t)| t.positions.iter().map(move |&p| p + Quiz::placement(i)))
        .collect();
    assert_eq!(points.len(), 6 * QUIZ_RESOLUTION * QUIZ_RESOLUTION);
    for size in crate::label_clearance::CANVASES {
        for k in 0..12 {
            let yaw = k as f32 * std::f32::consts::TAU / 12.0;
            for pitch in [-1.5, -0.6, 0.0, 0.4, 0.8, 1.2, 1.55] {
                let mut camera = OrbitCamera::from_view([0.0, -0.2, 0.2, 8.2, yaw, pitch]);
                camera.fit(&f.fit_points(), size, FIT_PAD_PX);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                for p in points.iter().step_by(5) {
                    let s = project_to_canvas(view_proj, size, *p).unwrap();
                    assert!(
                        s.cmpge(Vec2::ZERO).all() && s.cmple(size).all(),
                        "yaw {yaw}, pitch {pitch} on {size}: {p} lands at {s}"
                    );
                }
            }
        }
    }
}

/// Figure 1's graph and Figure 10's drawings lie in the plane z = 0, seen face on: their frames
/// say they are flat, and a drag on the page's canvas pans the camera, so the graph keeps its
/// width on screen, where an orbit (as a 3D figure gets) turns it towards edge-on.
#[test]
fn flat_figures_pan_on_a_drag_and_keep_their_width() {
    use glam::Vec2;
    let noise = Noise1d::new();
    let mut f = Frame::default();
    noise.draw(&mut f);
    assert!(f.flat, "Figure 1 is flat");
    let mut fractals = Fractals::new();
    let mut g = Frame::default();
    fractals.draw(&mut g);
    assert!(g.flat, "Figure 10 is flat");
    g.clear();
    assert!(!g.flat, "a cleared frame is not flat");
    // The page's camera for Figure 1 (lessons/05-noise/lesson.js); the graph's x range.
    let (lo, hi) = noise.view_box();
    let x_range = [Vec3::new(lo.x, 0.0, 0.0), Vec3::new(hi.x, 0.0, 0.0)];
    flat::assert_drag_pans(&f, [0.0, 0.0, 0.0, 7.5, 0.0, 0.0], Vec2::new(650.0, 420.0), x_range);
}

/// The mean and the largest height step between neighbouring vertices along u (metres): the
/// one-vertex needles of the octaves finer than the mesh are steps that flip sign at every vertex.
fn vertex_steps(t: &inbetween::terrain::Terrain) -> (f32, f32) {
    let n = t.resolution();
    let mut sum = 0.0;
    let mut max = 0.0f32;
    for j in 0..n {
        for i in 1..n {
            let d = (t.positions[j * n + i].y - t.positions[j * n + i - 1].y).abs();
            sum += d;
            max = max.max(d);
        }
    }
    (sum / (n * (n - 1)) as f32, max)
}

/// Figure 3's Try this: at α = 0.8, ω = 2 and N = 7 on 193 × 193 vertices, the tick keeps
/// octaves 0 to 5 (octave 5's cells are three spacings wide) and the one-vertex needles go: the
/// height steps from vertex to vertex shrink by more than a third, the mean and the largest.
#[test]
fn octaves_leave_out_the_needles_at_alpha_0_8() {
    let mut s = Octaves::new();
    s.set_params(7.0, 0.8, 2.0).unwrap();
    s.take_dirty();
    let (mean_all, max_all) = vertex_steps(&s.terrains()[0]);
    s.set_band_limit(true);
    s.take_dirty();
    assert_eq!(s.shown_fractal().n, 5);
    let (mean_cut, max_cut) = vertex_steps(&s.terrains()[0]);
    assert!(
        mean_cut < mean_all * 2.0 / 3.0 && max_cut < max_all * 2.0 / 3.0,
        "mean {mean_all} -> {mean_cut}, largest {max_all} -> {max_cut}"
    );
}
