//! The commands behind `gen-rapid`: each runs the pipeline stages it needs (`pipeline`), has
//! the output side make its text (`output`) and writes it. Only this module writes files (always
//! atomically) and stdout; `main.rs` only parses the command line and turns the result into an
//! exit status.

pub mod compare;
pub mod locate;
pub mod progress;
pub mod run;

use crate::error::Error;
use crate::pipeline::Loaded;
use std::io::Write;
use std::path::Path;

/// Prints the job's warnings (a robot without a controller file, ...) to stderr, one per line,
/// right after loading: before the summary line on success, before the error on failure.
/// Never on stdout.
pub fn warn(job: &Loaded) {
    for w in job.warnings() {
        eprintln!("{w}");
    }
}

/// Writes `bytes` to `path` atomically: a temporary file beside it, then a rename, so a failed
/// run leaves no half-written file and an existing file is replaced whole.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let err = |source| Error::Write {
        path: path.to_path_buf(),
        source,
    };
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result.map_err(err)
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

/// Writes to stdout (the module) or to a file; stdout only ever receives a complete result.
pub fn emit(output: Option<&Path>, bytes: &[u8]) -> Result<(), Error> {
    match output {
        Some(p) => write_atomically(p, bytes),
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(bytes)
                .and_then(|_| out.flush())
                .map_err(|source| Error::Write {
                    path: "<stdout>".into(),
                    source,
                })
        }
    }
}
