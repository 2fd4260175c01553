//! The native tests, one binary: each file `tests/NAME.rs` is the module `NAME` here, and
//! `tests/label_clearance/` the module `label_clearance`. One binary instead of one a file: the
//! crate is linked once and its tests share one harness, which runs them two at a time across all
//! files (2026-12-07, two cores: 115 s of CPU to compile, against 163 s as 55 binaries).
//!
//! One file's tests: `cargo test --test native figures_boids::`; one test:
//! `cargo test --test native figures_boids::NAME`. A new file under `tests/` is added here (or,
//! for a test that also runs under wasm, as a `[[test]]` in Cargo.toml): `autotests` is off, so a
//! file that is neither would never be compiled, and `every_test_file_is_built` below fails.
#![cfg(not(target_arch = "wasm32"))]

#[path = "blend_shapes.rs"]
mod blend_shapes;
#[path = "boids.rs"]
mod boids;
#[path = "cloth.rs"]
mod cloth;
#[path = "curves.rs"]
mod curves;
#[path = "draw_framing.rs"]
mod draw_framing;
#[path = "draw_layout.rs"]
mod draw_layout;
#[path = "draw_lines.rs"]
mod draw_lines;
#[path = "expressive.rs"]
mod expressive;
#[path = "figures_blend_shapes.rs"]
mod figures_blend_shapes;
#[path = "figures_blending.rs"]
mod figures_blending;
#[path = "figures_boids.rs"]
mod figures_boids;
#[path = "figures_cloth.rs"]
mod figures_cloth;
#[path = "figures_curves.rs"]
mod figures_curves;
#[path = "figures_expressive.rs"]
mod figures_expressive;
#[path = "figures_fluid.rs"]
mod figures_fluid;
#[path = "figures_gltf.rs"]
mod figures_gltf;
#[path = "figures_gpu.rs"]
mod figures_gpu;
#[path = "figures_ik.rs"]
mod figures_ik;
#[path = "figures_noise.rs"]
mod figures_noise;
#[path = "figures_noise_images.rs"]
mod figures_noise_images;
#[path = "figures_particles.rs"]
mod figures_particles;
#[path = "figures_particles_sprites.rs"]
mod figures_particles_sprites;
#[path = "figures_raster.rs"]
mod figures_raster;
#[path = "figures_rigid.rs"]
mod figures_rigid;
#[path = "figures_rigid_body.rs"]
mod figures_rigid_body;
#[path = "figures_rotations.rs"]
mod figures_rotations;
#[path = "figures_skeleton.rs"]
mod figures_skeleton;
#[path = "figures_skinning.rs"]
mod figures_skinning;
#[path = "figures_transforms.rs"]
mod figures_transforms;
#[path = "fluid.rs"]
mod fluid;
#[path = "gltf_import.rs"]
mod gltf_import;
#[path = "gltf_wire.rs"]
mod gltf_wire;
#[path = "hostile_figures.rs"]
mod hostile_figures;
#[path = "ik.rs"]
mod ik;
#[path = "internals/main.rs"]
mod internals;
#[path = "label_clearance/main.rs"]
mod label_clearance;
#[path = "lesson_text.rs"]
mod lesson_text;
#[path = "locomotion.rs"]
mod locomotion;
#[path = "noise.rs"]
mod noise;
#[path = "noise_simplex.rs"]
mod noise_simplex;
#[path = "particles.rs"]
mod particles;
#[path = "particles_sprites.rs"]
mod particles_sprites;
#[path = "quizzes.rs"]
mod quizzes;
#[path = "raster.rs"]
mod raster;
#[path = "rigid.rs"]
mod rigid;
#[path = "rigid_body.rs"]
mod rigid_body;
#[path = "rigid_body_contacts.rs"]
mod rigid_body_contacts;
#[path = "rotation.rs"]
mod rotation;
#[path = "skeleton.rs"]
mod skeleton;
#[path = "skinning.rs"]
mod skinning;

/// The camera a lesson's page sets on a viewer: the six numbers of `VIEWER.setCamera(...)` in the
/// page's script `js` (`include_str!` of its lesson.js), so that a framing test checks the view
/// the page really shows.
pub fn page_camera(js: &str, viewer: &str) -> [f32; 6] {
    js.split(&format!("{viewer}.setCamera("))
        .nth(1)
        .and_then(|s| s.split(')').next())
        .unwrap_or_else(|| panic!("the page sets no camera on {viewer}"))
        .split(',')
        .map(|x| x.trim().parse().unwrap())
        .collect::<Vec<f32>>()
        .try_into()
        .unwrap()
}

/// Every file under `tests/` that is a test (a `NAME.rs` there, or a folder's `main.rs`) is built:
/// a module of this binary or a `[[test]]` target of Cargo.toml.
#[test]
fn every_test_file_is_built() {
    let here = include_str!("native.rs");
    let manifest = include_str!("../Cargo.toml");
    let tests = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let mut missing = Vec::new();
    for entry in std::fs::read_dir(&tests).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_str().unwrap().to_owned();
        let file = if path.is_dir() {
            if !path.join("main.rs").exists() {
                continue;
            }
            format!("{name}/main.rs")
        } else if name.ends_with(".rs") && name != "native.rs" {
            name
        } else {
            continue;
        };
        let as_module = format!("#[path = \"{file}\"]");
        let as_target = format!("path = \"tests/{file}\"");
        if !here.contains(&as_module) && !manifest.contains(&as_target) {
            missing.push(file);
        }
    }
    assert!(
        missing.is_empty(),
        "never compiled: {missing:?} (add to tests/native.rs or Cargo.toml)"
    );
}

/// The crate has no test target of its own (`test = false` in Cargo.toml: it would compile the
/// whole crate again for a few tests), so a `#[cfg(test)]` module under `src/` would never run:
/// there is none. A check that must read private state is a `white_box` function built with
/// debug assertions (as `fluid::white_box`), called from a test here.
#[test]
fn no_test_module_hides_in_src() {
    fn walk(dir: &std::path::Path, found: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, found);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                if text.contains("#[cfg(test)]") || text.contains("#[test]") {
                    found.push(path.display().to_string());
                }
            }
        }
    }
    let mut found = Vec::new();
    walk(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), &mut found);
    assert!(found.is_empty(), "tests under src/ never run: {found:?} (move them to tests/)");
}
