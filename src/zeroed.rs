//! Large buffers that start all zero and cost only the pages a computation touches (beyond the
//! paper, for speed only).
//!
//! A leg's waves keep bit planes and numbers over the whole grid (`plan::wave`: 1.2 MB a plane
//! at 1 deg, several a wave, two waves a search), yet a wave numbers the ball between its two
//! ends, a small part of the grid. A `vec![0; n]` of that size is zeroed whole: on a worker
//! thread the allocator hands out memory it cannot know is zero and writes every byte, so each
//! page of the buffer is faulted in and cleared: a third of the 11 000 page faults of a run on
//! torch-trunk at 1 deg went to pages no wave ever reads (7 300 with this buffer). [`ZeroBuf`] asks the operating system
//! for an anonymous mapping instead (`memmap2::MmapMut::map_anon`), whose pages read as zero
//! and are made (zeroed by the kernel) only when first written. Small buffers, and any mapping
//! the system refuses, are ordinary zeroed vectors: the contents are the same either way, only
//! the cost differs.

use bytemuck::Pod;
use memmap2::MmapMut;
use std::fmt;
use std::ops::{Deref, DerefMut};

/// Buffers of at least this many bytes are mapped (below it a mapping saves nothing worth a
/// system call): 64 pages.
pub const MAP_MIN_BYTES: usize = 256 * 1024;

/// `len` values of `T`, all zero at the start (module doc). Derefs to `[T]`.
pub struct ZeroBuf<T: Pod> {
    store: Store<T>,
}

enum Store<T> {
    Heap(Vec<T>),
    /// The mapping holds exactly the buffer's values (its length is their size in bytes).
    Mapped(MmapMut),
}

impl<T: Pod> ZeroBuf<T> {
    /// `len` zeros: mapped from [`MAP_MIN_BYTES`] on, else (or where the system refuses the
    /// mapping) in an ordinary vector.
    pub fn zeros(len: usize) -> ZeroBuf<T> {
        let bytes = len.checked_mul(std::mem::size_of::<T>());
        if let Some(bytes) = bytes.filter(|&b| b >= MAP_MIN_BYTES) {
            if let Ok(map) = MmapMut::map_anon(bytes) {
                // A mapping starts on a page boundary, so it holds `T`s at their alignment:
                // checked once here, so the casts of `deref` cannot fail.
                if bytemuck::try_cast_slice::<u8, T>(&map).is_ok() {
                    return ZeroBuf {
                        store: Store::Mapped(map),
                    };
                }
            }
        }
        ZeroBuf {
            store: Store::Heap(vec![T::zeroed(); len]),
        }
    }

    /// Whether the buffer is a mapping (for tests).
    pub fn is_mapped(&self) -> bool {
        matches!(self.store, Store::Mapped(_))
    }
}

impl<T: Pod> Deref for ZeroBuf<T> {
    type Target = [T];

    #[inline]
    fn deref(&self) -> &[T] {
        match &self.store {
            Store::Heap(v) => v,
            Store::Mapped(map) => bytemuck::cast_slice(map),
        }
    }
}

impl<T: Pod> DerefMut for ZeroBuf<T> {
    #[inline]
    fn deref_mut(&mut self) -> &mut [T] {
        match &mut self.store {
            Store::Heap(v) => v,
            Store::Mapped(map) => bytemuck::cast_slice_mut(map),
        }
    }
}

impl<T: Pod> Clone for ZeroBuf<T> {
    fn clone(&self) -> ZeroBuf<T> {
        let mut copy = ZeroBuf::zeros(self.len());
        copy.copy_from_slice(self);
        copy
    }
}

impl<T: Pod + fmt::Debug> fmt::Debug for ZeroBuf<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("ZeroBuf")
            .field("len", &self.len())
            .field("mapped", &self.is_mapped())
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn large_buffers_are_mapped_and_read_and_write_as_vectors_do() {
        for len in [
            0,
            1,
            1000,
            MAP_MIN_BYTES / 8 - 1,
            MAP_MIN_BYTES / 8,
            3 * MAP_MIN_BYTES / 8 + 5,
        ] {
            let mut z = ZeroBuf::<u64>::zeros(len);
            let mut v = vec![0u64; len];
            assert_eq!(z.len(), len);
            // Mapped from the threshold on where the system maps (a refused mapping falls back
            // to a vector, so only small buffers are held to the heap everywhere).
            if len * 8 < MAP_MIN_BYTES || cfg!(target_os = "linux") {
                assert_eq!(z.is_mapped(), len * 8 >= MAP_MIN_BYTES, "len {len}");
            }
            assert!(z.iter().all(|&x| x == 0));
            // Scattered writes, as a wave's are.
            let mut k = 1usize;
            for i in 0..len.min(5000) {
                k = k
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let at = (k >> 17) % len;
                z[at] ^= i as u64 + 1;
                v[at] ^= i as u64 + 1;
            }
            assert_eq!(&z[..], &v[..]);
            let c = z.clone();
            assert_eq!(&c[..], &v[..]);
            assert_eq!(c.is_mapped(), z.is_mapped());
        }
        let u = ZeroBuf::<u16>::zeros(MAP_MIN_BYTES);
        assert!(u.len() == MAP_MIN_BYTES && u.iter().all(|&x| x == 0));
    }
}
