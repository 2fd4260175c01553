//! Browser tests of the lessons' bindings and cores under wasm (tests/web_cores/): bad input is an
//! `Err` with a readable message at the wasm boundary, never a panic, and valid input is `Ok`. One
//! binary, run on WebGL2 only (no browser flag changes what they test), since each wasm test binary
//! costs a link and a browser start.
#![cfg(target_arch = "wasm32")]

wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

/// The message a `JsError` carries to JavaScript (what a page would show).
fn message(e: wasm_bindgen::JsError) -> String {
    let value: wasm_bindgen::JsValue = e.into();
    js_sys::Reflect::get(&value, &"message".into())
        .ok()
        .and_then(|m| m.as_string())
        .unwrap_or_default()
}

#[path = "web_cores/cloth.rs"]
mod cloth;
#[path = "web_cores/curves.rs"]
mod curves;
#[path = "web_cores/hostile.rs"]
mod hostile;
#[path = "web_cores/ik.rs"]
mod ik;
#[path = "web_cores/particles.rs"]
mod particles;
#[path = "web_cores/rotation.rs"]
mod rotation;
#[path = "web_cores/skeleton.rs"]
mod skeleton;
#[path = "web_cores/skinning.rs"]
mod skinning;
