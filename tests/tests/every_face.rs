//! Every face with area is drawn. Random height fields (quads that are not planar, steep
//! or nearly flat) and random polygons that are not planar, not convex or cross
//! themselves in projection, seen from the axes, obliquely and at grazing angles, through
//! perspective and orthographic cameras: no face is called degenerate, every exact
//! ordering paints what exact ray casting sees, and seen from straight above each quad of
//! a height field paints exactly its cell.

use glam::DVec3;
use limn_check::paint;
use limn_depthsort::{OrderOptions, SortMode};
use limn_scene::{Camera, Material, Scene};
use limn_zbuffer::{DepthFormat, Method};
use proptest::prelude::*;

const EXACT_MODES: [SortMode; 3] = [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell];

/// Directions from the target to the eye: the axes, oblique ones and grazing ones (the
/// height fields lie across x and y).
const VIEWS: [[f64; 3]; 9] = [
    [0.0, 0.0, 1.0],
    [0.0, 0.0, -1.0],
    [1.0, 0.0, 0.0],
    [0.0, -1.0, 0.0],
    [1.0, 0.8, 1.6],
    [-0.7, 0.4, 0.9],
    [1.0, 0.3, 0.02],
    [0.2, -1.0, 0.005],
    [-1.0, -1.0, -0.3],
];

/// A small deterministic generator (splitmix64), so a case is its seed.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// An `n × n` height field over [-1, 1]² as quads `f a a+n a+n+1 a+1` (as plotting tools
/// write them), heights up to `amp` grid steps: random, or a smooth wave.
fn height_field(n: usize, amp: f64, smooth: bool, seed: u64) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("surface", [0.4, 0.5, 0.6]));
    let o = s.add_object("field");
    let step = 2.0 / (n - 1) as f64;
    let mut rng = Rng(seed);
    let (fx, fy) = (1.0 + 4.0 * rng.next(), 1.0 + 4.0 * rng.next());
    for j in 0..n {
        for i in 0..n {
            let (x, y) = (-1.0 + step * i as f64, -1.0 + step * j as f64);
            let z = if smooth {
                (fx * x).sin() * (fy * y).cos()
            } else {
                rng.next()
            };
            s.add_vertex(DVec3::new(x, y, z * amp * step));
        }
    }
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            let a = (j * n + i) as u32;
            let n = n as u32;
            s.add_face(&[a, a + n, a + n + 1, a + 1], m, o)
                .expect("valid quad");
        }
    }
    s
}

/// A few polygons of 4 to 9 corners: star-shaped or in random order (crossing
/// themselves), twisted out of their plane or nearly planar, scattered around the origin.
fn random_polygons(count: usize, seed: u64) -> Scene {
    let mut s = Scene::default();
    let o = s.add_object("polygons");
    let mut rng = Rng(seed);
    for k in 0..count {
        let m = s.add_material(Material::unlit(
            &format!("m{k}"),
            [rng.next(), rng.next(), rng.next()],
        ));
        let n = 4 + (rng.next() * 6.0) as usize;
        let mut angles: Vec<f64> = (0..n).map(|_| rng.next() * std::f64::consts::TAU).collect();
        let kind = (rng.next() * 3.0) as usize;
        if kind != 2 {
            angles.sort_by(f64::total_cmp);
        }
        let twist = match kind {
            0 => 1e-9,
            _ => rng.next(),
        };
        let centre = DVec3::new(rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5) * 2.0;
        let corners: Vec<DVec3> = angles
            .iter()
            .map(|a| {
                let r = 0.3 + rng.next();
                centre + DVec3::new(r * a.cos(), r * a.sin(), twist * (rng.next() - 0.5))
            })
            .collect();
        s.add_polygon(&corners, m, o).expect("valid polygon");
    }
    s
}

fn camera(scene: &Scene, view: [f64; 3], ortho: bool) -> Camera {
    let dir = DVec3::from(view);
    if ortho {
        Camera::framing_orthographic(scene, dir, 96, 72).expect("frames")
    } else {
        Camera::framing_scene(scene, dir, 45.0, 96, 72).expect("frames")
    }
}

/// Checks every exact ordering of `scene` through `cam` against ray casting.
fn agrees_with_ray_casting(scene: &Scene, cam: &Camera) -> Result<(), TestCaseError> {
    for sort in EXACT_MODES {
        let opts = OrderOptions {
            sort,
            ..OrderOptions::default()
        };
        let p = paint(scene, cam, &opts).expect("orders");
        prop_assert_eq!(
            p.ordered.stats.faces_degenerate,
            0,
            "{}: faces called degenerate",
            sort.name()
        );
        let r = p
            .reference(scene, Method::RayCast, DepthFormat::F64)
            .expect("ray casts");
        let c = p.compare(&r);
        prop_assert_eq!(
            c.mismatches_outside_band,
            0,
            "{}: pixels wrong; per face (wrong, shown): {:?}",
            sort.name(),
            c.per_face
                .iter()
                .filter(|(_, v)| v.0 > 0)
                .collect::<Vec<_>>()
        );
    }
    Ok(())
}

/// Sizes 2 to 60, small ones more often.
fn size() -> impl Strategy<Value = usize> {
    (0.0f64..1.0).prop_map(|u| 2 + (u * u * 58.0) as usize)
}

/// Heights from 1e-9 to 10 grid steps.
fn amplitude() -> impl Strategy<Value = f64> {
    (-9.0f64..1.0).prop_map(|e| 10f64.powf(e))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]

    #[test]
    fn random_height_fields_are_drawn_whole(
        n in size(),
        amp in amplitude(),
        smooth in any::<bool>(),
        seed in any::<u64>(),
        view in 0..VIEWS.len(),
        ortho in any::<bool>(),
    ) {
        let scene = height_field(n, amp, smooth, seed);
        agrees_with_ray_casting(&scene, &camera(&scene, VIEWS[view], ortho))?;
    }

    #[test]
    fn random_polygons_of_any_shape_are_drawn_whole(
        count in 1usize..5,
        seed in any::<u64>(),
        view in 0..VIEWS.len(),
        ortho in any::<bool>(),
    ) {
        let scene = random_polygons(count, seed);
        agrees_with_ray_casting(&scene, &camera(&scene, VIEWS[view], ortho))?;
    }
}

/// Twice the signed area of a screen polygon.
fn area2(pts: &[[f64; 2]]) -> f64 {
    (0..pts.len())
        .map(|i| {
            let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum()
}

#[test]
fn seen_from_above_each_quad_paints_its_cell() {
    // Steep random heights (up to 13 grid steps, as a 30 × 30 field of values in
    // [0, 0.9] has): the quads twist so much that most are not simple seen along x or y.
    for (n, amp, seed) in [(30, 13.0, 1), (12, 40.0, 7), (5, 1e-7, 3)] {
        let scene = height_field(n, amp, false, seed);
        let cam = camera(&scene, [0.0, 0.0, 1.0], true);
        let ordered =
            limn_depthsort::order(&scene, &cam, &OrderOptions::default()).expect("orders");
        assert_eq!(ordered.stats.faces_degenerate, 0);
        let mut painted = vec![0.0; scene.faces.len()];
        for f in &ordered.fragments {
            painted[f.face as usize] += area2(&f.points).abs() / 2.0;
        }
        let cell = painted.iter().sum::<f64>() / painted.len() as f64;
        for (face, a) in painted.iter().enumerate() {
            assert!(
                (a - cell).abs() <= 1e-9 * cell,
                "{n}×{n} field: face {face} paints {a} px², a cell is {cell}"
            );
        }
    }
}

#[test]
fn a_region_whose_hole_is_joined_by_a_cut_is_drawn_without_its_hole() {
    // A filled contour region or a glyph written as one outline: a 6 × 4 rectangle with
    // two 1 × 1 holes, the first joined to the outside by a cut run both ways and the
    // second to the first, tilted out of the coordinate planes. Seen from straight above
    // it paints 22/24 of what its rectangle alone paints (the same frame: the same
    // bounds).
    let keyhole = [
        [0.0, 0.0],
        [6.0, 0.0],
        [6.0, 4.0],
        [0.0, 4.0],
        [0.0, 0.0],
        [1.0, 2.0],
        [2.0, 2.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [4.0, 2.0],
        [4.0, 3.0],
        [5.0, 3.0],
        [5.0, 2.0],
        [4.0, 2.0],
        [1.0, 2.0],
    ];
    let painted = |outline: &[[f64; 2]], reversed: bool| {
        let mut s = Scene::default();
        let m = s.add_material(Material::unlit("region", [0.4, 0.5, 0.6]));
        let o = s.add_object("region");
        let mut corners: Vec<DVec3> = outline
            .iter()
            .map(|p| DVec3::new(p[0], p[1], 0.25 * p[0] + 0.125 * p[1]))
            .collect();
        if reversed {
            corners.reverse();
        }
        s.add_polygon(&corners, m, o).expect("valid polygon");
        let cam = camera(&s, [0.0, 0.0, 1.0], true);
        let ordered = limn_depthsort::order(&s, &cam, &OrderOptions::default()).expect("orders");
        let area: f64 = ordered
            .fragments
            .iter()
            .map(|f| area2(&f.points).abs() / 2.0)
            .sum();
        (area, s)
    };
    for reversed in [false, true] {
        let (rectangle, _) = painted(&keyhole[..4], reversed);
        let (region, scene) = painted(&keyhole, reversed);
        assert!(
            (region / rectangle - 22.0 / 24.0).abs() <= 1e-9,
            "reversed {reversed}: the region paints {region} px², its rectangle {rectangle} px²"
        );
        let cam = camera(&scene, [0.3, -0.5, 1.0], false);
        agrees_with_ray_casting(&scene, &cam).expect("agrees with ray casting");
    }
}
