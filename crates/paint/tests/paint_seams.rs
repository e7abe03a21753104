//! Seam-closing strokes: only opaque flat fills get them, in their own colour, and only
//! when asked for.

use limn_paint::{EpsPainter, PaintFragment, Painter, PdfPainter, Picture, SvgPainter};

fn picture(seams: f64) -> Picture {
    let mut p = Picture::new(40, 30);
    p.seams = seams;
    p.objects = vec!["o".into()];
    p.fragments.push(PaintFragment::new(
        vec![[1.0, 1.0], [20.0, 1.0], [1.0, 20.0]],
        [0.2, 0.4, 0.6, 1.0],
    ));
    let mut t = PaintFragment::new(
        vec![[5.0, 5.0], [30.0, 5.0], [5.0, 25.0]],
        [1.0, 0.0, 0.0, 0.5],
    );
    t.face = 1;
    p.fragments.push(t);
    p
}

fn text(painter: &dyn Painter, p: &Picture) -> String {
    let mut out = Vec::new();
    painter.paint(p, &mut out).unwrap();
    String::from_utf8_lossy(&out).into_owned()
}

#[test]
fn svg_strokes_opaque_fills_in_their_own_colour() {
    let s = text(&SvgPainter::default(), &picture(0.35));
    assert!(s.contains(r##"stroke-width="0.35""##), "{s}");
    assert!(s.contains(r##"fill="#336699" stroke="#336699"/>"##), "{s}");
    assert_eq!(
        s.matches("stroke=\"#").count(),
        1,
        "the translucent fill has no seam stroke"
    );
    let plain = text(&SvgPainter::default(), &picture(0.0));
    assert!(!plain.contains("stroke"), "{plain}");
}

#[test]
fn svg_outlines_keep_their_own_width_next_to_seams() {
    let mut p = picture(0.35);
    p.outline = Some(limn_paint::Outline {
        color: [0.0, 0.0, 0.0, 0.5],
        width: 1.5,
    });
    let s = text(&SvgPainter::default(), &p);
    assert!(
        s.contains(r##"fill="none" stroke="#000000" stroke-width="1.5" stroke-opacity="0.5""##),
        "{s}"
    );
}

#[test]
fn pdf_fills_and_strokes_opaque_runs() {
    let s = text(&PdfPainter::default(), &picture(0.35));
    assert!(
        s.contains("0.35 w") && s.contains("\nB\n"),
        "seams: fill and stroke with B"
    );
    let plain = text(&PdfPainter::default(), &picture(0.0));
    assert!(!plain.contains("\nB\n"));
}

#[test]
fn eps_defines_and_uses_the_seam_fill() {
    let s = text(&EpsPainter::default(), &picture(0.35));
    assert!(
        s.contains("/F{gsave f grestore") && s.contains("\nF\n"),
        "{s}"
    );
    let plain = text(&EpsPainter::default(), &picture(0.0));
    assert!(!plain.contains("/F{"));
}
