//! Names → indices, with the names kept one after the other in one buffer.
//!
//! A library of 10,000 materials looked up in another order than it was written (an OBJ
//! with one material per face) spends its time in cache misses: a `HashMap<String, _>`
//! reads each key's own allocation to compare it. Here a lookup compares with bytes of
//! one buffer (a fraction of the size of 10,000 allocations) and adding a name allocates
//! nothing of its own.

use std::hash::BuildHasher;

use hashbrown::HashTable;
use rustc_hash::FxBuildHasher;

/// A name's place in [`NameTable::text`] and the index it stands for.
#[derive(Debug, Clone, Copy)]
struct Entry {
    start: usize,
    end: usize,
    index: usize,
}

/// Distinct names, each standing for an index.
#[derive(Debug, Default)]
pub(crate) struct NameTable {
    /// Every name, one after the other.
    text: Vec<u8>,
    table: HashTable<Entry>,
}

fn hash(name: &[u8]) -> u64 {
    FxBuildHasher.hash_one(name)
}

impl NameTable {
    /// Makes room for `additional` more names.
    pub(crate) fn reserve(&mut self, additional: usize) {
        let text = &self.text;
        self.table
            .reserve(additional, |e| hash(&text[e.start..e.end]));
    }

    /// The index `name` stands for.
    pub(crate) fn get(&self, name: &str) -> Option<usize> {
        let (text, name) = (&self.text, name.as_bytes());
        self.table
            .find(hash(name), |e| &text[e.start..e.end] == name)
            .map(|e| e.index)
    }

    /// Lets `name` stand for `index`: a new name, or one standing for another index
    /// until now.
    pub(crate) fn insert(&mut self, name: &str, index: usize) {
        let (text, bytes) = (&self.text, name.as_bytes());
        let h = hash(bytes);
        if let Some(e) = self.table.find_mut(h, |e| &text[e.start..e.end] == bytes) {
            e.index = index;
            return;
        }
        let start = self.text.len();
        self.text.extend_from_slice(bytes);
        let entry = Entry {
            start,
            end: self.text.len(),
            index,
        };
        let text = &self.text;
        self.table
            .insert_unique(h, entry, |e| hash(&text[e.start..e.end]));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_stand_for_their_last_index() {
        let mut t = NameTable::default();
        t.reserve(2);
        let names: Vec<String> = (0..1000).map(|i| format!("m{i}")).collect();
        for (i, n) in names.iter().enumerate() {
            t.insert(n, i);
        }
        t.insert("m7", 5000);
        t.insert("", 6000);
        for (i, n) in names.iter().enumerate() {
            assert_eq!(t.get(n), Some(if i == 7 { 5000 } else { i }), "{n}");
        }
        assert_eq!(t.get(""), Some(6000));
        // Prefixes and concatenations of stored names are not names.
        for n in ["m", "m1000", "m0m1", "m99 ", "0"] {
            assert_eq!(t.get(n), None, "{n}");
        }
    }
}
