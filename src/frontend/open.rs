//! `:open`: shows the last picture written (LANGUAGE.md §12) with the
//! system's viewer (`xdg-open`, or `open` on macOS) where one exists.

use super::commands::Reply;
use crate::session::Session;

/// The first of `names` found on the PATH.
fn on_path(names: &[&'static str]) -> Option<&'static str> {
    let path = std::env::var_os("PATH")?;
    names
        .iter()
        .copied()
        .find(|n| std::env::split_paths(&path).any(|d| d.join(n).is_file()))
}

/// `:open`.
pub fn open(session: &Session) -> Reply {
    let Some(file) = &session.last_picture else {
        return Reply::err("no picture yet: draw one first, e.g. pic = draw(Rotz(pi/4))");
    };
    let Some(viewer) = on_path(&["xdg-open", "open"]) else {
        return Reply::err(format!(
            "no picture viewer found (xdg-open or open); the picture is {file}"
        ));
    };
    let child = std::process::Command::new(viewer)
        .arg(file)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn();
    match child {
        Ok(mut c) => {
            // Reap the viewer's launcher when it ends, without waiting here.
            std::thread::spawn(move || c.wait());
            Reply::out(format!("opened {file} with {viewer}"))
        }
        Err(e) => Reply::err(format!("cannot start {viewer}: {e}")),
    }
}
