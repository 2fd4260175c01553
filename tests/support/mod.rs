//! Lets one test file run natively (`cargo test`) and in the browser (wasm-bindgen-test).

#[cfg(target_arch = "wasm32")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

/// `both! { fn name() { … } }` defines a test for the native harness and for wasm-bindgen-test.
#[macro_export]
macro_rules! both {
    ($(fn $name:ident() $body:block)*) => {
        $(
            #[cfg_attr(not(target_arch = "wasm32"), test)]
            #[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
            fn $name() $body
        )*
    };
}

/// Asserts `|a − b| ≤ eps` element-wise for anything with `to_cols_array` / arrays of f32.
#[macro_export]
macro_rules! assert_close {
    ($a:expr, $b:expr, $eps:expr) => {{
        let (a, b): (&[f32], &[f32]) = (&$a, &$b);
        assert_eq!(a.len(), b.len());
        for (i, (x, y)) in a.iter().zip(b).enumerate() {
            assert!(
                (x - y).abs() <= $eps,
                "element {i}: {x} vs {y} (eps {})\n left: {a:?}\nright: {b:?}",
                $eps
            );
        }
    }};
}
