//! Small arbitrary scenes through every ordering: up to 12 faces of 3 to 5 corners on a
//! small integer lattice (so shared vertices, coplanar and collinear faces are
//! frequent), with occasional raw f64 corners and ulp nudges, copies of earlier faces
//! shifted a little (coplanar and near-parallel pairs), corners at the eye and just
//! beyond the near plane. Every mode of `limn-depthsort` runs with the exact kernel
//! (and, for panics only, the float one); the exact modes (adaptive, BSP, Newell) must
//! pass the exact painter's checker of `limn-tests`.

use std::fmt;

use arbitrary::{Arbitrary, Unstructured};
use glam::DVec3;
use limn_depthsort::{order, Arith, CullMode, OrderOptions, SortMode};
use limn_scene::{Camera, Material, Scene};
use limn_tests::exact::try_exact_run;

use crate::VecLit;

/// A face corner.
#[derive(Debug, Clone, Arbitrary)]
pub enum Corner {
    /// A point of the lattice {-1.5, -1, …, 1.5}³ (each value taken modulo 7).
    Lattice([i8; 3]),
    /// The `n`-th corner given so far in the scene (modulo their number), shared.
    Shared(u8),
    /// A lattice point moved by `ulps` units in the last place on one axis.
    Nudged([i8; 3], u8, i8),
    /// Any f64 point, as bit patterns ([`f64::from_bits`]).
    Raw([u64; 3]),
    /// The eye itself.
    Eye,
    /// Just beyond the near plane: the eye, plus the near distance along the view
    /// direction scaled by `1 + k/64`, plus a lattice offset scaled by 1/64.
    NearEye(u8, [i8; 3]),
}

/// One face.
#[derive(Clone, Arbitrary)]
pub enum Face {
    /// Corners in order (3 to 5 are used; fewer skip the face).
    Corners(Vec<Corner>),
    /// The `of`-th earlier face (modulo their number) shifted by `shift / 64` and then
    /// nudged by `ulps` on the z axis: coplanar, parallel or nearly so.
    Copy {
        /// Which earlier face.
        of: u8,
        /// The shift, in 64ths.
        shift: [i8; 3],
        /// Ulps added on z to every corner.
        ulps: i8,
    },
    /// The `n`-th earlier face with its corners reversed (the same plane, flipped).
    Reversed(u8),
}

impl fmt::Debug for Face {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Face::Corners(c) => f.debug_tuple("Corners").field(&VecLit(c)).finish(),
            Face::Copy { of, shift, ulps } => f
                .debug_struct("Copy")
                .field("of", of)
                .field("shift", shift)
                .field("ulps", ulps)
                .finish(),
            Face::Reversed(n) => f.debug_tuple("Reversed").field(n).finish(),
        }
    }
}

/// One scene and its view.
#[derive(Clone, Arbitrary)]
pub struct Case {
    /// The faces (at most 12 are used).
    pub faces: Vec<Face>,
    /// The eye: each value modulo 13, minus 6 (so −6 to 6).
    pub eye: [i8; 3],
    /// The point looked at, on the lattice of [`Corner::Lattice`].
    pub target: [i8; 3],
    /// `Some(n)`: the near plane at `(n + 1) / 16`; `None`: chosen from the scene.
    pub near: Option<u8>,
    /// Back-face culling: auto, on or off (modulo 3).
    pub cull: u8,
    /// Merge adjacent fragments of one face.
    pub merge: bool,
    /// The BSP splitter seed.
    pub seed: u8,
}

impl fmt::Debug for Case {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Case")
            .field("faces", &VecLit(&self.faces))
            .field("eye", &self.eye)
            .field("target", &self.target)
            .field("near", &self.near)
            .field("cull", &self.cull)
            .field("merge", &self.merge)
            .field("seed", &self.seed)
            .finish()
    }
}

fn lattice(p: [i8; 3]) -> DVec3 {
    let c = p.map(|v| (v.rem_euclid(7) - 3) as f64 * 0.5);
    DVec3::from_array(c)
}

fn nudge(mut x: f64, ulps: i8) -> f64 {
    for _ in 0..ulps.unsigned_abs().min(16) {
        x = if ulps > 0 { x.next_up() } else { x.next_down() };
    }
    x
}

/// The camera of a case.
fn camera(case: &Case) -> Camera {
    let eye = DVec3::from_array(case.eye.map(|v| (v.rem_euclid(13) - 6) as f64));
    let mut c = Camera::new(eye, lattice(case.target), 64, 48);
    c.near = case.near.map(|n| (n as f64 + 1.0) / 16.0);
    c
}

/// The scene of a case: every face that has 3 to 5 corners.
fn scene(case: &Case, cam: &Camera) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("m", [0.5, 0.5, 0.5]));
    let o = s.add_object("soup");
    let forward = cam.forward();
    let near = cam.near.unwrap_or(0.1);
    let mut given: Vec<DVec3> = Vec::new();
    let mut faces: Vec<Vec<DVec3>> = Vec::new();
    for face in case.faces.iter().take(12) {
        let pts: Vec<DVec3> = match face {
            Face::Corners(cs) => cs
                .iter()
                .take(5)
                .map(|c| {
                    let p = match c {
                        Corner::Lattice(p) => lattice(*p),
                        Corner::Shared(n) if !given.is_empty() => given[*n as usize % given.len()],
                        Corner::Shared(_) => DVec3::ZERO,
                        Corner::Nudged(p, axis, ulps) => {
                            let mut v = lattice(*p).to_array();
                            let a = *axis as usize % 3;
                            v[a] = nudge(v[a], *ulps);
                            DVec3::from_array(v)
                        }
                        Corner::Raw(b) => DVec3::from_array(b.map(f64::from_bits)),
                        Corner::Eye => cam.eye,
                        Corner::NearEye(k, off) => {
                            cam.eye
                                + forward * near * (1.0 + *k as f64 / 64.0)
                                + DVec3::from_array(off.map(|v| v as f64 / 64.0))
                        }
                    };
                    given.push(p);
                    p
                })
                .collect(),
            Face::Copy { of, shift, ulps } if !faces.is_empty() => {
                let d = DVec3::from_array(shift.map(|v| v as f64 / 64.0));
                faces[*of as usize % faces.len()]
                    .iter()
                    .map(|&p| {
                        let p = p + d;
                        DVec3::new(p.x, p.y, nudge(p.z, *ulps))
                    })
                    .collect()
            }
            Face::Reversed(n) if !faces.is_empty() => {
                let mut f = faces[*n as usize % faces.len()].clone();
                f.reverse();
                f
            }
            Face::Copy { .. } | Face::Reversed(_) => Vec::new(),
        };
        if pts.len() >= 3 && s.add_polygon(&pts, m, o).is_ok() {
            faces.push(pts);
        }
    }
    s
}

/// The scene and camera a case describes (for turning a case into a regression test).
pub fn scene_and_camera(case: &Case) -> (Scene, Camera) {
    let cam = camera(case);
    (scene(case, &cam), cam)
}

/// Orders the case's scene with every mode and checks the exact ones.
pub fn run_case(case: &Case) {
    let (scene, cam) = scene_and_camera(case);
    let cull = CullMode::ALL[case.cull as usize % 3];
    for sort in SortMode::ALL {
        let opts = OrderOptions {
            sort,
            arith: Arith::Exact,
            cull,
            seed: u64::from(case.seed),
            merge: case.merge,
            ..OrderOptions::default()
        };
        // The float kernel has no exactness to check, but must not panic either.
        let _ = order(
            &scene,
            &cam,
            &OrderOptions {
                arith: Arith::Float,
                ..opts.clone()
            },
        );
        // Invalid scenes and cameras are refused with a typed error.
        let Ok(run) = try_exact_run(&scene, &cam, &opts) else {
            continue;
        };
        assert_eq!(
            run.ordered.fragments.len(),
            run.fragments.len(),
            "{}",
            sort.name()
        );
        if sort == SortMode::Simple {
            // One depth per polygon: wrong on hard cases by design.
            continue;
        }
        let v = run.checker.violations(&run.fragments);
        assert!(
            v.is_empty(),
            "{}: painted in the wrong order: {v:?}\ncase {case:?}",
            sort.name()
        );
    }
}

/// The [`Case`] that `data` decodes to, as [`run`] decodes it (`None`: skipped).
/// Its `Debug` form is Rust source for a regression test.
pub fn decode(data: &[u8]) -> Option<Case> {
    Case::arbitrary_take_rest(Unstructured::new(data)).ok()
}

/// Decodes a [`Case`] from `data` and runs it; undecodable bytes are skipped.
pub fn run(data: &[u8]) {
    if let Some(case) = decode(data) {
        run_case(&case);
    }
}
