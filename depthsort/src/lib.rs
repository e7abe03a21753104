//! Painter ordering.
