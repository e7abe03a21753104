//! Image-space references.
