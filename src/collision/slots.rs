//! The distances a bisection's intervals name, each kept while an interval on its stack names
//! it: a slot is freed when the last interval naming it is dropped and taken again by the next
//! distance measured. A bisection holds at most two slots per interval on its stack, however
//! many distances it measures (up to a million along a grazing move), so its memory stays a few
//! kilobytes; the distances are read and narrowed in place, shared by the two intervals that
//! meet at a midpoint.

/// Reference-counted slots of `T`.
pub(super) struct Slots<T> {
    items: Vec<T>,
    /// Per slot, the intervals that name it (0: free).
    refs: Vec<u32>,
    free: Vec<usize>,
}

impl<T> Slots<T> {
    pub(super) fn new() -> Self {
        Self {
            items: Vec::new(),
            refs: Vec::new(),
            free: Vec::new(),
        }
    }

    /// Every slot free, the memory kept.
    pub(super) fn clear(&mut self) {
        self.items.clear();
        self.refs.clear();
        self.free.clear();
    }

    /// Keeps `value` for `refs` intervals; its slot.
    pub(super) fn put(&mut self, value: T, refs: u32) -> usize {
        if let Some(i) = self.free.pop() {
            self.items[i] = value;
            self.refs[i] = refs;
            i
        } else {
            self.items.push(value);
            self.refs.push(refs);
            self.items.len() - 1
        }
    }

    /// One interval fewer names slot `i`; the slot is free when none does.
    pub(super) fn release(&mut self, i: usize) {
        if let Some(r) = self.refs.get_mut(i) {
            *r = r.saturating_sub(1);
            if *r == 0 {
                self.free.push(i);
            }
        }
    }

    /// The value of slot `i`.
    pub(super) fn get(&mut self, i: usize) -> &mut T {
        &mut self.items[i]
    }

    /// The values of two different slots.
    pub(super) fn two(&mut self, i: usize, j: usize) -> (&mut T, &mut T) {
        if i < j {
            let (a, b) = self.items.split_at_mut(j);
            (&mut a[i], &mut b[0])
        } else {
            let (a, b) = self.items.split_at_mut(i);
            (&mut b[0], &mut a[j])
        }
    }

    /// Slots in use or free (the memory held, in values).
    #[cfg(test)]
    pub(super) fn capacity_used(&self) -> usize {
        self.items.len()
    }
}

#[cfg(test)]
mod tests {
    use super::Slots;

    #[test]
    fn a_slot_is_taken_again_once_no_interval_names_it() {
        let mut s = Slots::new();
        let a = s.put(1.0, 1);
        let b = s.put(2.0, 2);
        assert_ne!(a, b);
        s.release(b);
        // Still named once: a new value takes a fresh slot.
        let c = s.put(3.0, 1);
        assert!(c != a && c != b);
        s.release(b);
        let d = s.put(4.0, 1);
        assert_eq!(d, b, "the freed slot is taken again");
        assert_eq!(*s.get(d), 4.0);
        assert_eq!(*s.get(a), 1.0);
        let (x, y) = s.two(c, a);
        assert_eq!((*x, *y), (3.0, 1.0));
        assert_eq!(s.capacity_used(), 3);
    }

    #[test]
    fn a_depth_first_bisection_holds_few_slots() {
        // A bisection of 2^16 leaves, as the proofs run it: an interval's ends named by its
        // stack entry, the midpoint named by both halves.
        let mut s = Slots::new();
        let (a, b) = (s.put(0u32, 1), s.put(1u32, 1));
        let mut stack = vec![(0u32, 16u32, a, b)];
        let mut measured = 2usize;
        while let Some((t, depth, i0, i1)) = stack.pop() {
            if depth == 0 {
                s.release(i0);
                s.release(i1);
                continue;
            }
            let im = s.put(t + 1, 2);
            measured += 1;
            stack.push((t + 1, depth - 1, im, i1));
            stack.push((t, depth - 1, i0, im));
        }
        assert_eq!(measured, (1 << 16) + 1);
        assert!(
            s.capacity_used() <= 2 * 17 + 2,
            "{} slots",
            s.capacity_used()
        );
    }
}
