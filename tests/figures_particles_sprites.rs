//! Lesson 11's sprite figure: the smoke column and its draw order.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec3;
use inbetween::camera::OrbitCamera;
use inbetween::draw::{Frame, TextureId};
use inbetween::figures::particles::EmitterFigure;
use inbetween::figures::particles_sprites::*;

#[test]
fn the_left_column_is_sorted_back_to_front_and_the_right_one_left_in_storage_order() {
    let mut s = SmokeFigure::new();
    let eye = Vec3::new(1.0, 2.0, 6.0);
    let mut f = Frame::default();
    let note = s.draw(&mut f, TextureId(7), eye, Vec3::ZERO, 1.3).unwrap();
    assert!(
        note.contains("Left: drawn back to front")
            && note.contains("Right: the same puffs in storage")
    );
    assert_eq!(f.sprite_texture, Some(TextureId(7)));
    assert_eq!(f.sprites.len(), 60);
    let (sorted, unsorted) = f.sprites.split_at(30);
    // Depth along the view direction (towards the origin), which the depth test compares.
    let depth = |ps: &[inbetween::texture::SpriteInstance]| -> Vec<f32> {
        ps.iter()
            .map(|p| (Vec3::from(p.center) - eye).dot(-eye.normalize()))
            .collect()
    };
    assert!(
        depth(sorted).windows(2).all(|w| w[0] >= w[1]),
        "deepest first"
    );
    assert!(
        !depth(unsorted).windows(2).all(|w| w[0] >= w[1]),
        "storage order is not depth order"
    );
    // The same puffs in both columns, COLUMN_GAP apart.
    let key = |ps: &[inbetween::texture::SpriteInstance], offset: Vec3| {
        // Rounded to 0.1 mm: adding the gap and taking it away again rounds the last bit.
        let mut k: Vec<[i32; 3]> = ps
            .iter()
            .map(|p| {
                (Vec3::from(p.center) - offset)
                    .to_array()
                    .map(|x| (x * 1e4).round() as i32)
            })
            .collect();
        k.sort();
        k
    };
    assert_eq!(key(sorted, Vec3::ZERO), key(unsorted, COLUMN_GAP));
    let labels: Vec<&str> = f.labels.iter().map(|l| l.text.as_str()).collect();
    assert!(
        labels.contains(&"sorted back to front") && labels.contains(&"unsorted (storage order)")
    );
}

#[test]
fn the_two_columns_never_overlap_on_screen_in_the_pages_view() {
    // Side by side at every moment of the timeline, at the most puffs: a puff of one column
    // drawn over the other would mix the comparison.
    let camera = OrbitCamera::from_view([-0.4, 1.1, 0.0, 6.0, 0.25, 0.15]);
    let view = camera.view();
    let mut s = SmokeFigure::new();
    s.set_params(80.0, 4.0).unwrap();
    for k in 0..40 {
        let t = k as f32 * 0.2;
        let mut f = Frame::default();
        s.draw(&mut f, TextureId(0), camera.eye(), camera.target, t)
            .unwrap();
        let (left, right) = f.sprites.split_at(80);
        let right_edge = left
            .iter()
            .map(|p| view.transform_point3(p.center.into()).x + p.half_size)
            .fold(f32::MIN, f32::max);
        let left_edge = right
            .iter()
            .map(|p| view.transform_point3(p.center.into()).x - p.half_size)
            .fold(f32::MAX, f32::min);
        assert!(
            right_edge < left_edge,
            "t = {t}: {right_edge} ≥ {left_edge}"
        );
    }
}

#[test]
fn puffs_play_the_atlas_over_their_life_and_show_it() {
    let mut s = SmokeFigure::new();
    assert_eq!(s.atlas().len(), 4 * ATLAS_SIDE * ATLAS_SIDE);
    let mut f = Frame::default();
    s.draw(&mut f, TextureId(0), Vec3::Z * 5.0, Vec3::ZERO, 2.0)
        .unwrap();
    let frames: std::collections::BTreeSet<[u32; 4]> =
        f.sprites.iter().map(|p| p.uv.map(f32::to_bits)).collect();
    assert!(
        frames.len() > 8,
        "many atlas frames at once: {}",
        frames.len()
    );
    assert!(f
        .sprites
        .iter()
        .all(|p| p.uv[2] - p.uv[0] == 0.25 && p.uv[3] - p.uv[1] == 0.25));
    assert_eq!(f.quads.len(), 1, "the atlas is shown");
    s.set_animate_frames(false);
    s.set_show_atlas(false);
    let mut g = Frame::default();
    s.draw(&mut g, TextureId(0), Vec3::Z * 5.0, Vec3::ZERO, 2.0)
        .unwrap();
    assert!(g.sprites.iter().all(|p| p.uv == [0.0, 0.0, 0.25, 0.25]));
    assert!(g.quads.is_empty());
}

#[test]
fn bad_input_is_refused() {
    let mut s = SmokeFigure::new();
    assert!(s.set_params(0.0, 4.0).unwrap_err().contains("puffs"));
    assert!(s.set_params(201.0, 4.0).unwrap_err().contains("puffs"));
    assert!(s.set_params(10.5, 4.0).unwrap_err().contains("whole"));
    assert!(s
        .set_params(10.0, f32::NAN)
        .unwrap_err()
        .contains("lifetime"));
    assert!(s
        .draw(
            &mut Frame::default(),
            TextureId(0),
            Vec3::Z,
            Vec3::ZERO,
            f32::NAN
        )
        .is_err());
    s.set_params(200.0, 1.0).unwrap();
    let mut f = Frame::default();
    s.draw(&mut f, TextureId(0), Vec3::Z, Vec3::ZERO, 0.5)
        .unwrap();
    assert_eq!(f.sprites.len(), 2 * MAX_PUFFS, "both columns");
}

#[test]
fn emitter_particles_become_atlas_sprites_once_a_texture_is_given() {
    let mut e = EmitterFigure::new();
    let eye = Vec3::new(0.0, 2.0, 5.0);
    let mut f = Frame::default();
    e.draw(&mut f, eye, Vec3::ZERO, 1.0).unwrap();
    assert!(f.sprites.is_empty() && !f.points.is_empty());
    e.set_sprite_texture(Some(TextureId(2)));
    let mut g = Frame::default();
    e.draw(&mut g, eye, Vec3::ZERO, 1.0).unwrap();
    assert_eq!(g.sprites.len(), f.points.len());
    assert!(g.points.is_empty());
    assert_eq!(g.sprite_texture, Some(TextureId(2)));
    // Sorted by depth along the view (the camera looks at the origin), deepest first.
    let forward = (-eye).normalize();
    let d: Vec<f32> = g
        .sprites
        .iter()
        .map(|p| (Vec3::from(p.center) - eye).dot(forward))
        .collect();
    assert!(d.windows(2).all(|w| w[0] >= w[1] - 1e-5), "deepest first");
}

#[test]
fn the_note_counts_one_puff_in_the_singular() {
    let mut s = SmokeFigure::new();
    s.set_params(1.0, 4.0).unwrap();
    let note = s
        .draw(
            &mut Frame::default(),
            TextureId(0),
            Vec3::Z * 5.0,
            Vec3::ZERO,
            2.0,
        )
        .unwrap();
    assert!(note.starts_with("1 puff, living"), "{note}");
    s.set_params(2.0, 4.0).unwrap();
    let note = s
        .draw(
            &mut Frame::default(),
            TextureId(0),
            Vec3::Z * 5.0,
            Vec3::ZERO,
            2.0,
        )
        .unwrap();
    assert!(note.starts_with("2 puffs, each living"), "{note}");
}

#[test]
fn sorted_puffs_that_overlap_on_screen_are_drawn_deepest_first_in_the_pages_view() {
    // The page's camera (lesson.js: setCamera(-0.4, 1.1, 0, 6.0, 0.25, 0.15)). Sorted by their
    // distance from the eye, 23 overlapping pairs at 4 s would be drawn nearer first, each
    // cutting a hard-edged notch into the puff behind it: the squares face the camera, so the
    // depth test compares view depths, and the sort must use those.
    let camera = OrbitCamera::from_view([-0.4, 1.1, 0.0, 6.0, 0.25, 0.15]);
    let view = camera.view();
    for t in [1.0, 2.0, 4.0, 5.0, 7.5] {
        let mut s = SmokeFigure::new();
        s.set_params(80.0, 4.0).unwrap();
        let mut f = Frame::default();
        s.draw(&mut f, TextureId(0), camera.eye(), camera.target, t)
            .unwrap();
        let sprites = &f.sprites[..80]; // the sorted column
        for (i, a) in sprites.iter().enumerate() {
            for b in &sprites[i + 1..] {
                let (va, vb) = (
                    view.transform_point3(a.center.into()),
                    view.transform_point3(b.center.into()),
                );
                let reach = a.half_size + b.half_size;
                let overlap = (va.x - vb.x).abs() < reach && (va.y - vb.y).abs() < reach;
                // View space looks down -z: the deeper puff has the smaller z, and goes first.
                assert!(
                    !overlap || va.z <= vb.z,
                    "t = {t}: a puff at view depth {} drawn before one behind it at {}",
                    -va.z,
                    -vb.z
                );
            }
        }
    }
}
