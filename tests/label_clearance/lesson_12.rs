//! Lesson 12: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_12_rule_names_keep_off_the_cells_the_circle_and_the_arrows() {
    // Figure 1 at its page camera (lessons/12-boids/lesson.js: the figure's view, fitted to its
    // grid), both canvases, at the defaults and after every slider has moved: each rule's name
    // is shown where the figure put it and keeps 2 px off the cells' squares, the radius circle,
    // the field-of-view edges, the arrows and the dots. As on the page, the figure places them
    // for the view of the frame before.
    use inbetween::figures::boids::RulesFigure;
    let mut failures = Vec::new();
    // (x, z, heading °, radius, field of view °, cell size): the defaults, the page sweep's
    // last state, and a few between.
    let states = [
        (0.0, 0.0, 0.0, 1.2, 270.0, 1.2),
        (-1.15, -1.15, -110.0, 2.4, 70.0, 0.6),
        (0.8, -0.4, 45.0, 1.5, 270.0, 1.0),
        (-0.5, 0.9, 160.0, 2.0, 200.0, 0.8),
        (1.2, 1.2, -45.0, 3.0, 360.0, 1.5),
    ];
    for (x, z, heading, radius, fov, cell) in states {
        for size in CANVASES {
            let mut scene = RulesFigure::new();
            scene.set_cell_size(cell).unwrap();
            scene.set_position(x, z).unwrap();
            scene.set_heading_deg(heading).unwrap();
            scene.set_radius(radius).unwrap();
            scene.set_fov_deg(fov).unwrap();
            let view = scene.view();
            let (frame, camera) = drawn!(&mut scene, view, size);
            let name = format!("12 rules at ({x}, {z}), heading {heading}, cell {cell}");
            let named: Vec<usize> = (0..frame.labels.len()).collect();
            assert!(!named.is_empty(), "{name}");
            failures.extend(failure_of(|| {
                assert_shown_clear_by(&name, &frame, &camera, size, &named, 2.0)
            }));
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_12_leader_and_predator_names_keep_off_the_neighbour_lines() {
    // Figure 2 at its page camera (lessons/12-boids/lesson.js: target 0, distance 9, yaw 0.5,
    // pitch 0.45, fitted to the box), both canvases, with the leader and the predator on, as the
    // flock flies: "leader" and "predator" are shown where the figure put them and keep 2 px off
    // the boids' tails, the orange boid's neighbour lines, its steering arrow and the box.
    use inbetween::figures::boids::{FlockFigure, ROLE_DOT_PX};
    let view = [0.0, 0.0, 0.0, 9.0, 0.5, 0.45];
    let mut failures = Vec::new();
    for size in CANVASES {
        let mut scene = FlockFigure::new();
        scene.set_leader(true);
        scene.set_predator(true);
        for k in 0..=300 {
            scene.advance_to(k as f32 / 60.0).unwrap();
            if k % 30 != 0 {
                continue;
            }
            let (frame, camera) = drawn!(&mut scene, view, size);
            // The leader and the predator are outlined dots over everything, the size the
            // names are placed round.
            let roles = frame.markers.iter().filter(|m| m.size_px == -ROLE_DOT_PX);
            assert_eq!(roles.count(), 2, "t {k}");
            let name = format!("12 flock at t {}", k as f32 / 60.0);
            let named: Vec<usize> = (0..frame.labels.len()).collect();
            assert_eq!(named.len(), 2, "{name}");
            failures.extend(failure_of(|| {
                assert_shown_clear_by(&name, &frame, &camera, size, &named, 2.0)
            }));
        }
    }
    assert_none_failed(&failures);
}
