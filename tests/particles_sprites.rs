//! Sprites (src/particles/sprites.rs): the smoke atlas and the back-to-front order.
#![cfg(not(target_arch = "wasm32"))]

use glam::{Vec2, Vec3};
use inbetween::noise::Permutation;
use inbetween::particles::sprites::*;
use proptest::prelude::*;

const SIDE: usize = 16;

fn atlas() -> Vec<u8> {
    let mut rgba = vec![0; 4 * (4 * SIDE) * (4 * SIDE)];
    fill_smoke_atlas(&Permutation::perlin(), SIDE, &mut rgba).unwrap();
    rgba
}

fn alpha(rgba: &[u8], frame: usize, i: usize, j: usize) -> u8 {
    let (c, r) = (frame % 4, frame / 4);
    rgba[4 * ((r * SIDE + j) * 4 * SIDE + c * SIDE + i) + 3]
}

#[test]
fn every_frame_is_clear_on_its_border_and_dense_inside() {
    let rgba = atlas();
    for frame in 0..16 {
        for k in 0..SIDE {
            for (i, j) in [(k, 0), (k, SIDE - 1), (0, k), (SIDE - 1, k)] {
                assert_eq!(
                    alpha(&rgba, frame, i, j),
                    0,
                    "frame {frame} border ({i}, {j})"
                );
            }
        }
        let centre = alpha(&rgba, frame, SIDE / 2, SIDE / 2);
        assert!(centre > 20, "frame {frame}: centre alpha {centre}");
    }
}

#[test]
fn the_puff_grows_and_thins_out_over_its_life() {
    let rgba = atlas();
    let texels = |frame| {
        let rgba = &rgba;
        (0..SIDE).flat_map(move |j| (0..SIDE).map(move |i| alpha(rgba, frame, i, j)))
    };
    let peak = |frame| texels(frame).max().unwrap();
    let covered = |frame| texels(frame).filter(|&a| a > 0).count();
    assert!(
        2 * peak(15) < peak(0),
        "fainter: {} vs {}",
        peak(0),
        peak(15)
    );
    assert!(
        covered(15) > covered(0),
        "larger: {} vs {}",
        covered(0),
        covered(15)
    );
    let perm = Permutation::perlin();
    assert_eq!(
        smoke_opacity(&perm, Vec2::new(0.7, 0.0), 0.0),
        0.0,
        "outside the young puff"
    );
}

#[test]
fn atlas_sizes_are_checked() {
    let perm = Permutation::perlin();
    assert!(fill_smoke_atlas(&perm, 2, &mut vec![0; 4 * 64]).is_err());
    assert!(fill_smoke_atlas(&perm, MAX_FRAME_SIDE + 1, &mut []).is_err());
    assert!(fill_smoke_atlas(&perm, 8, &mut [0; 10])
        .unwrap_err()
        .contains("bytes"));
}

proptest! {
    #[test]
    fn back_to_front_is_a_permutation_sorted_by_decreasing_depth_along_the_view(
        points in proptest::collection::vec((-10f32..10.0, -10f32..10.0, -10f32..10.0), 0..60),
        eye in (-20f32..20.0, -20f32..20.0, -20f32..20.0),
        look in (-1f32..1.0, -1f32..1.0, -1f32..1.0),
    ) {
        let positions: Vec<Vec3> = points.iter().map(|&(x, y, z)| Vec3::new(x, y, z)).collect();
        let eye = Vec3::new(eye.0, eye.1, eye.2);
        // A unit view direction, or none (then the squared distance is the key).
        let forward = Vec3::new(look.0, look.1, look.2).normalize_or_zero();
        let mut order = Vec::new();
        sort_back_to_front(&mut order, &positions, eye, forward);
        prop_assert_eq!(order.len(), positions.len());
        let mut seen: Vec<u32> = order.iter().map(|&(_, i)| i).collect();
        seen.sort();
        prop_assert!(seen.iter().enumerate().all(|(k, &i)| k as u32 == i), "each index once");
        let depth = |i: u32| {
            let d = positions[i as usize] - eye;
            if forward == Vec3::ZERO { d.length_squared() } else { d.dot(forward) }
        };
        for w in order.windows(2) {
            prop_assert!(depth(w[0].1) >= depth(w[1].1), "deepest first");
            prop_assert!(depth(w[0].1) > depth(w[1].1) || w[0].1 < w[1].1, "ties in index order");
        }
    }
}

#[test]
fn depth_along_the_view_not_distance_decides_the_order() {
    // The camera at the origin looks down −z. A sprite far off to the side but shallow and one
    // straight ahead but deeper: by distance the side one is farther, by depth (what the depth
    // test compares for squares parallel to the image plane) the one ahead is, so it goes first.
    let (eye, forward) = (Vec3::ZERO, -Vec3::Z);
    let positions = [Vec3::new(4.0, 0.0, -2.0), Vec3::new(0.0, 0.0, -3.0)];
    assert!(positions[0].length() > positions[1].length());
    let mut order = Vec::new();
    sort_back_to_front(&mut order, &positions, eye, forward);
    assert_eq!(order.iter().map(|&(_, i)| i).collect::<Vec<_>>(), [1, 0]);
    assert_eq!(order[0].0, 3.0);
    // Without a view direction the key is the squared distance.
    sort_back_to_front(&mut order, &positions, eye, Vec3::ZERO);
    assert_eq!(order.iter().map(|&(_, i)| i).collect::<Vec<_>>(), [0, 1]);
}

#[test]
fn ties_keep_storage_order_and_storage_is_reused() {
    let positions = [Vec3::X, Vec3::Y, Vec3::Z * 3.0, -Vec3::X];
    let mut order = Vec::with_capacity(8);
    let ptr = order.as_ptr();
    sort_back_to_front(&mut order, &positions, Vec3::ZERO, Vec3::Z);
    let idx: Vec<u32> = order.iter().map(|&(_, i)| i).collect();
    assert_eq!(idx, [2, 0, 1, 3]);
    assert_eq!(order.as_ptr(), ptr, "no reallocation");
}
