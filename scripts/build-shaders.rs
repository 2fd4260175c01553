//! Cargo's build script for the crate (`build` in Cargo.toml): writes the WGSL shaders of
//! `src/render/shaders/` into `OUT_DIR`, where the renderer includes them from
//! (`render::shader_source!`). A release build drops their comments, indentation and blank lines:
//! the prose in those files is for the people who read them, and the figures module has a size
//! limit. A debug build copies them as they are, so a shader error names the line of the file.
use std::{env, fs, path::Path};

fn main() {
    let shaders = Path::new("src/render/shaders");
    println!("cargo:rerun-if-changed={}", shaders.display());
    let out = env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    let release = env::var("PROFILE").is_ok_and(|p| p == "release");
    let mut entries: Vec<_> = fs::read_dir(shaders)
        .expect("src/render/shaders")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "wgsl"))
        .collect();
    entries.sort();
    for path in entries {
        println!("cargo:rerun-if-changed={}", path.display());
        let text = fs::read_to_string(&path).expect("a shader's text");
        let text = if release { minify(&text) } else { text };
        let name = path.file_name().expect("a file name");
        fs::write(Path::new(&out).join(name), text).expect("OUT_DIR is writable");
    }
}

/// The shader without `//` comments (WGSL has no string literals, so `//` always starts one),
/// without leading and trailing spaces and without blank lines. WGSL's block comments are not
/// used in these files; one would be an error here, so that it is not kept silently.
fn minify(source: &str) -> String {
    assert!(!source.contains("/*"), "block comments are not minified: use //");
    let mut out = String::with_capacity(source.len());
    for line in source.lines() {
        let code = line.split_once("//").map_or(line, |(code, _)| code).trim();
        if !code.is_empty() {
            out.push_str(code);
            out.push('\n');
        }
    }
    out
}
