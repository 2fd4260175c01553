//! glTF 2.0 import: a file's first skin becomes a [`Skeleton`], its animations [`RawClip`]s and
//! its skinned meshes [`SkinnedMesh`]es, read with the `gltf` crate (not a hand parser).
//!
//! This is the one module outside `render/` and `web/` with a dependency besides glam: reading
//! the format is the `gltf` crate's job (and `base64`'s, for buffers embedded as data URIs).
//!
//! What the importer does, in order:
//! - Parses and validates the JSON (or the `.glb` container) with `gltf::Gltf::from_slice`;
//!   buffers are the GLB's binary chunk or `data:` URIs (external files cannot be fetched from
//!   here and are reported). Every buffer must be as long as it says, and every accessor must fit
//!   inside its buffer view and buffer, before anything is read: the crate's readers slice
//!   without checking, and a malformed file must give an error, not a panic.
//! - Orders the skin's joints parents first (depth-first from the roots, children in the order
//!   the file lists them): glTF lists them in any order, [`Skeleton`] requires `parents[i] < i`.
//!   A joint's parent is its nearest ancestor node that is also a joint. [`Imported::nodes`]
//!   maps back to the file's node indices; meshes' joint indices are remapped.
//! - The nodes above the root joints (often a node turning Z-up into Y-up) are not joints; their
//!   world transform is [`Imported::root_transform`], applied above the skeleton. All root
//!   joints must share it.
//! - Animations: channels on joints become tracks (channels on other nodes and morph-target
//!   weights are skipped and listed in [`Imported::notes`]). LINEAR rotations are slerped, as the
//!   glTF specification says. A clip whose samplers are all LINEAR or all STEP keeps its keys;
//!   otherwise (CUBICSPLINE, or a mix) every channel is resampled into linear keys, 8 per key
//!   interval for cubic splines (rotations normalised after interpolation), which is within
//!   about 1e-3 of the spline for the motions in typical files.
//! - Skinned meshes: positions, normals, indices, `JOINTS_0` and `WEIGHTS_0`. Weights are kept
//!   as stored; [`SkinnedMesh::weight_sum_range`] tells how far their sums are from 1 (the
//!   skinning core decides what to do with them).
//!
//! Caps: [`MAX_FILE_BYTES`], [`MAX_VERTICES`], the skeleton's and clips' own caps.

pub mod wire;

use crate::curves::Track;
use crate::skeleton::{JointTracks, RawClip, Skeleton, Transform};
use glam::{Mat4, Quat, Vec3, Vec4};
use std::fmt;

/// The largest file the importer reads, bytes.
pub const MAX_FILE_BYTES: usize = 64 << 20;
/// The most vertices over all skinned meshes.
pub const MAX_VERTICES: usize = 1 << 20;
/// The largest magnitude of a vertex coordinate or a node's world-matrix entry: a model that
/// large would overflow the squares and products its viewer takes (the camera's framing of it).
pub const MAX_COORDINATE: f32 = 1e6;
/// Linear keys per key interval when a cubic-spline channel is resampled.
pub const CUBIC_RESAMPLING: usize = 8;

/// Why a file could not be imported. Each says what to fix.
#[derive(Clone, Debug, PartialEq)]
pub enum ImportError {
    TooLarge {
        bytes: usize,
    },
    /// The JSON or the GLB container is malformed, or the document breaks a glTF rule.
    Invalid(String),
    /// A buffer is not embedded (a separate `.bin` file) or its data URI does not decode.
    Buffer {
        index: usize,
        why: String,
    },
    /// An accessor points outside its buffer view or buffer.
    Accessor {
        index: usize,
        why: String,
    },
    NoSkin,
    /// The skeleton it describes is not valid (see [`crate::skeleton::SkeletonError`]).
    Skeleton(String),
    /// An animation could not become a clip.
    Animation {
        name: String,
        why: String,
    },
    Unsupported(String),
}

impl fmt::Display for ImportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ImportError::TooLarge { bytes } => write!(
                f,
                "the file has {bytes} bytes; the importer reads at most {MAX_FILE_BYTES}"
            ),
            ImportError::Invalid(why) => write!(f, "not a valid glTF 2.0 file: {why}"),
            ImportError::Buffer { index, why } => write!(f, "buffer {index}: {why}"),
            ImportError::Accessor { index, why } => write!(f, "accessor {index}: {why}"),
            ImportError::NoSkin => write!(
                f,
                "the file has no skin (no skeleton to animate); export it with its armature"
            ),
            ImportError::Skeleton(why) => write!(f, "its skeleton is not valid: {why}"),
            ImportError::Animation { name, why } => write!(f, "animation {name:?}: {why}"),
            ImportError::Unsupported(why) => write!(f, "not supported: {why}"),
        }
    }
}

impl std::error::Error for ImportError {}

/// A skinned mesh primitive, its joint indices in skeleton order.
#[derive(Clone, Debug, PartialEq)]
pub struct SkinnedMesh {
    pub positions: Vec<Vec3>,
    /// Unit normals; computed from the triangles when the file has none.
    pub normals: Vec<Vec3>,
    /// Three per triangle.
    pub indices: Vec<u32>,
    /// Up to four joints per vertex (skeleton indices).
    pub joints: Vec<[u16; 4]>,
    pub weights: Vec<[f32; 4]>,
    /// The mesh node's world transform (glTF ignores it for skinned meshes; kept for viewers).
    pub node_transform: Mat4,
}

impl SkinnedMesh {
    /// The smallest and largest per-vertex weight sum.
    pub fn weight_sum_range(&self) -> (f32, f32) {
        self.weights
            .iter()
            .map(|w| w.iter().sum::<f32>())
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), s| {
                (lo.min(s), hi.max(s))
            })
    }
}

/// What a file gives.
#[derive(Clone, Debug)]
pub struct Imported {
    pub skeleton: Skeleton,
    /// The glTF node index of each joint, in skeleton order.
    pub nodes: Vec<usize>,
    /// The world transform of the nodes above the root joints.
    pub root_transform: Mat4,
    /// The skin's inverse bind matrices, in skeleton order (identity when the file has none).
    pub inverse_bind: Vec<Mat4>,
    pub clips: Vec<RawClip>,
    pub meshes: Vec<SkinnedMesh>,
    /// What was skipped, in words.
    pub notes: Vec<String>,
}

/// Imports a `.gltf` (JSON with embedded buffers) or `.glb` file.
pub fn import(bytes: &[u8]) -> Result<Imported, ImportError> {
    if bytes.len() > MAX_FILE_BYTES {
        return Err(ImportError::TooLarge { bytes: bytes.len() });
    }
    // Neither container: say so, rather than the JSON parser's "expected value at line 1".
    let first = bytes.iter().find(|b| !b.is_ascii_whitespace());
    if !bytes.starts_with(b"glTF") && first != Some(&b'{') {
        return Err(ImportError::Invalid(
            "it starts with neither the binary header \"glTF\" (.glb) nor a JSON object (.gltf)"
                .into(),
        ));
    }
    // Parsed, checked for what makes the crate's own validation index out of bounds (found by
    // fuzzing: a primitive attribute naming an accessor that does not exist), then validated.
    let raw = gltf::Gltf::from_slice_without_validation(bytes)
        .map_err(|e| ImportError::Invalid(e.to_string()))?;
    precheck(raw.document.as_json())?;
    let gltf = gltf::Gltf {
        document: gltf::Document::from_json(raw.document.into_json())
            .map_err(|e| ImportError::Invalid(e.to_string()))?,
        blob: raw.blob,
    };
    let buffers = load_buffers(&gltf)?;
    check_accessors(&gltf.document, &buffers)?;
    let doc = &gltf.document;
    let skin = doc.skins().next().ok_or(ImportError::NoSkin)?;
    let mut notes = Vec::new();
    if doc.skins().len() > 1 {
        notes.push(format!(
            "the file has {} skins; the first one is imported",
            doc.skins().len()
        ));
    }

    // Node parents, from the children lists. A node has at most one parent and is not its own
    // child: a second parent would make its place in the hierarchy ambiguous.
    let all_nodes: Vec<gltf::Node> = doc.nodes().collect();
    let node_count = all_nodes.len();
    let mut node_parent = vec![usize::MAX; node_count];
    for node in &all_nodes {
        for child in node.children() {
            let (c, n) = (child.index(), node.index());
            if c == n {
                return Err(ImportError::Invalid(format!(
                    "node {n} lists itself as a child"
                )));
            }
            if node_parent[c] != usize::MAX {
                return Err(ImportError::Invalid(format!(
                    "node {c} has two parents (nodes {} and {n}); a node has at most one parent",
                    node_parent[c]
                )));
            }
            node_parent[c] = n;
        }
    }
    // Parents before children: a breadth-first walk from the nodes without a parent. A node it
    // does not reach lies on a cycle (each node has at most one parent, so nothing else hides
    // it). One pass: the work grows linearly with the node count, however deep the chains.
    let mut top_down: Vec<usize> = (0..node_count)
        .filter(|&n| node_parent[n] == usize::MAX)
        .collect();
    let mut next = 0;
    while next < top_down.len() {
        let n = top_down[next];
        next += 1;
        top_down.extend(all_nodes[n].children().map(|c| c.index()));
    }
    if top_down.len() != node_count {
        return Err(ImportError::Invalid(
            "the node hierarchy has a cycle".into(),
        ));
    }
    let skin_joints: Vec<usize> = skin.joints().map(|n| n.index()).collect();
    if skin_joints.is_empty() {
        return Err(ImportError::Skeleton("the skin lists no joints".into()));
    }
    // The skeleton's cap, checked before any work that grows with the joint count.
    if skin_joints.len() > crate::skeleton::MAX_JOINTS {
        return Err(ImportError::Skeleton(format!(
            "the skin lists {} joints; a skeleton has at most {}",
            skin_joints.len(),
            crate::skeleton::MAX_JOINTS
        )));
    }
    let mut joint_of_node = vec![usize::MAX; node_count];
    for (k, &n) in skin_joints.iter().enumerate() {
        if joint_of_node[n] != usize::MAX {
            return Err(ImportError::Skeleton(format!(
                "node {n} is listed twice in the skin"
            )));
        }
        joint_of_node[n] = k;
    }
    // Each node's nearest ancestor that is a joint (skin order), or None, and its world
    // matrix, both in one top-down pass.
    let mut joint_above = vec![None; node_count];
    let mut world = vec![Mat4::IDENTITY; node_count];
    for &n in &top_down {
        let p = node_parent[n];
        if p != usize::MAX {
            joint_above[n] = if joint_of_node[p] != usize::MAX {
                Some(joint_of_node[p])
            } else {
                joint_above[p]
            };
            world[n] = world[p] * local_matrix(&all_nodes[n]);
        } else {
            world[n] = local_matrix(&all_nodes[n]);
        }
    }
    if let Some(n) = (0..node_count).find(|&n| {
        let m = world[n];
        !m.is_finite() || m.to_cols_array().iter().any(|v| v.abs() > MAX_COORDINATE)
    }) {
        return Err(ImportError::Unsupported(format!(
            "node {n}'s transform reaches past ±{MAX_COORDINATE} (a scale or translation that \
             large cannot be framed)"
        )));
    }
    let skin_parents: Vec<Option<usize>> = skin_joints.iter().map(|&n| joint_above[n]).collect();
    // Depth-first order from the roots, children in skin order.
    let mut children = vec![Vec::new(); skin_joints.len()];
    let mut roots = Vec::new();
    for (k, p) in skin_parents.iter().enumerate() {
        match p {
            Some(p) => children[*p].push(k),
            None => roots.push(k),
        }
    }
    let mut order = Vec::with_capacity(skin_joints.len());
    let mut stack: Vec<usize> = roots.iter().rev().copied().collect();
    while let Some(k) = stack.pop() {
        order.push(k);
        stack.extend(children[k].iter().rev());
    }
    if order.len() != skin_joints.len() {
        return Err(ImportError::Skeleton(
            "the joints' hierarchy has a cycle".into(),
        ));
    }
    let mut new_index = vec![0usize; skin_joints.len()];
    for (i, &k) in order.iter().enumerate() {
        new_index[k] = i;
    }

    // Above the roots: one shared world transform.
    let above = |k: usize| {
        let p = node_parent[skin_joints[k]];
        if p == usize::MAX {
            Mat4::IDENTITY
        } else {
            world[p]
        }
    };
    let root_transform = above(roots[0]);
    for &r in &roots[1..] {
        if !above(r).abs_diff_eq(root_transform, 1e-5) {
            return Err(ImportError::Unsupported(
                "root joints under differently transformed nodes".into(),
            ));
        }
    }

    let nodes: Vec<usize> = order.iter().map(|&k| skin_joints[k]).collect();
    let names: Vec<String> = nodes
        .iter()
        .map(|&n| {
            let node = &all_nodes[n];
            match node.name() {
                Some(name) if !name.is_empty() => format!("{name} (node {n})"),
                _ => format!("node {n}"),
            }
        })
        .collect();
    let parents: Vec<i32> = order
        .iter()
        .map(|&k| skin_parents[k].map_or(-1, |p| new_index[p] as i32))
        .collect();
    let rest: Vec<Transform> = nodes
        .iter()
        .map(|&n| {
            let (t, r, s) = all_nodes[n].transform().decomposed();
            Transform {
                translation: Vec3::from(t),
                rotation: Quat::from_array(r).normalize(),
                scale: Vec3::from(s),
            }
        })
        .collect();
    let skeleton =
        Skeleton::new(names, parents, rest).map_err(|e| ImportError::Skeleton(e.to_string()))?;

    let get = |b: gltf::Buffer| buffers.get(b.index()).map(|v| v.as_slice());
    let mut inverse_bind = vec![Mat4::IDENTITY; skin_joints.len()];
    if let Some(accessor) = skin.inverse_bind_matrices() {
        use gltf::accessor::{DataType, Dimensions};
        check_kind(
            &accessor,
            "the inverse bind matrices",
            Dimensions::Mat4,
            &[DataType::F32],
        )
        .map_err(ImportError::Skeleton)?;
    }
    if let Some(iter) = skin.reader(get).read_inverse_bind_matrices() {
        let read: Vec<Mat4> = iter.map(|m| Mat4::from_cols_array_2d(&m)).collect();
        if read.len() != skin_joints.len() {
            return Err(ImportError::Skeleton(format!(
                "{} inverse bind matrices for {} joints",
                read.len(),
                skin_joints.len()
            )));
        }
        for (k, m) in read.into_iter().enumerate() {
            if !m.is_finite() {
                return Err(ImportError::Skeleton(format!(
                    "the inverse bind matrix of joint {k} is not finite"
                )));
            }
            inverse_bind[new_index[k]] = m;
        }
    }

    let mut clips = Vec::new();
    for (a, animation) in doc.animations().enumerate() {
        let name = animation
            .name()
            .filter(|n| !n.is_empty())
            .map_or_else(|| format!("animation {a}"), str::to_string);
        let clip = import_animation(
            &animation,
            &name,
            &joint_of_node,
            &new_index,
            get,
            &mut notes,
        )
        .map_err(|why| ImportError::Animation {
            name: name.clone(),
            why,
        })?;
        if let Some(clip) = clip {
            clips.push(clip);
        }
    }

    let mut meshes = Vec::new();
    let mut vertices = 0usize;
    for node in doc.nodes() {
        let (Some(mesh), Some(node_skin)) = (node.mesh(), node.skin()) else {
            continue;
        };
        if node_skin.index() != skin.index() {
            continue;
        }
        for primitive in mesh.primitives() {
            if primitive.mode() != gltf::mesh::Mode::Triangles {
                notes.push(format!(
                    "mesh {}: a primitive that is not triangles was skipped",
                    mesh.index()
                ));
                continue;
            }
            let m = import_primitive(&primitive, &new_index, get, world[node.index()])
                .map_err(|why| ImportError::Invalid(format!("mesh {}: {why}", mesh.index())))?;
            vertices += m.positions.len();
            if vertices > MAX_VERTICES {
                return Err(ImportError::Unsupported(format!(
                    "more than {MAX_VERTICES} skinned vertices"
                )));
            }
            meshes.push(m);
        }
    }

    Ok(Imported {
        skeleton,
        nodes,
        root_transform,
        inverse_bind,
        clips,
        meshes,
        notes,
    })
}

/// What the crate's validation reads without checking (accessor indices), and the enumerations
/// its accessors unwrap (an unknown accessor type or animation path must be an error here, not a
/// panic there).
fn precheck(root: &gltf::json::Root) -> Result<(), ImportError> {
    use gltf::json::validation::Checked;
    let invalid = |what: String| Err(ImportError::Invalid(what));
    for (k, a) in root.accessors.iter().enumerate() {
        if !matches!(a.type_, Checked::Valid(_)) || !matches!(a.component_type, Checked::Valid(_)) {
            return invalid(format!(
                "accessor {k} has an unknown type or component type"
            ));
        }
    }
    for (k, animation) in root.animations.iter().enumerate() {
        if animation
            .channels
            .iter()
            .any(|c| !matches!(c.target.path, Checked::Valid(_)))
            || animation
                .samplers
                .iter()
                .any(|s| !matches!(s.interpolation, Checked::Valid(_)))
        {
            return invalid(format!(
                "animation {k} has an unknown target path or interpolation"
            ));
        }
    }
    // Every index the importer follows, in range.
    let check = |what: &str, index: usize, len: usize| {
        if index >= len {
            Err(ImportError::Invalid(format!(
                "{what} refers to index {index}, but there are {len}"
            )))
        } else {
            Ok(())
        }
    };
    let (nodes, accessors) = (root.nodes.len(), root.accessors.len());
    for (k, node) in root.nodes.iter().enumerate() {
        for c in node.children.iter().flatten() {
            check(&format!("node {k}'s child"), c.value(), nodes)?;
        }
        if let Some(m) = node.mesh {
            check(&format!("node {k}'s mesh"), m.value(), root.meshes.len())?;
        }
        if let Some(skin) = node.skin {
            check(&format!("node {k}'s skin"), skin.value(), root.skins.len())?;
        }
    }
    for (k, skin) in root.skins.iter().enumerate() {
        for j in &skin.joints {
            check(&format!("skin {k}'s joint"), j.value(), nodes)?;
        }
        if let Some(a) = skin.inverse_bind_matrices {
            check(
                &format!("skin {k}'s inverse bind matrices"),
                a.value(),
                accessors,
            )?;
        }
    }
    for (k, animation) in root.animations.iter().enumerate() {
        for c in &animation.channels {
            check(
                &format!("animation {k}'s channel target"),
                c.target.node.value(),
                nodes,
            )?;
            check(
                &format!("animation {k}'s channel sampler"),
                c.sampler.value(),
                animation.samplers.len(),
            )?;
        }
        for s in &animation.samplers {
            check(
                &format!("animation {k}'s sampler input"),
                s.input.value(),
                accessors,
            )?;
            check(
                &format!("animation {k}'s sampler output"),
                s.output.value(),
                accessors,
            )?;
        }
    }
    for (k, a) in root.accessors.iter().enumerate() {
        if let Some(v) = a.buffer_view {
            check(
                &format!("accessor {k}'s buffer view"),
                v.value(),
                root.buffer_views.len(),
            )?;
        }
    }
    for (k, v) in root.buffer_views.iter().enumerate() {
        check(
            &format!("buffer view {k}'s buffer"),
            v.buffer.value(),
            root.buffers.len(),
        )?;
    }
    let count = accessors;
    for (m, mesh) in root.meshes.iter().enumerate() {
        for primitive in &mesh.primitives {
            if !matches!(primitive.mode, Checked::Valid(_))
                || primitive
                    .attributes
                    .keys()
                    .any(|k| !matches!(k, Checked::Valid(_)))
            {
                return invalid(format!(
                    "mesh {m} has an unknown primitive mode or attribute"
                ));
            }
            let targets = primitive.targets.iter().flatten().flat_map(|t| {
                [&t.positions, &t.normals, &t.tangents]
                    .into_iter()
                    .flatten()
                    .map(|i| i.value())
            });
            let used = primitive
                .attributes
                .values()
                .map(|i| i.value())
                .chain(primitive.indices.iter().map(|i| i.value()))
                .chain(targets);
            for index in used {
                if index >= count {
                    return Err(ImportError::Invalid(format!(
                        "mesh {m} uses accessor {index}, but the file has {count}"
                    )));
                }
            }
        }
    }
    Ok(())
}

/// A node's local matrix (glTF: `T · R · S`, or the matrix it gives).
fn local_matrix(node: &gltf::Node) -> Mat4 {
    Mat4::from_cols_array_2d(&node.transform().matrix())
}

/// The binary chunk of a `.glb`, or each buffer's `data:` URI decoded; each checked against its
/// declared length.
fn load_buffers(gltf: &gltf::Gltf) -> Result<Vec<Vec<u8>>, ImportError> {
    use base64::Engine;
    let mut out = Vec::new();
    for buffer in gltf.document.buffers() {
        let index = buffer.index();
        let data = match buffer.source() {
            gltf::buffer::Source::Bin => gltf.blob.clone().ok_or(ImportError::Buffer {
                index,
                why: "it refers to the GLB binary chunk, which is missing".into(),
            })?,
            gltf::buffer::Source::Uri(uri) => {
                let Some(rest) = uri.strip_prefix("data:") else {
                    return Err(ImportError::Buffer {
                        index,
                        why: format!(
                            "it is a separate file ({uri}); use a .glb or a .gltf with embedded buffers"
                        ),
                    });
                };
                let Some((_, payload)) = rest.split_once(";base64,") else {
                    return Err(ImportError::Buffer {
                        index,
                        why: "its data URI is not base64".into(),
                    });
                };
                base64::engine::general_purpose::STANDARD
                    .decode(payload)
                    .map_err(|e| ImportError::Buffer {
                        index,
                        why: format!("its base64 does not decode: {e}"),
                    })?
            }
        };
        if data.len() < buffer.length() {
            return Err(ImportError::Buffer {
                index,
                why: format!("it says {} bytes but holds {}", buffer.length(), data.len()),
            });
        }
        out.push(data);
    }
    Ok(out)
}

/// Every accessor with a buffer view fits inside it, and every view inside its buffer.
fn check_accessors(doc: &gltf::Document, buffers: &[Vec<u8>]) -> Result<(), ImportError> {
    for view in doc.views() {
        let end = view.offset().checked_add(view.length());
        let have = buffers.get(view.buffer().index()).map_or(0, Vec::len);
        if end.is_none_or(|end| end > have) {
            return Err(ImportError::Invalid(format!(
                "buffer view {} reaches past the end of buffer {}",
                view.index(),
                view.buffer().index()
            )));
        }
    }
    for accessor in doc.accessors() {
        if accessor.sparse().is_some() {
            return Err(ImportError::Accessor {
                index: accessor.index(),
                why: "sparse accessors are not supported".into(),
            });
        }
        let Some(view) = accessor.view() else {
            continue;
        };
        let size = accessor.size();
        let stride = view.stride().unwrap_or(size);
        let count = accessor.count();
        if count == 0 {
            return Err(ImportError::Accessor {
                index: accessor.index(),
                why: "it has no elements (glTF requires at least one)".into(),
            });
        }
        let needed = (count - 1)
            .checked_mul(stride)
            .and_then(|x| x.checked_add(size))
            .and_then(|x| x.checked_add(accessor.offset()));
        if stride < size || needed.is_none_or(|n| n > view.length()) {
            return Err(ImportError::Accessor {
                index: accessor.index(),
                why: format!(
                    "{count} elements of {size} bytes (stride {stride}) from offset {} do not fit in \
                     buffer view {} ({} bytes)",
                    accessor.offset(),
                    view.index(),
                    view.length()
                ),
            });
        }
    }
    Ok(())
}

/// The accessor has one of these shapes and component types (the crate's readers assume it).
fn check_kind(
    accessor: &gltf::Accessor,
    what: &str,
    dimensions: gltf::accessor::Dimensions,
    types: &[gltf::accessor::DataType],
) -> Result<(), String> {
    if accessor.dimensions() != dimensions || !types.contains(&accessor.data_type()) {
        return Err(format!(
            "{what} (accessor {}) is {:?} of {:?}, expected {dimensions:?} of {types:?}",
            accessor.index(),
            accessor.dimensions(),
            accessor.data_type()
        ));
    }
    Ok(())
}

/// One channel's keys, as read.
enum Keys {
    Vec3(Vec<Vec3>),
    Quat(Vec<Vec4>),
}

fn import_animation<'a, 's>(
    animation: &gltf::Animation<'a>,
    name: &str,
    joint_of_node: &[usize],
    new_index: &[usize],
    get: impl Clone + Fn(gltf::Buffer<'a>) -> Option<&'s [u8]>,
    notes: &mut Vec<String>,
) -> Result<Option<RawClip>, String> {
    use gltf::animation::util::ReadOutputs;
    use gltf::animation::{Interpolation as I, Property};
    let mut joints = vec![JointTracks::default(); new_index.len()];
    let interpolations: Vec<I> = animation
        .channels()
        .map(|c| c.sampler().interpolation())
        .collect();
    let keep_keys = interpolations.iter().all(|&i| i == I::Linear)
        || interpolations.iter().all(|&i| i == I::Step);
    let mut duration = 0.0f32;
    let mut used = 0;
    for channel in animation.channels() {
        let node = channel.target().node().index();
        let property = channel.target().property();
        if joint_of_node[node] == usize::MAX {
            notes.push(format!(
                "{name}: a channel on node {node}, not a joint, was skipped"
            ));
            continue;
        }
        if property == Property::MorphTargetWeights {
            notes.push(format!("{name}: morph-target weights were skipped"));
            continue;
        }
        let joint = new_index[joint_of_node[node]];
        {
            use gltf::accessor::{DataType as D, Dimensions};
            let sampler = channel.sampler();
            check_kind(&sampler.input(), "key times", Dimensions::Scalar, &[D::F32])?;
            match property {
                Property::Rotation => check_kind(
                    &sampler.output(),
                    "rotation keys",
                    Dimensions::Vec4,
                    &[D::F32, D::I8, D::U8, D::I16, D::U16],
                )?,
                _ => check_kind(&sampler.output(), "keys", Dimensions::Vec3, &[D::F32])?,
            }
        }
        let reader = channel.reader(get.clone());
        let times: Vec<f32> = reader
            .read_inputs()
            .ok_or("a channel has no key times")?
            .collect();
        let keys = match reader.read_outputs().ok_or("a channel has no values")? {
            ReadOutputs::Translations(it) | ReadOutputs::Scales(it) => {
                Keys::Vec3(it.map(Vec3::from).collect())
            }
            ReadOutputs::Rotations(it) => Keys::Quat(it.into_f32().map(Vec4::from).collect()),
            ReadOutputs::MorphTargetWeights(_) => continue,
        };
        if let Some(bad) = times.iter().find(|t| !t.is_finite() || **t < 0.0) {
            return Err(format!(
                "a key time is {bad}; times must be finite and not negative"
            ));
        }
        duration = times.iter().copied().fold(duration, f32::max);
        let interpolation = channel.sampler().interpolation();
        let (times, keys) = if keep_keys {
            (times, keys)
        } else {
            resample(&times, keys, interpolation)?
        };
        let track_error = |e: crate::curves::TrackError| format!("joint {joint}: {e}");
        let tracks = &mut joints[joint];
        match (property, keys) {
            (Property::Translation, Keys::Vec3(v)) => {
                tracks.translation = Some(Track::new(times, v).map_err(track_error)?)
            }
            (Property::Scale, Keys::Vec3(v)) => {
                tracks.scale = Some(Track::new(times, v).map_err(track_error)?)
            }
            (Property::Rotation, Keys::Quat(v)) => {
                tracks.rotation = Some(Track::new(times, v).map_err(track_error)?)
            }
            _ => return Err("a channel's values do not match its property".into()),
        }
        used += 1;
    }
    if used == 0 {
        notes.push(format!("{name}: no channel moves a joint; skipped"));
        return Ok(None);
    }
    // A clip needs a positive duration; a pose held by single keys at time 0 gets one frame.
    let duration = duration.max(1.0 / 30.0);
    let mut clip = RawClip::new(name, duration, true, joints).map_err(|e| e.to_string())?;
    if keep_keys && interpolations[0] == I::Step {
        clip.set_interpolation(crate::skeleton::KeyInterpolation::Step);
    }
    clip.set_rotation_interpolation(crate::skeleton::QuatInterpolation::Slerp);
    Ok(Some(clip))
}

/// A channel as linear keys: STEP holds each value until just before the next key; CUBICSPLINE
/// (values stored as in-tangent, value, out-tangent) is evaluated at [`CUBIC_RESAMPLING`] points
/// per interval, rotations normalised.
fn resample(
    times: &[f32],
    keys: Keys,
    interpolation: gltf::animation::Interpolation,
) -> Result<(Vec<f32>, Keys), String> {
    use gltf::animation::Interpolation as I;
    fn go<T: Copy>(
        times: &[f32],
        values: &[T],
        interpolation: I,
        hermite: impl Fn(T, T, T, T, f32, f32) -> T,
    ) -> Result<(Vec<f32>, Vec<T>), String> {
        let n = times.len();
        match interpolation {
            I::Linear => Ok((times.to_vec(), values.to_vec())),
            I::Step => {
                let mut t = Vec::with_capacity(2 * n);
                let mut v = Vec::with_capacity(2 * n);
                for k in 0..n {
                    t.push(times[k]);
                    v.push(values[k]);
                    if k + 1 < n {
                        let gap = times[k + 1] - times[k];
                        t.push(times[k + 1] - (gap * 0.25).min(1e-4));
                        v.push(values[k]);
                    }
                }
                Ok((t, v))
            }
            I::CubicSpline => {
                if values.len() != 3 * n {
                    return Err(format!(
                        "a cubic-spline channel has {} values for {n} keys (3 per key expected)",
                        values.len()
                    ));
                }
                let (a_in, value, b_out) = (
                    |k: usize| values[3 * k],
                    |k: usize| values[3 * k + 1],
                    |k: usize| values[3 * k + 2],
                );
                let mut t = Vec::with_capacity(n * CUBIC_RESAMPLING);
                let mut v = Vec::with_capacity(n * CUBIC_RESAMPLING);
                for k in 0..n {
                    if k + 1 == n {
                        t.push(times[k]);
                        v.push(value(k));
                        break;
                    }
                    let dt = times[k + 1] - times[k];
                    for s in 0..CUBIC_RESAMPLING {
                        let u = s as f32 / CUBIC_RESAMPLING as f32;
                        t.push(times[k] + u * dt);
                        v.push(hermite(
                            value(k),
                            b_out(k),
                            value(k + 1),
                            a_in(k + 1),
                            u,
                            dt,
                        ));
                    }
                }
                Ok((t, v))
            }
        }
    }
    // glTF's cubic Hermite: p(u) = h00 v0 + h10 dt b0 + h01 v1 + h11 dt a1.
    let h = |u: f32| {
        let (u2, u3) = (u * u, u * u * u);
        (
            2.0 * u3 - 3.0 * u2 + 1.0,
            u3 - 2.0 * u2 + u,
            -2.0 * u3 + 3.0 * u2,
            u3 - u2,
        )
    };
    match keys {
        Keys::Vec3(values) => {
            let (t, v) = go(times, &values, interpolation, |v0, b0, v1, a1, u, dt| {
                let (h00, h10, h01, h11) = h(u);
                v0 * h00 + b0 * (h10 * dt) + v1 * h01 + a1 * (h11 * dt)
            })?;
            Ok((t, Keys::Vec3(v)))
        }
        Keys::Quat(values) => {
            let (t, v) = go(times, &values, interpolation, |v0, b0, v1, a1, u, dt| {
                let (h00, h10, h01, h11) = h(u);
                (v0 * h00 + b0 * (h10 * dt) + v1 * h01 + a1 * (h11 * dt)).normalize_or(v0)
            })?;
            Ok((t, Keys::Quat(v)))
        }
    }
}

fn import_primitive<'a, 's>(
    primitive: &'a gltf::Primitive<'a>,
    new_index: &[usize],
    get: impl Clone + Fn(gltf::Buffer<'a>) -> Option<&'s [u8]>,
    node_transform: Mat4,
) -> Result<SkinnedMesh, String> {
    {
        use gltf::accessor::{DataType as D, Dimensions};
        use gltf::Semantic;
        for (semantic, accessor) in primitive.attributes() {
            match semantic {
                Semantic::Positions | Semantic::Normals => check_kind(
                    &accessor,
                    "positions or normals",
                    Dimensions::Vec3,
                    &[D::F32],
                )?,
                Semantic::Joints(_) => {
                    check_kind(&accessor, "joints", Dimensions::Vec4, &[D::U8, D::U16])?
                }
                Semantic::Weights(_) => check_kind(
                    &accessor,
                    "weights",
                    Dimensions::Vec4,
                    &[D::F32, D::U8, D::U16],
                )?,
                _ => {}
            }
        }
        if let Some(accessor) = primitive.indices() {
            check_kind(
                &accessor,
                "indices",
                Dimensions::Scalar,
                &[D::U8, D::U16, D::U32],
            )?;
        }
    }
    let reader = primitive.reader(get);
    let positions: Vec<Vec3> = reader
        .read_positions()
        .ok_or("a primitive has no positions")?
        .map(Vec3::from)
        .collect();
    let n = positions.len();
    if positions.iter().any(|p| !p.is_finite()) {
        return Err("a position is not finite".into());
    }
    if positions
        .iter()
        .any(|p| p.abs().max_element() > MAX_COORDINATE)
    {
        return Err(format!(
            "a position lies beyond ±{MAX_COORDINATE} (see MAX_COORDINATE)"
        ));
    }
    let indices: Vec<u32> = match reader.read_indices() {
        Some(it) => it.into_u32().collect(),
        None => (0..n as u32).collect(),
    };
    if !indices.len().is_multiple_of(3) || indices.iter().any(|&i| i as usize >= n) {
        return Err(format!(
            "{} indices for {n} vertices: not whole triangles of valid vertices",
            indices.len()
        ));
    }
    let normals: Vec<Vec3> = match reader.read_normals() {
        Some(it) => it.map(|v| Vec3::from(v).normalize_or(Vec3::Y)).collect(),
        None => {
            let mut acc = vec![Vec3::ZERO; n];
            for t in indices.chunks_exact(3) {
                let [a, b, c] = [t[0], t[1], t[2]].map(|i| i as usize);
                let face = (positions[b] - positions[a]).cross(positions[c] - positions[a]);
                for i in [a, b, c] {
                    acc[i] += face;
                }
            }
            acc.into_iter().map(|v| v.normalize_or(Vec3::Y)).collect()
        }
    };
    let joints: Vec<[u16; 4]> = reader
        .read_joints(0)
        .ok_or("a skinned primitive has no JOINTS_0")?
        .into_u16()
        .collect();
    let weights: Vec<[f32; 4]> = reader
        .read_weights(0)
        .ok_or("a skinned primitive has no WEIGHTS_0")?
        .into_f32()
        .collect();
    if normals.len() != n || joints.len() != n || weights.len() != n {
        return Err(format!(
            "{n} positions but {} normals, {} joint sets, {} weight sets",
            normals.len(),
            joints.len(),
            weights.len()
        ));
    }
    let joints = joints
        .into_iter()
        .map(|j| {
            let mut out = [0u16; 4];
            for (o, &k) in out.iter_mut().zip(&j) {
                *o = *new_index.get(k as usize).ok_or_else(|| {
                    format!(
                        "joint index {k} is not in the skin ({} joints)",
                        new_index.len()
                    )
                })? as u16;
            }
            Ok(out)
        })
        .collect::<Result<Vec<_>, String>>()?;
    if weights.iter().flatten().any(|w| !w.is_finite() || *w < 0.0) {
        return Err("a weight is negative or not finite".into());
    }
    Ok(SkinnedMesh {
        positions,
        normals,
        indices,
        joints,
        weights,
        node_transform,
    })
}
