//! A vector kept in chunks of a fixed size, which never moves what it holds: the
//! ordering's pieces. A dense scene makes ten or twenty times as many pieces as it has
//! faces; in one vector, every time it filled up all of them were copied into a new one
//! twice as large (a 10,000-triangle soup of size 0.3 wrote 200 MB of fresh memory for
//! 70 MB of pieces, a tenth of its ordering time spent by the system clearing pages).

use std::ops::{Index, IndexMut};

/// Bytes per chunk, about: below the sizes an allocator hands out from the system
/// directly (and may give back between uses), so that chunks are reused like any small
/// allocation. Chunks of 1,024 pieces (350 KB) instead made the ordering of a sparse
/// soup 7 % slower; chunks of 256, 8 % faster than 1,024 on a dense one.
const CHUNK_BYTES: usize = 96 << 10;

/// Items `0..len()`, item `i` in chunk `i / CHUNK` (`CHUNK` a power of two, about
/// [`CHUNK_BYTES`] of items). Every chunk but the last is full; the first grows as a
/// vector does until it holds `CHUNK` items, and every later one is made with room for
/// `CHUNK`.
pub(crate) struct Chunked<T> {
    chunks: Vec<Vec<T>>,
    len: usize,
}

impl<T> Default for Chunked<T> {
    fn default() -> Self {
        Chunked {
            chunks: Vec::new(),
            len: 0,
        }
    }
}

impl<T> Chunked<T> {
    /// log2 of the items per chunk: the largest power of two of them in [`CHUNK_BYTES`].
    const SHIFT: u32 = {
        let per = CHUNK_BYTES
            / if size_of::<T>() == 0 {
                1
            } else {
                size_of::<T>()
            };
        if per < 2 {
            0
        } else {
            per.ilog2()
        }
    };
    /// Items per chunk.
    const CHUNK: usize = 1 << Self::SHIFT;

    /// An empty vector with room for `n` items in its first chunk (at most a chunk).
    pub(crate) fn with_capacity(n: usize) -> Self {
        Chunked {
            chunks: vec![Vec::with_capacity(n.min(Self::CHUNK))],
            len: 0,
        }
    }

    /// How many items there are.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Appends `item`; its index is the length before.
    pub(crate) fn push(&mut self, item: T) {
        match self.chunks.last_mut() {
            Some(last) if last.len() < Self::CHUNK => last.push(item),
            _ => {
                let mut chunk = Vec::with_capacity(if self.chunks.is_empty() {
                    1
                } else {
                    Self::CHUNK
                });
                chunk.push(item);
                self.chunks.push(chunk);
            }
        }
        self.len += 1;
    }
}

impl<T> IntoIterator for Chunked<T> {
    type Item = T;
    type IntoIter = std::iter::Flatten<std::vec::IntoIter<Vec<T>>>;

    /// The items in order, moved out.
    fn into_iter(self) -> Self::IntoIter {
        self.chunks.into_iter().flatten()
    }
}

impl<T> FromIterator<T> for Chunked<T> {
    fn from_iter<I: IntoIterator<Item = T>>(items: I) -> Self {
        let items = items.into_iter();
        let mut c = Chunked::with_capacity(items.size_hint().0);
        for item in items {
            c.push(item);
        }
        c
    }
}

impl<T> Index<usize> for Chunked<T> {
    type Output = T;

    #[inline]
    fn index(&self, i: usize) -> &T {
        &self.chunks[i >> Self::SHIFT][i & (Self::CHUNK - 1)]
    }
}

impl<T> IndexMut<usize> for Chunked<T> {
    #[inline]
    fn index_mut(&mut self, i: usize) -> &mut T {
        &mut self.chunks[i >> Self::SHIFT][i & (Self::CHUNK - 1)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn items_stay_where_they_were_put() {
        const CHUNK: usize = Chunked::<usize>::CHUNK;
        const {
            assert!(
                CHUNK > 1000,
                "a chunk of items of 8 bytes holds over a thousand"
            )
        };
        for start in [0, 1, 5, CHUNK, 3 * CHUNK] {
            let mut c = Chunked::with_capacity(start);
            let mut first = None;
            for i in 0..3 * CHUNK + 7 {
                c.push(i);
                if i == CHUNK + 1 {
                    first = Some(std::ptr::from_ref(&c[CHUNK + 1]));
                }
            }
            assert_eq!(c.len(), 3 * CHUNK + 7);
            assert_eq!(
                first,
                Some(std::ptr::from_ref(&c[CHUNK + 1])),
                "an item moved"
            );
            for i in (0..c.len()).step_by(97) {
                assert_eq!(c[i], i);
            }
            c[CHUNK] = 0;
            let back: Vec<usize> = c.into_iter().collect();
            assert_eq!(back.len(), 3 * CHUNK + 7);
            assert_eq!(back.iter().filter(|&&v| v == 0).count(), 2);
            assert!((1..back.len()).all(|i| i == CHUNK || back[i] == i));
        }
        let c: Chunked<u32> = (0..100_000).collect();
        assert_eq!((c.len(), c[99_999], c[1024]), (100_000, 99_999, 1024));
        // Large items: a chunk of one.
        let big: Chunked<[u8; 200_000]> = (0..3u8).map(|k| [k; 200_000]).collect();
        assert_eq!(Chunked::<[u8; 200_000]>::CHUNK, 1);
        assert_eq!((big.len(), big[2][7]), (3, 2));
    }

    #[test]
    #[should_panic]
    fn an_index_past_the_end_panics() {
        let c: Chunked<u8> = (0..10).collect();
        let _ = c[10];
    }
}
