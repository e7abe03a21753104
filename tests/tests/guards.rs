//! The fragment limit: a scene whose faces cross each other very often stops with an
//! error in every ordering, and ordinary hard scenes stay far below the default limit.

use limn_depthsort::{default_max_fragments, order, Arith, OrderError, OrderOptions, SortMode};
use limn_tests::corpus;

#[test]
fn dense_soup_stops_at_the_limit_in_every_ordering() {
    // 300 large triangles in a small cube: most pairs cross.
    let case = corpus::soup(300, 7, 1.5);
    for sort in [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell] {
        for arith in Arith::ALL {
            let opts = OrderOptions {
                sort,
                arith,
                max_fragments: Some(1_000),
                ..OrderOptions::default()
            };
            match order(&case.scene, &case.camera, &opts) {
                Err(OrderError::TooManyFragments { limit, faces }) => {
                    assert_eq!((limit, faces), (1_000, case.scene.faces.len()));
                }
                other => panic!("{sort:?} {arith:?}: {:?}", other.map(|o| o.stats)),
            }
        }
    }
}

#[test]
fn hard_cases_stay_far_below_the_default_limit() {
    for case in corpus::all() {
        let o = order(&case.scene, &case.camera, &OrderOptions::default()).unwrap();
        let limit = default_max_fragments(case.scene.faces.len());
        assert_eq!(o.stats.fragment_limit, limit);
        assert!(
            o.stats.fragments_made * 20 < limit,
            "{}: {} of {limit}",
            case.name,
            o.stats.fragments_made
        );
    }
    // A limit just above what a run needs lets it finish with the same result.
    let case = corpus::soup(300, 7, 1.5);
    let free = order(&case.scene, &case.camera, &OrderOptions::default()).unwrap();
    let tight = OrderOptions {
        max_fragments: Some(free.stats.fragments_made),
        ..OrderOptions::default()
    };
    let bound = order(&case.scene, &case.camera, &tight).unwrap();
    assert_eq!(bound.fragments.len(), free.fragments.len());
}

/// `copies` copies of the corpus' woven grid, appended one after another.
fn copies_of(case: &corpus::Case, copies: usize) -> limn_scene::Scene {
    let mut s = limn_scene::Scene::default();
    for _ in 0..copies {
        s.append(&case.scene);
    }
    s
}

#[test]
fn identical_copies_are_ordered_once() {
    let case = corpus::woven_grid();
    let one = order(&case.scene, &case.camera, &OrderOptions::default()).unwrap();
    let many = copies_of(&case, 300);
    for sort in [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell] {
        let opts = OrderOptions {
            sort,
            ..OrderOptions::default()
        };
        let o = order(&many, &case.camera, &opts).unwrap();
        assert_eq!(
            o.stats.faces_coincident,
            299 * case.scene.faces.len(),
            "{sort:?}"
        );
        // Only the last copy is ordered: as many fragments as one copy alone, and every
        // fragment belongs to the last copy.
        let first_of_last = 299 * case.scene.faces.len() as u32;
        assert!(o.fragments.iter().all(|f| f.face >= first_of_last));
        if sort == SortMode::Adaptive {
            assert_eq!(o.fragments.len(), one.fragments.len());
        }
    }
}

#[test]
fn a_translucent_later_copy_hides_nothing() {
    let case = corpus::woven_grid();
    let mut two = copies_of(&case, 2);
    let glass = two.add_material(limn_scene::Material {
        opacity: 0.5,
        ..limn_scene::Material::default_grey()
    });
    let n = case.scene.faces.len();
    for f in &mut two.faces[n..] {
        f.material = glass;
    }
    let o = order(&two, &case.camera, &OrderOptions::default()).unwrap();
    assert_eq!(o.stats.faces_coincident, 0);
    assert!(o.fragments.iter().any(|f| (f.face as usize) < n));
}

/// Components ordered apart on the pool ([`SortMode::Adaptive`] splits the whole set's
/// components in detached groups) share one limit: one piece fewer than a run makes is
/// an error on one thread and on two, and exactly as many finishes with the same result.
#[test]
fn components_ordered_apart_share_the_limit() {
    let case = corpus::soup(2_000, 11, 0.25);
    let free = order(&case.scene, &case.camera, &OrderOptions::default()).unwrap();
    assert!(free.stats.components > 20, "{:?}", free.stats);
    assert!(free.stats.splits > 0, "{:?}", free.stats);
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("thread pool");
        let with_limit = |limit: usize| {
            let opts = OrderOptions {
                max_fragments: Some(limit),
                ..OrderOptions::default()
            };
            pool.install(|| order(&case.scene, &case.camera, &opts))
        };
        let made = free.stats.fragments_made;
        match with_limit(made - 1) {
            Err(OrderError::TooManyFragments { limit, .. }) => assert_eq!(limit, made - 1),
            other => panic!("{threads} threads: {:?}", other.map(|o| o.stats)),
        }
        let bound = with_limit(made).unwrap();
        assert_eq!(bound.fragments, free.fragments, "{threads} threads");
    }
}
