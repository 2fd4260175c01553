use glam::Vec3;
use inbetween::boids::*;

/// A boid at a NaN position (clamped into the corner cell, where rows are missing on three
/// sides) makes the search read no row past the grid's border (in a debug build the search
/// asserts its reads are in bounds), and no other boid counts it as a neighbour.
#[test]
fn a_nan_position_reaches_no_missing_row() {
    let params = BoidParams::default();
    let mut flock = Flock::new(500, &params, 3).unwrap();
    flock.positions[3] = Vec3::NAN;
    flock.positions[4] = Vec3::new(f32::NAN, -params.bounds.y, 0.0);
    flock.step(&params, Search::Grid, 1.0 / 60.0);
    for (i, f) in flock.forces.iter().enumerate() {
        assert!(i == 3 || i == 4 || f.is_finite(), "boid {i}: {f}");
    }
}

/// The cell-order grid step gives every boid the force that the per-boid
/// [`Flock::steering`] finds through [`Grid::for_each_neighbour`], with a leader, a predator,
/// a field of view on and off: the same bits with a distance law (one candidate at a time,
/// in the same order), and the same up to rounding without one (four lanes of partial sums).
#[test]
fn cell_order_steering_matches_the_per_boid_path() {
    white_box::cell_order_steering_matches_the_per_boid_path();
}
