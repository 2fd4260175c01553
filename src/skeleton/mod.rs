//! # Skeletons: joint hierarchies, poses, clips and blending
//!
//! A **skeleton** is a list of joints stored in one flat array, every parent before its children
//! (the root's parent is `-1`), with a name, a rest (bind) transform and an inverse bind matrix per
//! joint. A **pose** gives each joint a local transform (translation, rotation, scale) relative to
//! its parent; one forward loop turns it into model-space matrices:
//! ```text
//! model[i] = local[i]                     if parents[i] = −1
//! model[i] = model[parents[i]] · local[i]  otherwise,      local = T · R · S
//! ```
//! A **clip** stores keys for each joint's translation, rotation and scale and fills a caller's
//! pose at any time; **blending** mixes poses (crossfade, N-way weights, additive layers, masks).
//!
//! | topic | items |
//! |---|---|
//! | hierarchy, validation, group sizes, inverse bind | [`Skeleton`], [`SkeletonError`], [`MAX_JOINTS`] |
//! | local transforms, TRS → affine, local-to-model | [`Transform`], [`trs_to_affine`], [`Pose`], [`local_to_model`] |
//! | clips: editable and runtime forms, sampling | [`RawClip`], [`JointTracks`], [`Clip`], [`ClipCursor`], [`KeyInterpolation`], [`QuatInterpolation`], [`sample_rotation_channel`] |
//! | blending | [`crossfade`], [`blend_weighted`], [`make_additive`], [`add_additive`], [`crossfade_masked`], [`subtree_mask`] |
//! | locomotion: normalised time, root motion, foot contacts | [`sample_synchronised`], [`RootMotion`], [`weight_for_speed`], [`Contact`], [`synchronised_contacts`], [`blend_contacts`] |
//! | a character that needs no asset | [`human`]: a procedural simple human and its clips |
//!
//! Conventions: see the crate root (Y up, column vectors, glam quaternions `(x, y, z, w)`,
//! seconds, metres). Nothing here allocates while sampling or blending: outputs go into the
//! caller's buffers. Lesson: `lessons/06-skeletons`.

mod blend;
mod clip;
mod hierarchy;
pub mod human;
mod locomotion;

pub use crate::transform::ScaleMode;
pub use blend::{
    add_additive, blend_weighted, crossfade, crossfade_masked, crossfade_transform, make_additive,
    subtree_mask, BlendError,
};
pub use clip::{
    sample_rotation_channel, Clip, ClipCursor, ClipError, Contact, JointTracks, KeyInterpolation,
    QuatInterpolation, RawClip, MAX_CLIP_KEYS,
};
pub use hierarchy::{
    local_to_model, trs_to_affine, Pose, Skeleton, SkeletonError, Transform, MAX_JOINTS,
};
pub use locomotion::{
    blend_contacts, sample_synchronised, synchronised_contacts, synchronised_cycle,
    weight_for_speed, RootMotion,
};
