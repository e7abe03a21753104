//! limn: draw 3D polygon scenes as resolution-independent pictures (SVG, PDF, EPS, TikZ,
//! PNG) with hidden surfaces removed exactly, in object space.
//!
//! This crate is limn's front door: a render [`Request`] (an input file or a scene built
//! in memory, every option by name with the command's defaults) and one function,
//! [`render`], that loads, orders, paints and writes it safely, returning typed
//! [`RenderStats`]; [`check`] compares the painter's picture with an image-space
//! reference. The `limn` command and the Python package are argument parsing and
//! messages over these.
//!
//! ```no_run
//! use limn::{render, Input, Request, RenderOptions, Silent};
//!
//! let req = Request {
//!     input: Input::File("bunny.obj".into()),
//!     output: Some("bunny.pdf".into()),
//!     options: RenderOptions::default(),
//! };
//! let done = render(&req, &mut Silent)?;
//! println!("{} fragments", done.stats.unwrap().fragments_out);
//! # Ok::<(), limn::Error>(())
//! ```
//!
//! The stages are crates of their own: `limn-scene` (the scene model), `limn-load`
//! (files), `limn-kernel` (exact planes and polygons), `limn-depthsort` (orderings),
//! `limn-paint` (pictures and writers), `limn-zbuffer` (image-space references) and
//! `limn-check` (comparisons).

mod check;
pub mod demo;
mod error;
mod events;
mod hidden_line;
mod input;
mod losses;
mod options;
mod output;
mod raster;
mod render;
mod settings;
mod stats;
pub mod values;

pub use check::{check, CheckReport};
pub use error::Error;
pub use events::{Collected, Events, Silent};
pub use hidden_line::hidden_line_scene;
pub use input::{load, Input, Loaded};
pub use limn_depthsort::{Arith, CullMode, SortMode};
pub use limn_load::SceneOptions;
pub use limn_paint::Format;
pub use limn_scene::{Scene, Shading};
pub use options::{
    Against, Background, CheckOptions, Look, Method, RenderOptions, ViewOptions, DEFAULT_CREASE,
    DEFAULT_SEAMS, DEFAULT_SHADING_TOLERANCE, DEFAULT_SHADOW_BIAS, DEFAULT_SHADOW_MAP_SIZE,
    DEFAULT_SIZE, DEFAULT_TEXTURE_SAMPLES,
};
pub use output::{check_writable, write_atomic, OutputError};
pub use render::{order_scene, render, render_into, Rendered, Request};
pub use settings::{camera, format_of, order_options};
pub use stats::{LineStats, RenderStats, Timing};
