//! Exact plane-based polygon kernel.
