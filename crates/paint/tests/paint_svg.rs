//! Exact SVG output for small pictures.

use limn_paint::{Outline, PaintFragment, PaintStats, Painter, Picture, SvgOptions, SvgPainter};

fn frag(
    face: u32,
    object: u32,
    points: &[[f64; 2]],
    fill: [f64; 4],
    edges: &[bool],
) -> PaintFragment {
    PaintFragment {
        points: points.to_vec(),
        fill,
        vertex_colors: None,
        face,
        object,
        original_edges: edges.to_vec(),
        texture: None,
        flap: false,
    }
}

fn svg(picture: &Picture) -> (String, PaintStats) {
    svg_with(SvgPainter::default(), picture)
}

fn svg_with(painter: SvgPainter, picture: &Picture) -> (String, PaintStats) {
    let mut out = Vec::new();
    let stats = painter.paint(picture, &mut out).unwrap();
    assert_eq!(stats.bytes, out.len() as u64);
    (String::from_utf8(out).unwrap(), stats)
}

const BLUE: [f64; 4] = [0.2, 0.4, 0.6, 1.0];

#[test]
fn golden_picture() {
    let mut p = Picture::new(200, 100);
    p.background = Some([1.0, 1.0, 1.0, 1.0]);
    p.objects = vec!["cube <&\"'> ü".to_string(), "plane".to_string()];
    p.outline = Some(Outline {
        color: [0.0, 0.0, 0.0, 1.0],
        width: 0.5,
    });
    let t = true;
    let f = false;
    p.fragments = vec![
        // Face 0 split in two: one path with two subpaths; outline only on original edges.
        frag(
            0,
            0,
            &[[10.0, 10.0], [60.004, 10.0], [10.125, 59.999]],
            BLUE,
            &[t, f, t],
        ),
        frag(
            0,
            0,
            &[[60.004, 10.0], [60.0, 60.0], [10.125, 59.999]],
            BLUE,
            &[t, t, f],
        ),
        // Same face, other opacity: a path of its own; no original edges: no outline.
        frag(
            0,
            0,
            &[[20.0, 20.0], [30.0, 20.0], [20.0, 30.0]],
            [0.2, 0.4, 0.6, 0.5],
            &[f, f, f],
        ),
        // Another object; tiny negatives print as 0; channels clamp; every edge original.
        frag(
            1,
            1,
            &[[-0.004, 0.0], [100.0, -0.0], [100.0, 50.0]],
            [1.2, -0.1, 0.5, 1.0],
            &[t, t, t],
        ),
        // Invalid: skipped.
        frag(3, 1, &[[f64::NAN, 0.0], [1.0, 0.0], [0.0, 1.0]], BLUE, &[]),
        frag(3, 1, &[[0.0, 0.0], [1.0, 0.0]], BLUE, &[]),
        // Back to object 0: a new group. Huge coordinate: clipped to the guard box
        // (200 + 2 · 0.5 = 201 around the page); the cut edge is not outlined.
        frag(
            2,
            0,
            &[[0.0, 0.0], [1e12, 0.0], [0.0, 50.0]],
            [0.0, 0.0, 0.0, 1.0],
            &[t, t, t],
        ),
    ];
    let (text, stats) = svg(&p);
    let expected = r##"<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100" viewBox="0 0 200 100" stroke-width="0.5" stroke-linecap="round" stroke-linejoin="round">
<rect width="200" height="100" fill="#ffffff"/>
<g data-name="cube &lt;&amp;&quot;&apos;&gt; ü">
<path d="M10 10L60 10 10.13 60ZM60 10L60 60 10.13 60Z" fill="#336699"/>
<path d="M10.13 60L10 10 60 10M60 10L60 60 10.13 60" fill="none" stroke="#000000"/>
<path d="M20 20L30 20 20 30Z" fill="#336699" fill-opacity="0.5"/>
</g>
<g data-name="plane">
<path d="M0 0L100 0 100 50Z" fill="#ff0080"/>
<path d="M0 0L100 0 100 50Z" fill="none" stroke="#000000"/>
</g>
<g data-name="cube &lt;&amp;&quot;&apos;&gt; ü">
<path d="M0 0L401 0 401 50 0 50Z" fill="#000000"/>
<path d="M401 50L0 50 0 0 401 0" fill="none" stroke="#000000"/>
</g>
</svg>
"##;
    assert_eq!(text, expected);
    assert_eq!(stats.paths, 4);
    assert_eq!(stats.strokes, 3);
    assert_eq!(stats.skipped, 2);
    assert_eq!(stats.clipped, 1);
    assert_eq!(stats.approximated, 0);
}

#[test]
fn empty_picture_is_a_valid_document() {
    let (text, stats) = svg(&Picture::new(3, 2));
    assert_eq!(
        text,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"3\" height=\"2\" viewBox=\"0 0 3 2\">\n</svg>\n"
    );
    assert_eq!(stats.paths, 0);

    let mut p = Picture::new(3, 2);
    p.background = Some([0.0, 0.0, 0.0, 0.25]);
    let (text, _) = svg(&p);
    assert!(
        text.contains("<rect width=\"3\" height=\"2\" fill=\"#000000\" fill-opacity=\"0.25\"/>\n")
    );
}

#[test]
fn illum_0_colour_is_exact() {
    let mut p = Picture::new(10, 10);
    p.fragments.push(PaintFragment::new(
        vec![[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]],
        BLUE,
    ));
    let (text, _) = svg(&p);
    assert!(text.contains("fill=\"#336699\""), "{text}");
}

#[test]
fn merging_needs_same_face_object_and_style() {
    let tri = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]];
    let mut p = Picture::new(10, 10);
    p.objects = vec!["a".into(), "b".into()];
    // Same face, colours that differ only below 8 bits: merged.
    p.fragments
        .push(frag(7, 0, &tri, [0.2, 0.4, 0.6, 1.0], &[]));
    p.fragments
        .push(frag(7, 0, &tri, [0.2001, 0.4, 0.6, 1.0], &[]));
    // Same style, other face: new path.
    p.fragments.push(frag(8, 0, &tri, BLUE, &[]));
    // Same face, other object: new group and path.
    p.fragments.push(frag(8, 1, &tri, BLUE, &[]));
    // Same face again after an interruption: new path.
    p.fragments.push(frag(7, 0, &tri, BLUE, &[]));
    let (text, stats) = svg(&p);
    assert_eq!(stats.paths, 4);
    assert_eq!(text.matches("<path").count(), 4);
    assert_eq!(text.matches("<g ").count(), 3);
    assert!(text.contains("d=\"M0 0L4 0 0 4ZM0 0L4 0 0 4Z\""));
    assert_eq!(stats.strokes, 0);
}

#[test]
fn merged_subpaths_turn_the_same_way() {
    // The second fragment is given counter-clockwise: it is written reversed so that the
    // non-zero rule fills the union.
    let mut p = Picture::new(10, 10);
    p.fragments
        .push(frag(0, 0, &[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]], BLUE, &[]));
    p.fragments
        .push(frag(0, 0, &[[4.0, 0.0], [0.0, 4.0], [4.0, 4.0]], BLUE, &[]));
    let (text, _) = svg(&p);
    assert!(text.contains("d=\"M0 0L4 0 0 4ZM4 4L0 4 4 0Z\""), "{text}");
}

#[test]
fn out_of_range_object_gets_an_unnamed_group() {
    let mut p = Picture::new(10, 10);
    p.fragments
        .push(frag(0, 5, &[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]], BLUE, &[]));
    let (text, _) = svg(&p);
    assert!(text.contains("\n<g>\n<path"), "{text}");
}

#[test]
fn gouraud_is_a_fitted_cover_under_pieces_within_the_tolerance() {
    let mut p = Picture::new(10, 10);
    let mut f = PaintFragment::new(vec![[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]], BLUE);
    // A little off one line in RGB.
    f.vertex_colors = Some(vec![
        [0.2, 0.2, 0.2, 1.0],
        [0.8, 0.8, 0.8, 1.0],
        [0.5, 0.52, 0.5, 1.0],
    ]);
    p.fragments.push(f.clone());
    let (text, stats) = svg(&p);
    // The whole fragment first, in the gradient nearest its colours, then the pieces.
    assert!(text.contains("<g>\n<linearGradient id=\"s0\""), "{text}");
    let cover = text
        .find("d=\"M0 0L4 0 0 4Z\" fill=\"url(#s0)\"")
        .expect(&text);
    assert!(text[cover..].matches("<path").count() > 4, "{text}");
    assert_eq!(stats.approximated, 0);
    // Far from one line: three channel ramps added, exactly.
    f.vertex_colors = Some(vec![
        [1.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 1.0],
    ]);
    p.fragments = vec![f.clone()];
    let (text, _) = svg(&p);
    // An isolated group clipped to the triangle: the ramps fill a rectangle under it.
    assert!(
        text.contains("<g clip-path=\"url(#c0)\"><g style=\"isolation:isolate\">"),
        "{text}"
    );
    assert_eq!(text.matches("<path").count(), 1, "{text}");
    assert_eq!(text.matches("<rect").count(), 3, "{text}");
    // Colours on one line in RGB: one exact gradient.
    f.vertex_colors = Some(vec![
        [0.2, 0.2, 0.2, 1.0],
        [0.6, 0.6, 0.6, 1.0],
        [1.0, 1.0, 1.0, 1.0],
    ]);
    p.fragments = vec![f];
    let (text, _) = svg(&p);
    assert_eq!(text.matches("<linearGradient").count(), 1, "{text}");
    assert!(
        text.contains("<stop stop-color=\"#ffffff\"/><stop offset=\"1\" stop-color=\"#333333\"/>"),
        "{text}"
    );
    assert!(text.contains("fill=\"url(#s0)\""), "{text}");
}

#[test]
fn decimals_option() {
    let mut p = Picture::new(10, 10);
    p.fragments.push(PaintFragment::new(
        vec![[0.123456, 1.5], [4.0, 0.0], [0.0, 4.0]],
        BLUE,
    ));
    let (text, _) = svg_with(
        SvgPainter::new(SvgOptions {
            decimals: 4,
            ..SvgOptions::default()
        }),
        &p,
    );
    assert!(text.contains("d=\"M0.1235 1.5L4 0 0 4Z\""), "{text}");
    let (text, _) = svg_with(
        SvgPainter::new(SvgOptions {
            decimals: 0,
            ..SvgOptions::default()
        }),
        &p,
    );
    assert!(text.contains("d=\"M0 2L4 0 0 4Z\""), "{text}");
}

#[test]
fn outline_opacity_and_zero_width() {
    let mut p = Picture::new(10, 10);
    p.fragments.push(PaintFragment::new(
        vec![[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]],
        BLUE,
    ));
    p.outline = Some(Outline {
        color: [1.0, 0.0, 0.0, 0.5],
        width: 2.0,
    });
    let (text, stats) = svg(&p);
    assert!(text.contains(" stroke-width=\"2\" stroke-linecap=\"round\" stroke-linejoin=\"round\" stroke-opacity=\"0.5\">"));
    assert!(text.contains("<path d=\"M0 0L4 0 0 4Z\" fill=\"none\" stroke=\"#ff0000\"/>"));
    assert_eq!(stats.strokes, 1);
    p.outline = Some(Outline {
        color: [1.0, 0.0, 0.0, 1.0],
        width: 0.0,
    });
    let (text, stats) = svg(&p);
    assert!(!text.contains("stroke"));
    assert_eq!(stats.strokes, 0);
}

#[test]
fn names_with_controls_and_non_ascii() {
    let mut p = Picture::new(10, 10);
    p.objects = vec!["tab\there\nline \u{1}ctl 日本".into()];
    p.fragments.push(PaintFragment::new(
        vec![[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]],
        BLUE,
    ));
    let (text, _) = svg(&p);
    assert!(
        text.contains("<g data-name=\"tab&#9;here&#10;line \u{fffd}ctl 日本\">"),
        "{text}"
    );
}

#[test]
fn output_is_byte_for_byte_repeatable() {
    let mut p = Picture::new(640, 480);
    for i in 0..200 {
        let x = f64::from(i) * 3.3;
        p.fragments.push(frag(
            i / 3,
            0,
            &[[x, 1.0 / 3.0], [x + 10.0, 2.0 / 3.0], [x, 400.0]],
            [x / 700.0, 0.5, 0.25, 0.9],
            &[true],
        ));
    }
    let (a, _) = svg(&p);
    let (b, _) = svg(&p);
    assert_eq!(a, b);
    assert!(!a.contains("-0 ") && !a.contains("e-") && !a.contains("e+"));
}

#[test]
fn bad_picture_values_are_errors() {
    let mut out = Vec::new();
    assert!(SvgPainter::default()
        .paint(&Picture::new(0, 5), &mut out)
        .is_err());
    let mut p = Picture::new(5, 5);
    p.background = Some([f64::NAN, 0.0, 0.0, 1.0]);
    assert!(SvgPainter::default().paint(&p, &mut out).is_err());
    let mut p = Picture::new(5, 5);
    p.outline = Some(Outline {
        color: [0.0; 4],
        width: -1.0,
    });
    assert!(SvgPainter::default().paint(&p, &mut out).is_err());
}

/// A writer that fails after a few bytes.
struct Failing(usize);

impl std::io::Write for Failing {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if self.0 < buf.len() {
            return Err(std::io::Error::other("disk full"));
        }
        self.0 -= buf.len();
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

#[test]
fn io_errors_are_reported() {
    let mut p = Picture::new(100, 100);
    p.fragments.push(PaintFragment::new(
        vec![[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]],
        BLUE,
    ));
    let err = SvgPainter::default()
        .paint(&p, &mut Failing(10))
        .unwrap_err();
    assert!(matches!(err, limn_paint::PaintError::Io(_)), "{err}");
}
