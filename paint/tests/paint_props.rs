//! Random pictures, biased toward bad input: every backend paints them without error,
//! skips exactly the invalid fragments, and writes the same bytes every time.

use limn_paint::{painter_for, Format, Outline, PaintFragment, Picture};
use proptest::prelude::*;

/// Coordinates: mostly on the page, sometimes far away, huge or not finite.
fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -10.0..80.0f64,
        1 => -1e6..1e6f64,
        1 => prop_oneof![
            Just(1e300),
            Just(-1e300),
            Just(f64::MAX),
            Just(f64::NAN),
            Just(f64::INFINITY),
            Just(-0.0),
        ],
    ]
}

fn channel() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => 0.0..=1.0f64,
        1 => -1.0..2.0f64,
        1 => Just(f64::NAN),
    ]
}

fn fragment() -> impl Strategy<Value = PaintFragment> {
    (
        prop::collection::vec([coord(), coord()], 0..7),
        [channel(), channel(), channel(), channel()],
        any::<bool>(),
        0u32..4,
        0u32..3,
        prop::collection::vec(any::<bool>(), 0..8),
    )
        .prop_map(|(points, fill, gouraud, face, object, original_edges)| {
            let vertex_colors = gouraud.then(|| {
                points
                    .iter()
                    .map(|p| [(p[0] / 80.0).fract().abs(), 0.5, 0.25, 1.0])
                    .collect()
            });
            PaintFragment {
                points,
                fill,
                vertex_colors,
                face,
                object,
                original_edges,
            }
        })
}

fn picture() -> impl Strategy<Value = Picture> {
    (
        prop::collection::vec(fragment(), 0..12),
        any::<bool>(),
        prop::option::of(0.0..3.0f64),
    )
        .prop_map(|(fragments, background, outline)| Picture {
            width: 64,
            height: 48,
            background: background.then_some([0.9, 0.9, 0.8, 1.0]),
            objects: vec!["a".into(), "<b & c>".into()],
            fragments,
            outline: outline.map(|width| Outline {
                color: [0.0, 0.0, 0.0, 0.7],
                width,
            }),
            seams: if background { 0.5 } else { 0.0 },
        })
}

/// The documented validity rule, written out independently.
fn is_invalid(f: &PaintFragment) -> bool {
    f.points.len() < 3
        || f.points.iter().flatten().any(|v| !v.is_finite())
        || f.fill.iter().any(|v| !v.is_finite())
        || f.vertex_colors.as_ref().is_some_and(|cs| {
            cs.len() != f.points.len() || cs.iter().flatten().any(|v| !v.is_finite())
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn every_backend_paints_random_pictures(picture in picture()) {
        let invalid = picture.fragments.iter().filter(|f| is_invalid(f)).count();
        for format in Format::ALL {
            let painter = painter_for(format);
            let mut a = Vec::new();
            let stats = painter.paint(&picture, &mut a).unwrap();
            prop_assert_eq!(stats.bytes, a.len() as u64);
            // Overflowing clips are skipped too, so at least the invalid ones.
            prop_assert!(stats.skipped >= invalid, "{} skipped {} < {}", format, stats.skipped, invalid);
            prop_assert!(stats.skipped + stats.clipped <= picture.fragments.len());
            let mut b = Vec::new();
            painter.paint(&picture, &mut b).unwrap();
            prop_assert!(a == b, "{} output differs between runs", format);
            if matches!(format, Format::Svg | Format::Eps) {
                let text = String::from_utf8_lossy(&a);
                prop_assert!(!text.contains("NaN") && !text.contains("inf"));
                prop_assert!(!text.contains("-0 ") && !text.contains("e+"));
            }
        }
    }
}
