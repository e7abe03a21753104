//! Structure of the PDF and EPS outputs.

use limn_paint::{EpsPainter, Outline, PaintFragment, PaintStats, Painter, PdfPainter, Picture};

const BLUE: [f64; 4] = [0.2, 0.4, 0.6, 1.0];

fn paint(painter: &dyn Painter, picture: &Picture) -> (Vec<u8>, PaintStats) {
    let mut out = Vec::new();
    let stats = painter.paint(picture, &mut out).unwrap();
    assert_eq!(stats.bytes, out.len() as u64);
    (out, stats)
}

/// The bytes as text, each non-ASCII byte shown as `?` so that offsets are kept.
fn text(bytes: &[u8]) -> String {
    bytes
        .iter()
        .map(|&b| if b.is_ascii() { char::from(b) } else { '?' })
        .collect()
}

/// A triangle near the top left of a 200 × 100 page.
fn one_triangle() -> Picture {
    let mut p = Picture::new(200, 100);
    p.fragments.push(PaintFragment::new(
        vec![[10.0, 10.0], [60.0, 10.0], [10.0, 60.0]],
        BLUE,
    ));
    p
}

fn gouraud_square(face: u32) -> PaintFragment {
    let mut f = PaintFragment::new(
        vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]],
        BLUE,
    );
    f.face = face;
    f.vertex_colors = Some(vec![
        [1.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 1.0],
        [1.0, 1.0, 1.0, 1.0],
    ]);
    f
}

/// Checks the cross-reference table: every in-use entry points at `N 0 obj`.
fn check_xref(pdf: &[u8]) -> usize {
    let s = text(pdf);
    assert!(s.starts_with("%PDF-1."), "header");
    assert!(s.ends_with("%%EOF") || s.ends_with("%%EOF\n"), "trailer");
    let at = s.rfind("startxref").expect("startxref");
    let offset: usize = s[at + 9..]
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        s[offset..].starts_with("xref\n"),
        "startxref points at xref"
    );
    let mut lines = s[offset..].lines().skip(1);
    let header: Vec<usize> = lines
        .next()
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(header[0], 0);
    let mut objects = 0;
    for id in 0..header[1] {
        let entry = lines.next().unwrap();
        let fields: Vec<&str> = entry.split_whitespace().collect();
        if fields[2] == "n" {
            let pos: usize = fields[0].parse().unwrap();
            assert!(
                s[pos..].starts_with(&format!("{id} 0 obj")),
                "object {id} at {pos}"
            );
            objects += 1;
        }
    }
    objects
}

/// The content stream of the single page.
fn content(pdf: &[u8]) -> String {
    let s = text(pdf);
    let start = s.find("4 0 obj").unwrap();
    let body = &s[start..];
    let a = body.find("stream\n").unwrap() + 7;
    let b = body.find("\nendstream").unwrap();
    body[a..b].to_string()
}

#[test]
fn pdf_header_media_box_and_xref() {
    let (pdf, stats) = paint(&PdfPainter::default(), &one_triangle());
    assert_eq!(check_xref(&pdf), 4);
    let s = text(&pdf);
    assert!(s.contains("/MediaBox [0 0 200 100]"), "{s}");
    assert_eq!(stats.paths, 1);
}

#[test]
fn pdf_flips_y() {
    let (pdf, _) = paint(&PdfPainter::default(), &one_triangle());
    let c = content(&pdf);
    // (10, 10) is 10 below the top of a 100-high page: y = 90.
    assert_eq!(c, "0.2 0.4 0.6 rg\n10 90 m 60 90 l 10 40 l h\nf\n");
}

#[test]
fn pdf_empty_picture_and_background() {
    let (pdf, stats) = paint(&PdfPainter::default(), &Picture::new(5, 7));
    check_xref(&pdf);
    assert!(text(&pdf).contains("/MediaBox [0 0 5 7]"));
    assert_eq!(content(&pdf), "");
    assert_eq!(stats.paths, 0);

    let mut p = Picture::new(5, 7);
    p.background = Some([1.0, 1.0, 1.0, 0.5]);
    let (pdf, _) = paint(&PdfPainter::default(), &p);
    check_xref(&pdf);
    assert_eq!(content(&pdf), "/a500 gs\n1 1 1 rg\n0 0 5 7 re f\n");
    assert!(text(&pdf).contains("/ca 0.5"));
}

#[test]
fn pdf_opacity_uses_ext_g_states() {
    let mut p = one_triangle();
    let mut f = p.fragments[0].clone();
    f.fill[3] = 0.25;
    f.face = 1;
    p.fragments.push(f);
    let mut g = p.fragments[0].clone();
    g.face = 2;
    p.fragments.push(g);
    let (pdf, stats) = paint(&PdfPainter::default(), &p);
    check_xref(&pdf);
    let c = content(&pdf);
    assert_eq!(c.matches("/a250 gs").count(), 1);
    assert_eq!(c.matches("/a1000 gs").count(), 1, "{c}");
    // The colour is unchanged, so it is not set again.
    assert_eq!(c.matches(" rg").count(), 1);
    let s = text(&pdf);
    assert!(s.contains("/a250 ") && s.contains("/ca 0.25"));
    assert!(s.contains("/a1000 ") && s.contains("/ca 1"));
    assert_eq!(stats.paths, 3);
}

#[test]
fn pdf_gouraud_is_a_type_4_shading() {
    let mut p = Picture::new(20, 20);
    p.fragments.push(gouraud_square(0));
    // A second fragment of the same face joins the same shading.
    let mut second = gouraud_square(0);
    second.points = vec![[10.0, 0.0], [20.0, 0.0], [20.0, 10.0]];
    second.vertex_colors.as_mut().unwrap().pop();
    p.fragments.push(second);
    let (pdf, stats) = paint(&PdfPainter::default(), &p);
    assert_eq!(check_xref(&pdf), 5);
    let s = text(&pdf);
    assert!(s.contains("/ShadingType 4"));
    assert!(s.contains("/BitsPerCoordinate 32"));
    assert!(s.contains("/BitsPerComponent 16"));
    assert!(s.contains("/BitsPerFlag 8"));
    // Bounding box of the run in PDF coordinates: x 0..20, y 10..20.
    assert!(s.contains("/Decode [0 20 10 20 0 1 0 1 0 1]"), "{s}");
    // 2 + 1 triangles of 3 vertices of 15 bytes.
    assert!(s.contains("/Length 135"), "{s}");
    assert_eq!(content(&pdf), "/Sh0 sh\n");
    assert_eq!(stats.paths, 1);

    // First vertex: flag 0, x = 0 → 0, y = 20 − 0 = 20 → top of the range, red.
    let at = s.find("/ShadingType 4").unwrap();
    let data_at = pdf[at..].windows(7).position(|w| w == b"stream\n").unwrap() + at + 7;
    let v = &pdf[data_at..data_at + 15];
    assert_eq!(v[0], 0);
    assert_eq!(&v[1..5], &[0, 0, 0, 0]);
    assert_eq!(&v[5..9], &[255, 255, 255, 255]);
    assert_eq!(&v[9..15], &[255, 255, 0, 0, 0, 0]);
}

#[test]
fn pdf_outlines_only_original_edges() {
    let mut p = one_triangle();
    p.fragments[0].original_edges = vec![true, false, false];
    p.outline = Some(Outline {
        color: [0.0, 0.0, 0.0, 0.5],
        width: 2.0,
    });
    let (pdf, stats) = paint(&PdfPainter::default(), &p);
    check_xref(&pdf);
    let c = content(&pdf);
    assert!(c.starts_with("2 w 1 J 1 j\n0 0 0 RG\n/s500 gs\n"), "{c}");
    assert!(c.ends_with("f\n10 90 m 60 90 l S\n"), "{c}");
    assert!(text(&pdf).contains("/CA 0.5"));
    assert_eq!(stats.strokes, 1);
}

#[test]
fn pdf_is_deterministic() {
    let mut p = one_triangle();
    p.fragments.push(gouraud_square(3));
    let (a, _) = paint(&PdfPainter::default(), &p);
    let (b, _) = paint(&PdfPainter::default(), &p);
    assert_eq!(a, b);
}

#[test]
fn eps_header_and_flip() {
    let (eps, stats) = paint(&EpsPainter::default(), &one_triangle());
    let s = text(&eps);
    let mut lines = s.lines();
    assert_eq!(lines.next(), Some("%!PS-Adobe-3.0 EPSF-3.0"));
    assert_eq!(lines.next(), Some("%%BoundingBox: 0 0 200 100"));
    assert!(s.contains("%%LanguageLevel: 2\n"));
    assert!(
        s.contains("\n0.2 0.4 0.6 c\n10 90 m 60 90 l 10 40 l h\nf\n"),
        "{s}"
    );
    assert!(s.ends_with("end\nshowpage\n%%EOF\n"));
    assert_eq!(s.matches(" begin").count(), s.matches("\nend\n").count());
    assert_eq!(stats.paths, 1);
    assert_eq!(stats.approximated, 0);
}

#[test]
fn eps_flattens_translucency() {
    let mut p = one_triangle();
    p.fragments[0].fill = [0.0, 0.0, 0.0, 0.5];
    let (eps, stats) = paint(&EpsPainter::default(), &p);
    assert!(text(&eps).contains("0.5 0.5 0.5 c\n"));
    assert_eq!(stats.approximated, 1);

    // Over a background it blends with the background, not the paper.
    p.background = Some([0.0, 0.0, 1.0, 1.0]);
    let (eps, _) = paint(&EpsPainter::default(), &p);
    let s = text(&eps);
    assert!(s.contains("0 0 1 c\n0 0 200 100 rectfill\n"), "{s}");
    assert!(s.contains("0 0 0.5 c\n"), "{s}");

    // Fully transparent fills are not painted.
    p.fragments[0].fill[3] = 0.0;
    let (eps, stats) = paint(&EpsPainter::default(), &p);
    assert!(!text(&eps).contains(" m "));
    assert_eq!(stats.paths, 0);
}

#[test]
fn eps_gouraud_uses_shfill_in_small_arrays() {
    let mut p = Picture::new(20, 20);
    p.fragments.push(gouraud_square(0));
    let (eps, stats) = paint(&EpsPainter::default(), &p);
    let s = text(&eps);
    assert!(s.contains("%%LanguageLevel: 3\n"));
    assert!(s.contains("/ShadingType 4"));
    assert!(
        s.contains("[0 0 20 1 0 0\n0 10 20 0 1 0\n0 10 10 0 0 1\n0 0 20 1 0 0\n"),
        "{s}"
    );
    assert_eq!(s.matches("] g\n").count(), 1);
    assert_eq!(stats.paths, 1);

    // 100 triangles of one face: arrays of at most 27 triangles.
    let mut p = Picture::new(20, 20);
    for i in 0..100 {
        let mut f = gouraud_square(0);
        f.points = vec![[0.0, 0.0], [f64::from(i) * 0.1, 1.0], [0.0, 1.0]];
        f.vertex_colors.as_mut().unwrap().pop();
        p.fragments.push(f);
    }
    let (eps, stats) = paint(&EpsPainter::default(), &p);
    let s = text(&eps);
    assert_eq!(s.matches("] g\n").count(), 4);
    for array in s.split('[').skip(1) {
        let array = &array[..array.find(']').unwrap()];
        assert!(array.split_whitespace().count() <= 27 * 18);
    }
    assert_eq!(stats.paths, 1);
}

#[test]
fn eps_outline() {
    let mut p = one_triangle();
    p.fragments[0].original_edges = vec![false, true, false];
    p.outline = Some(Outline {
        color: [1.0, 0.0, 0.0, 1.0],
        width: 0.75,
    });
    let (eps, stats) = paint(&EpsPainter::default(), &p);
    let s = text(&eps);
    assert!(s.contains("1 setlinecap 1 setlinejoin 0.75 setlinewidth\n"));
    assert!(s.contains("f\n1 0 0 c\n60 90 m 10 40 l s\n"), "{s}");
    assert_eq!(stats.strokes, 1);
}

#[test]
fn eps_long_runs_are_filled_in_pieces() {
    let mut p = Picture::new(100, 100);
    for i in 0..600 {
        let x = f64::from(i) * 0.1;
        p.fragments.push(PaintFragment::new(
            vec![[x, 0.0], [x + 0.1, 0.0], [x, 1.0]],
            BLUE,
        ));
    }
    let (eps, stats) = paint(&EpsPainter::default(), &p);
    let s = text(&eps);
    // 1800 points in pieces of at most 1000.
    assert_eq!(s.matches("\nf\n").count(), 2);
    assert_eq!(stats.paths, 1);
}

#[test]
fn empty_eps_is_valid() {
    let (eps, _) = paint(&EpsPainter::default(), &Picture::new(1, 1));
    let s = text(&eps);
    assert!(s.starts_with("%!PS-Adobe-3.0 EPSF-3.0\n%%BoundingBox: 0 0 1 1\n"));
    assert!(s.ends_with("end\nshowpage\n%%EOF\n"));
}
