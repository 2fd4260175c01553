//! Browser-only test of GPU skinning (the vertex-shader path, `src/render/skin.rs`): the built-in
//! human skinned on the CPU and skinned in the vertex shader must render the same image, by LBS
//! and by DQS. `scripts/test` runs it on WebGL2 and on WebGPU (the two webdriver flag sets).
//!
//! Why images: on WebGL2 nothing the vertex shader computes can be read back (no storage
//! buffers, no transform feedback in wgpu), so the rendered pixels are what both backends can
//! compare. On WebGPU the second test also runs the shader's formulas (`skin_common.wgsl`, shared
//! with the vertex shader) in a compute shader on the same uniform palette and compares the
//! skinned positions and normals with the CPU's number by number. Natively, `tests/figures_gpu.rs`
//! checks the packing with the formulas written in Rust (`lbs_like_shader` / `dqs_like_shader`).
#![cfg(target_arch = "wasm32")]

use glam::Vec3;
use inbetween::camera::OrbitCamera;
use inbetween::figures::skinning::HumanFigure;
use inbetween::mesh::MeshData;
use inbetween::render::{BackendChoice, Gpu, Renderer};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;

const W: u32 = 160;
const H: u32 = 160;

async fn gpu() -> Gpu {
    let document = web_sys::window().unwrap().document().unwrap();
    let canvas: web_sys::HtmlCanvasElement = document
        .create_element("canvas")
        .unwrap()
        .dyn_into()
        .unwrap();
    canvas.set_width(W);
    canvas.set_height(H);
    document.body().unwrap().append_child(&canvas).unwrap();
    let gpu = Gpu::new(canvas, BackendChoice::Auto)
        .await
        .expect("an adapter (WebGPU or WebGL2)");
    if let Some(expected) = crate::EXPECTED_BACKEND {
        assert_eq!(gpu.backend_name, expected, "adapter: {}", gpu.adapter_name);
    }
    gpu
}

fn camera() -> OrbitCamera {
    let mut c = OrbitCamera {
        target: Vec3::new(0.0, 0.9, 0.0),
        distance: 2.4,
        ..Default::default()
    };
    c.orbit(0.5, 0.15);
    c
}

/// The human at `time_sec`, skinned on the CPU (`gpu = false`) or in the vertex shader.
async fn render(
    gpu: &Gpu,
    renderer: &mut Renderer,
    method: &str,
    on_gpu: bool,
    time_sec: f32,
) -> Vec<u8> {
    let mut figure = HumanFigure::new();
    figure.set_method(method).unwrap();
    figure.set_heat_joint("none").unwrap();
    figure.set_gpu(on_gpu);
    figure.skin(time_sec).unwrap();
    let c = figure.character();
    if on_gpu {
        let id = renderer
            .skin
            .create(gpu, &c.mesh, Some(&figure.mesh.colors), &c.skin)
            .unwrap();
        figure.draw_gpu(&mut renderer.frame, id).unwrap();
        assert_eq!(renderer.frame.skinned.len(), 1);
        assert!(renderer.frame.meshes.is_empty());
    } else {
        let data = MeshData {
            positions: figure.mesh.positions.clone(),
            normals: figure.mesh.normals.clone(),
            indices: c.mesh.indices.clone(),
        };
        let id = renderer.create_mesh(gpu, &data, Some(&figure.mesh.colors));
        figure.draw(&mut renderer.frame, id);
        assert!(renderer.frame.skinned.is_empty());
    }
    renderer
        .render_to_rgba(gpu, &camera(), W, H)
        .await
        .expect("pixels")
}

/// (fraction of pixels whose colour differs by more than `threshold` in some channel, mean
/// absolute difference per channel).
fn compare(a: &[u8], b: &[u8], threshold: u8) -> (f64, f64) {
    let mut differ = 0usize;
    let mut total = 0u64;
    for (pa, pb) in a.chunks_exact(4).zip(b.chunks_exact(4)) {
        let d = (0..3).map(|i| pa[i].abs_diff(pb[i])).max().unwrap();
        total += (0..3).map(|i| pa[i].abs_diff(pb[i]) as u64).sum::<u64>();
        if d > threshold {
            differ += 1;
        }
    }
    let pixels = a.len() / 4;
    (
        differ as f64 / pixels as f64,
        total as f64 / (3 * pixels) as f64,
    )
}

/// Fraction of pixels that are not the background (the corner's colour).
fn coverage(a: &[u8]) -> f64 {
    let bg = [a[0], a[1], a[2]];
    let n = a
        .chunks_exact(4)
        .filter(|p| (0..3).any(|i| p[i].abs_diff(bg[i]) > 24))
        .count();
    n as f64 / (a.len() / 4) as f64
}

#[wasm_bindgen_test]
async fn gpu_skinning_renders_what_cpu_skinning_renders() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    for method in ["LBS", "DQS"] {
        let cpu = render(&gpu, &mut renderer, method, false, 0.37).await;
        let on_gpu = render(&gpu, &mut renderer, method, true, 0.37).await;
        let (differ, mean) = compare(&cpu, &on_gpu, 24);
        let covered = coverage(&cpu);
        assert!(
            covered > 0.05,
            "{method}: the body covers {covered:.3} of the image"
        );
        // Same pose, same weights: only rounding in the shader differs (an edge pixel here and there).
        assert!(
            differ < 0.01 && mean < 1.0,
            "{method} on {}: {:.4} of the pixels differ, mean difference {mean:.3}",
            gpu.backend_name,
            differ
        );
        // The comparison can fail: another time of the clip (another pose) differs clearly.
        let later = render(&gpu, &mut renderer, method, true, 0.37 + 0.45).await;
        let (moved, _) = compare(&cpu, &later, 24);
        assert!(
            moved > 0.01,
            "{method}: another pose changed only {moved:.4} of the pixels"
        );
    }
}

/// WebGPU: the shader's formulas, run in a compute shader on the same uniform palette the vertex
/// shader reads, give the CPU's skinned positions and normals number by number. (WebGL2 has no
/// compute: there the image comparison above is the check.)
#[wasm_bindgen_test]
async fn gpu_skinning_formulas_match_the_cpu_numerically_on_webgpu() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    if !gpu.compute {
        let frame = inbetween::draw::Frame::default();
        let e = renderer
            .skin
            .skin_on_compute(&gpu, &frame, 0)
            .await
            .unwrap_err();
        assert!(e.contains("needs WebGPU"), "{e}");
        return;
    }
    for method in ["LBS", "DQS"] {
        let mut cpu = HumanFigure::new();
        cpu.set_method(method).unwrap();
        cpu.skin(0.61).unwrap();
        let mut figure = HumanFigure::new();
        figure.set_method(method).unwrap();
        figure.set_gpu(true);
        figure.skin(0.61).unwrap();
        let c = figure.character();
        let bind = c.mesh.positions.clone();
        let id = renderer
            .skin
            .create(&gpu, &c.mesh, Some(&figure.mesh.colors), &c.skin)
            .unwrap();
        let mut frame = inbetween::draw::Frame::default();
        figure.draw_gpu(&mut frame, id).unwrap();
        let (p, n) = renderer
            .skin
            .skin_on_compute(&gpu, &frame, 0)
            .await
            .unwrap();
        assert_eq!(p.len(), cpu.mesh.positions.len());
        let worst = |a: &[Vec3], b: &[Vec3]| {
            a.iter()
                .zip(b)
                .map(|(x, y)| (*x - *y).length())
                .fold(0.0f32, f32::max)
        };
        let (ep, en) = (worst(&p, &cpu.mesh.positions), worst(&n, &cpu.mesh.normals));
        assert!(
            ep < 1e-4 && en < 1e-4,
            "{method}: positions off by {ep} m, normals by {en}"
        );
        // And the check can fail: the bind pose is far from the walk at 0.61 s.
        assert!(worst(&p, &bind) > 0.05, "{method}");
    }
}
