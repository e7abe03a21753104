//! Options, statistics and errors of the orderings.

use limn_kernel::KernelError;
use limn_scene::{CameraError, SceneError};
use thiserror::Error;

/// Which visibility ordering to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SortMode {
    /// Pairs whose projections may overlap are oriented exactly, the occlusion graph is
    /// sorted topologically, and only strongly connected components (cycles,
    /// interpenetration) are split, recursively. The default.
    #[default]
    Adaptive,
    /// A Fuchs–Kedem–Naylor BSP tree of all polygons, traversed back to front.
    Bsp,
    /// Newell–Newell–Sancha depth sort with its five tests, swapping and splitting.
    Newell,
    /// One depth per polygon (the mean distance of its vertices); wrong on hard cases,
    /// kept as the baseline that plotting libraries use. The coplanar rule (later face
    /// wins) applies only to exact ties of that depth.
    Simple,
}

impl SortMode {
    /// Parses `adaptive`, `bsp`, `newell` or `simple`.
    pub fn from_name(s: &str) -> Option<SortMode> {
        match s {
            "adaptive" => Some(SortMode::Adaptive),
            "bsp" => Some(SortMode::Bsp),
            "newell" => Some(SortMode::Newell),
            "simple" => Some(SortMode::Simple),
            _ => None,
        }
    }

    /// The mode's name as accepted by [`SortMode::from_name`].
    pub fn name(self) -> &'static str {
        match self {
            SortMode::Adaptive => "adaptive",
            SortMode::Bsp => "bsp",
            SortMode::Newell => "newell",
            SortMode::Simple => "simple",
        }
    }

    /// All modes.
    pub const ALL: [SortMode; 4] = [
        SortMode::Adaptive,
        SortMode::Bsp,
        SortMode::Newell,
        SortMode::Simple,
    ];
}

/// Which polygon kernel decides.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Arith {
    /// The exact plane-based kernel (the default).
    #[default]
    Exact,
    /// The f64 kernel with an epsilon: the measured baseline.
    Float,
}

impl Arith {
    /// Parses `exact` or `float`.
    pub fn from_name(s: &str) -> Option<Arith> {
        match s {
            "exact" => Some(Arith::Exact),
            "float" => Some(Arith::Float),
            _ => None,
        }
    }

    /// The name accepted by [`Arith::from_name`].
    pub fn name(self) -> &'static str {
        match self {
            Arith::Exact => "exact",
            Arith::Float => "float",
        }
    }

    /// Both kernels.
    pub const ALL: [Arith; 2] = [Arith::Exact, Arith::Float];
}

/// Back-face culling.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CullMode {
    /// Cull the back faces of every object that is a closed surface with only opaque
    /// materials, of every closed opaque shell (faces connected through shared edges) of
    /// the other objects, and of every single-sided object
    /// ([`limn_scene::Object::single_sided`]) (the default).
    #[default]
    Auto,
    /// Cull every back face.
    On,
    /// Cull no back face (faces seen exactly edge-on are still dropped: they cover no
    /// area).
    Off,
}

impl CullMode {
    /// Parses `auto`, `on` or `off`.
    pub fn from_name(s: &str) -> Option<CullMode> {
        match s {
            "auto" => Some(CullMode::Auto),
            "on" => Some(CullMode::On),
            "off" => Some(CullMode::Off),
            _ => None,
        }
    }

    /// The name accepted by [`CullMode::from_name`].
    pub fn name(self) -> &'static str {
        match self {
            CullMode::Auto => "auto",
            CullMode::On => "on",
            CullMode::Off => "off",
        }
    }

    /// Every mode.
    pub const ALL: [CullMode; 3] = [CullMode::Auto, CullMode::On, CullMode::Off];
}

/// Options of [`crate::order`].
#[derive(Debug, Clone, PartialEq)]
pub struct OrderOptions {
    /// The ordering. Default: adaptive.
    pub sort: SortMode,
    /// The kernel. Default: exact.
    pub arith: Arith,
    /// Back-face culling. Default: auto.
    pub cull: CullMode,
    /// Seed of the splitter choice in BSP trees (deterministic). Default: 1.
    pub seed: u64,
    /// Number of random splitter candidates tried per BSP node. Default: 5.
    pub candidates: usize,
    /// Merge fragments of one face and one plane that are adjacent in the order. Default:
    /// true.
    pub merge: bool,
    /// Most fragments the ordering may make, counting every polygon of a face and every
    /// piece a split makes (also those split again); `None` = [`default_max_fragments`]
    /// of the scene's face count. Scenes whose faces cross each other very often
    /// (thousands of triangles in a tiny cube) stop with
    /// [`OrderError::TooManyFragments`] instead of running for minutes.
    pub max_fragments: Option<usize>,
    /// The visible map: split every fragment exactly along what hides it from the eye
    /// and leave out the hidden parts, so that each point of the picture is painted by
    /// one opaque fragment (and the translucent ones in front of it). Default: false.
    pub visible: bool,
    /// Cut translucent fragments exactly along what opaque faces hide and paint their
    /// visible parts after every opaque fragment (the same picture; one glass surface's
    /// fragments then follow one another, so writers can blend them as one layer; see
    /// `translucent_last.rs`). Off for callers that draw a translucent polygon whole
    /// wherever its fragments follow one another (the matplotlib bridge). Default: true.
    pub translucent_last: bool,
}

/// The default fragment limit for a scene of `faces` faces: 50 per face plus 200,000,
/// about 20 times what ordinary hard scenes make (a 10,000-triangle soup with 54,797
/// splits makes about 120,000).
pub fn default_max_fragments(faces: usize) -> usize {
    faces.saturating_mul(50).saturating_add(200_000)
}

impl Default for OrderOptions {
    fn default() -> Self {
        OrderOptions {
            sort: SortMode::Adaptive,
            arith: Arith::Exact,
            cull: CullMode::Auto,
            seed: 1,
            candidates: 5,
            merge: true,
            max_fragments: None,
            visible: false,
            translucent_last: true,
        }
    }
}

/// What an ordering did, for reports and benchmarks.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Stats {
    /// Faces in the scene.
    pub faces_in: usize,
    /// Faces of zero area as given (fewer than three distinct corners, or all of them on
    /// one line): dropped. Every other face draws something.
    pub faces_degenerate: usize,
    /// Faces drawn over entirely by an identical later opaque face (same corners in the
    /// same order): not ordered, and nothing of them would show.
    pub faces_coincident: usize,
    /// Faces culled as back faces or seen exactly edge-on.
    pub faces_culled: usize,
    /// Faces removed entirely by the near plane or outside the view.
    pub faces_clipped: usize,
    /// Faces of which the near plane cut away a part in front of the eye (drawn only in
    /// part, or not at all): geometry closer to the eye than the near plane is lost.
    pub faces_near_clipped: usize,
    /// Convex polygons entering the ordering.
    pub polygons: usize,
    /// Pairs whose projections may overlap (after the float prefilter).
    pub candidate_pairs: usize,
    /// Pairs that constrain the order (edges of the occlusion graph).
    pub constraints: usize,
    /// Strongly connected components with more than one polygon (adaptive), or cycles
    /// broken (newell).
    pub components: usize,
    /// Size of the largest such component.
    pub largest_component: usize,
    /// Polygon splits, near-plane clipping included.
    pub splits: usize,
    /// Parts that large sets (BSP's, or the adaptive ordering's large components) were
    /// split into on one thread and then ordered on every core; 0 when no set was that
    /// large.
    pub parts_apart: usize,
    /// Fragments in the order before merging.
    pub fragments_before_merge: usize,
    /// Fragments out.
    pub fragments_out: usize,
    /// Fragments made while ordering (faces' polygons and every piece of every split),
    /// the quantity [`OrderOptions::max_fragments`] bounds.
    pub fragments_made: usize,
    /// The fragment limit in force.
    pub fragment_limit: usize,
    /// Exact predicates that fell back from their floating-point filter.
    pub filter_fallbacks: u64,
    /// Milliseconds spent converting, culling and clipping.
    pub ms_prepare: f64,
    /// Milliseconds spent ordering.
    pub ms_order: f64,
    /// Milliseconds spent merging and building fragments.
    pub ms_merge: f64,
    /// Fragments in the shadow of some light (0 unless a light casts shadows).
    pub fragments_in_shadow: usize,
    /// Milliseconds spent splitting fragments along shadows (0 unless a light casts
    /// shadows).
    pub ms_shadows: f64,
    /// Parts of fragments left out as hidden from the eye: of every fragment under
    /// [`OrderOptions::visible`], else of translucent ones (their parts behind opaque
    /// faces, cut off so that they can be painted after every opaque piece).
    pub fragments_hidden: usize,
    /// Milliseconds spent splitting fragments along what hides them from the eye (and
    /// along shadows, done in the same pass; 0 unless [`OrderOptions::visible`] or the
    /// scene has translucent and opaque faces).
    pub ms_visible: f64,
}

impl Stats {
    /// Adds the ordering's counts of `other` (a context that ordered part of the scene
    /// apart, [`crate::pieces::Ctx::detached`]): pairs, constraints, components, splits,
    /// and the largest component.
    pub(crate) fn add_ordering(&mut self, other: &Stats) {
        self.candidate_pairs += other.candidate_pairs;
        self.constraints += other.constraints;
        self.components += other.components;
        self.largest_component = self.largest_component.max(other.largest_component);
        self.splits += other.splits;
        self.parts_apart += other.parts_apart;
    }
}

/// Errors of the orderings: all come from invalid input.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum OrderError {
    /// The scene is inconsistent.
    #[error("invalid scene: {0}")]
    Scene(#[from] SceneError),
    /// The camera is invalid.
    #[error("invalid camera: {0}")]
    Camera(#[from] CameraError),
    /// The geometry cannot be represented by the kernel.
    #[error("geometry: {0}")]
    Kernel(#[from] KernelError),
    /// Splitting made more fragments than [`OrderOptions::max_fragments`] allows.
    #[error(
        "splitting made more than {limit} fragments from {faces} faces (they cross each \
         other very often); nothing was drawn"
    )]
    TooManyFragments {
        /// The limit in force.
        limit: usize,
        /// Faces in the scene.
        faces: usize,
    },
}
