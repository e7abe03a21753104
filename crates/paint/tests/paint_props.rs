//! Random pictures, biased toward bad input: every backend paints them without error,
//! skips exactly the invalid fragments, and writes the same bytes every time.

use limn_paint::{narrow_color, painter_for, Format, Outline, PaintFragment, Picture};
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
                    .map(|p| narrow_color([(p[0] / 80.0).fract().abs(), 0.5, 0.25, 1.0]))
                    .collect()
            });
            PaintFragment {
                points,
                fill,
                vertex_colors,
                face,
                object,
                original_edges,
                texture: None,
                flap: false,
            }
        })
}

fn picture() -> impl Strategy<Value = Picture> {
    (
        prop::collection::vec(fragment(), 0..12),
        any::<bool>(),
        prop::option::of(0.0..3.0f64),
        any::<bool>(),
    )
        .prop_map(|(fragments, background, outline, merge_pieces)| Picture {
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
            marks: Vec::new(),
            textures: Vec::new(),
            merge_pieces,
            face_outlines: Default::default(),
            page_image: None,
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

/// One painted path as the text formats write it: stroke or fill, colour, opacity in
/// thousandths as written, and its subpaths (corners as written, closed or not).
type WrittenPath = (bool, [u8; 3], String, Vec<(Vec<(String, String)>, bool)>);

fn hex(s: &str) -> [u8; 3] {
    let s = s.trim_start_matches('#');
    [0, 2, 4].map(|k| u8::from_str_radix(&s[k..k + 2], 16).unwrap())
}

fn attr<'a>(line: &'a str, name: &str) -> Option<&'a str> {
    let start = line.find(&format!(" {name}=\""))? + name.len() + 3;
    let len = line[start..].find('"')?;
    Some(&line[start..start + len])
}

/// The paths of an SVG from [`limn_paint::SvgPainter`].
fn svg_paths(text: &str) -> Vec<WrittenPath> {
    let mut paths = Vec::new();
    // Strokes inherit the root's opacity unless they state their own.
    let root = text.lines().next().unwrap();
    let root_stroke_opacity = attr(root, "stroke-opacity");
    for line in text.lines().filter(|l| l.starts_with("<path ")) {
        let d = attr(line, "d").unwrap();
        let stroke = attr(line, "fill") == Some("none");
        let (colour, opacity) = if stroke {
            (
                attr(line, "stroke").unwrap(),
                attr(line, "stroke-opacity").or(root_stroke_opacity),
            )
        } else {
            (attr(line, "fill").unwrap(), attr(line, "fill-opacity"))
        };
        let mut subpaths: Vec<(Vec<(String, String)>, bool)> = Vec::new();
        let mut numbers: Vec<String> = Vec::new();
        let flush = |numbers: &mut Vec<String>,
                     subpaths: &mut Vec<(Vec<(String, String)>, bool)>| {
            if let Some(last) = subpaths.last_mut() {
                for pair in numbers.chunks(2) {
                    last.0.push((pair[0].clone(), pair[1].clone()));
                }
            }
            numbers.clear();
        };
        let mut token = String::new();
        for c in d.chars() {
            match c {
                'M' | 'L' | 'Z' | ' ' => {
                    if !token.is_empty() {
                        numbers.push(std::mem::take(&mut token));
                    }
                    match c {
                        'M' => {
                            flush(&mut numbers, &mut subpaths);
                            subpaths.push((Vec::new(), false));
                        }
                        'Z' => {
                            flush(&mut numbers, &mut subpaths);
                            subpaths.last_mut().unwrap().1 = true;
                        }
                        _ => {}
                    }
                }
                _ => token.push(c),
            }
        }
        if !token.is_empty() {
            numbers.push(token);
        }
        flush(&mut numbers, &mut subpaths);
        paths.push((
            stroke,
            hex(colour),
            opacity.unwrap_or("1").to_string(),
            subpaths,
        ));
    }
    paths
}

/// The paths of a TikZ picture from [`limn_paint::TikzPainter`].
fn tikz_paths(text: &str) -> Vec<WrittenPath> {
    let mut colours = std::collections::HashMap::new();
    let mut paths = Vec::new();
    for line in text.lines() {
        if let Some(rest) = line.strip_prefix("\\definecolor{") {
            let (name, rest) = rest.split_once("}{RGB}{").unwrap();
            let rgb: Vec<u8> = rest
                .trim_end_matches('}')
                .split(',')
                .map(|v| v.parse().unwrap())
                .collect();
            colours.insert(name.to_string(), [rgb[0], rgb[1], rgb[2]]);
            continue;
        }
        let stroke = line.starts_with("\\draw[");
        if !(stroke || line.starts_with("\\fill[") || line.starts_with("\\filldraw[")) {
            continue;
        }
        if line.contains(" rectangle ") {
            continue; // the background
        }
        let open = line.find('[').unwrap();
        let close = line.find(']').unwrap();
        let options: Vec<&str> = line[open + 1..close].split(',').collect();
        let colour = colours[options[0]];
        let key = if stroke {
            "draw opacity="
        } else {
            "fill opacity="
        };
        let opacity = options
            .iter()
            .find_map(|o| o.strip_prefix(key))
            .unwrap_or("1")
            .to_string();
        let body = line[close + 1..].trim_end_matches(';');
        let mut subpaths: Vec<(Vec<(String, String)>, bool)> = Vec::new();
        let mut joined = false;
        for token in body.split_whitespace() {
            match token {
                "--" => joined = true,
                "cycle" => {
                    subpaths.last_mut().unwrap().1 = true;
                    joined = false;
                }
                point => {
                    let (x, y) = point
                        .trim_start_matches('(')
                        .trim_end_matches(')')
                        .split_once(',')
                        .unwrap();
                    if !joined {
                        subpaths.push((Vec::new(), false));
                    }
                    subpaths.last_mut().unwrap().0.push((x.into(), y.into()));
                    joined = false;
                }
            }
        }
        paths.push((stroke, colour, opacity, subpaths));
    }
    paths
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// TikZ paints exactly the polygons and outlines SVG paints, in the same order,
    /// colours and opacities: two independent text forms of one picture. Smooth
    /// fragments are flattened first (their fill the mean of their corner colours, as
    /// TikZ paints them): SVG draws them as gradients and pieces instead.
    #[test]
    fn tikz_paints_what_svg_paints(picture in picture()) {
        let mut picture = picture;
        for f in &mut picture.fragments {
            if let Some(cs) = f.vertex_colors.take() {
                if cs.len() == f.points.len() && !cs.is_empty() {
                    for k in 0..3 {
                        f.fill[k] = cs.iter().map(|c| f64::from(c[k])).sum::<f64>() / cs.len() as f64;
                    }
                } else {
                    f.points.clear(); // invalid in both writers: skipped by both
                }
            }
        }
        let mut svg = Vec::new();
        let s = painter_for(Format::Svg).paint(&picture, &mut svg).unwrap();
        let mut tikz = Vec::new();
        let t = painter_for(Format::Tikz).paint(&picture, &mut tikz).unwrap();
        prop_assert_eq!((s.paths, s.strokes, s.skipped, s.clipped), (t.paths, t.strokes, t.skipped, t.clipped));
        let svg = String::from_utf8(svg).unwrap();
        let tikz = String::from_utf8(tikz).unwrap();
        prop_assert_eq!(svg_paths(&svg), tikz_paths(&tikz));
        prop_assert_eq!(svg.contains("<rect "), tikz.contains("] (0,0) rectangle (64,48);"));
    }
}
