//! Painting the first piece of a split opaque face as the whole face ("seamless" mode)
//! must not change which face is seen anywhere.

use limn_depthsort::{order, OrderOptions, SortMode};
use limn_paint::{covers, picture, Style};
use limn_tests::corpus;
use limn_zbuffer::{compare, default_band_tolerance, edge_band, rasterize_ids};

#[test]
fn whole_face_covers_give_the_same_ids_as_the_fragments() {
    let mut covered = 0;
    for case in corpus::all() {
        for sort in [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell] {
            let o = order(
                &case.scene,
                &case.camera,
                &OrderOptions {
                    sort,
                    ..OrderOptions::default()
                },
            )
            .unwrap();
            covered += covers(&case.scene, &o)
                .iter()
                .filter(|c| c.is_some())
                .count();
            let (w, h) = (o.camera.width, o.camera.height);
            let frags: Vec<(Vec<[f64; 2]>, u32)> = o
                .fragments
                .iter()
                .map(|f| (f.points.clone(), f.face))
                .collect();
            let pic = picture(&case.scene, &o, &Style::default());
            let painted: Vec<(Vec<[f64; 2]>, u32)> = pic
                .fragments
                .iter()
                .map(|f| (f.points.clone(), f.face))
                .collect();
            let mut edges = Vec::new();
            for poly in frags.iter().chain(&painted) {
                let n = poly.0.len();
                for i in 0..n {
                    edges.push((poly.0[i], poly.0[(i + 1) % n]));
                }
            }
            let band = edge_band(&edges, w, h, default_band_tolerance(w, h));
            let c = compare(
                &rasterize_ids(&frags, w, h),
                &rasterize_ids(&painted, w, h),
                Some(&band),
            );
            assert_eq!(
                c.mismatches_outside_band,
                0,
                "{} / {}",
                case.name,
                sort.name()
            );
        }
    }
    assert!(covered > 5, "the corpus must exercise covers");
}
