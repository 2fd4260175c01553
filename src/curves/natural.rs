//! Natural cubic spline: the C2 interpolating cubic spline with zero curvature at both ends.

use super::Value;

/// Tangents (time derivatives, units per second) of the natural cubic spline through the keys.
/// ```text
/// h_i = t_{i+1} − t_i,   M_i = p″(t_i)   (unknown second derivatives)
/// for i = 1 … N−2:
///   h_{i−1} M_{i−1} + 2 (h_{i−1} + h_i) M_i + h_i M_{i+1}
///       = 6 [ (p_{i+1} − p_i) / h_i − (p_i − p_{i−1}) / h_{i−1} ]
/// natural ends: M_0 = M_{N−1} = 0
/// tangents:  d_i     = (p_{i+1} − p_i) / h_i − h_i (2 M_i + M_{i+1}) / 6,   i < N−1
///            d_{N−1} = (p_{N−1} − p_{N−2}) / h_{N−2} + h_{N−2} (M_{N−2} + 2 M_{N−1}) / 6
/// ```
/// Each segment is a cubic; asking the first *and second* derivatives to match at every interior
/// key gives one linear equation per key, a tridiagonal system solved here in `O(N)` by the
/// Thomas algorithm (forward elimination, back substitution; the matrix is strictly diagonally
/// dominant, so no pivoting is needed). The price of C2 continuity is locality: moving one key
/// moves the whole curve a little. The spline is returned as Hermite tangents so that one
/// evaluation routine serves every cubic scheme; `d_i` is the derivative of the segment cubic at
/// its end, the same from both sides. With two keys the spline is the straight segment; with one
/// key, the tangent is zero.
///
/// `scratch_diagonal` and `scratch_rhs` are work space (any contents, length `N`), so that
/// rebuilding the spline does not allocate.
///
/// # Panics
/// If a slice does not have the length of `times`.
pub fn natural_spline_tangents<T: Value>(
    times: &[f32],
    values: &[T],
    out: &mut [T],
    scratch_diagonal: &mut [f32],
    scratch_rhs: &mut [T],
) {
    let n = times.len();
    assert_eq!(
        values.len(),
        n,
        "natural_spline_tangents: one value per key time"
    );
    assert_eq!(
        out.len(),
        n,
        "natural_spline_tangents: one output tangent per key"
    );
    assert_eq!(
        scratch_diagonal.len(),
        n,
        "natural_spline_tangents: scratch of length N"
    );
    assert_eq!(
        scratch_rhs.len(),
        n,
        "natural_spline_tangents: scratch of length N"
    );
    if n < 2 {
        out.fill(T::ZERO);
        return;
    }
    let h = |i: usize| times[i + 1] - times[i];
    let slope = |i: usize| (values[i + 1] - values[i]) * (1.0 / h(i));

    // Forward elimination on rows 1 … N−2. After it, row i reads
    //   diag[i] M_i + h_i M_{i+1} = rhs[i]
    // (the sub-diagonal has been eliminated). Rows 0 and N−1 are M = 0.
    let (diag, rhs) = (scratch_diagonal, scratch_rhs);
    diag[0] = 1.0;
    rhs[0] = T::ZERO;
    for i in 1..n - 1 {
        let sub = if i == 1 { 0.0 } else { h(i - 1) }; // M_0 = 0 is known: no coupling to row 0
        let factor = sub / diag[i - 1];
        diag[i] = 2.0 * (h(i - 1) + h(i)) - factor * h(i - 1);
        rhs[i] = (slope(i) - slope(i - 1)) * 6.0 - rhs[i - 1] * factor;
    }
    // Back substitution, storing M_i in `rhs`.
    rhs[n - 1] = T::ZERO;
    for i in (1..n - 1).rev() {
        rhs[i] = (rhs[i] - rhs[i + 1] * h(i)) * (1.0 / diag[i]);
    }
    rhs[0] = T::ZERO;
    let second = rhs;
    for i in 0..n - 1 {
        out[i] = slope(i) - (second[i] * 2.0 + second[i + 1]) * (h(i) / 6.0);
    }
    let last = n - 2;
    out[n - 1] = slope(last) + (second[last] + second[n - 1] * 2.0) * (h(last) / 6.0);
}
