//! The `chasles` binary: the command line of [`chasles::cli`], run on a
//! thread with a generous stack.

/// The allocator: the language allocates small, short-lived nodes and
/// values for every statement, which mimalloc serves several times faster
/// than the system allocator (issue 14's script: see `benches/instructions.sh`).
#[global_allocator]
static ALLOCATOR: Mi = Mi;

/// mimalloc, asked through its plain entry points where the alignment
/// asked for is one every block of that size has anyway (at most 16 bytes
/// and no more than the size: mimalloc's own "naturally aligned" rule, as
/// the standard library's system allocator does with `malloc`). The
/// `mimalloc` crate's allocator always calls the aligned entry point,
/// about 80 instructions an allocation against about 25 (issue 40: ~12
/// allocations a statement); larger alignments still go through it.
struct Mi;

/// The largest alignment mimalloc gives a block of at least that size
/// (`MI_MAX_ALIGN_SIZE`).
const NATURAL: usize = 16;

// SAFETY: every block comes from mimalloc and goes back to it; a plain
// `mi_malloc` or `mi_realloc` block of `size >= align`, `align <= 16` is
// aligned to `align` (mimalloc's `mi_malloc_is_naturally_aligned`), and
// every other layout takes the aligned entry points, as before.
unsafe impl std::alloc::GlobalAlloc for Mi {
    #[inline]
    unsafe fn alloc(&self, layout: std::alloc::Layout) -> *mut u8 {
        let (size, align) = (layout.size(), layout.align());
        // SAFETY: as for `MiMalloc` (a non-zero size, a power-of-two align).
        unsafe {
            if align <= NATURAL && align <= size {
                libmimalloc_sys::mi_malloc(size).cast()
            } else {
                libmimalloc_sys::mi_malloc_aligned(size, align).cast()
            }
        }
    }
    #[inline]
    unsafe fn alloc_zeroed(&self, layout: std::alloc::Layout) -> *mut u8 {
        let (size, align) = (layout.size(), layout.align());
        // SAFETY: as in `alloc`.
        unsafe {
            if align <= NATURAL && align <= size {
                libmimalloc_sys::mi_zalloc(size).cast()
            } else {
                libmimalloc_sys::mi_zalloc_aligned(size, align).cast()
            }
        }
    }
    #[inline]
    unsafe fn dealloc(&self, ptr: *mut u8, _layout: std::alloc::Layout) {
        // SAFETY: `ptr` came from this allocator, that is from mimalloc.
        unsafe { libmimalloc_sys::mi_free(ptr.cast()) }
    }
    #[inline]
    unsafe fn realloc(&self, ptr: *mut u8, layout: std::alloc::Layout, new_size: usize) -> *mut u8 {
        let align = layout.align();
        // SAFETY: `ptr` came from mimalloc; a block kept in place was
        // aligned already, a new one is naturally aligned (as in `alloc`).
        unsafe {
            if align <= NATURAL && align <= new_size {
                libmimalloc_sys::mi_realloc(ptr.cast(), new_size).cast()
            } else {
                libmimalloc_sys::mi_realloc_aligned(ptr.cast(), new_size, align).cast()
            }
        }
    }
}

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
