//! Lesson 05's "Perlin, simplex, and the GPU" figure: images, the GPU comparison, the lattices.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec3;
use inbetween::draw::{palette, Frame, TextureId};
use inbetween::figures::noise_images::*;
use inbetween::noise::Permutation;

/// What the shader writes in packed mode for the noise value `n` (see noise.wgsl).
fn pack(n: f32) -> [u8; 4] {
    let q = (65535.0 * (0.5 + 0.5 * n).clamp(0.0, 1.0)).round() as u32;
    [(q >> 8) as u8, (q & 255) as u8, 0, 255]
}

fn packed_image(s: &NoiseImages, kind: NoiseKind, error: f32) -> Vec<u8> {
    let mut out = Vec::new();
    for j in 0..IMAGE_SIZE {
        for i in 0..IMAGE_SIZE {
            out.extend_from_slice(&pack(s.value(kind, i, j) + error));
        }
    }
    out
}

#[test]
fn images_hold_perlin_and_simplex_as_grey_levels() {
    let s = NoiseImages::new();
    let perm = Permutation::perlin();
    let [perlin, simplex] = s.images();
    assert_eq!(perlin.len(), 4 * IMAGE_SIZE * IMAGE_SIZE);
    let spec = s.spec();
    let (i, j) = (37, 90);
    let (x, y) = (
        (i as f32 + 0.5) * spec.step[0],
        (j as f32 + 0.5) * spec.step[1],
    );
    let grey = |n: f32| (255.0 * (0.5 + 0.5 * n)).round() as u8;
    let at = 4 * (j * IMAGE_SIZE + i);
    assert_eq!(spec.z, 0.0);
    assert_eq!(perlin[at], grey(perm.noise2(x, y)));
    assert_eq!(simplex[at], grey(perm.simplex2(x, y)));
    assert_eq!(&perlin[at..at + 3], &[perlin[at]; 3], "grey");
}

#[test]
fn gpu_images_that_agree_pass_and_others_fail() {
    let mut s = NoiseImages::new();
    for kind in [NoiseKind::Perlin, NoiseKind::Simplex] {
        s.set_gpu_kind(kind);
        let ok = s.compare_gpu(&packed_image(&s, kind, 0.0)).unwrap();
        assert!(ok.matches(), "{ok:?}");
        assert!(
            ok.max_error <= 2.0 / 65535.0,
            "only the 16-bit rounding: {ok:?}"
        );
        assert!(ok.note("WebGL2").contains("matches"));
        // The other noise is not a match.
        let other = if kind == NoiseKind::Perlin {
            NoiseKind::Simplex
        } else {
            NoiseKind::Perlin
        };
        let bad = s.compare_gpu(&packed_image(&s, other, 0.0)).unwrap();
        assert!(
            !bad.matches() && bad.note("WebGPU").contains("DIFFERS"),
            "{bad:?}"
        );
    }
    // One texel off by 1e-3 is found, with its place.
    s.set_gpu_kind(NoiseKind::Perlin);
    let mut img = packed_image(&s, NoiseKind::Perlin, 0.0);
    let at = 4 * (5 * IMAGE_SIZE + 9);
    let v = s.value(NoiseKind::Perlin, 9, 5);
    img[at..at + 4].copy_from_slice(&pack(v + 1e-3));
    let c = s.compare_gpu(&img).unwrap();
    assert_eq!(c.worst, (9, 5));
    assert!(!c.matches());
    assert!(s.compare_gpu(&img[..100]).is_err(), "wrong length");
}

#[test]
fn parameters_are_checked_and_change_the_images() {
    let mut s = NoiseImages::new();
    s.take_dirty();
    s.take_gpu_dirty();
    let before = s.images()[0].to_vec();
    s.set_params(7.5, 0.0).unwrap();
    assert!(s.take_dirty() && s.take_gpu_dirty());
    assert_ne!(s.images()[0], &before[..], "more cells, another image");
    assert!(s.set_params(f32::NAN, 0.0).is_err());
    assert!(s.set_params(6.0, 1.5).unwrap_err().contains("whole"));
    assert!(s.set_params(100.0, 0.0).unwrap_err().contains("cells"));
    s.set_params(6.0, 3.0).unwrap();
    assert_ne!(
        s.table(),
        Permutation::perlin().table(),
        "a seed shuffles the table"
    );
}

#[test]
fn draws_three_quads_and_the_lattices_inside_the_images() {
    let mut s = NoiseImages::new();
    let mut f = Frame::default();
    let ids = [TextureId(3), TextureId(4), TextureId(5)];
    s.draw(&mut f, ids);
    assert_eq!(f.quads.iter().map(|q| q.texture).collect::<Vec<_>>(), ids);
    assert!(f.lines.is_empty());
    s.set_lattice(true);
    f.clear();
    s.draw(&mut f, ids);
    let squares: Vec<_> = f.segments_of(palette::ORANGE).collect();
    let triangles: Vec<_> = f.segments_of(palette::TEAL).collect();
    // 6 cells: 7 vertical and 7 horizontal lines, all wide strokes (none of them 1 px lines).
    assert_eq!(squares.len(), 14);
    assert!(f.lines.is_empty());
    assert!(f.strokes.iter().all(|s| s.width_px == LATTICE_PX));
    // Finer lattices get thinner lines, never under 1 px.
    assert_eq!(lattice_px(6.0), LATTICE_PX);
    assert!(lattice_px(9.0) < LATTICE_PX && lattice_px(9.0) > 1.0);
    assert_eq!(lattice_px(25.5), 1.0);
    assert!(triangles.len() > 50);
    for (a, b) in triangles {
        for p in [a, b] {
            assert!(
                p.x >= -1.0 - 1e-4 && p.x <= 1.0 + 1e-4 && p.y.abs() <= 1.0 + 1e-4,
                "{p}"
            );
        }
    }
    // A fine lattice covers only the top-left LATTICE_CELLS cells (x from −1 and y from 1 on
    // the square): at 25.5 cells across, lines over the whole image would hide the noise.
    s.set_params(25.5, 0.0).unwrap();
    f.clear();
    let note = s.draw(&mut f, ids);
    assert!(note.contains("top-left 6 × 6 cells"), "{note}");
    // Its cells are a few pixels wide on the page (a flat figure zooms in no further than its
    // fit): the note says the lines run together, and how many cells show them apart.
    assert!(note.contains("run together: at 12 cells or fewer"), "{note}");
    assert!(!note.contains("zoom"), "{note}");
    s.set_params(9.0, 0.0).unwrap();
    assert!(!s.draw(&mut f, ids).contains("run together"));
    s.set_params(25.5, 0.0).unwrap();
    f.clear();
    s.draw(&mut f, ids);
    let corner = -1.0 + 2.0 * LATTICE_CELLS / 25.5;
    let (mut far_x, mut far_down) = (-1.0f32, -1.0f32);
    for (a, b) in f.segments_of(palette::ORANGE).chain(f.segments_of(palette::TEAL)) {
        for p in [a, b] {
            let x = if p.x < -1.1 { p.x + 2.2 } else { p.x };
            far_x = far_x.max(x);
            far_down = far_down.max(-p.y);
        }
    }
    assert!(
        (far_x - corner).abs() < 1e-3 && (far_down - corner).abs() < 1e-3,
        "{far_x}, {far_down}"
    );
    // Up to LATTICE_CELLS the lattices cover the whole image, and the note says nothing of it.
    s.set_params(LATTICE_CELLS, 0.0).unwrap();
    f.clear();
    assert!(!s.draw(&mut f, ids).contains("top-left"));
    assert_eq!(f.segments_of(palette::ORANGE).count(), 14);
}

#[test]
fn the_images_face_the_camera_upright_with_their_names_under_them() {
    // The page looks along −z (yaw 0, pitch 0): each image stands in the plane z = 0 facing +z,
    // its texel row 0 (the quad's z = −1 edge) at the top, so it shows square and unforeshortened;
    // a drag pans the figure instead of tipping the images away.
    let s = NoiseImages::new();
    let mut f = Frame::default();
    s.draw(&mut f, [TextureId(3), TextureId(4), TextureId(5)]);
    assert!(f.flat);
    assert_eq!(f.quads.len(), 3);
    let mut centres = Vec::new();
    for q in &f.quads {
        let at = |x: f32, z: f32| q.model.transform_point3(Vec3::new(x, 0.0, z));
        let normal = q.model.transform_vector3(Vec3::Y);
        assert!(normal.distance(Vec3::Z) < 1e-5, "faces {normal}");
        // Row 0 at the top, column 0 on the left, 2 m on a side.
        assert!((at(0.0, -1.0).y - 1.0).abs() < 1e-5 && (at(0.0, 1.0).y + 1.0).abs() < 1e-5);
        assert!((at(1.0, 0.0).x - at(-1.0, 0.0).x - 2.0).abs() < 1e-5);
        centres.push(at(0.0, 0.0));
    }
    assert!(centres.windows(2).all(|w| w[1].x > w[0].x + 2.0 && w[0].y == w[1].y));
    // Each name just under its image, from its left edge.
    assert_eq!(f.labels.len(), 3);
    for (label, c) in f.labels.iter().zip(&centres) {
        assert!((label.anchor.x - (c.x - 1.0)).abs() < 1e-5, "{:?}", label.anchor);
        assert!((-1.4..-1.0).contains(&label.anchor.y), "{:?}", label.anchor);
    }
}
