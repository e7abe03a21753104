//! Exact on the input as given (DESIGN, "Kernel: exact on the input as given"): every
//! exact ordering (adaptive, BSP, Newell) paints the same face as exact ray casting at
//! every pixel centre outside the edge band, on scenes where rounding or snapping the
//! input moves the lines where faces meet across whole regions of the picture:
//!
//! * two faces crossing at 1e-7, 1e-9 and 1e-12 rad, the crossing line through the
//!   middle of the picture;
//! * stacks of quads 1e-6 … 1e-9 apart, tilted by 1e-5 … 1e-9 rad so that neighbours
//!   pierce each other along lines inside the picture;
//! * the same translated by 1e7 and scaled by 1e-9 and 1e9, camera moved along;
//! * needles 1e-7 wide piercing a face, seen whole and through a narrow field of view;
//!
//! and the exact orderings are invariant under exact symmetries (rotations by 90°,
//! mirrors, translations, face permutations, rotated vertex lists).
//!
//! The referee is checked too: ray casting agrees with itself under the same symmetries
//! and after undoing the translation by 1e7, and with the f64 z-buffer away from the lines
//! where faces meet.
//!
//! With a kernel that is exact only on a copy of the input snapped to a 2^26 grid, the
//! first three tests fail: hundreds to thousands of pixels per scene (tens on the stack
//! 1e-6 apart), in every exact mode.
//!
//! The reference is always rendered with the camera as given (not the camera the
//! ordering reports), with the near and far planes the camera chooses for the scene.

use limn_depthsort::{Arith, OrderOptions, SortMode};
use limn_scene::Camera;
use limn_tests::corpus;
use limn_tests::hard_input::{self as np, Scenario};
use limn_tests::reference::paint;
use limn_zbuffer::{
    compare, default_band_tolerance, edge_band, render, scene_edges, IdImage, Mask, Method,
    RenderOptions, NO_FACE,
};

const EXACT_MODES: [SortMode; 3] = [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell];

fn opts(sort: SortMode, arith: Arith) -> OrderOptions {
    OrderOptions {
        sort,
        arith,
        ..OrderOptions::default()
    }
}

/// Exact ray casting with the camera as given.
fn ray_cast(s: &Scenario) -> IdImage {
    render(
        &s.scene,
        &s.camera,
        Method::RayCast,
        &RenderOptions::default(),
    )
    .unwrap_or_else(|e| panic!("{}: ray casting failed: {e}", s.name))
    .ids
}

/// Pixels within the default tolerance of a scene edge, as seen by the scenario's camera.
fn scene_band(s: &Scenario) -> Mask {
    let c = &s.camera;
    let edges = scene_edges(&s.scene, c, &RenderOptions::default())
        .unwrap_or_else(|e| panic!("{}: scene_edges failed: {e}", s.name));
    edge_band(
        &edges,
        c.width,
        c.height,
        default_band_tolerance(c.width, c.height),
    )
}

fn union(a: &Mask, b: &Mask) -> Mask {
    let mut m = a.clone();
    for (x, &y) in m.bits.iter_mut().zip(&b.bits) {
        *x |= y;
    }
    m
}

fn distinct_faces(ids: &IdImage) -> usize {
    let mut v: Vec<u32> = ids.ids.iter().copied().filter(|&i| i != NO_FACE).collect();
    v.sort_unstable();
    v.dedup();
    v.len()
}

/// Pixels outside the band where the painter (`sort`, `arith`) and `reference` differ,
/// and the number of fragments painted.
fn wrong_pixels(s: &Scenario, reference: &IdImage, sort: SortMode, arith: Arith) -> (usize, usize) {
    let p = paint(&s.scene, &s.camera, &opts(sort, arith));
    let c = p.compare(reference);
    (c.mismatches_outside_band, p.ordered.fragments.len())
}

/// Every exact mode against ray casting on every scenario; float modes are measured and
/// printed alongside, not checked. Prints one row per scenario and mode.
fn exact_modes_agree_with_ray_casting(scenarios: &[Scenario]) {
    let mut failures = Vec::new();
    eprintln!(
        "{:<30} {:<9} {:>7} {:>7} {:>6} {:>6}",
        "scene", "mode", "exact", "float", "frags", "faces"
    );
    for s in scenarios {
        let r = ray_cast(s);
        let faces = distinct_faces(&r);
        for mode in EXACT_MODES {
            let (bad, frags) = wrong_pixels(s, &r, mode, Arith::Exact);
            let (float_bad, _) = wrong_pixels(s, &r, mode, Arith::Float);
            eprintln!(
                "{:<30} {:<9} {:>7} {:>7} {:>6} {:>6}",
                s.name,
                mode.name(),
                bad,
                float_bad,
                frags,
                faces
            );
            if bad > 0 {
                failures.push(format!(
                    "{} / {}: {bad} pixels differ from ray casting outside the band",
                    s.name,
                    mode.name()
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn exact_modes_agree_with_ray_casting_on_faces_crossing_at_tiny_angles() {
    exact_modes_agree_with_ray_casting(&np::crossings());
}

#[test]
fn exact_modes_agree_with_ray_casting_on_stacks_of_nearly_parallel_quads() {
    exact_modes_agree_with_ray_casting(&np::stacks());
}

#[test]
fn exact_modes_agree_with_ray_casting_on_needles() {
    exact_modes_agree_with_ray_casting(&np::needle_scenes());
}

// ---------------------------------------------------------------------------------
// Invariance.

fn from_case(c: corpus::Case) -> Scenario {
    Scenario {
        name: c.name.to_string(),
        scene: c.scene,
        camera: Camera {
            width: np::SIZE,
            height: np::SIZE,
            ..c.camera
        },
        offset: glam::DVec3::ZERO,
    }
}

/// Hard scenes on a dyadic grid (2^-40), so that the translations of
/// [`np::symmetries`] are exact on them: the cyclic triple, two interpenetrating
/// triangles, two quads crossing at 1e-9 rad, oblique triangles crossing at 1e-9 rad
/// and a stack of quads 1e-8 apart.
fn hard_scenes() -> Vec<Scenario> {
    [
        from_case(corpus::cyclic_quads()),
        from_case(corpus::interpenetrating_triangles()),
        np::crossing_quads(1e-9),
        np::crossing_triangles(1e-9),
        np::stack(12, 1e-8, 1e-7, 3),
    ]
    .iter()
    .map(|s| np::dyadic(s, 40))
    .collect()
}

/// Moves the ids of a picture of the symmetric scene back to the base scene's frame:
/// face ids through `perm` (new id → old id), columns reversed if `mirrors`.
fn back_ids(ids: &IdImage, perm: &[u32], mirrors: bool) -> IdImage {
    let (w, h) = (ids.width as usize, ids.height as usize);
    let mut out = ids.clone();
    for j in 0..h {
        for i in 0..w {
            let src = if mirrors { w - 1 - i } else { i };
            let id = ids.ids[j * w + src];
            out.ids[j * w + i] = if id == NO_FACE { id } else { perm[id as usize] };
        }
    }
    out
}

fn back_mask(m: &Mask, mirrors: bool) -> Mask {
    let (w, h) = (m.width as usize, m.height as usize);
    let mut out = m.clone();
    if mirrors {
        for j in 0..h {
            for i in 0..w {
                out.bits[j * w + i] = m.bits[j * w + (w - 1 - i)];
            }
        }
    }
    out
}

/// The symmetric variants of `base` that f64 computes exactly, each with its faces
/// permuted and vertex lists rotated; with the permutation and whether it mirrors.
fn variants(base: &Scenario) -> Vec<(Scenario, Vec<u32>, bool)> {
    let perm = np::shuffle(base.scene.faces.len());
    np::symmetries()
        .iter()
        .filter(|sym| sym.exact_on(base))
        .map(|sym| {
            let mut t = np::permuted(&sym.image(base), &perm);
            t.name = format!("{} {}", base.name, sym.name);
            (t, perm.clone(), sym.mirrors)
        })
        .collect()
}

/// Each exact ordering paints the same face at every pixel centre (outside the union of
/// both bands) on a hard scene and on its images under exact symmetries with permuted
/// faces and rotated vertex lists.
#[test]
fn exact_modes_are_invariant_under_exact_symmetries() {
    let mut failures = Vec::new();
    for base in hard_scenes() {
        let all = variants(&base);
        assert_eq!(
            all.len(),
            np::symmetries().len(),
            "{}: a map was not exact",
            base.name
        );
        for mode in EXACT_MODES {
            let o = opts(mode, Arith::Exact);
            let p0 = paint(&base.scene, &base.camera, &o);
            let mut counts = Vec::new();
            for (t, perm, mirrors) in &all {
                let p = paint(&t.scene, &t.camera, &o);
                let ids = back_ids(&p.ids, perm, *mirrors);
                let band = union(&p0.band, &back_mask(&p.band, *mirrors));
                let c = compare(&p0.ids, &ids, Some(&band));
                counts.push(c.mismatches_outside_band);
                if c.mismatches_outside_band > 0 {
                    failures.push(format!(
                        "{} / {}: {} pixels differ from the base scene outside the band",
                        t.name,
                        mode.name(),
                        c.mismatches_outside_band
                    ));
                }
            }
            eprintln!(
                "{:<28} {:<9} differing pixels per symmetry {counts:?}",
                base.name,
                mode.name()
            );
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

// ---------------------------------------------------------------------------------
// The referee.

/// Ray casting gives the same face at every pixel centre (outside the scene-edge bands
/// and 0.05 px around the lines where faces meet) on every base scene and its exact
/// symmetric images.
#[test]
fn ray_casting_is_invariant_under_exact_symmetries() {
    let mut failures = Vec::new();
    let mut bases = hard_scenes();
    for s in np::all() {
        if s.offset == glam::DVec3::ZERO && !s.name.contains('*') {
            bases.push(s);
        }
    }
    for base in &bases {
        let r0 = ray_cast(base);
        let cross = np::crossing_band(
            &base.scene,
            &base.camera,
            base.camera.near_far(&base.scene),
            0.05,
        );
        let band0 = union(&scene_band(base), &cross);
        let mut counts = Vec::new();
        for (t, perm, mirrors) in variants(base) {
            let r = back_ids(&ray_cast(&t), &perm, mirrors);
            let band = union(&band0, &back_mask(&scene_band(&t), mirrors));
            let c = compare(&r0, &r, Some(&band));
            counts.push((
                t.name.rsplit(' ').next().unwrap_or("").to_string(),
                c.mismatches_outside_band,
            ));
            if c.mismatches_outside_band > 0 {
                failures.push(format!("{}: {} pixels", t.name, c.mismatches_outside_band));
            }
        }
        eprintln!(
            "{:<28} {:>5} faces, differing pixels {counts:?}",
            base.name,
            distinct_faces(&r0)
        );
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Ray casting on every scenario against (a) ray casting on the same scene moved back
/// to the origin (exactly: only the translated scenes move) and (b) the f64 z-buffer on
/// that recentred scene, outside the scene-edge band and away from the lines where faces
/// meet (1 px for the z-buffer, whose interpolated depths decide wrongly next to a
/// crossing at a tiny angle; 0.05 px for ray casting). Pixels where the z-buffer shows
/// another face exactly coplanar with the ray-cast one are ties (depth fighting), not
/// counted. The z-buffer is not asked on the narrow views of the needles: there the
/// square's corners project about 1e9 pixels away and its interpolated depth is off by
/// far more than the 1e-14 that separates the faces (the exact samples below cover
/// those views).
#[test]
fn ray_casting_agrees_with_itself_recentred_and_with_the_f64_zbuffer_off_the_crossings() {
    let mut failures = Vec::new();
    eprintln!(
        "{:<30} {:>9} {:>9} {:>6} {:>6}",
        "scene", "recentred", "zbuffer", "ties", "faces"
    );
    for s in np::all() {
        let r = ray_cast(&s);
        let c = np::recentred(&s);
        let near_far = c.camera.near_far(&c.scene);
        let edges = union(&scene_band(&s), &scene_band(&c));
        let rc = ray_cast(&c);
        let near = union(
            &edges,
            &np::crossing_band(&c.scene, &c.camera, near_far, 0.05),
        );
        let self_bad = compare(&r, &rc, Some(&near)).mismatches_outside_band;
        let z = render(
            &c.scene,
            &c.camera,
            Method::ZBuffer,
            &RenderOptions::default(),
        )
        .unwrap_or_else(|e| panic!("{}: z-buffer failed: {e}", c.name))
        .ids;
        let off = union(
            &edges,
            &np::crossing_band(&c.scene, &c.camera, near_far, 1.0),
        );
        let (mut z_bad, mut ties) = (0, 0);
        let mut tie_cache = std::collections::HashMap::new();
        let narrow = s.camera.fov_deg < 1.0;
        for k in 0..r.ids.len() {
            if narrow {
                break;
            }
            let (a, b) = (r.ids[k], z.ids[k]);
            if a == b || off.bits[k] {
                continue;
            }
            let tie = a != NO_FACE
                && b != NO_FACE
                && *tie_cache
                    .entry((a.min(b), a.max(b)))
                    .or_insert_with(|| np::exactly_coplanar(&s.scene, a, b));
            if tie {
                ties += 1;
            } else {
                z_bad += 1;
            }
        }
        eprintln!(
            "{:<30} {:>9} {:>9} {:>6} {:>6}",
            s.name,
            self_bad,
            if narrow {
                "-".to_string()
            } else {
                z_bad.to_string()
            },
            ties,
            distinct_faces(&r)
        );
        if self_bad > 0 || z_bad > 0 {
            failures.push(format!(
                "{}: {self_bad} pixels differ from the recentred ray casting, {z_bad} from \
                 the z-buffer",
                s.name
            ));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Ray casting against an independent exact evaluation (integer arithmetic on the f64
/// input scaled by a common power of two, the ray through the pixel centre built from the camera's frame in f64) at every
/// 16th pixel in each direction, skipping samples within the scene-edge band or 0.05 px
/// of a line where faces meet (where the two rays, rounded differently, may legitimately
/// disagree).
#[test]
fn ray_casting_agrees_with_exact_samples() {
    let mut failures = Vec::new();
    for s in np::all() {
        let r = ray_cast(&s);
        let c = &s.camera;
        let band = union(
            &scene_band(&s),
            &np::crossing_band(&s.scene, c, c.near_far(&s.scene), 0.05),
        );
        let (mut checked, mut bad, mut seen) = (0, 0, std::collections::BTreeSet::new());
        for j in (5..c.height).step_by(16) {
            for i in (3..c.width).step_by(16) {
                let k = (j * c.width + i) as usize;
                if band.bits[k] {
                    continue;
                }
                let np::ExactHit::First(hit) =
                    np::exact_first_hit(&s.scene, c.eye, np::pixel_ray_point(c, i, j))
                else {
                    continue;
                };
                checked += 1;
                let want = hit.unwrap_or(NO_FACE);
                seen.insert(want);
                if r.ids[k] != want {
                    bad += 1;
                }
            }
        }
        eprintln!(
            "{:<30} {checked:>4} samples, {:>2} ids, {bad} differ",
            s.name,
            seen.len()
        );
        if bad > 0 {
            failures.push(format!("{}: {bad} of {checked} samples", s.name));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
