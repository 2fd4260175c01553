//! The wasm modules' global allocator: the standard one (`std::alloc::System`, dlmalloc on
//! wasm32), called out of line.
//!
//! # Why a wrapper
//! Without a `#[global_allocator]`, `__rust_dealloc` is the standard library's own, and LTO
//! inlines it into every place that frees memory (each `Vec`, `String` and `Box` dropped),
//! together with dlmalloc's size check of the freed chunk (`Dlmalloc::free` asserts that the
//! chunk's size fits the `Layout`): about 2,900 copies in the figures module. Here each of the
//! four entry points is one function that calls `System`, so a call site passes its pointer and
//! layout and nothing more. The allocator, its checks and its results are the same; only where
//! the code sits changes. The kernels reuse their buffers from step to step (one grows only when
//! it is too small), so no hot loop pays the extra call.

use std::alloc::{GlobalAlloc, Layout, System};

/// `System`, behind functions that are never inlined (see the module's doc).
struct OutOfLine;

// SAFETY: every method forwards its arguments unchanged to `System`, which upholds
// `GlobalAlloc`'s contract; the caller's obligations pass through as they are.
unsafe impl GlobalAlloc for OutOfLine {
    #[inline(never)]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        unsafe { System.alloc(layout) }
    }

    #[inline(never)]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        unsafe { System.alloc_zeroed(layout) }
    }

    #[inline(never)]
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }

    #[inline(never)]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: OutOfLine = OutOfLine;
