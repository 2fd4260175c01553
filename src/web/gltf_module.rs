//! The glTF module's binding (built with the feature `gltf-module`): imports a file and hands the
//! result to the figures module as bytes ([`crate::gltf_import::wire`]).
//!
//! The page's glTF figure (`www/gltf-figure.js`, lessons 06 and 09) loads this module when it
//! first reads a file, and passes what [`import_gltf`] returns to `GltfScene.loadImported`. The
//! importer (the `gltf` crate and serde) lives here only, so the module every page loads first
//! does not carry it.

use crate::gltf_import::{self, wire, MAX_FILE_BYTES};
use wasm_bindgen::prelude::*;

/// Imports a `.gltf` (embedded buffers) or `.glb` file's bytes (a `Uint8Array`) and returns the
/// result for `GltfScene.loadImported`, or an error that says what is wrong with the file.
///
/// Caps (the import's work grows with the file): at most 64 MiB of bytes
/// (`gltf_import::MAX_FILE_BYTES`, checked before the bytes are copied out of JavaScript),
/// 2²⁰ skinned vertices (`MAX_VERTICES`), 2¹⁶ joints (`skeleton::MAX_JOINTS`) and 2¹⁶ keys per
/// clip (`MAX_CLIP_KEYS`); a file past any of them is rejected with the cap in the message.
#[wasm_bindgen(js_name = importGltf)]
pub fn import_gltf(bytes: JsValue) -> Result<Vec<u8>, JsError> {
    let array = super::bytes("bytes", &bytes)?;
    let len = array.length() as usize;
    if len > MAX_FILE_BYTES {
        return Err(JsError::new(&format!(
            "the file has {len} bytes; the importer reads at most {MAX_FILE_BYTES}"
        )));
    }
    gltf_import::import(&array.to_vec())
        .and_then(|imported| wire::encode(&imported))
        .map_err(|e| JsError::new(&e.to_string()))
}
