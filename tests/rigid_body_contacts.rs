//! Rigid bodies in contact: bounces, rest, friction, a stack, collisions between bodies.
#![cfg(not(target_arch = "wasm32"))]

use glam::{Quat, Vec3};
use inbetween::rigid_body::contact::{heap, Shape, World};
use inbetween::rigid_body::inertia::{solid_box, solid_sphere};
use inbetween::rigid_body::RigidBody;

const DT: f32 = 1.0 / 120.0;

fn ball(mass: f32, radius: f32, at: Vec3) -> (RigidBody, Shape) {
    let i = solid_sphere(mass, radius);
    let mut b = RigidBody::new(mass, Vec3::new(i.x_axis.x, i.y_axis.y, i.z_axis.z)).unwrap();
    b.position = at;
    (b, Shape::Sphere { radius })
}

fn cuboid(mass: f32, half: Vec3, at: Vec3) -> (RigidBody, Shape) {
    let i = solid_box(mass, half);
    let mut b = RigidBody::new(mass, Vec3::new(i.x_axis.x, i.y_axis.y, i.z_axis.z)).unwrap();
    b.position = at;
    (b, Shape::Cuboid { half })
}

fn run(world: &mut World, seconds: f32) {
    for _ in 0..(seconds / DT).round() as usize {
        world.step(DT).unwrap();
    }
}

#[test]
fn a_ball_dropped_with_e_1_bounces_back_to_its_height_and_with_e_0_comes_to_rest() {
    for e in [1.0, 0.0] {
        let mut world = World::default();
        world.restitution = e;
        let (b, s) = ball(1.0, 0.1, Vec3::new(0.0, 1.1, 0.0));
        world.add(b, s).unwrap();
        // Fall (0.47 s), bounce, and rise again: the highest point after the first bounce.
        let mut bounced = false;
        let mut highest = 0.0f32;
        for _ in 0..(1.5 / DT) as usize {
            world.step(DT).unwrap();
            let y = world.bodies[0].0.position.y;
            if world.bodies[0].0.velocity.y > 0.0 {
                bounced = true;
            }
            if bounced {
                highest = highest.max(y);
            }
        }
        if e == 1.0 {
            assert!(
                (highest - 1.1).abs() < 0.03,
                "e = 1: back up to {highest} m of 1.1 m"
            );
        } else {
            let b = world.bodies[0].0;
            assert!(highest < 0.11, "e = 0 bounced up to {highest}");
            assert!(
                b.velocity.length() < 1e-3 && (b.position.y - 0.1).abs() < 0.005,
                "{b:?}"
            );
        }
    }
}

#[test]
fn a_box_at_rest_on_the_ground_stays_put_for_1000_steps() {
    let mut world = World::default();
    let half = Vec3::new(0.3, 0.2, 0.25);
    let (b, s) = cuboid(2.0, half, Vec3::new(0.5, 0.2, -0.3));
    world.add(b, s).unwrap();
    let start = world.bodies[0].0;
    let mut fastest = 0.0f32;
    for _ in 0..1000 {
        world.step(DT).unwrap();
        fastest = fastest.max(world.bodies[0].0.velocity.length());
    }
    let end = world.bodies[0].0;
    // It settles into the slop (2 mm) and neither slides nor turns.
    assert!(
        (end.position - start.position).length() < 3e-3,
        "{} -> {}",
        start.position,
        end.position
    );
    assert!(end.orientation.dot(start.orientation).abs() > 1.0 - 1e-6);
    assert!(fastest < 0.05, "jitter up to {fastest} m/s");
    assert!(end.velocity.length() < 1e-3);
}

#[test]
fn friction_stops_a_sliding_box_after_v_squared_over_2_mu_g() {
    let mut world = World::default();
    world.friction = 0.5;
    let (mut b, s) = cuboid(1.0, Vec3::splat(0.1), Vec3::new(0.0, 0.1, 0.0));
    b.velocity = Vec3::new(2.0, 0.0, 0.0);
    world.add(b, s).unwrap();
    run(&mut world, 1.5);
    let slid = world.bodies[0].0.position.x;
    let expected = 2.0 * 2.0 / (2.0 * 0.5 * 9.81);
    assert!(
        (slid - expected).abs() < 0.05 * expected,
        "slid {slid} m, expected {expected} m"
    );
    assert!(world.bodies[0].0.velocity.length() < 1e-2);
}

#[test]
fn a_stack_of_three_boxes_stands_for_ten_seconds() {
    let mut world = World::default();
    let half = Vec3::new(0.25, 0.15, 0.25);
    for k in 0..3 {
        let (b, s) = cuboid(1.0, half, Vec3::new(0.0, 0.15 + 0.3 * k as f32, 0.0));
        world.add(b, s).unwrap();
    }
    run(&mut world, 10.0);
    for (k, (b, _)) in world.bodies.iter().enumerate() {
        let x = Vec3::new(b.position.x, 0.0, b.position.z).length();
        let y = b.position.y - (0.15 + 0.3 * k as f32);
        assert!(
            x < 0.01 && y.abs() < 0.01,
            "box {k} moved to {}",
            b.position
        );
        assert!((b.orientation * Vec3::Y).y > 0.999, "box {k} tilted");
    }
}

#[test]
fn two_balls_meeting_head_on_exchange_their_velocities_at_e_1_and_keep_the_momentum() {
    let mut world = World::default();
    world.restitution = 1.0;
    world.gravity = Vec3::ZERO;
    let (mut a, s) = ball(1.0, 0.1, Vec3::new(-0.5, 2.0, 0.0));
    a.velocity = Vec3::new(2.0, 0.0, 0.0);
    let (mut b, t) = ball(1.0, 0.1, Vec3::new(0.5, 2.0, 0.0));
    b.velocity = Vec3::new(-1.0, 0.0, 0.0);
    world.add(a, s).unwrap();
    world.add(b, t).unwrap();
    let momentum = |w: &World| {
        w.bodies
            .iter()
            .map(|(b, _)| b.linear_momentum())
            .sum::<Vec3>()
    };
    let p0 = momentum(&world);
    run(&mut world, 1.0);
    assert!((momentum(&world) - p0).length() < 1e-4);
    let (va, vb) = (world.bodies[0].0.velocity.x, world.bodies[1].0.velocity.x);
    assert!(
        (va + 1.0).abs() < 0.02 && (vb - 2.0).abs() < 0.02,
        "{va} {vb}"
    );
}

#[test]
fn a_box_tipped_on_its_edge_falls_flat() {
    let mut world = World::default();
    let half = Vec3::new(0.2, 0.2, 0.2);
    let (mut b, s) = cuboid(1.0, half, Vec3::new(0.0, 0.3, 0.0));
    // Standing on an edge, tilted past balance.
    b.orientation = Quat::from_rotation_z(0.7);
    world.add(b, s).unwrap();
    run(&mut world, 3.0);
    let b = world.bodies[0].0;
    // Some face points straight up again and the box rests on the ground.
    let up = [Vec3::X, Vec3::Y, Vec3::Z]
        .iter()
        .map(|a| (b.orientation * *a).y.abs())
        .fold(0.0, f32::max);
    assert!(up > 0.999, "no face up: {up}");
    assert!(
        (b.position.y - 0.2).abs() < 0.005 && b.velocity.length() < 1e-2,
        "{b:?}"
    );
}

#[test]
fn bad_steps_and_shapes_are_refused_and_change_nothing() {
    let mut world = World::default();
    let (b, s) = ball(1.0, 0.1, Vec3::new(0.0, 1.0, 0.0));
    world.add(b, s).unwrap();
    let before = world.bodies.clone();
    for dt in [f32::NAN, 0.0, -0.01, 0.5] {
        assert!(world.step(dt).unwrap_err().contains("time step"));
    }
    world.restitution = 1.5;
    assert!(world.step(DT).unwrap_err().contains("restitution"));
    world.restitution = 0.0;
    world.iterations = 0;
    assert!(world.step(DT).is_err());
    assert_eq!(world.bodies, before);
    assert!(world.add(b, Shape::Sphere { radius: -1.0 }).is_err());
    assert!(world
        .add(
            b,
            Shape::Cuboid {
                half: Vec3::new(1.0, f32::NAN, 1.0)
            }
        )
        .is_err());
}

#[test]
fn the_grid_finds_the_same_contacts_as_every_pair() {
    use inbetween::rigid_body::contact::BroadPhase;
    let mut grid = heap(300).unwrap();
    let mut all = grid.clone();
    all.broad_phase = BroadPhase::AllPairs;
    let mut most = 0;
    for step in 0..120 {
        if step % 20 == 0 {
            let (a, b) = (grid.contacts(), all.contacts());
            most = most.max(a.len());
            assert_eq!(a, b, "step {step}");
        }
        grid.step(DT).unwrap();
        all.step(DT).unwrap();
    }
    // Once the heap has landed, every body touches something.
    assert!(most > 300, "a heap has contacts: {most}");
    assert_eq!(grid.bodies, all.bodies);
}

#[test]
fn a_heap_has_a_documented_size() {
    assert!(heap(0).is_err() && heap(5000).is_err());
    assert_eq!(heap(7).unwrap().bodies.len(), 7);
}
