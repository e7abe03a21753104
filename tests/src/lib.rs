//! Cross-crate tests and the hard-case corpus.
