//! The Jupyter kernel (LANGUAGE.md §13): `chasles kernel --connection-file
//! F` serves one session over the Jupyter messaging protocol, and
//! `chasles kernel install` writes the kernelspec.
//!
//! A front end like the REPL, with no mathematics of its own: [`cell`]
//! runs a notebook cell through the REPL's session and commands,
//! [`rich`] turns each value into the MIME bundle a notebook shows
//! (`text/plain`, `text/latex`, `image/svg+xml`, `application/json`),
//! [`install`] writes the kernelspec; `wire` (the `jupyter` feature, on by
//! default) carries them over ZeroMQ.

pub mod cell;
pub mod install;
pub mod rich;
#[cfg(feature = "jupyter")]
mod wire;

/// Serves the kernel on the sockets named in `connection_file` until the
/// notebook shuts it down, its session under the command line's
/// `options`; Err is the message for exit code 2 or 1.
pub fn serve(connection_file: &std::path::Path, options: cell::Options) -> Result<(), String> {
    #[cfg(feature = "jupyter")]
    return wire::serve(connection_file, options);
    #[cfg(not(feature = "jupyter"))]
    let _ = options;
    #[cfg(not(feature = "jupyter"))]
    Err(format!(
        "this chasles was built without the `jupyter` feature; cannot serve '{}'",
        connection_file.display()
    ))
}
