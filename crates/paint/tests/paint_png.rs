//! PNG output, decoded and checked pixel by pixel.

use limn_paint::{
    narrow_color, Outline, PaintError, PaintFragment, Painter, Picture, PngOptions, PngPainter,
};
use tiny_skia::Pixmap;

const BLUE: [f64; 4] = [0.2, 0.4, 0.6, 1.0];

fn render(picture: &Picture) -> Pixmap {
    render_with(PngPainter::default(), picture)
}

fn render_with(painter: PngPainter, picture: &Picture) -> Pixmap {
    let mut out = Vec::new();
    let stats = painter.paint(picture, &mut out).unwrap();
    assert_eq!(stats.bytes, out.len() as u64);
    assert!(out.starts_with(b"\x89PNG\r\n\x1a\n"));
    let pixmap = Pixmap::decode_png(&out).unwrap();
    assert_eq!(
        (pixmap.width(), pixmap.height()),
        (picture.width, picture.height)
    );
    pixmap
}

/// Straight (not premultiplied) RGBA of pixel (x, y).
fn rgba(p: &Pixmap, x: u32, y: u32) -> [u8; 4] {
    let c = p.pixel(x, y).unwrap().demultiply();
    [c.red(), c.green(), c.blue(), c.alpha()]
}

fn square(x0: f64, y0: f64, x1: f64, y1: f64, fill: [f64; 4]) -> PaintFragment {
    PaintFragment::new(vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]], fill)
}

#[test]
fn illum_0_colour_is_exact_and_outside_is_transparent() {
    let mut p = Picture::new(40, 30);
    p.fragments.push(PaintFragment::new(
        vec![[5.0, 5.0], [35.0, 5.0], [5.0, 25.0]],
        BLUE,
    ));
    let px = render(&p);
    assert_eq!(rgba(&px, 10, 10), [51, 102, 153, 255]);
    assert_eq!(rgba(&px, 38, 28), [0, 0, 0, 0]);
    assert_eq!(rgba(&px, 0, 0), [0, 0, 0, 0]);
}

#[test]
fn y_points_down() {
    let mut p = Picture::new(20, 20);
    p.fragments.push(square(0.0, 0.0, 20.0, 5.0, BLUE));
    let px = render(&p);
    assert_eq!(rgba(&px, 10, 2)[3], 255);
    assert_eq!(rgba(&px, 10, 17)[3], 0);
}

#[test]
fn background_fills_the_rest() {
    let mut p = Picture::new(10, 10);
    p.background = Some([1.0, 0.5, 0.0, 1.0]);
    p.fragments.push(square(0.0, 0.0, 5.0, 5.0, BLUE));
    let px = render(&p);
    assert_eq!(rgba(&px, 8, 8), [255, 128, 0, 255]);
    assert_eq!(rgba(&px, 2, 2), [51, 102, 153, 255]);
}

#[test]
fn later_fragments_cover_earlier_ones() {
    let mut p = Picture::new(30, 30);
    let mut red = square(0.0, 0.0, 20.0, 20.0, [1.0, 0.0, 0.0, 1.0]);
    red.face = 0;
    let mut green = square(10.0, 10.0, 30.0, 30.0, [0.0, 1.0, 0.0, 1.0]);
    green.face = 1;
    p.fragments = vec![red.clone(), green.clone()];
    let px = render(&p);
    assert_eq!(rgba(&px, 15, 15), [0, 255, 0, 255]);
    assert_eq!(rgba(&px, 5, 5), [255, 0, 0, 255]);
    p.fragments = vec![green, red];
    let px = render(&p);
    assert_eq!(rgba(&px, 15, 15), [255, 0, 0, 255]);
}

/// A 40 × 40 square cut along its diagonal into two fragments.
fn split_square(second_face: u32) -> Picture {
    let mut p = Picture::new(60, 60);
    let a = PaintFragment::new(vec![[10.0, 10.0], [50.0, 10.0], [50.0, 50.0]], BLUE);
    let mut b = PaintFragment::new(vec![[10.0, 10.0], [50.0, 50.0], [10.0, 50.0]], BLUE);
    b.face = second_face;
    p.fragments = vec![a, b];
    p
}

#[test]
fn fragments_of_one_face_show_no_seam() {
    let px = render(&split_square(0));
    for i in 11..49 {
        assert_eq!(rgba(&px, i, i), [51, 102, 153, 255], "diagonal pixel {i}");
    }
    // Different faces: with per-path anti-aliasing the cut shows (the background bleeds
    // through both edge pixels); supersampling (the default) covers each sample once.
    let plain = PngPainter::new(PngOptions {
        supersample: 1,
        ..PngOptions::default()
    });
    let px = render_with(plain, &split_square(1));
    assert!((11..49).any(|i| rgba(&px, i, i)[3] < 255));
    let px = render(&split_square(1));
    assert!((11..49).all(|i| rgba(&px, i, i)[3] == 255));
}

#[test]
fn anti_aliasing_can_be_turned_off() {
    let mut p = Picture::new(20, 20);
    p.fragments.push(PaintFragment::new(
        vec![[0.0, 0.0], [20.0, 0.0], [0.0, 13.3]],
        BLUE,
    ));
    let aa = render(&p);
    let hard = render_with(
        PngPainter::new(PngOptions {
            anti_alias: false,
            ..PngOptions::default()
        }),
        &p,
    );
    let partial = |px: &Pixmap| {
        px.pixels()
            .iter()
            .filter(|c| c.alpha() != 0 && c.alpha() != 255)
            .count()
    };
    assert!(partial(&aa) > 0);
    assert_eq!(partial(&hard), 0);
}

#[test]
fn translucent_fill_blends_source_over() {
    let mut p = Picture::new(10, 10);
    p.background = Some([1.0, 1.0, 1.0, 1.0]);
    p.fragments
        .push(square(0.0, 0.0, 10.0, 10.0, [1.0, 0.0, 0.0, 0.5]));
    let c = rgba(&render(&p), 5, 5);
    assert_eq!(c[0], 255);
    assert!((126..=128).contains(&c[1]) && c[1] == c[2], "{c:?}");
    assert_eq!(c[3], 255);
}

#[test]
fn gouraud_uniform_colour_is_exact() {
    let mut p = Picture::new(20, 20);
    let mut f = square(2.0, 2.0, 18.0, 18.0, [0.0, 0.0, 0.0, 1.0]);
    f.vertex_colors = Some(vec![narrow_color(BLUE); 4]);
    p.fragments.push(f);
    let px = render(&p);
    for (x, y) in [(3, 3), (10, 10), (16, 16), (3, 16)] {
        assert_eq!(rgba(&px, x, y), [51, 102, 153, 255]);
    }
    assert_eq!(rgba(&px, 19, 19), [0, 0, 0, 0]);
}

#[test]
fn gouraud_interpolates() {
    let mut p = Picture::new(100, 100);
    let mut f = PaintFragment::new(vec![[0.0, 0.0], [100.0, 0.0], [0.0, 100.0]], BLUE);
    f.vertex_colors = Some(vec![
        [1.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 1.0],
    ]);
    p.fragments.push(f);
    let px = render(&p);
    let near_red = rgba(&px, 1, 1);
    assert!(
        near_red[0] > 245 && near_red[1] < 10 && near_red[2] < 10,
        "{near_red:?}"
    );
    let near_green = rgba(&px, 97, 1);
    assert!(near_green[1] > 235, "{near_green:?}");
    // Pixel (33, 33) has its centre at (33.5, 33.5): barycentric (0.33, 0.335, 0.335).
    let mid = rgba(&px, 33, 33);
    for (k, want) in [(0, 0.33), (1, 0.335), (2, 0.335)] {
        assert!((f64::from(mid[k]) - want * 255.0).abs() <= 1.0, "{mid:?}");
    }
    // Along the cut edge x + y = 100 the rim pixels stay in the colour range of the edge.
    let rim = rgba(&px, 50, 49);
    assert!(rim[0] < 5, "{rim:?}");
}

#[test]
fn outlines_only_on_original_edges() {
    let mut p = Picture::new(40, 40);
    let mut f = square(10.0, 10.0, 30.0, 30.0, BLUE);
    // Only the top edge (10,10)→(30,10) is original.
    f.original_edges = vec![true, false, false, false];
    p.fragments.push(f);
    p.outline = Some(Outline {
        color: [0.0, 0.0, 0.0, 1.0],
        width: 2.0,
    });
    let px = render(&p);
    assert_eq!(rgba(&px, 20, 10), [0, 0, 0, 255]);
    assert_eq!(rgba(&px, 20, 29), [51, 102, 153, 255]);
    assert_eq!(rgba(&px, 29, 20), [51, 102, 153, 255]);
    // The round cap (radius 1) covers a quarter disc of the pixel past the edge's end.
    assert!(
        (190..=225).contains(&rgba(&px, 30, 10)[3]),
        "{:?}",
        rgba(&px, 30, 10)
    );
    assert_eq!(rgba(&px, 31, 10)[3], 0);
}

#[test]
fn huge_and_invalid_fragments() {
    let mut p = Picture::new(10, 10);
    p.fragments.push(PaintFragment::new(
        vec![[-1e300, -1e300], [1e300, -1e300], [0.0, 1e300]],
        BLUE,
    ));
    p.fragments.push(PaintFragment::new(
        vec![[0.0, 0.0], [f64::INFINITY, 0.0], [0.0, 5.0]],
        [1.0; 4],
    ));
    let mut out = Vec::new();
    let stats = PngPainter::default().paint(&p, &mut out).unwrap();
    assert_eq!(stats.skipped, 1);
    assert_eq!(stats.clipped, 1);
    let px = Pixmap::decode_png(&out).unwrap();
    assert!(px.pixels().iter().all(|c| c.alpha() == 255));
}

#[test]
fn size_limits_are_errors() {
    let mut out = Vec::new();
    let err = PngPainter::default()
        .paint(&Picture::new(0, 10), &mut out)
        .unwrap_err();
    assert!(matches!(err, PaintError::Size { .. }));
    let small = PngPainter::new(PngOptions {
        max_pixels: 99,
        ..PngOptions::default()
    });
    let err = small.paint(&Picture::new(10, 10), &mut out).unwrap_err();
    assert!(matches!(err, PaintError::Size { .. }), "{err}");
    assert!(out.is_empty());
}

#[test]
fn empty_picture_is_transparent() {
    let px = render(&Picture::new(3, 4));
    assert!(px.pixels().iter().all(|c| c.alpha() == 0));
}

#[test]
fn gouraud_fragments_of_one_face_show_no_seam() {
    // A square with an affine colour ramp, cut along its diagonal into two fragments.
    let ramp = |p: [f64; 2]| [p[0] / 60.0, 0.5, 1.0 - p[0] / 60.0, 1.0];
    let tri = |pts: Vec<[f64; 2]>| {
        let mut f = PaintFragment::new(pts.clone(), BLUE);
        f.vertex_colors = Some(pts.into_iter().map(ramp).map(narrow_color).collect());
        f
    };
    let mut p = Picture::new(60, 60);
    p.fragments
        .push(tri(vec![[10.0, 10.0], [50.0, 10.0], [50.0, 50.0]]));
    p.fragments
        .push(tri(vec![[10.0, 10.0], [50.0, 50.0], [10.0, 50.0]]));
    let px = render(&p);
    for i in 11..49 {
        let c = rgba(&px, i, i);
        assert_eq!(c[3], 255, "diagonal pixel {i}");
        let want = ramp([f64::from(i) + 0.5, 0.0]).map(|v| v * 255.0);
        assert!((f64::from(c[0]) - want[0]).abs() <= 1.0, "{c:?} at {i}");
        assert!((f64::from(c[2]) - want[2]).abs() <= 1.0, "{c:?} at {i}");
    }
}
