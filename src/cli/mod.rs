//! The commands behind `gen-rapid`: each runs the pipeline stages it needs (`pipeline`), has
//! the output side make its text (`output`) and writes it. Only this module writes files (always
//! atomically) and stdout; `main.rs` only parses the command line and turns the result into an
//! exit status.

pub mod compare;
pub mod locate;
pub mod progress;
pub mod robots;
pub mod run;

use crate::error::Error;
use crate::pipeline::Loaded;
use std::io::Write;
use std::path::Path;

/// Prints the job's warnings (a robot without a controller file, ...) to stderr, one per line,
/// right after loading: before the summary line on success, before the error on failure.
/// Never on stdout.
pub fn warn(job: &Loaded) {
    for w in crate::pipeline::warnings(job) {
        eprintln!("{w}");
    }
}

/// Writes every file atomically and, as far as the file system allows, all or none: each goes
/// to a temporary file beside its place first (a path that is a directory, or a directory that
/// is missing or read-only, fails here, before any file is in place), and only when all of them
/// are written are they renamed into place, in order. On a failure every temporary file left is
/// removed, so a run that cannot write its module leaves no picture, page or report of it
/// either (a rename failing after others succeeded, which needs the file system to change under
/// the run, is the one way to keep some). A path that names something other than a file or a
/// directory (a device such as `/dev/null` or `/dev/stdout`, a pipe) is written in place,
/// after every file is in place: a rename would replace the device with a file. A path that is
/// a link to a file (`/dev/stdout` redirected to a file) replaces the file it leads to, not the
/// link.
fn write_all_atomically(files: &[(&Path, &[u8])]) -> Result<(), Error> {
    use std::path::PathBuf;
    let err = |path: &Path| {
        let path = path.to_path_buf();
        move |source| Error::Write { path, source }
    };
    // (temporary file, where it goes, the path as named)
    let mut written: Vec<(PathBuf, PathBuf, &Path)> = Vec::new();
    let mut in_place: Vec<(&Path, &[u8])> = Vec::new();
    let clean = |temps: &[(PathBuf, PathBuf, &Path)]| {
        for (tmp, _, _) in temps {
            let _ = std::fs::remove_file(tmp);
        }
    };
    for (i, &(named, bytes)) in files.iter().enumerate() {
        if std::fs::metadata(named).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
            in_place.push((named, bytes));
            continue;
        }
        let link = std::fs::symlink_metadata(named).is_ok_and(|m| m.file_type().is_symlink());
        let path = if link {
            std::fs::canonicalize(named).unwrap_or_else(|_| named.to_path_buf())
        } else {
            named.to_path_buf()
        };
        let dir = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let tmp = dir.join(format!(".{name}.{}.{i}.tmp", std::process::id()));
        let result = (|| {
            if path.is_dir() {
                return Err(std::io::Error::new(
                    std::io::ErrorKind::IsADirectory,
                    "it is a directory",
                ));
            }
            let mut f = std::fs::File::create(&tmp)?;
            written.push((tmp.clone(), path.clone(), named));
            f.write_all(bytes)?;
            f.sync_all()
        })();
        if let Err(e) = result {
            clean(&written);
            return Err(err(named)(e));
        }
    }
    for (k, (tmp, path, named)) in written.iter().enumerate() {
        if let Err(e) = std::fs::rename(tmp, path) {
            clean(&written[k..]);
            return Err(err(named)(e));
        }
    }
    for (path, bytes) in in_place {
        std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .and_then(|mut f| f.write_all(bytes))
            .map_err(err(path))?;
    }
    Ok(())
}

/// Whether two paths name the same file: equal, equal made absolute, or equal resolved (links
/// and `..` of paths that exist).
pub fn same_file(a: &Path, b: &Path) -> bool {
    a == b
        || matches!(
            (std::path::absolute(a), std::path::absolute(b)),
            (Ok(x), Ok(y)) if x == y
        )
        || matches!(
            (std::fs::canonicalize(a), std::fs::canonicalize(b)),
            (Ok(x), Ok(y)) if x == y
        )
}

/// [`write_all_atomically`] for a command on a loaded cell: refused, before anything is
/// written, where an output names the robot's URDF or controller file ([`refuse_inputs`]).
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
    write_all_atomically(files)
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

/// Writes to stdout (the module, `compare`'s table, `locate`'s report); stdout only ever
/// receives a complete result.
pub fn emit(bytes: &[u8]) -> Result<(), Error> {
    let mut out = std::io::stdout().lock();
    out.write_all(bytes)
        .and_then(|_| out.flush())
        .map_err(|source| Error::Write {
            path: "<stdout>".into(),
            source,
        })
}
