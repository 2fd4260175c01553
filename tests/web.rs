//! Browser-only tests (wasm-bindgen-test in headless Chromium), the suite in tests/web/suite.rs:
//! the renderer gets an adapter, draws, and reads its pixels back; the web layer turns bad input
//! into errors, not panics. `scripts/test` runs this binary with the WebGL2 flag set and sets
//! `INBETWEEN_EXPECT_BACKEND=WebGL2` (read when it compiles: a page has no environment), so that
//! every GPU the tests create must be WebGL2; tests/web_webgpu.rs is the same suite for the
//! WebGPU flag set. Two binaries rather than one built twice: each keeps its build, where one
//! binary would be compiled again at every switch of the variable.
#![cfg(target_arch = "wasm32")]

wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

/// The backend every GPU of the suite must get, if any.
const EXPECTED_BACKEND: Option<&str> = option_env!("INBETWEEN_EXPECT_BACKEND");

#[path = "web/suite.rs"]
mod suite;
