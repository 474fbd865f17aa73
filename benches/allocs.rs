//! Heap allocations per statement of the whole pipeline (parse → check →
//! evaluate → print), counted by a global allocator: `cargo bench --bench
//! allocs`. Prints one line per script; the README's speed table quotes it.

mod common;

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

/// The system allocator, counting calls and bytes.
struct Counting;

static ALLOCS: AtomicU64 = AtomicU64::new(0);
static REALLOCS: AtomicU64 = AtomicU64::new(0);
static BYTES: AtomicU64 = AtomicU64::new(0);

// SAFETY: every call is forwarded unchanged to the system allocator.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Relaxed);
        BYTES.fetch_add(layout.size() as u64, Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        REALLOCS.fetch_add(1, Relaxed);
        BYTES.fetch_add(new_size as u64, Relaxed);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn count(name: &str, src: &str, mode: Mode) {
    let n = src.lines().count() as f64;
    let (a0, r0, b0) = (
        ALLOCS.load(Relaxed),
        REALLOCS.load(Relaxed),
        BYTES.load(Relaxed),
    );
    let mut session = Session::new(Settings::default());
    let (out, _, errors) = session.run_to_strings("bench.chs", src, mode, false);
    assert_eq!(errors, 0);
    let (a, r, b) = (
        ALLOCS.load(Relaxed) - a0,
        REALLOCS.load(Relaxed) - r0,
        BYTES.load(Relaxed) - b0,
    );
    println!(
        "{name:24} {:7.1} allocations + {:5.1} reallocations per statement, {:8.0} bytes ({} bytes printed)",
        a as f64 / n,
        r as f64 / n,
        b as f64 / n,
        out.len()
    );
}

fn main() {
    for n in [1_000usize, 10_000] {
        let src = common::screw_script(n);
        count(&format!("screw run {n}"), &src, Mode::Run);
        count(&format!("screw check {n}"), &src, Mode::Check);
        let src = common::book_script(n);
        count(&format!("book run {n}"), &src, Mode::Run);
    }
}
