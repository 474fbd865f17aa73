//! Start-up (issue 40): on Linux with glibc the `chasles` executable is
//! linked at a fixed address (`-no-pie`). A position-independent executable
//! makes the dynamic loader apply ~17,000 relocations at every start,
//! writing to ~70 pages of pointer tables (the builtins' table, vtables)
//! that each cost a page fault: about a quarter of `chasles -e 1`'s
//! instructions and page faults (callgrind: 1.06 M → 0.84 M instructions;
//! perf: ~310 → ~230 page faults). The code itself is compiled as before;
//! only the binaries' link changes, the library is untouched.
//!
//! The price is that the executable's own code is not placed at a random
//! address (ASLR still moves the stack, heap and shared libraries). A
//! packager who wants a position-independent executable sets
//! `CHASLES_PIE=1`: the relocations are then packed (DT_RELR, GNU ld 2.38,
//! glibc 2.36), which shrinks the file but not the faults.

fn main() {
    println!("cargo:rerun-if-env-changed=CHASLES_PIE");
    println!("cargo:rerun-if-changed=build.rs");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let env = std::env::var("CARGO_CFG_TARGET_ENV").unwrap_or_default();
    if os != "linux" || env != "gnu" {
        return;
    }
    if std::env::var_os("CHASLES_PIE").is_some() {
        println!("cargo:rustc-link-arg-bins=-Wl,-z,pack-relative-relocs");
    } else {
        println!("cargo:rustc-link-arg-bins=-no-pie");
    }
}
