//! Leaf: reads an input file (the cell, the URDF, the controller file, a `--template`) whole,
//! but at most [`MAX_INPUT_BYTES`]: a path naming `/dev/zero`, a device or a runaway file ends
//! in an error, not in the memory running out (a cell is a few KB, a URDF a few hundred). And
//! [`MAX_MAGNITUDE`], the bound of every number the cell and the URDF give.

use std::io::Read;
use std::path::Path;

/// The largest input file read (64 MiB).
pub const MAX_INPUT_BYTES: u64 = 64 * 1024 * 1024;

/// The largest magnitude of any number a cell gives (positions, box corners, shapes, frames,
/// the cog and base in mm, the clearance, the mass in kg, the yaw and joint values in deg):
/// 1 km in mm; a URDF's lengths are held to the same 1 km. Far beyond any work cell, and small
/// enough that every value the module writes (tooldata, wobjdata, robtargets) is a RAPID `num`
/// literal of a few digits and the geometry keeps its precision; 1e300 in a `cog` would
/// otherwise be written as 301 digits, which no controller loads.
pub const MAX_MAGNITUDE: f64 = 1e6;

/// The bytes of the file at `path`, or an error if it cannot be read or holds more than
/// [`MAX_INPUT_BYTES`].
pub fn read_bytes(path: &Path) -> std::io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    std::fs::File::open(path)?
        .take(MAX_INPUT_BYTES + 1)
        .read_to_end(&mut bytes)?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "it holds more than {} MiB, far more than any input gen-rapid reads (is it the right file?)",
                MAX_INPUT_BYTES / (1024 * 1024)
            ),
        ));
    }
    Ok(bytes)
}

/// The text of the file at `path` ([`read_bytes`], then UTF-8 as `std::fs::read_to_string`).
pub fn read_text(path: &Path) -> std::io::Result<String> {
    String::from_utf8(read_bytes(path)?).map_err(|_| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            "stream did not contain valid UTF-8",
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_is_read_whole_and_an_endless_one_is_refused() {
        let dir = std::env::temp_dir().join(format!("gen-rapid-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("dir");
        let f = dir.join("cell.yaml");
        std::fs::write(&f, "module: A\n").expect("write");
        assert_eq!(read_text(&f).expect("read"), "module: A\n");
        std::fs::write(&f, [0xff, 0xfe]).expect("write");
        assert!(read_text(&f).is_err());
        let _ = std::fs::remove_dir_all(&dir);
        // Before: read until the memory ran out (the process killed after about a minute).
        let zero = Path::new("/dev/zero");
        if zero.exists() {
            let e = read_bytes(zero).expect_err("endless");
            assert!(e.to_string().contains("more than 64 MiB"), "{e}");
        }
    }
}
