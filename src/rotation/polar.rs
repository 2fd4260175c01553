//! Polar decomposition `M = R D` of a 3x3 matrix (Shoemake & Duff, "Matrix Animation and Polar
//! Decomposition", Graphics Interface 1992).

use glam::{DMat3, DVec3, Mat3, Vec3};

use super::RotationError;

/// Default convergence tolerance of [`polar_decompose`]: the Frobenius norm of the change
/// between two iterates, relative to the size of the iterate (`‖R‖_F = √3` at the end).
pub const POLAR_TOLERANCE: f32 = 1e-6;

/// Default iteration cap of [`polar_decompose`]. Newton's iteration converges quadratically once
/// close; from far away (scale factors of 10⁶) it takes about 25 steps.
pub const POLAR_MAX_ITERATIONS: u32 = 64;

/// The factors of `M = R D`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolarDecomposition {
    /// Rotation (orthonormal, `det = +1`): the orientation part of the key.
    pub rotation: Mat3,
    /// Symmetric positive definite stretch `D = Rᵀ M`: scale and shear, in the key's local axes.
    pub stretch: Mat3,
    /// Iterations used (0 for [`polar_decompose_eigen`]).
    pub iterations: u32,
}

/// One step of the polar-decomposition iteration: the average of a matrix and its inverse
/// transpose.
/// ```text
/// R_{k+1} = ½ (R_k + R_k^{−T}),     R₀ = M
/// ```
/// For a rotation `R^{−T} = R`, so rotations are fixed points; every other singular value `σ`
/// moves to `½(σ + 1/σ)`, towards 1. Expects `det R_k ≠ 0` (a singular matrix gives NaN or
/// infinities).
///
/// This is the reference for the "one polar-decomposition iteration" exercise.
pub fn polar_step(r: Mat3) -> Mat3 {
    (r + r.inverse().transpose()) * 0.5
}

/// Polar decomposition `M = R D` with the default tolerance and iteration cap.
///
/// See [`polar_decompose_with`].
pub fn polar_decompose(m: Mat3) -> Result<PolarDecomposition, RotationError> {
    polar_decompose_with(m, POLAR_TOLERANCE, POLAR_MAX_ITERATIONS)
}

/// Polar decomposition `M = R D`: `R` a rotation, `D` symmetric positive definite.
/// ```text
/// R₀ = M,   R_{k+1} = ½ (γ R_k + (γ R_k)^{−T}),  γ = √(‖R_k⁻¹‖_F / ‖R_k‖_F),   until ‖R_{k+1} − R_k‖_F ≤ tolerance · ‖R_{k+1}‖_F
/// D = Rᵀ M   (symmetrised: ½ (D + Dᵀ))
/// ```
/// `R` is the rotation closest to `M`; the iteration runs in `f64` so the tolerance can be
/// tighter than `f32` round-off. With the SVD `M = W Σ Vᵀ`, `R = W Vᵀ` and `D = V Σ Vᵀ`
/// ([`polar_decompose_eigen`] computes it that way as a check).
///
/// # Errors
/// [`RotationError::NonFinite`]; [`RotationError::SingularMatrix`] when
/// `|det M| ≤ 1e-9 · ‖M‖_F³` (a key that flattens space has no unique rotation);
/// [`RotationError::Reflection`] when `det M < 0` (`R` would be a mirror);
/// [`RotationError::NotConverged`] when the cap is reached first.
pub fn polar_decompose_with(
    m: Mat3,
    tolerance: f32,
    max_iterations: u32,
) -> Result<PolarDecomposition, RotationError> {
    let m64 = check_invertible(m)?;
    let mut r = m64;
    let mut change = f64::INFINITY;
    for iteration in 1..=max_iterations {
        // Scaled by γ = √(‖R⁻¹‖/‖R‖) (Higham): the same limit, reached in a few steps even
        // when the singular values span many orders of magnitude (unscaled, σ = 1e38 would
        // take 127 halvings). γ → 1 as R_k approaches the rotation.
        let inv = r.inverse();
        let gamma = (frobenius(inv) / frobenius(r)).sqrt();
        let next = (r * gamma + inv.transpose() * (1.0 / gamma)) * 0.5;
        change = frobenius(next - r) / frobenius(next);
        r = next;
        if change <= f64::from(tolerance) {
            return Ok(finish(m64, r, iteration));
        }
    }
    Err(RotationError::NotConverged {
        iterations: max_iterations,
        change: change as f32,
    })
}

/// Below this `|det M| / (|c₀||c₁||c₂|)` a matrix counts as singular: its columns span a box
/// less than a ten-millionth of the volume they would span at right angles.
pub const SINGULAR_RATIO: f64 = 1e-7;

fn check_invertible(m: Mat3) -> Result<DMat3, RotationError> {
    if !m.is_finite() {
        return Err(RotationError::NonFinite { what: "matrix" });
    }
    let m64 = m.as_dmat3();
    let determinant = m64.determinant();
    // Singular relative to scale: |det M| ≤ |c₀||c₁||c₂| (Hadamard), with equality for orthogonal
    // columns, so the ratio measures how flat the box spanned by the columns is, whatever their
    // lengths (a key scaled by 1e12 is fine; one whose columns are nearly parallel is not).
    let columns = m64.x_axis.length() * m64.y_axis.length() * m64.z_axis.length();
    if columns == 0.0 || determinant.abs() <= SINGULAR_RATIO * columns {
        return Err(RotationError::SingularMatrix {
            determinant: determinant as f32,
        });
    }
    if determinant < 0.0 {
        return Err(RotationError::Reflection {
            determinant: determinant as f32,
        });
    }
    Ok(m64)
}

fn finish(m: DMat3, r: DMat3, iterations: u32) -> PolarDecomposition {
    let d = r.transpose() * m;
    let d = (d + d.transpose()) * 0.5;
    PolarDecomposition {
        rotation: r.as_mat3(),
        stretch: d.as_mat3(),
        iterations,
    }
}

fn frobenius(m: DMat3) -> f64 {
    (m.x_axis.length_squared() + m.y_axis.length_squared() + m.z_axis.length_squared()).sqrt()
}

/// Polar decomposition through the eigen-decomposition of `MᵀM`: an independent check of
/// [`polar_decompose`].
/// ```text
/// MᵀM = V Λ Vᵀ   (Λ = Σ², eigenvalues of a symmetric matrix, by Jacobi rotations)
/// D = V √Λ Vᵀ,   R = M D⁻¹
/// ```
/// # Errors
/// As [`polar_decompose_with`], without `NotConverged`.
pub fn polar_decompose_eigen(m: Mat3) -> Result<PolarDecomposition, RotationError> {
    let m64 = check_invertible(m)?;
    let (lambda, v) = jacobi_eigen(m64.transpose() * m64);
    let sigma = DMat3::from_diagonal(DVec3::new(
        lambda.x.max(0.0).sqrt(),
        lambda.y.max(0.0).sqrt(),
        lambda.z.max(0.0).sqrt(),
    ));
    let d = v * sigma * v.transpose();
    let r = m64 * d.inverse();
    Ok(PolarDecomposition {
        rotation: r.as_mat3(),
        stretch: d.as_mat3(),
        iterations: 0,
    })
}

/// Eigenvalues and eigenvectors of a symmetric 3x3 matrix by cyclic Jacobi rotations.
/// ```text
/// S = V Λ Vᵀ,   V orthonormal (eigenvectors in its columns),  Λ = diag(λ₀, λ₁, λ₂)
/// ```
/// Each Jacobi rotation zeroes one off-diagonal pair; sweeps repeat until the off-diagonal part
/// is negligible. Eigenvalues are not sorted. Expects `S` symmetric (only its upper triangle
/// matters in exact arithmetic).
pub fn symmetric_eigen(s: Mat3) -> (Vec3, Mat3) {
    let (lambda, v) = jacobi_eigen(s.as_dmat3());
    (lambda.as_vec3(), v.as_mat3())
}

fn jacobi_eigen(s: DMat3) -> (DVec3, DMat3) {
    let mut a = s.to_cols_array_2d(); // a[col][row]; symmetric, so also a[row][col]
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _sweep in 0..32 {
        let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        let diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if off <= 1e-30 * diag || off == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            // Rotation angle that zeroes a[p][q] (Golub & Van Loan, symmetric Schur).
            let tau = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = tau.signum() / (tau.abs() + (1.0 + tau * tau).sqrt());
            let c = 1.0 / (1.0 + t * t).sqrt();
            let s = t * c;
            // A ← Jᵀ A J, V ← V J, with J the rotation in the (p, q) plane.
            for row in &mut a {
                let (x, y) = (row[p], row[q]);
                row[p] = c * x - s * y;
                row[q] = s * x + c * y;
            }
            let (rp, rq) = (a[p], a[q]);
            for k in 0..3 {
                a[p][k] = c * rp[k] - s * rq[k];
                a[q][k] = s * rp[k] + c * rq[k];
            }
            for row in &mut v {
                let (x, y) = (row[p], row[q]);
                row[p] = c * x - s * y;
                row[q] = s * x + c * y;
            }
        }
    }
    // v[row][col] was built as rows; glam takes columns, so transpose.
    let v = DMat3::from_cols_array_2d(&v).transpose();
    (DVec3::new(a[0][0], a[1][1], a[2][2]), v)
}
