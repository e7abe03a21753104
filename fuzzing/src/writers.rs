//! Arbitrary pictures through every writer of `limn-paint`: fragments with small,
//! raw or extreme coordinates (±∞, NaN, ±f64::MAX, subnormals), any colours and
//! opacities, Gouraud colours, textures under any projective map (and texture indices
//! out of range), object names that need escaping, outlines and seams.
//! Every writer either fails with a typed error or writes a file that parses: SVG as
//! XML (`roxmltree`), PDF with `lopdf`, PNG with the `png` decoder (of the picture's
//! size), EPS between `%!PS-Adobe` and `%%EOF`; and the reported byte count is the
//! output's length.

use std::fmt;

use arbitrary::{Arbitrary, Unstructured};
use limn_paint::{
    narrow_color, Format, Outline, PaintFragment, Painter, Picture, PngOptions, PngPainter,
    SvgPainter,
};

use crate::{OptVecLit, VecLit};

/// A number.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Num {
    /// `n / 8`.
    Small(i16),
    /// Any f64, as its bit pattern ([`f64::from_bits`]).
    Raw(u64),
    /// One of [`EXTREMES`] (modulo their number).
    Extreme(u8),
}

/// Values at the edges of f64.
pub const EXTREMES: [f64; 12] = [
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
    f64::MAX,
    f64::MIN,
    f64::MIN_POSITIVE,
    5e-324,
    -0.0,
    1e300,
    -1e300,
    1e15,
    0.5 - f64::EPSILON / 4.0,
];

impl Num {
    fn value(self) -> f64 {
        match self {
            Num::Small(n) => n as f64 / 8.0,
            Num::Raw(b) => f64::from_bits(b),
            Num::Extreme(i) => EXTREMES[i as usize % EXTREMES.len()],
        }
    }
}

/// A colour with opacity.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Colour {
    /// Channels `c / 255`.
    Bytes([u8; 4]),
    /// Any channels.
    Any([Num; 4]),
}

impl Colour {
    fn value(self) -> [f64; 4] {
        match self {
            Colour::Bytes(c) => c.map(|c| c as f64 / 255.0),
            Colour::Any(c) => c.map(Num::value),
        }
    }
}

/// Object names that need escaping in one format or another.
pub const NAMES: [&str; 10] = [
    "",
    "cube",
    "<&>\"'",
    "]]>",
    "--",
    "a\u{0}b",
    "\u{1b}[0m\r\n\t",
    "é ü 字 🙂",
    "(unbalanced \\",
    "%%EOF",
];

/// One fragment.
#[derive(Clone, Arbitrary)]
pub struct Frag {
    /// Corners, in pixels (at most 16 are used).
    pub points: Vec<[Num; 2]>,
    /// Fill colour and opacity.
    pub fill: Colour,
    /// Per-corner (Gouraud) colours.
    pub vertex_colors: Option<Vec<Colour>>,
    /// Face id.
    pub face: u8,
    /// Object index (out of range on purpose sometimes).
    pub object: u8,
    /// Which edges are original (outlined).
    pub edges: Vec<bool>,
    /// A texture: its index (the picture has [`TEXTURES`] of them) and the rows of the
    /// page-to-texture map.
    pub texture: Option<(u8, [Num; 9])>,
}

/// Textures in a picture with a textured fragment (indices at and past it are out of
/// range on purpose).
pub const TEXTURES: u8 = 2;

impl fmt::Debug for Frag {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Frag")
            .field("points", &VecLit(&self.points))
            .field("fill", &self.fill)
            .field("vertex_colors", &OptVecLit(self.vertex_colors.as_deref()))
            .field("face", &self.face)
            .field("object", &self.object)
            .field("edges", &VecLit(&self.edges))
            .field("texture", &self.texture)
            .finish()
    }
}

/// One picture.
#[derive(Clone, Arbitrary)]
pub struct Case {
    /// Page width (0 is refused with an error).
    pub width: u16,
    /// Page height.
    pub height: u16,
    /// Background colour.
    pub background: Option<Colour>,
    /// Object names, as indices into [`NAMES`] (modulo their number).
    pub objects: Vec<u8>,
    /// Fragments in painting order (at most 32 are used).
    pub fragments: Vec<Frag>,
    /// Outline colour and width.
    pub outline: Option<(Colour, Num)>,
    /// Seam stroke width.
    pub seams: Num,
}

impl fmt::Debug for Case {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Case")
            .field("width", &self.width)
            .field("height", &self.height)
            .field("background", &self.background)
            .field("objects", &VecLit(&self.objects))
            .field("fragments", &VecLit(&self.fragments))
            .field("outline", &self.outline)
            .field("seams", &self.seams)
            .finish()
    }
}

/// The picture a case describes.
pub fn picture(case: &Case) -> Picture {
    let mut p = Picture::new(u32::from(case.width), u32::from(case.height));
    p.background = case.background.map(Colour::value);
    p.objects = case
        .objects
        .iter()
        .take(8)
        .map(|&i| NAMES[i as usize % NAMES.len()].to_string())
        .collect();
    p.fragments = case
        .fragments
        .iter()
        .take(32)
        .map(|f| PaintFragment {
            points: f
                .points
                .iter()
                .take(16)
                .map(|[x, y]| [x.value(), y.value()])
                .collect(),
            fill: f.fill.value(),
            vertex_colors: f
                .vertex_colors
                .as_ref()
                .map(|c| c.iter().take(16).map(|c| narrow_color(c.value())).collect()),
            face: u32::from(f.face),
            object: u32::from(f.object),
            original_edges: f.edges.iter().take(17).copied().collect(),
            texture: f.texture.map(|(k, m)| {
                Box::new(limn_paint::TextureMap {
                    texture: u32::from(k % (TEXTURES + 1)),
                    screen_to_st: [
                        [m[0].value(), m[1].value(), m[2].value()],
                        [m[3].value(), m[4].value(), m[5].value()],
                        [m[6].value(), m[7].value(), m[8].value()],
                    ],
                    alpha: limn_paint::TextureAlpha::Opaque,
                })
            }),
            flap: false,
        })
        .collect();
    if p.has_textures() {
        // A 3 × 2 texture and a 1 × 1 one.
        let a: Vec<u8> = (0..24u8).map(|v| v.wrapping_mul(37)).collect();
        p.textures = vec![
            std::sync::Arc::new(limn_paint::Texture::new("a", 3, 2, a).expect("valid")),
            std::sync::Arc::new(
                limn_paint::Texture::new("b", 1, 1, vec![9, 99, 199, 255]).expect("valid"),
            ),
        ];
    }
    p.outline = case.outline.map(|(c, w)| Outline {
        color: c.value(),
        width: w.value(),
    });
    p.seams = case.seams.value();
    p
}

/// The largest PNG painted, in pixels: large pages are refused with a typed error
/// rather than rasterised, to keep every case fast.
const MAX_PNG_PIXELS: u64 = 1 << 16;

fn painter(format: Format) -> Box<dyn Painter> {
    match format {
        Format::Png => Box::new(PngPainter::new(PngOptions {
            max_pixels: MAX_PNG_PIXELS,
            ..PngOptions::default()
        })),
        Format::Svg => Box::new(SvgPainter::default()),
        other => limn_paint::painter_for(other),
    }
}

/// Checks that `out` is a well-formed file of `format` for `picture`.
fn check_output(format: Format, picture: &Picture, out: &[u8]) {
    match format {
        Format::Svg => {
            let text = std::str::from_utf8(out).expect("SVG is UTF-8");
            if let Err(e) = roxmltree::Document::parse(text) {
                panic!("SVG does not parse as XML: {e}\n{text}");
            }
        }
        Format::Pdf => {
            if let Err(e) = lopdf::Document::load_mem(out) {
                panic!("PDF does not parse: {e}");
            }
        }
        Format::Eps => {
            let text = String::from_utf8_lossy(out);
            assert!(text.starts_with("%!PS-Adobe"), "EPS header: {text}");
            assert!(text.trim_end().ends_with("%%EOF"), "EPS trailer: {text}");
        }
        Format::Tikz => {
            let text = std::str::from_utf8(out).expect("TikZ is UTF-8");
            check_tikz(text);
        }
        Format::Png => {
            let mut reader = png::Decoder::new(out)
                .read_info()
                .expect("PNG header decodes");
            let mut buf = vec![0; reader.output_buffer_size()];
            let info = reader.next_frame(&mut buf).expect("PNG image decodes");
            assert_eq!(
                (info.width, info.height),
                (picture.width, picture.height),
                "PNG size"
            );
        }
    }
}

/// Checks the structure of a TikZ picture: one environment, every command on its own
/// line and ended, brackets balanced, numbers plain.
fn check_tikz(text: &str) {
    assert!(text.starts_with("% limn picture"), "TikZ header: {text}");
    assert!(
        text.ends_with("\\end{tikzpicture}\n"),
        "TikZ trailer: {text}"
    );
    assert_eq!(text.matches("\\begin{tikzpicture}").count(), 1, "{text}");
    for line in text.lines() {
        if line.starts_with('%') {
            continue;
        }
        assert!(!line.contains("NaN") && !line.contains("inf") && !line.contains("e+"));
        let mut depth = [0i32; 3];
        for c in line.chars() {
            match c {
                '{' => depth[0] += 1,
                '}' => depth[0] -= 1,
                '[' => depth[1] += 1,
                ']' => depth[1] -= 1,
                '(' => depth[2] += 1,
                ')' => depth[2] -= 1,
                _ => {}
            }
            assert!(depth.iter().all(|&d| d >= 0), "unbalanced: {line}");
        }
        assert_eq!(depth, [0; 3], "unbalanced: {line}");
        if line.starts_with("\\fill") || line.starts_with("\\draw") || line.starts_with("\\use") {
            assert!(line.ends_with(';'), "unended command: {line}");
        }
    }
}

/// Paints the case's picture with every writer and checks every output.
pub fn run_case(case: &Case) {
    let picture = picture(case);
    for format in Format::ALL {
        let mut out = Vec::new();
        // Unusable pages and styles are refused with a typed error.
        let Ok(stats) = painter(format).paint(&picture, &mut out) else {
            continue;
        };
        assert_eq!(stats.bytes, out.len() as u64, "{format}: bytes reported");
        check_output(format, &picture, &out);
    }
}

/// The [`Case`] that `data` decodes to, as [`run`] decodes it (`None`: skipped).
/// Its `Debug` form is Rust source for a regression test.
pub fn decode(data: &[u8]) -> Option<Case> {
    Case::arbitrary_take_rest(Unstructured::new(data)).ok()
}

/// Decodes a [`Case`] from `data` and runs it; undecodable bytes are skipped.
pub fn run(data: &[u8]) {
    if let Some(case) = decode(data) {
        run_case(&case);
    }
}
