use inbetween::fluid::*;

/// The step's sums, which evaluate four neighbours at a time, against a loop over each list
/// one neighbour at a time with the scalar kernels: equal bit for bit (the lanes add their
/// terms in list order), on a splashing 3D and 2D dam break.
#[test]
fn the_four_lane_sums_are_the_scalar_loops_bit_for_bit() {
    white_box::the_four_lane_sums_are_the_scalar_loops_bit_for_bit();
}
