//! Property tests of the orderings on random scenes biased toward degeneracy (corners on a
//! coarse lattice, so shared corners, coplanar and collinear faces are frequent): the
//! exact checker passes, and every visible face is covered exactly once by its fragments.

use std::collections::BTreeMap;

use glam::DVec3;
use limn_depthsort::{OrderOptions, SortMode};
use limn_scene::{Camera, Material, Scene};
use limn_tests::checker::{area2_dropping, coplanar_overlap, normal, ExactFragment, Q};
use limn_tests::exact::exact_run;
use num_traits::{Signed, Zero};
use proptest::prelude::*;

fn scene_of(tris: &[[(i8, i8, i8); 3]]) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("m", [0.5, 0.5, 0.5]));
    let o = s.add_object("soup");
    for t in tris {
        let p: Vec<DVec3> = t
            .iter()
            .map(|&(x, y, z)| DVec3::new(x as f64, y as f64, z as f64) * 0.5)
            .collect();
        if (p[1] - p[0]).cross(p[2] - p[0]).length_squared() > 0.0 {
            s.add_polygon(&p, m, o).expect("valid");
        }
    }
    s
}

fn dominant(n: &[Q; 3]) -> usize {
    let a: Vec<Q> = n.iter().map(|c| c.abs()).collect();
    if a[0] >= a[1] && a[0] >= a[2] {
        0
    } else if a[1] >= a[2] {
        1
    } else {
        2
    }
}

fn areas(frags: &[ExactFragment]) -> BTreeMap<u32, Q> {
    let mut m = BTreeMap::new();
    for f in frags {
        let ax = dominant(&normal(&f.verts));
        *m.entry(f.face).or_insert_with(Q::zero) += area2_dropping(&f.verts, ax);
    }
    m
}

fn corner() -> impl Strategy<Value = (i8, i8, i8)> {
    (-2i8..=2, -2i8..=2, -2i8..=2)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn random_degenerate_soups_are_ordered_exactly(
        tris in prop::collection::vec([corner(), corner(), corner()], 2..9),
        eye in (3i8..=6, -4i8..=4, 2i8..=6),
    ) {
        let scene = scene_of(&tris);
        prop_assume!(!scene.faces.is_empty());
        let eye = DVec3::new(eye.0 as f64, eye.1 as f64, eye.2 as f64);
        let camera = Camera::new(eye, DVec3::ZERO, 64, 48);
        let whole = exact_run(&scene, &camera, &OrderOptions { sort: SortMode::Simple, ..OrderOptions::default() });
        let want = areas(&whole.fragments);
        for sort in [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell] {
            let run = exact_run(&scene, &camera, &OrderOptions { sort, ..OrderOptions::default() });
            let v = run.checker.violations(&run.fragments);
            prop_assert!(v.is_empty(), "{}: {:?}", sort.name(), v);
            prop_assert_eq!(&areas(&run.fragments), &want, "{}: areas", sort.name());
            let fr = &run.fragments;
            for i in 0..fr.len() {
                for j in i + 1..fr.len() {
                    if fr[i].face == fr[j].face {
                        let ax = dominant(&normal(&fr[i].verts));
                        prop_assert!(!coplanar_overlap(&fr[i].verts, &fr[j].verts, ax), "{}: overlap", sort.name());
                    }
                }
            }
        }
    }
}
