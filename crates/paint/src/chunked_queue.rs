//! A first-in, first-out queue kept in chunks of fixed size, each released as soon as it
//! is emptied: its memory follows what it holds, where a ring buffer keeps every page it
//! ever touched.

use std::collections::VecDeque;

/// Items per chunk.
const CHUNK: usize = 4096;

/// A queue of `T` in chunks of [`CHUNK`] items.
pub(crate) struct ChunkedQueue<T> {
    chunks: VecDeque<VecDeque<T>>,
}

impl<T> ChunkedQueue<T> {
    /// An empty queue.
    pub(crate) fn new() -> Self {
        ChunkedQueue {
            chunks: VecDeque::new(),
        }
    }

    /// Puts `item` at the back.
    pub(crate) fn push_back(&mut self, item: T) {
        match self.chunks.back_mut() {
            Some(last) if last.len() < CHUNK => last.push_back(item),
            _ => {
                let mut chunk = VecDeque::with_capacity(CHUNK);
                chunk.push_back(item);
                self.chunks.push_back(chunk);
            }
        }
    }

    /// Takes the item at the front, releasing its chunk when it was the chunk's last.
    pub(crate) fn pop_front(&mut self) -> Option<T> {
        let first = self.chunks.front_mut()?;
        let item = first.pop_front();
        if first.is_empty() {
            self.chunks.pop_front();
        }
        item
    }

    /// Whether the queue holds nothing.
    pub(crate) fn is_empty(&self) -> bool {
        self.chunks.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Items come out in the order they went in, across chunks, with pushes and pops
    /// interleaved, and every emptied chunk is released.
    #[test]
    fn first_in_first_out_across_chunks() {
        let mut q = ChunkedQueue::new();
        let mut next_out = 0usize;
        for i in 0..3 * CHUNK + 5 {
            q.push_back(i);
            if i % 3 == 0 {
                assert_eq!(q.pop_front(), Some(next_out));
                next_out += 1;
            }
        }
        assert!(q.chunks.len() <= 3);
        while let Some(v) = q.pop_front() {
            assert_eq!(v, next_out);
            next_out += 1;
        }
        assert_eq!(next_out, 3 * CHUNK + 5);
        assert!(q.is_empty() && q.chunks.is_empty());
    }
}
