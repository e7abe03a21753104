//! Sets of the scene's lights, by index: the lights that cast shadows, and the lights a
//! point lies in the shadow of.

/// A set of light indices (into [`crate::Scene::lights`]), at most
/// [`LightSet::CAPACITY`] of them. A fragment's set names the lights it is in the shadow
/// of: those lights are left out when it is shaded (ambient light never is).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct LightSet(u64);

impl LightSet {
    /// No light.
    pub const EMPTY: LightSet = LightSet(0);
    /// How many lights a set can name (indices `0..CAPACITY`).
    pub const CAPACITY: usize = 64;

    /// Whether the set names no light.
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// Whether light `index` is in the set (always `false` beyond the capacity).
    pub fn contains(self, index: usize) -> bool {
        index < Self::CAPACITY && self.0 >> index & 1 == 1
    }

    /// Adds light `index` (ignored beyond the capacity).
    pub fn insert(&mut self, index: usize) {
        if index < Self::CAPACITY {
            self.0 |= 1 << index;
        }
    }

    /// The set with light `index` added.
    pub fn with(mut self, index: usize) -> LightSet {
        self.insert(index);
        self
    }

    /// The indices in the set, in increasing order.
    pub fn iter(self) -> impl Iterator<Item = usize> {
        (0..Self::CAPACITY).filter(move |&i| self.contains(i))
    }

    /// The set as bits (bit `i` for light `i`).
    pub fn bits(self) -> u64 {
        self.0
    }

    /// How many lights the set names.
    pub fn len(self) -> usize {
        self.0.count_ones() as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sets_hold_what_was_inserted() {
        let mut s = LightSet::EMPTY;
        assert!(s.is_empty());
        s.insert(3);
        s.insert(63);
        s.insert(64); // beyond the capacity: ignored
        assert_eq!(s.iter().collect::<Vec<_>>(), [3, 63]);
        assert_eq!(s.len(), 2);
        assert!(s.contains(3) && !s.contains(4) && !s.contains(64));
        assert_eq!(LightSet::EMPTY.with(5).iter().collect::<Vec<_>>(), [5]);
    }
}
