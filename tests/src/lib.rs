//! Cross-crate integration tests and the hard-case corpus for limn.
//!
//! * [`corpus`]: the hard cases, built in code.
//! * [`checker`]: an exact (rational) checker of the painter's invariant.
//! * [`exact`]: exact runs of the orderings, ready for the checker.
//! * [`sample`]: which face the painter shows at sample points, for invariance tests.
//! * [`reference`](mod@reference): the painter's face ids against the image-space references.
//! * [`hard_input`]: near-parallel scenes with narrow views, exact symmetries and an exact single-ray check.
//! * [`near_parallel`]: crossings at tiny angles, near-coincident stacks, needles.

pub mod checker;
pub mod corpus;
pub mod exact;
pub mod hard_input;
pub mod near_parallel;
pub mod reference;
pub mod sample;
pub mod viewers;
