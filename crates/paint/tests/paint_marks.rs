//! Marks in every writer: paint position among the fragments, line styles, markers,
//! labels and arrow heads, invalid marks skipped.

use limn_paint::{
    painter_for, ArrowHead, Format, Label, LabelAnchor, LinePiece, LineStyle, Mark, MarkKind,
    Marker, MarkerShape, PaintFragment, PaintStats, Painter, Picture, PngPainter,
};
use tiny_skia::Pixmap;

const BLUE: [f64; 4] = [0.2, 0.4, 0.6, 1.0];
const RED: [f64; 4] = [1.0, 0.0, 0.0, 1.0];

fn line(points: Vec<[f64; 2]>, width: f64, dash: Vec<f64>) -> MarkKind {
    MarkKind::Line(LinePiece {
        points,
        style: LineStyle {
            color: RED,
            width,
            dash,
        },
        dash_offset: 0.0,
        line: 0,
    })
}

fn mark(before: usize, kind: MarkKind) -> Mark {
    Mark {
        before,
        object: 0,
        kind,
    }
}

/// A blue square over the middle with a thick red horizontal line through it, painted
/// before (`before = 0`) or after (`before = 1`) the square.
fn crossing(before: usize) -> Picture {
    let mut p = Picture::new(40, 40);
    p.objects.push("o".into());
    p.fragments.push(PaintFragment::new(
        vec![[10.0, 10.0], [30.0, 10.0], [30.0, 30.0], [10.0, 30.0]],
        BLUE,
    ));
    p.marks.push(mark(
        before,
        line(vec![[0.0, 20.0], [40.0, 20.0]], 4.0, vec![]),
    ));
    p
}

fn all_marks() -> Picture {
    let mut p = crossing(1);
    p.marks.push(mark(
        1,
        line(vec![[0.0, 5.0], [40.0, 5.0]], 1.0, vec![3.0, 1.0, 2.0]),
    ));
    for (i, shape) in [
        MarkerShape::Dot,
        MarkerShape::Circle,
        MarkerShape::Square,
        MarkerShape::Triangle,
        MarkerShape::Cross,
        MarkerShape::Plus,
    ]
    .into_iter()
    .enumerate()
    {
        p.marks.push(mark(
            1,
            MarkKind::Marker(Marker {
                at: [5.0 + 6.0 * i as f64, 35.0],
                shape,
                size: 5.0,
                color: [0.0, 0.5, 0.0, 0.5],
                stroke: 1.0,
            }),
        ));
    }
    p.marks.push(mark(
        1,
        MarkKind::Label(Label {
            at: [20.0, 20.0],
            offset: [1.0, -1.0],
            anchor: LabelAnchor::SouthWest,
            text: "a<(b)>&\\ é".into(),
            size: 8.0,
            color: [0.0, 0.0, 0.0, 1.0],
        }),
    ));
    p.marks.push(mark(
        1,
        MarkKind::Head(ArrowHead {
            points: [[40.0, 20.0], [34.0, 18.0], [34.0, 22.0]],
            color: RED,
        }),
    ));
    p
}

fn paint(format: Format, p: &Picture) -> (Vec<u8>, PaintStats) {
    let mut out = Vec::new();
    let stats = painter_for(format).paint(p, &mut out).unwrap();
    assert_eq!(stats.bytes, out.len() as u64);
    (out, stats)
}

fn text(b: &[u8]) -> String {
    b.iter()
        .map(|&c| if c.is_ascii() { c as char } else { '?' })
        .collect()
}

#[test]
fn every_writer_counts_every_mark() {
    for f in [Format::Svg, Format::Pdf, Format::Eps, Format::Png] {
        let (_, s) = paint(f, &all_marks());
        assert_eq!(
            (s.lines, s.markers, s.labels, s.heads),
            (2, 6, 1, 1),
            "{f:?}"
        );
        assert_eq!(s.paths, 1, "{f:?}");
        assert_eq!(s.skipped, 0, "{f:?}");
    }
}

#[test]
fn png_paints_marks_at_their_position() {
    let px = |p: &Picture| {
        let mut out = Vec::new();
        PngPainter::default().paint(p, &mut out).unwrap();
        let pm = Pixmap::decode_png(&out).unwrap();
        let c = pm.pixel(20, 20).unwrap().demultiply();
        let outside = pm.pixel(3, 20).unwrap().demultiply();
        (
            [c.red(), c.green(), c.blue()],
            [outside.red(), outside.alpha()],
        )
    };
    // Painted before the square: the square covers it; outside the square it shows.
    assert_eq!(px(&crossing(0)), ([51, 102, 153], [255, 255]));
    // Painted after: the line is on top.
    assert_eq!(px(&crossing(1)), ([255, 0, 0], [255, 255]));
}

#[test]
fn svg_interleaves_marks_and_writes_styles() {
    let (out, _) = paint(Format::Svg, &crossing(0));
    let t = String::from_utf8(out).unwrap();
    let line = t.find("stroke=\"#ff0000\"").unwrap();
    let fill = t.find("fill=\"#336699\"").unwrap();
    assert!(line < fill, "{t}");
    let (out, _) = paint(Format::Svg, &all_marks());
    let t = String::from_utf8(out).unwrap();
    assert!(t.find("fill=\"#336699\"").unwrap() < t.find("stroke=\"#ff0000\"").unwrap());
    assert!(t.contains("stroke-dasharray=\"3 1 2 3 1 2\""), "{t}");
    assert!(t.contains("stroke-linecap=\"butt\""));
    assert!(t.contains(">a&lt;(b)&gt;&amp;\\ é</text>"), "{t}");
    assert!(
        t.contains("<circle cx=\"5\" cy=\"35\" r=\"2.5\" fill=\"#008000\" fill-opacity=\"0.5\"/>"),
        "{t}"
    );
}

#[test]
fn pdf_and_eps_use_helvetica_and_escape_text() {
    let (out, s) = paint(Format::Pdf, &all_marks());
    let t = text(&out);
    assert!(t.contains("/BaseFont /Helvetica"), "{t}");
    assert!(t.contains("(a<\\(b\\)>&\\\\ ?) Tj"), "{t}");
    assert!(t.contains("[3 1 2 3 1 2] 0 d"));
    assert_eq!(s.approximated, 1, "the non-ASCII character");
    let (out, s) = paint(Format::Eps, &all_marks());
    let t = text(&out);
    assert!(t.contains("/Helvetica findfont 8 scalefont setfont"), "{t}");
    assert!(t.contains("(a<\\(b\\)>&\\\\ ?) show"));
    assert!(t.contains("[3 1 2 3 1 2] 0 setdash"));
    // The label, and the six translucent markers.
    assert_eq!(s.approximated, 7);
    // Crossing(0): the line comes before the fill.
    let (out, _) = paint(Format::Pdf, &crossing(0));
    let t = text(&out);
    assert!(t.find(" S Q").unwrap() < t.find("h\nf\n").unwrap(), "{t}");
}

#[test]
fn invalid_marks_are_skipped_and_far_ones_clipped() {
    let mut p = crossing(1);
    p.marks.push(mark(1, line(vec![[0.0, 1.0]], 1.0, vec![])));
    p.marks.push(mark(
        1,
        line(vec![[0.0, 1.0], [f64::NAN, 2.0]], 1.0, vec![]),
    ));
    p.marks
        .push(mark(1, line(vec![[0.0, 1.0], [3.0, 2.0]], 0.0, vec![])));
    p.marks.push(mark(
        1,
        MarkKind::Marker(Marker {
            at: [1e9, 0.0],
            shape: MarkerShape::Dot,
            size: 3.0,
            color: RED,
            stroke: 1.0,
        }),
    ));
    // A long line is clipped to the guard box but still drawn.
    p.marks.push(mark(
        1,
        line(vec![[-1e12, 10.0], [1e12, 12.0]], 1.0, vec![]),
    ));
    for f in [Format::Svg, Format::Pdf, Format::Eps, Format::Png] {
        let (out, s) = paint(f, &p);
        assert_eq!(
            (s.skipped, s.clipped, s.lines, s.markers),
            (3, 1, 2, 0),
            "{f:?}"
        );
        if f == Format::Svg {
            assert!(!text(&out).contains("e+"), "no exponent");
            assert!(!text(&out).contains("1000000000000"));
        }
    }
}
