//! [`Imported`] as bytes, so that the import can run in one wasm module and the figure that
//! draws the result in another.
//!
//! The importer needs the `gltf` crate and serde, which would be about a twentieth of the
//! figures module, loaded by every page although only the glTF figure (lessons 06 and 09) reads
//! files. So the *glTF module* (feature `gltf-module`, `src/web/gltf_module.rs`) imports a file
//! and [`encode`]s the result; the page hands the bytes to the figures module, which
//! [`decode`]s them. The figures module never links the importer.
//!
//! The bytes come from JavaScript, so [`decode`] trusts nothing: every count is checked against
//! the bytes left before anything is allocated, and the result passes the same checks as an
//! import (the skeleton's and clips' own constructors, and the mesh rules of
//! [`super::import`]). Its work grows linearly with the length, at most [`MAX_WIRE_BYTES`].
//!
//! Layout (little-endian; a string is a `u32` byte count and UTF-8; a list is a `u32` count and
//! its items):
//! ```text
//! "IBGW" version:u32
//! skeleton: scale_mode:u8, joints: [name, parent:i32, translation 3×f32, rotation 4×f32, scale 3×f32]
//! nodes: [u32]                 root_transform: 16×f32      inverse_bind: [16×f32]
//! clips: [name, duration:f32, looping:u8, interpolation:u8, rotation_interpolation:u8,
//!         joints: [translation track, rotation track, scale track], contacts: [joint:u32, [2×f32]]]
//!         a track: present:u8, then times: [f32] and as many values (3 or 4 f32 each)
//! meshes: [positions: [3×f32], normals 3×f32 per vertex, indices: [u32], joints 4×u16 per vertex,
//!          weights 4×f32 per vertex, node_transform 16×f32]
//! notes: [string]
//! ```

use super::{ImportError, Imported, SkinnedMesh, MAX_COORDINATE, MAX_VERTICES};
use crate::curves::Track;
use crate::skeleton::{Contact, JointTracks, KeyInterpolation, QuatInterpolation, RawClip};
use crate::skeleton::{Skeleton, Transform};
use crate::transform::ScaleMode;
use glam::{Mat4, Quat, Vec3, Vec4};

/// The most bytes [`decode`] reads and [`encode`] writes.
pub const MAX_WIRE_BYTES: usize = 256 << 20;

const MAGIC: &[u8; 4] = b"IBGW";
const VERSION: u32 = 1;

/// The import's result as bytes ([`decode`] reads them back), or an error when they would pass
/// [`MAX_WIRE_BYTES`].
pub fn encode(imported: &Imported) -> Result<Vec<u8>, ImportError> {
    let mut w = Writer(Vec::new());
    w.0.extend_from_slice(MAGIC);
    w.u32(VERSION);
    let skeleton = &imported.skeleton;
    w.u8(match skeleton.scale_mode() {
        ScaleMode::Inherited => 0,
        ScaleMode::NotInherited => 1,
    });
    w.len(skeleton.len());
    for ((name, &parent), rest) in skeleton
        .names()
        .iter()
        .zip(skeleton.parents())
        .zip(skeleton.rest())
    {
        w.str(name);
        w.0.extend_from_slice(&parent.to_le_bytes());
        w.f32s(&rest.translation.to_array());
        w.f32s(&rest.rotation.to_array());
        w.f32s(&rest.scale.to_array());
    }
    w.len(imported.nodes.len());
    for &n in &imported.nodes {
        w.u32(u32::try_from(n).unwrap_or(u32::MAX));
    }
    w.f32s(&imported.root_transform.to_cols_array());
    w.len(imported.inverse_bind.len());
    for m in &imported.inverse_bind {
        w.f32s(&m.to_cols_array());
    }
    w.len(imported.clips.len());
    for clip in &imported.clips {
        w.str(clip.name());
        w.f32(clip.duration_sec());
        w.u8(clip.looping() as u8);
        w.u8(match clip.interpolation() {
            KeyInterpolation::Step => 0,
            KeyInterpolation::Linear => 1,
            KeyInterpolation::Cubic => 2,
        });
        w.u8(match clip.rotation_interpolation() {
            QuatInterpolation::Nlerp => 0,
            QuatInterpolation::Slerp => 1,
        });
        w.len(clip.joints().len());
        for tracks in clip.joints() {
            w.track(tracks.translation.as_ref(), |v: &Vec3| {
                v.to_array().to_vec()
            });
            w.track(tracks.rotation.as_ref(), |v: &Vec4| v.to_array().to_vec());
            w.track(tracks.scale.as_ref(), |v: &Vec3| v.to_array().to_vec());
        }
        w.len(clip.contacts().len());
        for contact in clip.contacts() {
            w.len(contact.joint());
            w.len(contact.intervals().len());
            for iv in contact.intervals() {
                w.f32s(iv);
            }
        }
    }
    w.len(imported.meshes.len());
    for mesh in &imported.meshes {
        w.len(mesh.positions.len());
        for p in &mesh.positions {
            w.f32s(&p.to_array());
        }
        for n in &mesh.normals {
            w.f32s(&n.to_array());
        }
        w.len(mesh.indices.len());
        for &i in &mesh.indices {
            w.u32(i);
        }
        for j in &mesh.joints {
            for &k in j {
                w.0.extend_from_slice(&k.to_le_bytes());
            }
        }
        for weights in &mesh.weights {
            w.f32s(weights);
        }
        w.f32s(&mesh.node_transform.to_cols_array());
    }
    w.len(imported.notes.len());
    for note in &imported.notes {
        w.str(note);
    }
    if w.0.len() > MAX_WIRE_BYTES {
        return Err(ImportError::Unsupported(format!(
            "the imported model takes {} bytes to hand to the figure; at most {MAX_WIRE_BYTES}",
            w.0.len()
        )));
    }
    Ok(w.0)
}

/// Reads what [`encode`] wrote, checking everything (see the module's documentation).
pub fn decode(bytes: &[u8]) -> Result<Imported, ImportError> {
    if bytes.len() > MAX_WIRE_BYTES {
        return Err(ImportError::Invalid(format!(
            "the imported model has {} bytes; the figure reads at most {MAX_WIRE_BYTES}",
            bytes.len()
        )));
    }
    let mut r = Reader { bytes, at: 0 };
    if r.take(4)? != MAGIC || r.u32()? != VERSION {
        return Err(bad("they do not start as the glTF module's output does"));
    }
    let scale_mode = match r.u8()? {
        0 => ScaleMode::Inherited,
        1 => ScaleMode::NotInherited,
        _ => return Err(bad("unknown scale mode")),
    };
    // A joint takes at least 4 + 4 + 40 bytes, so the count is checked against what is left.
    let joints = r.count(48)?;
    let (mut names, mut parents, mut rest) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..joints {
        names.push(r.str()?);
        parents.push(r.u32()? as i32);
        let [tx, ty, tz, qx, qy, qz, qw, sx, sy, sz] = r.f32_array::<10>()?;
        rest.push(Transform {
            translation: Vec3::new(tx, ty, tz),
            rotation: Quat::from_xyzw(qx, qy, qz, qw),
            scale: Vec3::new(sx, sy, sz),
        });
    }
    let skeleton = Skeleton::new(names, parents, rest)
        .and_then(|s| s.with_scale_mode(scale_mode))
        .map_err(|e| ImportError::Skeleton(e.to_string()))?;
    let node_count = r.count(4)?;
    let nodes = (0..node_count)
        .map(|_| r.u32().map(|n| n as usize))
        .collect::<Result<Vec<_>, _>>()?;
    if nodes.len() != joints {
        return Err(bad("the joints' node list has the wrong length"));
    }
    let root_transform = r.matrix("the root transform")?;
    let binds = r.count(64)?;
    if binds != joints {
        return Err(bad("one inverse bind matrix per joint is needed"));
    }
    let inverse_bind = (0..binds)
        .map(|_| r.matrix("an inverse bind matrix"))
        .collect::<Result<Vec<_>, _>>()?;

    let clip_count = r.count(16)?;
    let mut clips = Vec::with_capacity(clip_count);
    for _ in 0..clip_count {
        let name = r.str()?;
        let duration = r.f32()?;
        let looping = r.flag()?;
        let interpolation = match r.u8()? {
            0 => KeyInterpolation::Step,
            1 => KeyInterpolation::Linear,
            2 => KeyInterpolation::Cubic,
            _ => return Err(bad("unknown key interpolation")),
        };
        let rotation_interpolation = match r.u8()? {
            0 => QuatInterpolation::Nlerp,
            1 => QuatInterpolation::Slerp,
            _ => return Err(bad("unknown rotation interpolation")),
        };
        let tracks_count = r.count(3)?;
        let mut tracks = Vec::with_capacity(tracks_count);
        for _ in 0..tracks_count {
            tracks.push(JointTracks {
                translation: r.track(|v| Vec3::from_slice(v), 3)?,
                rotation: r.track(|v| Vec4::from_slice(v), 4)?,
                scale: r.track(|v| Vec3::from_slice(v), 3)?,
            });
        }
        let contact_count = r.count(8)?;
        let mut contacts = Vec::with_capacity(contact_count);
        for _ in 0..contact_count {
            let joint = r.u32()? as usize;
            let intervals = (0..r.count(8)?)
                .map(|_| r.f32_array::<2>())
                .collect::<Result<Vec<_>, _>>()?;
            contacts.push(Contact::new(joint, intervals).map_err(|e| clip_error(&name, e))?);
        }
        let mut clip = RawClip::new(name.clone(), duration, looping, tracks)
            .and_then(|c| c.with_contacts(contacts))
            .map_err(|e| clip_error(&name, e))?;
        clip.set_interpolation(interpolation);
        clip.set_rotation_interpolation(rotation_interpolation);
        clips.push(clip);
    }

    let mesh_count = r.count(72)?;
    let mut meshes = Vec::with_capacity(mesh_count);
    let mut vertices = 0usize;
    for _ in 0..mesh_count {
        // A vertex takes 3 + 3 + 4 floats and 4 joints: 48 bytes.
        let n = r.count(48)?;
        vertices += n;
        if vertices > MAX_VERTICES {
            return Err(ImportError::Unsupported(format!(
                "more than {MAX_VERTICES} skinned vertices"
            )));
        }
        let positions = r.vec3s(n)?;
        if positions
            .iter()
            .any(|p| !p.is_finite() || p.abs().max_element() > MAX_COORDINATE)
        {
            return Err(bad(
                "a position is not finite or lies beyond MAX_COORDINATE",
            ));
        }
        let normals = r.vec3s(n)?;
        if normals.iter().any(|v| !v.is_normalized()) {
            return Err(bad("a normal is not of unit length"));
        }
        let index_count = r.count(4)?;
        let indices = (0..index_count)
            .map(|_| r.u32())
            .collect::<Result<Vec<_>, _>>()?;
        if !indices.len().is_multiple_of(3) || indices.iter().any(|&i| i as usize >= n) {
            return Err(bad("the indices are not whole triangles of valid vertices"));
        }
        let joint_sets = (0..n)
            .map(|_| {
                let b = r.take(8)?;
                Ok(std::array::from_fn(|k| {
                    u16::from_le_bytes([b[2 * k], b[2 * k + 1]])
                }))
            })
            .collect::<Result<Vec<[u16; 4]>, ImportError>>()?;
        if joint_sets.iter().flatten().any(|&k| k as usize >= joints) {
            return Err(bad("a vertex names a joint the skeleton does not have"));
        }
        let weights = (0..n)
            .map(|_| r.f32_array::<4>())
            .collect::<Result<Vec<_>, _>>()?;
        if weights.iter().flatten().any(|w| !w.is_finite() || *w < 0.0) {
            return Err(bad("a weight is negative or not finite"));
        }
        let node_transform = r.matrix("a mesh's node transform")?;
        meshes.push(SkinnedMesh {
            positions,
            normals,
            indices,
            joints: joint_sets,
            weights,
            node_transform,
        });
    }
    let note_count = r.count(4)?;
    let notes = (0..note_count)
        .map(|_| r.str())
        .collect::<Result<Vec<_>, _>>()?;
    if r.at != bytes.len() {
        return Err(bad("bytes are left over after the model"));
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

fn bad(why: &str) -> ImportError {
    ImportError::Invalid(format!("the imported model's bytes are malformed: {why}"))
}

fn clip_error(name: &str, e: crate::skeleton::ClipError) -> ImportError {
    ImportError::Animation {
        name: name.to_string(),
        why: e.to_string(),
    }
}

struct Writer(Vec<u8>);

impl Writer {
    fn u8(&mut self, v: u8) {
        self.0.push(v);
    }

    fn u32(&mut self, v: u32) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }

    /// A count or an index; the importer's caps keep them far below `u32::MAX`.
    fn len(&mut self, n: usize) {
        self.u32(u32::try_from(n).unwrap_or(u32::MAX));
    }

    fn f32(&mut self, v: f32) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }

    fn f32s(&mut self, v: &[f32]) {
        for &x in v {
            self.f32(x);
        }
    }

    fn str(&mut self, s: &str) {
        self.len(s.len());
        self.0.extend_from_slice(s.as_bytes());
    }

    fn track<T: crate::curves::Value>(
        &mut self,
        track: Option<&Track<T>>,
        floats: impl Fn(&T) -> Vec<f32>,
    ) {
        let Some(track) = track else {
            self.u8(0);
            return;
        };
        self.u8(1);
        self.len(track.times().len());
        self.f32s(track.times());
        for v in track.values() {
            self.f32s(&floats(v));
        }
    }
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn take(&mut self, n: usize) -> Result<&[u8], ImportError> {
        let end = self
            .at
            .checked_add(n)
            .filter(|&end| end <= self.bytes.len())
            .ok_or_else(|| bad("they end too early"))?;
        let slice = &self.bytes[self.at..end];
        self.at = end;
        Ok(slice)
    }

    fn u8(&mut self) -> Result<u8, ImportError> {
        Ok(self.take(1)?[0])
    }

    fn flag(&mut self) -> Result<bool, ImportError> {
        match self.u8()? {
            0 => Ok(false),
            1 => Ok(true),
            _ => Err(bad("a flag is neither 0 nor 1")),
        }
    }

    fn u32(&mut self) -> Result<u32, ImportError> {
        let b = self.take(4)?;
        Ok(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    }

    fn f32(&mut self) -> Result<f32, ImportError> {
        self.u32().map(f32::from_bits)
    }

    fn f32_array<const N: usize>(&mut self) -> Result<[f32; N], ImportError> {
        let b = self.take(4 * N)?;
        Ok(std::array::from_fn(|k| {
            f32::from_le_bytes([b[4 * k], b[4 * k + 1], b[4 * k + 2], b[4 * k + 3]])
        }))
    }

    /// A count of items of at least `item_bytes` each: more than the bytes left could hold is
    /// an error before anything is allocated for them.
    fn count(&mut self, item_bytes: usize) -> Result<usize, ImportError> {
        let n = self.u32()? as usize;
        let left = self.bytes.len() - self.at;
        if n.saturating_mul(item_bytes) > left {
            return Err(bad("a count is larger than the bytes that follow"));
        }
        Ok(n)
    }

    fn str(&mut self) -> Result<String, ImportError> {
        let n = self.count(1)?;
        String::from_utf8(self.take(n)?.to_vec()).map_err(|_| bad("a name is not UTF-8"))
    }

    fn vec3s(&mut self, n: usize) -> Result<Vec<Vec3>, ImportError> {
        (0..n)
            .map(|_| self.f32_array::<3>().map(Vec3::from_array))
            .collect()
    }

    fn matrix(&mut self, what: &str) -> Result<Mat4, ImportError> {
        let m = Mat4::from_cols_array(&self.f32_array::<16>()?);
        if !m.is_finite() {
            return Err(bad(&format!("{what} is not finite")));
        }
        Ok(m)
    }

    fn track<T: crate::curves::Value>(
        &mut self,
        value: impl Fn(&[f32]) -> T,
        floats: usize,
    ) -> Result<Option<Track<T>>, ImportError> {
        if !self.flag()? {
            return Ok(None);
        }
        let n = self.count(4 + 4 * floats)?;
        let times = (0..n).map(|_| self.f32()).collect::<Result<Vec<_>, _>>()?;
        let mut values = Vec::with_capacity(n);
        for _ in 0..n {
            let b = self.take(4 * floats)?;
            let v: Vec<f32> = b
                .chunks_exact(4)
                .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                .collect();
            values.push(value(&v));
        }
        Track::new(times, values)
            .map(Some)
            .map_err(|e| bad(&format!("a track's keys: {e}")))
    }
}
