//! Lesson 00 core, "From triangles to pixels": the graphics that the rest of the course stands on.
//!
//! - [`storage`]: a mesh as a triangle soup or as indexed geometry plus connectivity, and what each
//!   costs in bytes;
//! - [`projection`]: the perspective matrix in the course's OpenGL form (depth in `[−1, 1]`) and in
//!   the form this project renders with (wgpu, depth in `[0, 1]`), depth as a function of distance,
//!   and how finely a depth buffer of `b` bits tells two distances apart;
//! - [`normals`]: face normals, averaged per-vertex normals, and the normal matrix (the inverse
//!   transpose of the model matrix);
//! - [`shading`]: the ambient, diffuse and specular terms of Phong and Blinn-Phong shading of one
//!   fragment, and a small CPU image of a shaded sphere.
//!
//! Conventions as in the crate root: right-handed, the camera looks down −z in view space, column
//! vectors. Lesson: lessons/00-triangles-to-pixels.

pub mod normals;
pub mod projection;
pub mod shading;
pub mod storage;

pub use normals::{face_normal, flat_shaded, normal_matrix, vertex_normals};
pub use projection::{
    depth_step, ndc_depth_gl, ndc_depth_wgpu, perspective_gl, perspective_wgpu, project, Projected,
};
pub use shading::{blinn_phong, phong, shade, Material, ShadingModel, ShadingTerms};
pub use storage::{mesh_sizes, tetrahedron, to_soup, weld, MeshSizes};

/// What a caller can get wrong with a mesh or a projection.
#[derive(Clone, Debug, PartialEq)]
pub enum RasterError {
    /// An index points past the end of the positions.
    IndexOutOfRange { index: u32, vertices: usize },
    /// The index count is not a multiple of 3.
    NotTriangles(usize),
    /// An output slice has the wrong length.
    OutputLength { expected: usize, got: usize },
    /// A projection parameter is out of its range (the message says which and why).
    Parameter(String),
}

impl std::fmt::Display for RasterError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RasterError::IndexOutOfRange { index, vertices } => write!(
                f,
                "index {index} points past the {vertices} vertices of the mesh"
            ),
            RasterError::NotTriangles(n) => {
                write!(f, "{n} indices is not a whole number of triangles (3 each)")
            }
            RasterError::OutputLength { expected, got } => {
                write!(f, "the output needs {expected} entries, got {got}")
            }
            RasterError::Parameter(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for RasterError {}
