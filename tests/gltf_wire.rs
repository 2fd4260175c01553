//! The import's result as bytes (src/gltf_import/wire.rs), the hand-over from the glTF module to
//! the figures module: everything survives the round trip, and no bytes make the decoder panic
//! or pass a model the importer itself would reject.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec3;
use inbetween::fixtures::tiny_skinned_gltf as tiny;
use inbetween::gltf_import::wire::{decode, encode};
use inbetween::gltf_import::{import, Imported};
use proptest::prelude::*;
use std::path::PathBuf;

/// The Khronos sample characters when present (see tests/gltf_import.rs), and the tiny file.
fn models() -> Vec<(String, Imported)> {
    let mut out = vec![("tiny".to_string(), import(tiny().as_bytes()).unwrap())];
    let dir = std::env::var_os("INBETWEEN_GLTF_ASSETS")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/assets/gltf"));
    let present = dir.join("RiggedSimple.gltf").exists();
    assert!(
        present || std::env::var_os("INBETWEEN_REQUIRE_ASSETS").is_none(),
        "the glTF sample characters are not in {}",
        dir.display()
    );
    if present {
        for name in ["RiggedSimple", "RiggedFigure", "CesiumMan"] {
            let bytes = std::fs::read(dir.join(format!("{name}.gltf"))).unwrap();
            out.push((name.to_string(), import(&bytes).unwrap()));
        }
    }
    out
}

#[test]
fn every_part_of_an_import_survives_the_round_trip() {
    for (name, a) in models() {
        let b = decode(&encode(&a).unwrap()).unwrap_or_else(|e| panic!("{name}: {e}"));
        let s = (&a.skeleton, &b.skeleton);
        assert_eq!(s.0.names(), s.1.names(), "{name}");
        assert_eq!(s.0.parents(), s.1.parents(), "{name}");
        assert_eq!(s.0.rest(), s.1.rest(), "{name}");
        assert_eq!(s.0.scale_mode(), s.1.scale_mode(), "{name}");
        assert_eq!(a.nodes, b.nodes, "{name}");
        assert_eq!(a.root_transform, b.root_transform, "{name}");
        assert_eq!(a.inverse_bind, b.inverse_bind, "{name}");
        assert_eq!(a.meshes, b.meshes, "{name}");
        assert_eq!(a.notes, b.notes, "{name}");
        assert_eq!(a.clips.len(), b.clips.len(), "{name}");
        for (x, y) in a.clips.iter().zip(&b.clips) {
            assert_eq!(x.name(), y.name());
            assert_eq!(x.duration_sec(), y.duration_sec());
            assert_eq!(x.looping(), y.looping());
            assert_eq!(x.interpolation(), y.interpolation());
            assert_eq!(x.rotation_interpolation(), y.rotation_interpolation());
            assert_eq!(x.contacts(), y.contacts());
            assert_eq!(x.joints().len(), y.joints().len());
            for (p, q) in x.joints().iter().zip(y.joints()) {
                assert_eq!(p.translation, q.translation, "{name}");
                assert_eq!(p.scale, q.scale, "{name}");
                // Rotations are normalised again on the way in: equal to a float's rounding.
                match (&p.rotation, &q.rotation) {
                    (Some(r), Some(s)) => {
                        assert_eq!(r.times(), s.times());
                        for (u, v) in r.values().iter().zip(s.values()) {
                            assert!(u.abs_diff_eq(*v, 1e-6), "{name}: {u} vs {v}");
                        }
                    }
                    (None, None) => {}
                    _ => panic!("{name}: a rotation track was lost"),
                }
            }
        }
    }
}

#[test]
fn bytes_cut_short_or_with_a_changed_count_are_rejected_with_a_message() {
    let bytes = encode(&import(tiny().as_bytes()).unwrap()).unwrap();
    for end in 0..bytes.len() {
        let e = decode(&bytes[..end]).map(|_| ()).unwrap_err().to_string();
        assert!(
            e.contains("malformed") || e.contains("not valid"),
            "{end}: {e}"
        );
    }
    let mut longer = bytes.clone();
    longer.push(0);
    assert!(decode(&longer)
        .map(|_| ())
        .unwrap_err()
        .to_string()
        .contains("left over"));
    // The joint count (after the magic, the version and the scale mode) made huge: rejected
    // before anything is allocated for it.
    let mut huge = bytes.clone();
    huge[9..13].copy_from_slice(&u32::MAX.to_le_bytes());
    assert!(decode(&huge)
        .map(|_| ())
        .unwrap_err()
        .to_string()
        .contains("larger than the bytes"));
}

#[test]
fn a_model_the_importer_would_reject_is_rejected_when_decoded() {
    let model = import(tiny().as_bytes()).unwrap();
    let fails = |change: &dyn Fn(&mut Imported), expect: &str| {
        let mut m = model.clone();
        change(&mut m);
        let e = decode(&encode(&m).unwrap())
            .map(|_| ())
            .unwrap_err()
            .to_string();
        assert!(e.contains(expect), "{expect}: {e}");
    };
    fails(&|m| m.meshes[0].positions[0] = Vec3::NAN, "position");
    fails(&|m| m.meshes[0].positions[0] = Vec3::splat(1e7), "position");
    fails(&|m| m.meshes[0].indices[0] = 99, "indices");
    fails(
        &|m| m.meshes[0].indices.pop().map(|_| ()).unwrap(),
        "indices",
    );
    fails(&|m| m.meshes[0].joints[0][2] = 7, "joint");
    fails(&|m| m.meshes[0].weights[0][1] = -1.0, "weight");
    fails(&|m| m.meshes[0].normals[0] = Vec3::ZERO, "normal");
    fails(
        &|m| m.inverse_bind.pop().map(|_| ()).unwrap(),
        "inverse bind",
    );
    fails(&|m| m.nodes.pop().map(|_| ()).unwrap(), "node list");
    fails(
        &|m| m.root_transform.x_axis.x = f32::INFINITY,
        "root transform",
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, .. ProptestConfig::default() })]

    /// Fuzzing: bytes changed anywhere never make the decoder panic, and what it accepts is a
    /// model whose vertices name joints that exist.
    #[test]
    fn no_bytes_make_the_decoder_panic(
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..8),
    ) {
        let mut bytes = encode(&import(tiny().as_bytes()).unwrap()).unwrap();
        for (at, byte) in edits {
            let i = at.index(bytes.len());
            bytes[i] = byte;
        }
        if let Ok(m) = decode(&bytes) {
            let joints = m.skeleton.len();
            prop_assert!(m.meshes.iter().flat_map(|x| x.joints.iter().flatten()).all(|&k| (k as usize) < joints));
        }
    }
}

/// The figure shows a file handed over as bytes exactly as one it imported itself: the same
/// summary and the same drawing at several moments, and bad bytes leave the note's "could not
/// load" with what is still shown.
#[test]
fn the_figure_draws_a_handed_over_import_as_its_own() {
    use inbetween::draw::Frame;
    use inbetween::figures::gltf::GltfFigure;
    let file = tiny();
    let (mut own, mut handed) = (GltfFigure::new(), GltfFigure::new());
    let a = own.load("tiny.gltf", file.as_bytes()).unwrap();
    let bytes = encode(&import(file.as_bytes()).unwrap()).unwrap();
    let b = handed.load_imported("tiny.gltf", &bytes).unwrap();
    assert_eq!(a, b);
    for t in [0.0, 0.3, 0.9] {
        let (mut f, mut g) = (Frame::default(), Frame::default());
        let notes = (
            own.draw(&mut f, t, &[]).unwrap(),
            handed.draw(&mut g, t, &[]).unwrap(),
        );
        assert_eq!(notes.0, notes.1);
        assert_eq!(
            format!("{:?}", f.meshes),
            format!("{:?}", g.meshes),
            "at {t} s"
        );
    }
    let e = handed
        .load_imported("cut.gltf", &bytes[..bytes.len() / 2])
        .unwrap_err();
    assert!(
        e.starts_with("cut.gltf: ") && e.contains("malformed"),
        "{e}"
    );
    let mut f = Frame::default();
    let note = handed.draw(&mut f, 0.0, &[]).unwrap();
    assert!(
        note.contains("Could not load cut.gltf") && note.contains("still shows tiny.gltf"),
        "{note}"
    );
}
