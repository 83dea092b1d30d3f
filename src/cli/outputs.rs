//! The process's outputs, committed together at the end of a command: the files it writes (each
//! made in a temporary file beside its place as soon as the command has it), what it prints on
//! stdout, and the summary line on stderr. Nothing reaches a file's place, stdout or the summary
//! line until the command is over, and then in an order that leaves nothing behind on a failure:
//!
//! 1. stdout (the module, `compare`'s table, `locate`'s report): if it cannot be written (a
//!    closed pipe, a full disk, `/dev/full`), no file is put in place;
//! 2. the summary line on stderr: if stderr cannot be written (or an earlier warning could not
//!    be), no file is put in place either, and the exit status is 4;
//! 3. the temporary files renamed into place, in order (a rename failing after others succeeded,
//!    which needs the file system to change under the run, is the one way to keep some);
//! 4. the outputs that are devices or pipes (`/dev/null`, a FIFO), written in place, last (a
//!    rename would replace the device with a file).
//!
//! One command runs per process (`main.rs`), so the pending outputs are the process's: a
//! `Mutex`, not an argument threaded through every command. Every write to stderr goes through
//! [`say`], which never panics (`eprintln!` panics on a failed write, `2>/dev/full`) and
//! remembers a failure for step 2.

use crate::error::Error;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// What the command has made and not yet committed.
#[derive(Default)]
struct Pending {
    /// (temporary file, the file it replaces, the path as named on the command line).
    renames: Vec<(PathBuf, PathBuf, PathBuf)>,
    /// Devices and pipes, written in place at the end.
    in_place: Vec<(PathBuf, Vec<u8>)>,
    stdout: Vec<u8>,
}

static PENDING: Mutex<Pending> = Mutex::new(Pending {
    renames: Vec::new(),
    in_place: Vec::new(),
    stdout: Vec::new(),
});

/// A write to stderr failed (`2>/dev/full`): the run cannot report itself, so it fails (exit 4).
static STDERR_FAILED: AtomicBool = AtomicBool::new(false);

/// Numbers the temporary files of the process (two outputs beside each other never share one).
static TEMPORARIES: AtomicUsize = AtomicUsize::new(0);

fn pending() -> std::sync::MutexGuard<'static, Pending> {
    // A panic while holding the lock cannot leave the lists half-changed in a way that matters:
    // they are only pushed to and drained.
    PENDING.lock().unwrap_or_else(|e| e.into_inner())
}

/// Writes `text` to stderr, never panicking; a failure is remembered ([`stderr_failed`]).
pub fn say(text: &str) {
    let mut err = std::io::stderr().lock();
    if err
        .write_all(text.as_bytes())
        .and_then(|_| err.flush())
        .is_err()
    {
        STDERR_FAILED.store(true, Ordering::SeqCst);
    }
}

/// Whether a write to stderr has failed in this process.
pub fn stderr_failed() -> bool {
    STDERR_FAILED.load(Ordering::SeqCst)
}

/// The error of a write to a path.
fn write_error(path: &Path) -> impl Fn(std::io::Error) -> Error + '_ {
    move |source| Error::Write {
        path: path.to_path_buf(),
        source,
    }
}

/// The file a path writes: a link is followed (its target is replaced, not the link), also a
/// link to a file not yet written; anything else is the path itself.
pub fn target_of(named: &Path) -> PathBuf {
    let mut path = named.to_path_buf();
    // As the system follows links: at most 40 of them.
    for _ in 0..40 {
        let link = std::fs::symlink_metadata(&path).is_ok_and(|m| m.file_type().is_symlink());
        if !link {
            return path;
        }
        if let Ok(real) = std::fs::canonicalize(&path) {
            return real;
        }
        match std::fs::read_link(&path) {
            Ok(to) => {
                path = match path.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                }
            }
            Err(_) => return path,
        }
    }
    path
}

/// Whether the path names a device, a pipe or a socket (written in place, never renamed over).
fn is_device(path: &Path) -> bool {
    std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir())
}

/// Stages `files`: each goes to a temporary file beside its place now (a path that is a
/// directory, or whose directory is missing or read-only, fails here, and the temporaries of
/// this call are removed), to be renamed into place by [`commit`]. A device or pipe is kept to
/// be written in place by [`commit`], last.
pub fn stage(files: &[(&Path, &[u8])]) -> Result<(), Error> {
    let mut made: Vec<(PathBuf, PathBuf, PathBuf)> = Vec::new();
    let mut devices: Vec<(PathBuf, Vec<u8>)> = Vec::new();
    let clean = |made: &[(PathBuf, PathBuf, PathBuf)]| {
        for (tmp, _, _) in made {
            let _ = std::fs::remove_file(tmp);
        }
    };
    for &(named, bytes) in files {
        if is_device(named) {
            devices.push((named.to_path_buf(), bytes.to_vec()));
            continue;
        }
        let path = target_of(named);
        let dir = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let i = TEMPORARIES.fetch_add(1, Ordering::SeqCst);
        let tmp = dir.join(format!(".{name}.{}.{i}.tmp", std::process::id()));
        let result = (|| {
            if path.is_dir() {
                return Err(std::io::Error::new(
                    std::io::ErrorKind::IsADirectory,
                    "it is a directory",
                ));
            }
            let mut f = std::fs::File::create(&tmp)?;
            made.push((tmp.clone(), path.clone(), named.to_path_buf()));
            f.write_all(bytes)?;
            f.sync_all()
        })();
        if let Err(e) = result {
            clean(&made);
            return Err(write_error(named)(e));
        }
    }
    let mut p = pending();
    p.renames.extend(made);
    p.in_place.extend(devices);
    Ok(())
}

/// Keeps `bytes` for stdout ([`commit`] writes them).
pub fn print(bytes: &[u8]) {
    pending().stdout.extend_from_slice(bytes);
}

/// Removes every temporary file staged and forgets what was pending.
pub fn abandon() {
    let mut p = pending();
    for (tmp, _, _) in p.renames.drain(..) {
        let _ = std::fs::remove_file(tmp);
    }
    p.in_place.clear();
    p.stdout.clear();
}

/// Commits what is pending, in the order of the module docs; `summary` is the success line for
/// stderr (`None`: a failed command, or `--quiet`). On a failed command (`failed`) an earlier
/// failure to write stderr does not stop the pictures of the failure from being committed (the
/// exit status is an error already).
pub fn commit(summary: Option<&str>, failed: bool) -> Result<(), Error> {
    let stdout = std::mem::take(&mut pending().stdout);
    let stderr_error = || Error::Write {
        path: "<stderr>".into(),
        source: std::io::Error::other("stderr cannot be written, so the run cannot report itself"),
    };
    if !failed && stderr_failed() {
        abandon();
        return Err(stderr_error());
    }
    if !stdout.is_empty() {
        let mut out = std::io::stdout().lock();
        if let Err(source) = out.write_all(&stdout).and_then(|_| out.flush()) {
            abandon();
            return Err(Error::Write {
                path: "<stdout>".into(),
                source,
            });
        }
    }
    if let Some(line) = summary {
        say(&format!("{line}\n"));
        if stderr_failed() {
            abandon();
            return Err(stderr_error());
        }
    }
    let (renames, in_place) = {
        let mut p = pending();
        (
            std::mem::take(&mut p.renames),
            std::mem::take(&mut p.in_place),
        )
    };
    for (k, (tmp, path, named)) in renames.iter().enumerate() {
        if let Err(e) = std::fs::rename(tmp, path) {
            for (tmp, _, _) in &renames[k..] {
                let _ = std::fs::remove_file(tmp);
            }
            return Err(write_error(named)(e));
        }
    }
    for (path, bytes) in in_place {
        std::fs::OpenOptions::new()
            .write(true)
            .open(&path)
            .and_then(|mut f| f.write_all(&bytes))
            .map_err(write_error(&path))?;
    }
    Ok(())
}
