//! The commands behind `gen-rapid`: each runs the pipeline stages it needs (`pipeline`), has
//! the output side make its text (`output`) and writes it. Only this module writes files (always
//! atomically) and stdout; `main.rs` only parses the command line and turns the result into an
//! exit status.

pub mod compare;
pub mod locate;
pub mod outputs;
pub mod progress;
pub mod robots;
pub mod run;
pub mod warnings;

use crate::error::Error;
use crate::pipeline::Loaded;
use std::path::{Path, PathBuf};

/// Prints the job's warnings (a robot without a controller file, ...) to stderr, grouped by
/// kind ([`warnings::grouped`]), right after loading: before the summary line on success,
/// before the error on failure. Never on stdout.
pub fn warn(job: &Loaded) {
    warn_lines(&crate::pipeline::warnings(job));
}

/// Prints warnings to stderr, grouped by kind ([`warnings::grouped`]).
pub fn warn_lines(lines: &[String]) {
    for line in warnings::grouped(lines) {
        outputs::say(&format!("{line}\n"));
    }
}

/// Whether two paths name the same file: the same destination ([`destination`]: resolved links
/// and `..`, whether the file exists or not), or the same file on the disk (a hard link, or
/// `/dev/stdout` and the file stdout goes to).
pub fn same_file(a: &Path, b: &Path) -> bool {
    if a == b {
        return true;
    }
    if let (Some(x), Some(y)) = (destination(a), destination(b)) {
        if x == y {
            return true;
        }
    }
    matches!((identity(a), identity(b)), (Some(x), Some(y)) if x == y)
}

/// The file a path will be once written, as an absolute path with no link and no `.` or `..`
/// left: a link followed as the writer follows it ([`outputs::target_of`], also a link to a
/// file not yet written), the longest part of it that exists resolved by the file system, the
/// rest, which does not exist yet, taken as written (`d/../a.svg` and `./a.svg` are one file
/// when `d` is a directory). `None` when the path cannot be resolved
/// (a `..` after a part that does not exist: such a path cannot be written at all).
pub fn destination(path: &Path) -> Option<PathBuf> {
    use std::path::Component;
    let absolute = std::path::absolute(outputs::target_of(path)).ok()?;
    let mut resolved = PathBuf::new();
    let mut missing = false;
    for part in absolute.components() {
        match part {
            Component::Prefix(_) | Component::RootDir => resolved.push(part.as_os_str()),
            Component::CurDir => {}
            Component::ParentDir if missing => return None,
            Component::ParentDir => {
                resolved.pop();
            }
            Component::Normal(name) => {
                resolved.push(name);
                if !missing {
                    match std::fs::canonicalize(&resolved) {
                        Ok(real) => resolved = real,
                        Err(_) => missing = true,
                    }
                }
            }
        }
    }
    Some(resolved)
}

/// The device and inode of the file a path names, following links, if it exists.
fn identity(path: &Path) -> Option<(u64, u64)> {
    use std::os::unix::fs::MetadataExt;
    std::fs::metadata(path).ok().map(|m| (m.dev(), m.ino()))
}

/// The device and inode of the file stdout writes (a file, a pipe, a terminal), if it is open.
pub fn stdout_identity() -> Option<(u64, u64)> {
    use std::os::fd::AsFd;
    use std::os::unix::fs::MetadataExt;
    let fd = std::io::stdout().as_fd().try_clone_to_owned().ok()?;
    let m = std::fs::File::from(fd).metadata().ok()?;
    Some((m.dev(), m.ino()))
}

/// Whether the path names the file stderr writes (`/dev/stderr`, or the file stderr goes to);
/// `/dev/null` never counts.
pub fn is_stderr(path: &Path) -> bool {
    use std::os::fd::AsFd;
    use std::os::unix::fs::MetadataExt;
    let err = std::io::stderr()
        .as_fd()
        .try_clone_to_owned()
        .ok()
        .and_then(|fd| std::fs::File::from(fd).metadata().ok())
        .map(|m| (m.dev(), m.ino()));
    let null = identity(Path::new("/dev/null"));
    match (identity(path), err) {
        (Some(x), Some(y)) => x == y && Some(x) != null,
        _ => false,
    }
}

/// Whether the path names the file stdout writes (`/dev/stdout`, `/proc/self/fd/1`, or the
/// file stdout is redirected to); `/dev/null` never counts (discarding twice loses nothing).
pub fn is_stdout(path: &Path) -> bool {
    let null = identity(Path::new("/dev/null"));
    match (identity(path), stdout_identity()) {
        (Some(x), Some(y)) => x == y && Some(x) != null,
        _ => false,
    }
}

/// An output that cannot be written whatever the run makes, found before the run: a directory,
/// or a file in a directory that does not exist. (The write itself still checks, and all the
/// rest: a read-only directory, a full disk.)
pub fn unwritable(path: &Path) -> Option<Error> {
    let why = if path.is_dir() {
        "it is a directory"
    } else {
        let dir = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        if target_of_exists(path) || dir.is_dir() {
            return None;
        }
        "its directory does not exist"
    };
    Some(Error::Write {
        path: path.to_path_buf(),
        source: std::io::Error::new(std::io::ErrorKind::NotFound, why),
    })
}

/// Whether the path (followed through links) names something that exists.
fn target_of_exists(path: &Path) -> bool {
    std::fs::metadata(path).is_ok()
}

/// Stages a command's files ([`outputs::stage`]: each in a temporary file now, renamed into
/// place when the command is over): refused, before anything is written, where an output names
/// the robot's URDF or controller file ([`refuse_inputs`]).
/// Every command's files go through here (a run's, its failure's pictures, `locate`'s and
/// `compare`'s pictures).
pub fn write_for(job: &crate::pipeline::Loaded, files: &[(&Path, &[u8])]) -> Result<(), Error> {
    let robot = &job.robot;
    // A shipped model's files are built in: the run reads none.
    let read: Vec<&Path> = match robot.model {
        Some(_) => Vec::new(),
        None => std::iter::once(robot.urdf_path.as_path())
            .chain(robot.controller.source.as_deref())
            .collect(),
    };
    refuse_inputs(files, &read)?;
    outputs::stage(files)
}

/// Refuses to write over a file the run reads (the robot's URDF or controller file, known
/// only once the cell is loaded; the cell and the template the command line checks first).
fn refuse_inputs(outputs: &[(&Path, &[u8])], inputs: &[&Path]) -> Result<(), Error> {
    for (path, _) in outputs {
        if inputs.iter().any(|input| same_file(path, input)) {
            return Err(Error::Write {
                path: path.to_path_buf(),
                source: std::io::Error::other("it is a file the run reads"),
            });
        }
    }
    Ok(())
}

/// A report as pretty JSON with a final newline (for `--json`).
pub fn to_json<T: serde::Serialize>(value: &T) -> Result<String, Error> {
    let mut text = serde_json::to_string_pretty(value).map_err(|e| Error::Write {
        path: "<stdout>".into(),
        source: std::io::Error::other(e),
    })?;
    text.push('\n');
    Ok(text)
}

/// Keeps the bytes for stdout (the module, `compare`'s table, `locate`'s report), written when
/// the command is over ([`outputs::commit`]): stdout only ever receives a complete result.
pub fn emit(bytes: &[u8]) -> Result<(), Error> {
    outputs::print(bytes);
    Ok(())
}
