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
