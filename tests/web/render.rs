//! Browser-only pixel tests of wide lines and markers (`src/render/shaders/stroke.wgsl`,
//! `marker.wgsl`): WebGL2 has no wide lines, so the width comes from the vertex shader's
//! expansion, and these tests read it back from the rendered image on both backends
//! (`scripts/test` runs them with the WebGL2 and the WebGPU flag sets).
#![cfg(target_arch = "wasm32")]

use glam::Vec3;
use inbetween::camera::OrbitCamera;
use inbetween::draw::{palette, MeshId, StrokeStyle};
use inbetween::render::{BackendChoice, Gpu, Renderer};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;

const W: u32 = 240;
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

/// Looking straight down −Z at the origin from 5 m.
fn camera() -> OrbitCamera {
    OrbitCamera {
        target: Vec3::ZERO,
        distance: 5.0,
        yaw_rad: 0.0,
        pitch_rad: 0.0,
        ..OrbitCamera::default()
    }
}

/// Pixels of row `y` darker than the light background, as runs `(start, length)`.
fn dark_runs(pixels: &[u8], y: u32) -> Vec<(u32, u32)> {
    runs(pixels, y, |p| {
        p.iter().map(|&c| c as u32).sum::<u32>() < 3 * 128
    })
}

/// Runs `(start, length)` of the pixels of row `y` for which `keep` holds.
fn runs(pixels: &[u8], y: u32, keep: impl Fn(&[u8]) -> bool) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    let mut start = None;
    for x in 0..=W {
        let hit = x < W && {
            let i = ((y * W + x) * 4) as usize;
            keep(&pixels[i..i + 3])
        };
        match (hit, start) {
            (true, None) => start = Some(x),
            (false, Some(s)) => {
                out.push((s, x - s));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// How many pixels' worth of ink of colour `ink` row `y` holds between columns `from` and `to`:
/// each pixel counts for how far it has gone from the background towards the ink (its
/// antialiased coverage), so a line of width w adds up to about w wherever it falls on the grid.
fn ink(pixels: &[u8], y: u32, from: u32, to: u32, ink: u8) -> f32 {
    let bg = pixels[(y * W * 4) as usize + 1] as f32;
    (from..to)
        .map(|x| {
            let g = pixels[((y * W + x) * 4 + 1) as usize] as f32;
            ((bg - g) / (bg - ink as f32)).clamp(0.0, 1.0)
        })
        .sum()
}

#[wasm_bindgen_test]
async fn a_wide_line_is_as_wide_as_asked_on_this_backend() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    // palette::KEY is #222222: its green channel is 0x22.
    let key = 0x22;
    for px_per_css in [1.0, 2.0] {
        for width in [1.0f32, 3.0, 6.0] {
            renderer.px_per_css = px_per_css;
            // A vertical line through the middle, and a 1-pixel line 1 m to its right.
            renderer.frame.wide_line(
                Vec3::new(0.0, -1.5, 0.0),
                Vec3::new(0.0, 1.5, 0.0),
                palette::KEY,
                width,
            );
            renderer.frame.line(
                Vec3::new(1.0, -1.5, 0.0),
                Vec3::new(1.0, 1.5, 0.0),
                palette::KEY,
            );
            let pixels = renderer
                .render_to_rgba(&gpu, &camera(), W, H)
                .await
                .unwrap();
            let expected = width * px_per_css;
            let wide = ink(&pixels, H / 2, 0, W / 2 + 20, key);
            let thin = ink(&pixels, H / 2, W / 2 + 20, W, key);
            assert!(
                (wide - expected).abs() <= 1.0_f32.max(0.2 * expected),
                "{}: a {width} px line at {px_per_css} pixels per CSS pixel is {wide} pixels wide",
                gpu.backend_name
            );
            assert!(
                (0.5..=1.6).contains(&thin),
                "{}: the 1-pixel line beside it is {thin} pixels wide",
                gpu.backend_name
            );
        }
    }
}

#[wasm_bindgen_test]
async fn a_polyline_joins_without_gaps_and_dashes_leave_gaps() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    renderer.px_per_css = 1.0;
    // A sharp zigzag across the middle row: every column it crosses is dark in some row near
    // the joins, and the row through a join shows no break.
    let zig = [
        Vec3::new(-2.0, -0.5, 0.0),
        Vec3::new(-1.0, 0.0, 0.0),
        Vec3::new(0.0, -0.5, 0.0),
        Vec3::new(1.0, 0.0, 0.0),
    ];
    renderer.frame.wide_polyline(&zig, palette::KEY, 6.0);
    let pixels = renderer
        .render_to_rgba(&gpu, &camera(), W, H)
        .await
        .unwrap();
    let centre = |p: Vec3| {
        let c = camera();
        let vp = c.projection(W as f32 / H as f32) * c.view();
        inbetween::camera::project_to_canvas(vp, glam::Vec2::new(W as f32, H as f32), p).unwrap()
    };
    for join in [zig[1], zig[2]] {
        let px = centre(join);
        let (x, y) = (px.x.round() as u32, px.y.round() as u32);
        // The join's own pixel and a small square around it are covered.
        for dy in [-1i32, 0, 1] {
            for dx in [-1i32, 0, 1] {
                let i = (((y as i32 + dy) as u32 * W + (x as i32 + dx) as u32) * 4) as usize;
                let sum: u32 = pixels[i..i + 3].iter().map(|&c| c as u32).sum();
                assert!(
                    sum < 3 * 128,
                    "{}: a gap at the join {join} ({x}, {y}) + ({dx}, {dy})",
                    gpu.backend_name
                );
            }
        }
    }
    // Dashes: a horizontal dashed line breaks into several runs along its row.
    let y = 0.8;
    renderer.frame.stroke(
        &[Vec3::new(-2.0, y, 0.0), Vec3::new(2.0, y, 0.0)],
        palette::KEY,
        StrokeStyle::dashed(4.0, 0.25, 0.25),
    );
    let pixels = renderer
        .render_to_rgba(&gpu, &camera(), W, H)
        .await
        .unwrap();
    let row = centre(Vec3::new(0.0, y, 0.0)).y.round() as u32;
    let runs = dark_runs(&pixels, row);
    assert!(
        (7..=9).contains(&runs.len()),
        "{}: 4 m of 0.25 m dashes and gaps: {runs:?}",
        gpu.backend_name
    );
}

#[wasm_bindgen_test]
async fn a_marker_keeps_its_size_in_pixels_at_any_distance() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    renderer.px_per_css = 1.0;
    for distance in [2.0, 40.0] {
        renderer.frame.marker(Vec3::ZERO, 16.0, palette::KEY);
        let c = OrbitCamera {
            distance,
            ..camera()
        };
        let pixels = renderer.render_to_rgba(&gpu, &c, W, H).await.unwrap();
        // The marker is everything that is not the background (the white ring too): the row
        // through its centre spans its 16 pixels.
        let bg = [pixels[0], pixels[1], pixels[2]];
        let across = runs(&pixels, H / 2, |p| (0..3).any(|i| p[i].abs_diff(bg[i]) > 6));
        assert!(
            across.len() == 1 && (15..=17).contains(&across[0].1),
            "{} at {distance} m: {across:?}",
            gpu.backend_name
        );
        // And its middle is the marker's colour.
        let i = ((H / 2 * W + W / 2) * 4) as usize;
        assert!(
            pixels[i + 1] < 0x40,
            "{}: the fill is {:?}",
            gpu.backend_name,
            &pixels[i..i + 3]
        );
    }
}

#[wasm_bindgen_test]
async fn a_tick_is_its_colour_across_its_width() {
    // Equal-time ticks on a path along x through the middle: the middle one is a bar 6 px wide
    // along the path, its colour inside a dark rim with no white ring (which left a 1 px line of
    // colour in a white box). The pixels whose centres lie 0.5 and 1.5 px either side of its
    // centre line (x = 120 in device pixels) are its colour.
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    renderer.px_per_css = 1.0;
    let samples = [-0.8, 0.0, 0.8].map(|x| Vec3::new(x, 0.0, 0.0));
    renderer.frame.ticks(&samples, 16.0, palette::ORANGE);
    let pixels = renderer.render_to_rgba(&gpu, &camera(), W, H).await.unwrap();
    for dx in [-2i32, -1, 0, 1] {
        for dy in [-4i32, 0, 4] {
            let (x, y) = ((W / 2) as i32 + dx, (H / 2) as i32 + dy);
            let i = ((y as u32 * W + x as u32) * 4) as usize;
            let p = &pixels[i..i + 3];
            assert!(
                p[0] > 0xb0 && p[2] < 0x60,
                "{}: the tick at ({dx}, {dy}) px is {p:?}, not orange",
                gpu.backend_name
            );
        }
    }
}

#[wasm_bindgen_test]
async fn a_contact_shadow_darkens_the_ground_under_an_object() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    renderer.px_per_css = 1.0;
    // Looking almost straight down on a ball 0.1 m across hanging 0.25 m above the ground.
    let c = OrbitCamera {
        distance: 2.0,
        pitch_rad: 1.5,
        ..camera()
    };
    let ball = glam::Mat4::from_scale_rotation_translation(
        Vec3::splat(0.1),
        glam::Quat::IDENTITY,
        Vec3::new(0.0, 0.35, 0.0),
    );
    // A ground point beside the ball's silhouette, inside its shadow.
    let vp = c.projection(W as f32 / H as f32) * c.view();
    let px = inbetween::camera::project_to_canvas(
        vp,
        glam::Vec2::new(W as f32, H as f32),
        Vec3::new(0.14, 0.0, 0.0),
    )
    .unwrap();
    let i = ((px.y.round() as u32 * W + px.x.round() as u32) * 4) as usize;
    let mut green = Vec::new();
    for shadow in [false, true] {
        renderer.frame.mesh(MeshId::SPHERE, ball, palette::ORANGE);
        if shadow {
            renderer
                .frame
                .contact_shadow(Vec3::new(0.0, 0.25, 0.0), 0.1);
        }
        let pixels = renderer.render_to_rgba(&gpu, &c, W, H).await.unwrap();
        green.push(pixels[i + 1]);
    }
    assert!(
        green[1] + 5 < green[0],
        "{}: the ground beside the ball goes from {} to {} with its shadow",
        gpu.backend_name,
        green[0],
        green[1]
    );
}

#[wasm_bindgen_test]
async fn a_wide_line_lying_on_a_textured_quad_stays_visible() {
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    renderer.px_per_css = 1.0;
    // A light grey 2 × 2 image on the square [−1, 1]² turned to face the camera (the xz plane
    // rotated into the xy plane), and a 3 px line 1 cm in front of it: the quad writes depth
    // and the line only tests it, so the quad must be drawn first or it paints over the line.
    let grey = [200u8, 200, 200, 255].repeat(4);
    let texture = renderer.create_texture(&gpu, 2, 2, &grey).unwrap();
    renderer.frame.textured_quad(
        texture,
        glam::Mat4::from_rotation_x(std::f32::consts::FRAC_PI_2),
        inbetween::draw::UvRect::FULL,
    );
    renderer.frame.wide_line(
        Vec3::new(0.3, -0.8, 0.01),
        Vec3::new(0.3, 0.8, 0.01),
        palette::KEY,
        3.0,
    );
    let pixels = renderer
        .render_to_rgba(&gpu, &camera(), W, H)
        .await
        .unwrap();
    // The row through the middle: the quad's grey around the centre, and one dark run of
    // about 3 pixels where the line crosses it.
    let centre = ((H / 2 * W + W / 2) * 4) as usize;
    assert!(
        (150..=230).contains(&pixels[centre + 1]),
        "{}: the quad is {:?} at the centre",
        gpu.backend_name,
        &pixels[centre..centre + 3]
    );
    let dark = dark_runs(&pixels, H / 2);
    assert!(
        dark.len() == 1 && (2..=4).contains(&dark[0].1) && dark[0].0 > W / 2,
        "{}: dark runs {dark:?} along the middle row",
        gpu.backend_name
    );
}

#[wasm_bindgen_test]
async fn an_inset_shows_the_scene_from_above_in_its_corner() {
    use inbetween::draw::inset::{inset_rect, InsetView};
    let gpu = gpu().await;
    let mut renderer = Renderer::new(&gpu);
    renderer.px_per_css = 1.0;
    let rect = inset_rect(glam::Vec2::new(W as f32, H as f32));
    let at = |p: glam::Vec2| ((p.y.round() as u32 * W + p.x.round() as u32) * 4) as usize;
    let centre = at(rect.min + 0.5 * rect.size);
    let corner = at(rect.min + glam::Vec2::splat(6.0));
    let border = at(rect.min + glam::Vec2::new(0.5, 0.5 * rect.size.y));
    let mut shots = Vec::new();
    for inset in [false, true] {
        // A ball at the origin; from above it fills the middle of the inset's box.
        renderer.frame.mesh(
            MeshId::SPHERE,
            glam::Mat4::from_scale(Vec3::splat(0.5)),
            palette::ORANGE,
        );
        if inset {
            renderer.frame.inset(
                InsetView::Top,
                "from above",
                Vec3::splat(-1.0),
                Vec3::splat(1.0),
            );
        }
        shots.push(
            renderer
                .render_to_rgba(&gpu, &camera(), W, H)
                .await
                .unwrap(),
        );
    }
    let rgb = |shot: &Vec<u8>, i: usize| [shot[i], shot[i + 1], shot[i + 2]];
    let name = &gpu.backend_name;
    // Without the inset that corner of the canvas is background; with it, the ball is in the
    // inset's middle (orange: red well above blue), its fill is white and its border grey.
    let (plain, with) = (&shots[0], &shots[1]);
    assert!(
        rgb(plain, centre) == rgb(plain, corner),
        "{name}: no inset, yet {:?} and {:?}",
        rgb(plain, centre),
        rgb(plain, corner)
    );
    let ball = rgb(with, centre);
    assert!(
        ball[0] as i32 - ball[2] as i32 > 60,
        "{name}: the inset's middle is {ball:?}"
    );
    assert!(
        rgb(with, corner).iter().all(|&c| c >= 250),
        "{name}: the fill is {:?}",
        rgb(with, corner)
    );
    let edge = rgb(with, border);
    assert!(
        edge.iter().all(|&c| (100..=200).contains(&c)),
        "{name}: the border is {edge:?}"
    );
    // The main view outside the inset is drawn too (WebGL2 resolves through the scissor).
    let outside = at(glam::Vec2::new(4.0, 4.0));
    assert_eq!(
        rgb(with, outside),
        rgb(plain, outside),
        "{name}: the main view's corner"
    );
}
