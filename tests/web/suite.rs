//! The browser-only tests of tests/web.rs and tests/web_webgpu.rs (wasm-bindgen-test in headless
//! Chromium): the renderer gets an adapter, draws, and reads its pixels back; the web layer turns
//! bad input into errors, not panics. `crate::EXPECTED_BACKEND`, when set, is the backend every
//! GPU the tests create must get.

use glam::{Mat4, Vec3};
use inbetween::camera::OrbitCamera;
use inbetween::render::{BackendChoice, Gpu, Renderer};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;

// The other tests that draw or compute on the GPU (tests/web/), and the bindings' and cores' tests
// (tests/web_cores/), in this suite: scripts/test runs it on both backends, and each wasm test
// binary costs a link and a browser start.
#[path = "../web_cores/mod.rs"]
mod web_cores;
#[path = "gpu_compute.rs"]
mod gpu_compute;
#[path = "gpu_fluid.rs"]
mod gpu_fluid;
#[path = "gpu_skin.rs"]
mod gpu_skin;
#[path = "render.rs"]
mod render;

fn canvas(width: u32, height: u32) -> web_sys::HtmlCanvasElement {
    let document = web_sys::window().unwrap().document().unwrap();
    let canvas: web_sys::HtmlCanvasElement = document
        .create_element("canvas")
        .unwrap()
        .dyn_into()
        .unwrap();
    canvas.set_width(width);
    canvas.set_height(height);
    document.body().unwrap().append_child(&canvas).unwrap();
    canvas
}

async fn gpu() -> Gpu {
    let gpu = Gpu::new(canvas(96, 64), BackendChoice::Auto)
        .await
        .expect("an adapter (WebGPU or WebGL2)");
    if let Some(expected) = crate::EXPECTED_BACKEND {
        assert_eq!(gpu.backend_name, expected, "adapter: {}", gpu.adapter_name);
    }
    gpu
}

fn pixel(rgba: &[u8], width: u32, x: u32, y: u32) -> [u8; 4] {
    let i = ((y * width + x) * 4) as usize;
    [rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]]
}

#[wasm_bindgen_test]
async fn renderer_draws_a_lit_cube_and_reads_it_back() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    let camera = OrbitCamera {
        target: Vec3::ZERO,
        distance: 5.0,
        yaw_rad: 0.6,
        pitch_rad: 0.4,
        ..Default::default()
    };
    renderer
        .frame
        .mesh(renderer.cube, Mat4::IDENTITY, Vec3::new(1.0, 0.0, 0.0));
    let (w, h) = (96, 64);
    let rgba = renderer
        .render_to_rgba(&gpu, &camera, w, h)
        .await
        .expect("pixels");
    assert_eq!(rgba.len(), (w * h * 4) as usize);
    // Corners show the background (sRGB 0.96, 0.96, 0.97 → about 245, 245, 247).
    for [x, y] in [[0, 0], [w - 1, 0], [0, h - 1], [w - 1, h - 1]] {
        let p = pixel(&rgba, w, x, y);
        assert!(
            p[0] > 235 && p[1] > 235 && p[2] > 235,
            "corner ({x},{y}) = {p:?}"
        );
    }
    // The centre shows the red cube: red dominates and it is shaded, not flat background.
    let c = pixel(&rgba, w, w / 2, h / 2);
    assert!(c[0] > 60 && c[1] < 80 && c[2] < 80, "centre = {c:?}");
    // Three faces are visible, lit differently: count distinct reds along a horizontal line and a column.
    let mut reds: Vec<u8> = (0..w)
        .chain(0..h)
        .map(|i| {
            if i < w {
                pixel(&rgba, w, i, h / 2 + 6)[0]
            } else {
                pixel(&rgba, w, w / 2, i - w)[0]
            }
        })
        .collect();
    reds.sort_unstable();
    reds.dedup_by(|a, b| a.abs_diff(*b) < 8);
    assert!(reds.len() >= 3, "expected several shades, got {reds:?}");
}

#[wasm_bindgen_test]
async fn lines_points_and_depth() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    let camera = OrbitCamera {
        target: Vec3::ZERO,
        distance: 4.0,
        yaw_rad: 0.0,
        pitch_rad: 0.0,
        ..Default::default()
    };
    let (w, h) = (64, 64);
    // A green point in front of a blue box: depth testing keeps the nearer one.
    renderer.frame.mesh(
        renderer.cube,
        Mat4::from_scale(Vec3::splat(0.8)),
        Vec3::new(0.0, 0.0, 1.0),
    );
    renderer
        .frame
        .point(Vec3::new(0.0, 0.0, 1.5), 0.2, Vec3::new(0.0, 1.0, 0.0));
    renderer.frame.line(
        Vec3::new(-3.0, 1.0, 0.0),
        Vec3::new(3.0, 1.0, 0.0),
        Vec3::new(1.0, 0.0, 0.0),
    );
    let rgba = renderer
        .render_to_rgba(&gpu, &camera, w, h)
        .await
        .expect("pixels");
    let c = pixel(&rgba, w, w / 2, h / 2);
    assert!(
        c[1] > 100 && c[0] < 80 && c[2] < 80,
        "point in front: {c:?}"
    );
    let side = pixel(&rgba, w, w / 2 + 14, h / 2);
    assert!(side[2] > 100 && side[0] < 80, "box behind: {side:?}");
    let has_red_line = (0..h).any(|y| {
        let p = pixel(&rgba, w, 8, y);
        // 1 px wide and multisampled: the line may cover only part of a pixel, so look for a red tint.
        p[0] as i32 - p[1] as i32 > 40 && p[0] as i32 - p[2] as i32 > 40
    });
    assert!(has_red_line, "the red line crosses the left of the image");
    // Drawing clears the frame: the next render is background only.
    let empty = renderer
        .render_to_rgba(&gpu, &camera, w, h)
        .await
        .expect("pixels");
    assert!(
        empty.chunks(4).all(|p| p[0] > 235),
        "frame list is cleared after each draw"
    );
}

/// A frame the canvas already shows is not drawn again; a change to the frame, the camera, a
/// mesh's vertices, the size (a resize clears the canvas) or compute-shader points draws it.
#[wasm_bindgen_test]
async fn an_unchanged_frame_is_not_drawn_again() {
    let mut gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    let mut camera = OrbitCamera::default();
    let data = inbetween::mesh::cuboid(Vec3::splat(0.5));
    let id = renderer.create_mesh(&gpu, &data, None);
    let present = |renderer: &mut Renderer, gpu: &Gpu, camera: &OrbitCamera, x: f32| {
        renderer
            .frame
            .mesh(id, Mat4::from_translation(Vec3::X * x), Vec3::ONE);
        let fingerprint = renderer.frame.fingerprint();
        renderer.render(gpu, camera, fingerprint).expect("drawn");
        assert!(
            renderer.frame.meshes.is_empty(),
            "the frame is cleared either way"
        );
        renderer.canvas_frames()
    };
    assert_eq!(present(&mut renderer, &gpu, &camera, 0.0), 1);
    assert_eq!(
        present(&mut renderer, &gpu, &camera, 0.0),
        1,
        "same frame: kept"
    );
    assert_eq!(
        present(&mut renderer, &gpu, &camera, 0.1),
        2,
        "the frame moved"
    );
    camera.orbit(0.1, 0.0);
    assert_eq!(
        present(&mut renderer, &gpu, &camera, 0.1),
        3,
        "the camera moved"
    );
    renderer
        .update_mesh(&gpu, id, &data.positions, &data.normals)
        .expect("same vertex count");
    assert_eq!(
        present(&mut renderer, &gpu, &camera, 0.1),
        4,
        "a mesh changed"
    );
    assert_eq!(present(&mut renderer, &gpu, &camera, 0.1), 4);
    gpu.resize(80, 48);
    renderer.canvas_cleared();
    assert_eq!(present(&mut renderer, &gpu, &camera, 0.1), 5, "resized");
    let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 64,
        usage: wgpu::BufferUsages::VERTEX,
        mapped_at_creation: false,
    });
    renderer.gpu_points = vec![(buffer, 0)];
    assert_eq!(
        present(&mut renderer, &gpu, &camera, 0.1),
        6,
        "compute points"
    );
    assert!(
        renderer.gpu_points.is_empty(),
        "drawn once, then cleared with the frame"
    );
    assert_eq!(present(&mut renderer, &gpu, &camera, 0.1), 6);
}

#[wasm_bindgen_test]
async fn meshes_update_in_place() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    let data = inbetween::mesh::cuboid(Vec3::splat(0.5));
    let id = renderer.create_mesh(&gpu, &data, None);
    let moved: Vec<Vec3> = data.positions.iter().map(|p| *p + Vec3::X * 10.0).collect();
    renderer
        .update_mesh(&gpu, id, &moved, &data.normals)
        .expect("same vertex count");
    let err = renderer
        .update_mesh(&gpu, id, &moved[..3], &data.normals[..3])
        .unwrap_err();
    assert!(err.contains("24 vertices"), "{err}");
}

#[wasm_bindgen_test]
async fn a_freed_mesh_is_gone_and_drawing_it_draws_nothing() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    let data = inbetween::mesh::cuboid(Vec3::splat(0.5));
    let id = renderer.create_mesh(&gpu, &data, None);
    renderer.free_mesh(id);
    renderer.free_mesh(id); // twice: harmless
    let err = renderer
        .update_mesh(&gpu, id, &data.positions, &data.normals)
        .unwrap_err();
    assert!(err.contains("unknown mesh"), "{err}");
    // A stale id in the draw list is skipped: the image is background only, and no panic.
    let camera = OrbitCamera {
        target: Vec3::ZERO,
        distance: 4.0,
        ..Default::default()
    };
    renderer.frame.mesh(id, Mat4::IDENTITY, Vec3::X);
    let rgba = renderer
        .render_to_rgba(&gpu, &camera, 32, 32)
        .await
        .expect("pixels");
    assert!(
        rgba.chunks(4).all(|p| p[0] > 235 && p[1] > 235),
        "nothing drawn"
    );
    // The next mesh gets a fresh id and draws.
    let next = renderer.create_mesh(&gpu, &data, None);
    assert_ne!(next, id);
    renderer.frame.mesh(next, Mat4::IDENTITY, Vec3::X);
    let rgba = renderer
        .render_to_rgba(&gpu, &camera, 32, 32)
        .await
        .expect("pixels");
    let c = pixel(&rgba, 32, 16, 16);
    assert!(c[0] > 60 && c[1] < 80, "the new mesh is drawn: {c:?}");
}

#[wasm_bindgen_test]
async fn viewer_rejects_an_unknown_backend_with_a_message() {
    let result = inbetween::web::Viewer::create(canvas(8, 8).into(), "vulkan".into()).await;
    assert!(result.is_err());
    assert_eq!(BackendChoice::parse("webgl2"), Ok(BackendChoice::WebGl2));
    assert!(BackendChoice::parse("vulkan")
        .unwrap_err()
        .contains("auto, webgpu or webgl2"));
}

/// The message of a `JsError` as JavaScript would see it.
fn message(error: wasm_bindgen::JsError) -> String {
    let value: wasm_bindgen::JsValue = error.into();
    js_sys::Reflect::get(&value, &"message".into())
        .ok()
        .and_then(|m| m.as_string())
        .unwrap_or_default()
}

#[wasm_bindgen_test]
fn lesson_01_bindings_reject_bad_input_with_messages() {
    use inbetween::web::{HierarchyScene, SingleShapeScene};
    let mut scene = HierarchyScene::new();
    let m = message(
        scene
            .set_joint_angles_deg(0.0, f32::NAN, 0.0, 0.0)
            .unwrap_err(),
    );
    assert!(m.contains("x must be a finite number"), "{m}");
    let m = message(scene.set_joint_scale(1.0, 99.0, 1.0, 1.0).unwrap_err());
    assert!(m.contains("sx must lie in [0.1, 4]"), "{m}");
    let m = message(scene.select(99.0).unwrap_err());
    assert!(m.contains("out of range") && m.contains("11 joints"), "{m}");
    assert!(scene.sample_cycle(1.0, 1.2).is_err());
    assert!(scene.sample_cycle(50.0, f32::INFINITY).is_err());
    assert!(scene.set_joint_angles_deg(3.0, 10.0, 20.0, 30.0).is_ok());
    let back = scene.joint_angles_deg(3.0).unwrap();
    assert!(
        back.iter()
            .zip([10.0, 20.0, 30.0])
            .all(|(a, b)| (a - b).abs() < 1e-4),
        "{back:?}"
    );
    // Selecting a joint keeps its scale (the panel reads it back).
    scene.set_joint_scale(3.0, 1.0, 2.0, 1.0).unwrap();
    scene.select(0.0).unwrap();
    scene.select(3.0).unwrap();
    assert_eq!(scene.joint_scale(3.0).unwrap(), vec![1.0, 2.0, 1.0]);
    let mut shape = SingleShapeScene::new();
    assert_ne!(
        shape.matrix_of(false.into()).unwrap(),
        shape.matrix_of(true.into()).unwrap(),
        "T·R and R·T differ"
    );
    let m = message(
        shape
            .set_transform(0.0, f32::NEG_INFINITY, 0.0, 0.0, 0.0, 0.0)
            .unwrap_err(),
    );
    assert!(m.contains("ty"), "{m}");
}
