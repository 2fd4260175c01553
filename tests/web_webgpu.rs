//! The browser-only suite of tests/web.rs (tests/web/suite.rs), for the run with the WebGPU flag
//! set: every GPU the tests create must be WebGPU (see tests/web.rs).
#![cfg(target_arch = "wasm32")]

wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

/// The backend every GPU of the suite must get.
const EXPECTED_BACKEND: Option<&str> = Some("WebGPU");

#[path = "web/suite.rs"]
mod suite;
