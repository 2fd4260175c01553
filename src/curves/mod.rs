//! # Keyframes and splines: in-betweens from a few keys
//!
//! An animator sets *keys*, pairs `(t_i, p_i)` of a time in seconds and a value (a position, a
//! scale, one channel of a curve editor), and the computer fills in the frames between them.
//! This module is the core of the lesson "Keyframes and splines":
//!
//! | topic | items |
//! |---|---|
//! | keys, validation, evaluation, end behaviour | [`Track`], [`TrackError`], [`validate_keys`], [`Sample`], [`EndBehaviour`] |
//! | schemes | [`Interpolation`]: step, linear, [`lagrange`], Hermite ([`hermite_basis`], [`hermite_segment`]), cardinal ([`cardinal_tangents`]), natural ([`natural_spline_tangents`]), centripetal Catmull-Rom ([`centripetal_tangents`], [`barry_goldman`]) |
//! | finding the segment | [`find_segment`] (binary search), [`Cursor`] (remembers the last segment) |
//! | constant speed along the path | [`ArcLengthTable`], [`arc_length_invert`] |
//! | timing and spacing | [`Ease`], [`TimeWarp`] |
//!
//! Every cubic scheme is evaluated the same way, as a cubic Hermite segment between two keys;
//! the schemes differ only in how they choose the tangent (velocity) at each key:
//! ```text
//! for t ∈ [t_i, t_{i+1}]:  h = t_{i+1} − t_i,  s = (t − t_i) / h
//! p(t) = h00(s) p_i + h10(s) h d_i + h01(s) p_{i+1} + h11(s) h d_{i+1}
//! ```
//! | scheme | tangents `d_i` | continuity | local? |
//! |---|---|---|---|
//! | Hermite | given by the animator, in and out may differ | C0 at broken keys, else C1 | yes |
//! | cardinal (tension `μ`) | `μ (p_{i+1} − p_{i−1}) / (t_{i+1} − t_{i−1})` | C1 | yes |
//! | natural spline | from a tridiagonal system | C2 | no |
//! | centripetal Catmull-Rom | from knots `Δτ = |Δp|^½` | smooth path, speed may jump | yes |
//!
//! Conventions: times in seconds (`time_sec`), strictly increasing; tangents, velocities in value
//! units per second; `s ∈ [0, 1]` is the parameter inside one segment. Nothing here allocates
//! while sampling: functions that produce many samples write into a caller's `&mut [T]`.
//!
//! The graded exercises of the lesson have these reference solutions: [`hermite_basis`],
//! [`cardinal_tangents`], [`find_segment`], [`arc_length_invert`].

mod arclength;
mod cardinal;
mod hermite;
mod lagrange;
mod natural;
mod segment;
mod timing;
mod track;
mod value;

pub use arclength::{arc_length_invert, ArcLengthTable};
pub use cardinal::{
    barry_goldman, cardinal_tangents, centripetal_segment_points, centripetal_tangents,
    CENTRIPETAL_ALPHA,
};
pub use hermite::{
    hermite_basis, hermite_basis_derivative, hermite_basis_second_derivative, hermite_segment,
};
pub use lagrange::lagrange;
pub use natural::natural_spline_tangents;
pub use segment::{find_segment, Cursor};
pub use timing::{Ease, TimeWarp};
pub use track::{
    validate_keys, EndBehaviour, Interpolation, Sample, Track, TrackError, MAX_LAGRANGE_KEYS,
};
pub use value::Value;
