//! `chasles kernel install [--user|--sys-prefix]` (LANGUAGE.md §13): the
//! kernelspec that makes Jupyter, JupyterLab and VS Code list chasles — a
//! folder `kernels/chasles/` with `kernel.json` (the command that starts
//! the kernel) and the logo, in Jupyter's user data folder or the active
//! Python environment's.

use std::path::{Path, PathBuf};

use serde_json::json;

/// Where a kernelspec goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    /// The user's Jupyter data folder: `$JUPYTER_DATA_DIR`, else the
    /// platform's (`~/.local/share/jupyter`, `~/Library/Jupyter`,
    /// `%APPDATA%\jupyter`).
    User,
    /// The active Python environment (`$VIRTUAL_ENV` or `$CONDA_PREFIX`),
    /// else the one `pip install chasles` put this binary in (its folder's
    /// parent holds `pyvenv.cfg` or `conda-meta`): `PREFIX/share/jupyter`.
    SysPrefix,
}

/// The kernel's name in Jupyter (`jupyter kernelspec list`).
pub const NAME: &str = "chasles";

/// The Jupyter data folder for `place`, as `jupyter --data-dir` reports it.
pub fn data_dir(place: Place) -> Result<PathBuf, String> {
    let var = |name: &str| std::env::var_os(name).filter(|v| !v.is_empty());
    match place {
        Place::User => {
            if let Some(d) = var("JUPYTER_DATA_DIR") {
                return Ok(PathBuf::from(d));
            }
            let base = if cfg!(target_os = "macos") {
                dirs::home_dir().map(|h| h.join("Library").join("Jupyter"))
            } else {
                dirs::data_dir().map(|d| d.join("jupyter"))
            };
            base.ok_or_else(|| "cannot find the user's data folder; set JUPYTER_DATA_DIR".into())
        }
        Place::SysPrefix => var("VIRTUAL_ENV")
            .or_else(|| var("CONDA_PREFIX"))
            .map(PathBuf::from)
            .or_else(own_environment)
            .map(|p| p.join("share").join("jupyter"))
            .ok_or_else(|| {
                "--sys-prefix needs an active Python environment (VIRTUAL_ENV or CONDA_PREFIX); \
                 use --user"
                    .into()
            }),
    }
}

/// The Python environment this binary was installed in by pip (a wheel
/// puts it in `PREFIX/bin` or `PREFIX\Scripts`), if it is one.
fn own_environment() -> Option<PathBuf> {
    environment_of(&std::env::current_exe().ok()?)
}

/// The Python environment holding the binary `exe`, if it is in one.
fn environment_of(exe: &Path) -> Option<PathBuf> {
    let prefix = exe.parent()?.parent()?;
    (prefix.join("pyvenv.cfg").is_file() || prefix.join("conda-meta").is_dir())
        .then(|| prefix.to_path_buf())
}

/// The `kernel.json` that starts `binary` as the kernel.
pub fn kernel_json(binary: &Path) -> serde_json::Value {
    json!({
        "argv": [binary.to_string_lossy(), "kernel", "--connection-file", "{connection_file}"],
        "display_name": "chasles",
        "language": "chasles",
        "interrupt_mode": "message",
        "metadata": { "debugger": false },
    })
}

/// The logo: the axes of a frame, x̂ red, ŷ green, ẑ blue, as `draw` shows them.
pub fn logo_svg(size: u32) -> String {
    format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" viewBox="0 0 64 64">
<rect width="64" height="64" rx="10" fill="#ffffff"/>
<g stroke-width="6" stroke-linecap="round">
<line x1="22" y1="44" x2="56" y2="44" stroke="#d62728"/>
<line x1="22" y1="44" x2="22" y2="8" stroke="#2ca02c"/>
<line x1="22" y1="44" x2="6" y2="60" stroke="#1f77b4"/>
</g>
<circle cx="22" cy="44" r="5" fill="#333333"/>
</svg>
"##
    )
}

/// Writes the kernelspec for `binary` into `data/kernels/chasles/`;
/// returns that folder.
pub fn install_into(data: &Path, binary: &Path) -> Result<PathBuf, String> {
    let dir = data.join("kernels").join(NAME);
    let fail = |what: &Path, e: std::io::Error| {
        format!(
            "cannot write '{}': {}",
            what.display(),
            crate::effects::atomic::reason(&e)
        )
    };
    std::fs::create_dir_all(&dir).map_err(|e| fail(&dir, e))?;
    let spec = serde_json::to_string_pretty(&kernel_json(binary)).unwrap_or_default();
    let files: Vec<(&str, Vec<u8>)> = vec![
        ("kernel.json", format!("{spec}\n").into_bytes()),
        ("logo-svg.svg", logo_svg(64).into_bytes()),
        ("logo-32x32.png", crate::draw::file::png(&logo_svg(32))?),
        ("logo-64x64.png", crate::draw::file::png(&logo_svg(64))?),
    ];
    for (name, bytes) in files {
        let path = dir.join(name);
        crate::effects::atomic::write(&path, &bytes, true).map_err(|e| fail(&path, e))?;
    }
    Ok(dir)
}

/// `chasles kernel install`: the spec for the running binary in `place`.
pub fn install(place: Place) -> Result<PathBuf, String> {
    let binary = std::env::current_exe()
        .and_then(|p| p.canonicalize())
        .map_err(|e| format!("cannot find the chasles binary: {e}"))?;
    install_into(&data_dir(place)?, &binary)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_binary_in_a_virtual_environment_knows_its_prefix() {
        let venv = std::env::temp_dir().join(format!("chasles-venv-{}", std::process::id()));
        std::fs::create_dir_all(venv.join("bin")).unwrap();
        let exe = venv.join("bin").join("chasles");
        assert_eq!(environment_of(&exe), None);
        std::fs::write(venv.join("pyvenv.cfg"), "home = /usr/bin\n").unwrap();
        assert_eq!(environment_of(&exe), Some(venv.clone()));
        let _ = std::fs::remove_dir_all(&venv);
    }

    #[test]
    fn the_spec_starts_the_kernel_with_the_connection_file() {
        let j = kernel_json(Path::new("/opt/bin/chasles"));
        assert_eq!(
            j["argv"],
            json!([
                "/opt/bin/chasles",
                "kernel",
                "--connection-file",
                "{connection_file}"
            ])
        );
        assert_eq!(j["language"], "chasles");
    }

    #[test]
    fn install_writes_the_spec_and_logos() {
        let tmp = std::env::temp_dir().join(format!("chasles-spec-{}", std::process::id()));
        let dir = install_into(&tmp, Path::new("/bin/chasles")).expect("installs");
        for f in [
            "kernel.json",
            "logo-svg.svg",
            "logo-32x32.png",
            "logo-64x64.png",
        ] {
            assert!(dir.join(f).is_file(), "{f}");
        }
        let png = std::fs::read(dir.join("logo-32x32.png")).expect("png");
        assert_eq!(&png[1..4], b"PNG");
        let _ = std::fs::remove_dir_all(&tmp);
    }
}
