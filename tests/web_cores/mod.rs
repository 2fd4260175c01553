//! Browser tests of the lessons' bindings and cores under wasm: bad input is an `Err` with a
//! readable message at the wasm boundary, never a panic, and valid input is `Ok`. A module of the
//! `web` test binary (tests/web.rs), since each wasm test binary costs a link and a browser start.

/// The message a `JsError` carries to JavaScript (what a page would show).
fn message(e: wasm_bindgen::JsError) -> String {
    let value: wasm_bindgen::JsValue = e.into();
    js_sys::Reflect::get(&value, &"message".into())
        .ok()
        .and_then(|m| m.as_string())
        .unwrap_or_default()
}

mod cloth;
mod curves;
mod hostile;
mod ik;
mod particles;
mod rotation;
mod skeleton;
mod skinning;
