//! The `chasles` binary: the command line of [`chasles::cli`], run on a
//! thread with a generous stack.

/// The allocator: the language allocates small, short-lived nodes and
/// values for every statement, which mimalloc serves several times faster
/// than the system allocator (issue 14's script: see `benches/instructions.sh`).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    // OS strings: an argument that is not UTF-8 is an error, not a panic.
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    let worker = std::thread::Builder::new()
        .name("chasles".into())
        .stack_size(256 * 1024 * 1024)
        .spawn(move || chasles::cli::main_with_args(args));
    let code = match worker {
        Ok(handle) => handle.join().unwrap_or(101),
        Err(_) => chasles::cli::main_with_args(std::env::args_os()),
    };
    std::process::exit(code);
}
