//! An ordered parallel map on the machine's cores (std threads, no pool): the items are handed
//! out one at a time as each thread asks for the next, so items of very different cost keep every
//! core busy, and the results come back in the items' order, whoever computed them. Used where a
//! stage does independent, deterministic work per item: the smallest clearance of each move in
//! `plan::certify`, the zoned corners' proofs and clearances in `refine::zones`, each leg's
//! proofs in `refine::shortcut`, and with a limit on threads ([`map_on`]) the legs of a route in
//! `plan::route`.

use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock};

/// `items.iter().map(f).collect()`, computed on up to `available_parallelism` threads. A panic
/// in `f` makes this panic too (`std::thread::scope`, with its own message; the panic hook has
/// printed the first one).
pub fn map<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    map_on(usize::MAX, items, f)
}

/// The machine's cores (1 where it cannot tell), asked of the system once.
fn cores() -> usize {
    static CORES: OnceLock<usize> = OnceLock::new();
    *CORES.get_or_init(|| {
        std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
    })
}

/// Threads computing items of a map now, its caller included, counting the thread that
/// first calls a map as one ([`map_on`]).
static RUNNING: AtomicUsize = AtomicUsize::new(1);

/// [`map`] on at most `max_threads` threads (and no more than the cores or the items): at most
/// that many items are in hand at once, whatever memory each holds. `max_threads` 0 or 1
/// computes every item here, in order.
///
/// The caller computes items too, beside the threads it starts (and counts as idle once it only
/// waits for them), and a map asked while other maps' threads keep the cores busy (a map inside
/// a map's item) starts only as many threads as cores are left: a thread costs tens of
/// microseconds to start, and more threads than cores only share them. Which thread computes an
/// item never changes its result.
pub fn map_on<T: Sync, R: Send>(
    max_threads: usize,
    items: &[T],
    f: impl Fn(&T) -> R + Sync,
) -> Vec<R> {
    let idle = cores().saturating_sub(RUNNING.load(Ordering::Relaxed));
    let threads = (1 + idle).min(max_threads).min(items.len());
    if threads <= 1 {
        return items.iter().map(f).collect();
    }
    let next = AtomicUsize::new(0);
    let done: Mutex<Vec<(usize, R)>> = Mutex::new(Vec::with_capacity(items.len()));
    let work = || {
        let mut mine = Vec::new();
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(item) = items.get(i) else {
                break;
            };
            mine.push((i, f(item)));
        }
        // A poisoned lock only means another thread panicked; the scope re-raises it.
        if let Ok(mut all) = done.lock() {
            all.extend(mine);
        }
    };
    let waiting = Waiting(Cell::new(false));
    std::thread::scope(|s| {
        for _ in 1..threads {
            RUNNING.fetch_add(1, Ordering::Relaxed);
            s.spawn(|| {
                // Counted out when it has no more items, or when its item panicked.
                let _running = Running;
                work();
            });
        }
        work();
        // No more items: the caller waits for its threads, and its core is free for theirs.
        RUNNING.fetch_sub(1, Ordering::Relaxed);
        waiting.0.set(true);
    });
    drop(waiting);
    let mut all = done.into_inner().unwrap_or_else(|e| e.into_inner());
    all.sort_unstable_by_key(|&(i, _)| i);
    all.into_iter().map(|(_, r)| r).collect()
}

/// The caller of a map, counted out of [`RUNNING`] while it waits for the threads it started
/// (when it holds `true`), and back in when it is dropped.
struct Waiting(Cell<bool>);

impl Drop for Waiting {
    fn drop(&mut self) {
        if self.0.get() {
            RUNNING.fetch_add(1, Ordering::Relaxed);
        }
    }
}

/// A thread a map started, counted in [`RUNNING`] until it is dropped.
struct Running;

impl Drop for Running {
    fn drop(&mut self) {
        RUNNING.fetch_sub(1, Ordering::Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::map;

    #[test]
    fn results_come_back_in_the_items_order() {
        // Items of very different cost, so the threads finish them out of order.
        let items: Vec<u64> = (0..200).map(|i| (i * 7919) % 1000).collect();
        let slow = |&n: &u64| (0..n * 1000).fold(n, |a, k| a.wrapping_mul(31).wrapping_add(k));
        let want: Vec<u64> = items.iter().map(slow).collect();
        assert_eq!(map(&items, slow), want);
        assert_eq!(map(&items[..1], slow), want[..1]);
        assert!(map(&items[..0], slow).is_empty());
    }

    #[test]
    fn never_more_items_in_hand_than_threads_allowed() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        let (now, most) = (AtomicUsize::new(0), AtomicUsize::new(0));
        let items: Vec<u64> = (0..64).collect();
        let f = |&n: &u64| {
            let k = now.fetch_add(1, Ordering::SeqCst) + 1;
            most.fetch_max(k, Ordering::SeqCst);
            std::thread::sleep(std::time::Duration::from_micros(200));
            now.fetch_sub(1, Ordering::SeqCst);
            n * 3
        };
        let want: Vec<u64> = items.iter().map(|n| n * 3).collect();
        assert_eq!(super::map_on(1, &items, f), want);
        assert_eq!(most.load(Ordering::SeqCst), 1);
        assert_eq!(super::map_on(2, &items, f), want);
        assert!(most.load(Ordering::SeqCst) <= 2);
    }

    /// Maps inside a map's items start no thread beyond the cores: at most as many inner items
    /// are computed at once as there are cores (each of the 4 outer items asking for 16 inner
    /// ones, a map that started a thread a core whatever the others do would compute up to the
    /// square of the cores at once). The results come back in order all the same.
    #[test]
    fn maps_inside_maps_use_no_more_threads_than_cores() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        let (now, most) = (AtomicUsize::new(0), AtomicUsize::new(0));
        let outer: Vec<u64> = (0..4).collect();
        let inner: Vec<u64> = (0..16).collect();
        let got = map(&outer, |&o| {
            map(&inner, |&i| {
                let k = now.fetch_add(1, Ordering::SeqCst) + 1;
                most.fetch_max(k, Ordering::SeqCst);
                std::thread::sleep(std::time::Duration::from_micros(300));
                now.fetch_sub(1, Ordering::SeqCst);
                o * 100 + i
            })
        });
        let want: Vec<Vec<u64>> = outer
            .iter()
            .map(|o| inner.iter().map(|i| o * 100 + i).collect())
            .collect();
        assert_eq!(got, want);
        let most = most.load(Ordering::SeqCst);
        assert!(most >= 1 && most <= super::cores(), "{most} at once");
    }
}
