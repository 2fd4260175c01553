//! The glTF importer (src/gltf_import.rs): the Khronos sample characters against three.js's joint
//! world matrices and skinned vertex positions (skinned here by src/skinning) (tests/data/gltf_three.json, made by scripts/reference/gltf_three.mjs), bad
//! files, and a fuzz property (no input makes it panic).
//!
//! The sample files are not committed (../shared/assets/gltf, or $INBETWEEN_GLTF_ASSETS).
//! `scripts/test` sets INBETWEEN_REQUIRE_ASSETS=1 when they are present, so a missing file
//! fails there instead of being passed over.
// Native only: proptest and the file system are not available in the browser build.
#![cfg(not(target_arch = "wasm32"))]

use glam::{Affine3A, Mat4};
use inbetween::fixtures::tiny_skinned_gltf as tiny;
use inbetween::gltf_import::{import, ImportError};
use inbetween::skeleton::{Clip, ClipCursor};
use inbetween::skinning::{skin_lbs, skinning_palette, SkinWeights};
use proptest::prelude::*;
use std::path::PathBuf;

fn assets() -> Option<PathBuf> {
    let dir = std::env::var_os("INBETWEEN_GLTF_ASSETS")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/assets/gltf"));
    if dir.join("RiggedSimple.gltf").exists() {
        Some(dir)
    } else {
        assert!(
            std::env::var_os("INBETWEEN_REQUIRE_ASSETS").is_none(),
            "the glTF sample characters are not in {}",
            dir.display()
        );
        eprintln!(
            "glTF sample characters not found in {}: sample checks not run",
            dir.display()
        );
        None
    }
}

fn sample(name: &str) -> Option<Vec<u8>> {
    assets().map(|dir| std::fs::read(dir.join(format!("{name}.gltf"))).expect("readable"))
}

fn model_matrices(
    imported: &inbetween::gltf_import::Imported,
    pose: &inbetween::skeleton::Pose,
) -> Vec<Mat4> {
    let mut model = vec![Affine3A::IDENTITY; imported.skeleton.len()];
    imported.skeleton.model_matrices(pose, &mut model).unwrap();
    model
        .iter()
        .map(|m| imported.root_transform * Mat4::from(*m))
        .collect()
}

/// The largest coordinate of the reference's skinned vertices (the tolerance's scale).
fn reference_size(r: &serde_json::Value) -> f32 {
    r["skinned"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|t| t.as_array().unwrap())
        .flat_map(|v| v.as_array().unwrap())
        .map(|x| x.as_f64().unwrap().abs() as f32)
        .fold(1.0, f32::max)
}

fn assert_matrices_close(ours: Mat4, theirs: &[f64], what: &str) {
    let theirs: Vec<f32> = theirs.iter().map(|&x| x as f32).collect();
    let theirs = Mat4::from_cols_slice(&theirs);
    let scale = theirs
        .to_cols_array()
        .iter()
        .fold(1.0f32, |m, x| m.max(x.abs()));
    let error = (ours - theirs)
        .to_cols_array()
        .iter()
        .fold(0.0f32, |m, x| m.max(x.abs()));
    assert!(
        error <= 2e-4 * scale,
        "{what}: off by {error}\nours   {ours}\nthree  {theirs}"
    );
}

#[test]
fn sample_characters_match_threejs_joints_and_skinned_vertices() {
    let reference: serde_json::Value =
        serde_json::from_str(include_str!("data/gltf_three.json")).unwrap();
    assert!(reference["tool"]
        .as_str()
        .unwrap()
        .starts_with("three.js r170"));
    for name in ["RiggedSimple", "RiggedFigure", "CesiumMan"] {
        let Some(bytes) = sample(name) else { return };
        let imported = import(&bytes).unwrap_or_else(|e| panic!("{name}: {e}"));
        let r = &reference["models"][name];
        let nodes: Vec<usize> = r["nodes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|n| n.as_u64().unwrap() as usize)
            .collect();
        assert_eq!(imported.skeleton.len(), nodes.len(), "{name}: joint count");
        let ours_of = |node: usize| imported.nodes.iter().position(|&n| n == node).unwrap();
        let matrix = |v: &serde_json::Value| -> Vec<f64> {
            v.as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        };
        // The rest pose (the nodes' own transforms).
        let rest = model_matrices(&imported, &imported.skeleton.rest_pose());
        for (k, &node) in nodes.iter().enumerate() {
            assert_matrices_close(
                rest[ours_of(node)],
                &matrix(&r["rest"][k]),
                &format!("{name} rest, node {node}"),
            );
        }
        // The first animation at the reference's times.
        // Both forms of the clip: the editable one and the runtime one.
        let raw = &imported.clips[0];
        let clip = Clip::from_raw(raw, &imported.skeleton).unwrap();
        let mut cursor = ClipCursor::new();
        let mut cursors = raw.cursors();
        let mut pose = imported.skeleton.rest_pose();
        let mut raw_pose = imported.skeleton.rest_pose();
        for (i, t) in r["times"].as_array().unwrap().iter().enumerate() {
            let t = t.as_f64().unwrap() as f32;
            clip.sample(t, &mut cursor, &mut pose);
            raw.sample(t, imported.skeleton.rest(), &mut cursors, &mut raw_pose);
            for (a, b) in model_matrices(&imported, &pose)
                .iter()
                .zip(model_matrices(&imported, &raw_pose))
            {
                assert!(
                    a.abs_diff_eq(b, 1e-4),
                    "{name}: runtime and editable clips agree at t = {t}"
                );
            }
            let world = model_matrices(&imported, &pose);
            for (k, &node) in nodes.iter().enumerate() {
                assert_matrices_close(
                    world[ours_of(node)],
                    &matrix(&r["world"][i][k]),
                    &format!("{name} at t = {t}, node {node}"),
                );
            }
            // Skinned by the skinning core (lesson 09) with the file's inverse bind matrices:
            // K_j = (root · M_j) · B_j⁻¹, positions by linear blend skinning.
            let model: Vec<Affine3A> = world.iter().map(|m| Affine3A::from_mat4(*m)).collect();
            let inverse_bind: Vec<Affine3A> = imported
                .inverse_bind
                .iter()
                .map(|m| Affine3A::from_mat4(*m))
                .collect();
            let mut palette = vec![Affine3A::IDENTITY; model.len()];
            skinning_palette(&model, &inverse_bind, &mut palette).unwrap();
            let mesh = &imported.meshes[0];
            let skin =
                SkinWeights::new(mesh.joints.clone(), mesh.weights.clone(), model.len()).unwrap();
            let n = mesh.positions.len();
            let (mut p, mut nrm) = (vec![glam::Vec3::ZERO; n], vec![glam::Vec3::ZERO; n]);
            skin_lbs(
                &palette,
                &skin,
                &mesh.positions,
                &mesh.normals,
                &mut p,
                &mut nrm,
            )
            .unwrap();
            let size = reference_size(r);
            for (k, v) in r["vertices"].as_array().unwrap().iter().enumerate() {
                let v = v.as_u64().unwrap() as usize;
                let theirs = glam::Vec3::from_slice(
                    &matrix(&r["skinned"][i][k])
                        .iter()
                        .map(|&x| x as f32)
                        .collect::<Vec<_>>(),
                );
                let error = (p[v] - theirs).length();
                assert!(
                    error <= 2e-4 * size,
                    "{name} at t = {t}, vertex {v}: ours {}, three.js {theirs} (off by {error})",
                    p[v]
                );
            }
        }
        // The skinned meshes: joints in range, weights finite.
        assert!(!imported.meshes.is_empty(), "{name}: a skinned mesh");
        for m in &imported.meshes {
            assert!(m
                .joints
                .iter()
                .flatten()
                .all(|&j| (j as usize) < imported.skeleton.len()));
            let (lo, hi) = m.weight_sum_range();
            assert!(lo > 0.0 && hi < 1.01, "{name}: weight sums {lo}..{hi}");
        }
    }
}

#[test]
fn a_small_file_imports_parents_first_with_its_clip_and_mesh() {
    let imported = import(tiny().as_bytes()).unwrap();
    // The skin lists the knee before the hip; the skeleton puts the parent first.
    assert_eq!(imported.skeleton.names(), ["hip (node 1)", "knee (node 2)"]);
    assert_eq!(imported.skeleton.parents(), [-1, 0]);
    assert_eq!(imported.nodes, [1, 2]);
    // Inverse binds and mesh joints follow the reordering.
    assert!(imported.inverse_bind[1].abs_diff_eq(Mat4::IDENTITY, 1e-6));
    assert_eq!(imported.meshes[0].joints[0], [1, 0, 1, 1]);
    assert_eq!(imported.clips[0].name(), "bend");
    assert_eq!(imported.clips[0].duration_sec(), 1.0);
    assert_eq!(imported.meshes[0].weight_sum_range(), (1.0, 1.0));
}

/// Replaces `from` by `to` in the tiny file (which must contain it) and imports it.
fn tiny_with(from: &str, to: &str) -> Result<inbetween::gltf_import::Imported, ImportError> {
    let text = tiny();
    assert!(text.contains(from), "{from}");
    import(text.replacen(from, to, 1).as_bytes())
}

#[test]
fn bad_files_get_clear_errors() {
    let msg = |r: Result<_, ImportError>| r.map(|_| ()).unwrap_err().to_string();
    assert!(msg(import(b"")).contains("not a valid glTF"));
    // Text that is neither a .glb nor JSON is named as such, not by the JSON parser's position.
    for junk in [&b"hello world, not a glb"[..], b"", b"  \n", b"GLTF{}"] {
        let e = msg(import(junk));
        assert!(e.contains("neither the binary header \"glTF\" (.glb) nor a JSON object"), "{e}");
        assert!(!e.contains("line 1"), "{e}");
    }
    assert!(msg(import(b"{\"asset\":{\"version\":\"2.0\"}}")).contains("no skin"));
    assert!(msg(import(&tiny().as_bytes()[..400])).contains("not a valid glTF"));
    // A buffer that says it is longer than its data.
    assert!(msg(tiny_with("\"byteLength\":264", "\"byteLength\":999")).contains("buffer 0"));
    // An accessor reaching past its view.
    let e = msg(tiny_with(
        "\"count\":3,\"type\":\"VEC4\"}",
        "\"count\":30,\"type\":\"VEC4\"}",
    ));
    assert!(e.contains("accessor") || e.contains("not a valid"), "{e}");
    // A separate .bin file.
    let e = msg(tiny_with(
        "\"uri\":\"data:",
        "\"uri\":\"model.bin\",\"x\":\"data:",
    ));
    assert!(e.contains("separate file"), "{e}");
    // A joint listed twice.
    assert!(msg(tiny_with("\"joints\":[2,1]", "\"joints\":[2,2]")).contains("twice"));
    // A node hierarchy that loops.
    let e = msg(tiny_with(
        "{\"name\":\"knee\",",
        "{\"name\":\"knee\",\"children\":[1],",
    ));
    assert!(e.contains("cycle") || e.contains("not a valid"), "{e}");
    // A joint index outside the skin.
    let e = msg(tiny_with(
        "\"inverseBindMatrices\":3",
        "\"inverseBindMatrices\":0",
    ));
    assert!(
        e.contains("inverse bind") || e.contains("not a valid"),
        "{e}"
    );
}

static SIMPLE: std::sync::LazyLock<Option<Vec<u8>>> =
    std::sync::LazyLock::new(|| sample("RiggedSimple"));

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, .. ProptestConfig::default() })]

    /// Fuzzing: bytes changed, cut or repeated anywhere never make the importer panic (it
    /// returns an import or an error).
    #[test]
    fn no_input_makes_the_importer_panic(
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..6),
        cut in any::<prop::sample::Index>(),
        base in 0u8..2,
    ) {
        // Our tiny file, or a real one (more accessors, a longer animation) when present.
        let mut bytes = match base {
            1 => SIMPLE.clone().unwrap_or_else(|| tiny().into_bytes()),
            _ => tiny().into_bytes(),
        };
        for (at, byte, kind) in edits {
            let i = at.index(bytes.len());
            match kind {
                0 => bytes[i] = byte,
                1 => bytes[i] = b"0123456789-.e,[]{}\""[byte as usize % 19],
                _ => { let b = bytes[i]; bytes.insert(i, b); }
            }
        }
        if cut.index(8) == 0 {
            bytes.truncate(cut.index(bytes.len()));
        }
        let _ = import(&bytes);
    }
}

/// The tiny file with `n` chained non-joint nodes under the hip's sibling list and `n` joint
/// leaves, one under each chain node (no inverse binds: identity).
fn deep_chain(n: usize) -> String {
    let first = 3; // the tiny file's nodes are 0, 1, 2
    let mut nodes = String::new();
    for k in 0..n {
        let chain = first + 2 * k;
        let next = if k + 1 < n {
            format!("{},", chain + 2)
        } else {
            String::new()
        };
        nodes.push_str(&format!(
            ",{{\"children\":[{next}{}]}},{{\"name\":\"leaf{k}\"}}",
            chain + 1
        ));
    }
    let leaves: String = (0..n).map(|k| format!(",{}", first + 2 * k + 1)).collect();
    tiny()
        .replacen(
            "{\"name\":\"knee\",\"translation\":[0,1,0]}]",
            &format!("{{\"name\":\"knee\",\"translation\":[0,1,0]}}{nodes}]"),
            1,
        )
        .replacen("\"nodes\":[0,1]", &format!("\"nodes\":[0,1,{first}]"), 1)
        .replacen(
            "\"joints\":[2,1],\"inverseBindMatrices\":3",
            &format!("\"joints\":[2,1{leaves}]"),
            1,
        )
}

#[test]
fn a_deep_chain_of_non_joint_nodes_imports_in_linear_time() {
    // 60,000 chain nodes, each with a joint leaf: walking up the chain from every leaf is
    // 1.8·10⁹ steps; one top-down pass is 120,000.
    let n = 60_000;
    let text = deep_chain(n);
    let start = std::time::Instant::now();
    let imported = import(text.as_bytes()).unwrap();
    let seconds = start.elapsed().as_secs_f32();
    assert_eq!(imported.skeleton.len(), n + 2);
    assert!(seconds < 8.0, "{seconds} s for {n} chained nodes");
    // Each leaf is a root (no joint above it), under the identity chain.
    assert_eq!(
        imported
            .skeleton
            .parents()
            .iter()
            .filter(|&&p| p < 0)
            .count(),
        n + 1
    );
}

#[test]
fn a_node_with_two_parents_or_its_own_child_is_rejected() {
    let msg = |r: Result<_, ImportError>| r.map(|_| ()).unwrap_err().to_string();
    // The knee (node 2) under the hip and under the mesh node too.
    let e = msg(tiny_with(
        "{\"mesh\":0,\"skin\":0}",
        "{\"mesh\":0,\"skin\":0,\"children\":[2]}",
    ));
    assert!(
        e.contains("node 2 has two parents") && e.contains("at most one parent"),
        "{e}"
    );
    let e = msg(tiny_with(
        "{\"name\":\"hip\",\"children\":[2]}",
        "{\"name\":\"hip\",\"children\":[2,1]}",
    ));
    assert!(
        e.contains("lists itself as a child") || e.contains("not a valid"),
        "{e}"
    );
}

#[test]
fn a_model_too_large_to_frame_is_rejected() {
    let msg = |r: Result<_, ImportError>| r.map(|_| ()).unwrap_err().to_string();
    let e = msg(tiny_with(
        "{\"name\":\"knee\",\"translation\":[0,1,0]}",
        "{\"name\":\"knee\",\"translation\":[0,3e38,0]}",
    ));
    assert!(
        e.contains("node 2's transform reaches past ±1000000"),
        "{e}"
    );
    let e = msg(tiny_with(
        "{\"name\":\"hip\",",
        "{\"name\":\"hip\",\"scale\":[3e38,3e38,3e38],",
    ));
    assert!(e.contains("transform reaches past"), "{e}");
}
