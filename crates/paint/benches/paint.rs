//! Writing 100k fragments (random triangles and quads on a 1920 × 1080 page) to SVG, PDF,
//! EPS and PNG in memory, and the same SVG built with the `svg` crate for comparison.
//!
//! Run with `cargo bench -p limn-depthsort --bench paint`.

use std::sync::OnceLock;

use divan::counter::BytesCount;
use divan::Bencher;
use limn_paint::{
    EpsPainter, Outline, PaintFragment, Painter, PdfPainter, Picture, PngPainter, SvgPainter,
};

const FRAGMENTS: usize = 100_000;

fn main() {
    // LIMN_PAINT_SUMMARY=0 skips the table (for profiling one benchmark).
    if std::env::var_os("LIMN_PAINT_SUMMARY").is_none_or(|v| v != "0") {
        summary();
    }
    divan::main();
}

/// CPU time this thread has used, in seconds (`CLOCK_THREAD_CPUTIME_ID`; 0 where there
/// is none).
fn thread_cpu() -> f64 {
    cpu_time::ThreadTime::try_now().map_or(0.0, |t| t.as_duration().as_secs_f64())
}

/// Best wall and CPU times of `runs` calls of `f`, in milliseconds.
fn best_of(runs: usize, mut f: impl FnMut()) -> (f64, f64) {
    let (mut wall, mut cpu) = (f64::MAX, f64::MAX);
    for _ in 0..runs {
        let (t, c) = (std::time::Instant::now(), thread_cpu());
        f();
        cpu = cpu.min(thread_cpu() - c);
        wall = wall.min(t.elapsed().as_secs_f64());
    }
    (wall * 1e3, cpu * 1e3)
}

/// One table with sizes and best times (wall and CPU: the machine may be shared).
fn summary() {
    let p = picture();
    eprintln!("| writer | bytes | paths | best wall ms | best CPU ms |");
    eprintln!("|---|---:|---:|---:|---:|");
    for (name, painter) in painters() {
        let mut out = Vec::new();
        let stats = painter.paint(p, &mut out).unwrap_or_default();
        let runs = if name == "png" { 3 } else { 15 };
        let (wall, cpu) = best_of(runs, || {
            let mut out = Vec::with_capacity(out.len());
            let _ = divan::black_box(painter.paint(p, &mut out));
        });
        eprintln!(
            "| {name} | {} | {} | {wall:.1} | {cpu:.1} |",
            out.len(),
            stats.paths
        );
    }
    let bytes = svg_crate(p).len();
    let (wall, cpu) = best_of(5, || {
        divan::black_box(svg_crate(p));
    });
    eprintln!(
        "| svg crate | {bytes} | {} | {wall:.1} | {cpu:.1} |",
        p.fragments.len()
    );
}

fn painters() -> [(&'static str, Box<dyn Painter>); 4] {
    [
        ("svg", Box::new(SvgPainter::default())),
        ("pdf", Box::new(PdfPainter::default())),
        ("eps", Box::new(EpsPainter::default())),
        ("png", Box::new(PngPainter::default())),
    ]
}

/// xorshift64*: deterministic without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn make_picture(outline: bool) -> Picture {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut p = Picture::new(1920, 1080);
    p.background = Some([1.0, 1.0, 1.0, 1.0]);
    p.objects = (0..10).map(|i| format!("object {i}")).collect();
    for i in 0..FRAGMENTS {
        let (cx, cy) = (rng.next() * 1920.0, rng.next() * 1080.0);
        let r = 4.0 + rng.next() * 30.0;
        let corners = if rng.next() < 0.5 { 3 } else { 4 };
        let start = rng.next() * std::f64::consts::TAU;
        let points = (0..corners)
            .map(|k| {
                let a = start + std::f64::consts::TAU * f64::from(k) / f64::from(corners);
                [cx + r * a.cos(), cy + r * a.sin()]
            })
            .collect();
        let mut f = PaintFragment::new(points, [rng.next(), rng.next(), rng.next(), 1.0]);
        f.face = i as u32;
        f.object = (i * 10 / FRAGMENTS) as u32;
        p.fragments.push(f);
    }
    if outline {
        p.outline = Some(Outline {
            color: [0.0, 0.0, 0.0, 1.0],
            width: 0.5,
        });
    }
    p
}

fn picture() -> &'static Picture {
    static P: OnceLock<Picture> = OnceLock::new();
    P.get_or_init(|| make_picture(false))
}

fn outlined() -> &'static Picture {
    static P: OnceLock<Picture> = OnceLock::new();
    P.get_or_init(|| make_picture(true))
}

fn run(bencher: Bencher, painter: &dyn Painter, picture: &'static Picture) {
    let mut probe = Vec::new();
    let _ = painter.paint(picture, &mut probe);
    let capacity = probe.len();
    bencher.counter(BytesCount::new(capacity)).bench_local(|| {
        let mut out = Vec::with_capacity(capacity);
        let stats = painter.paint(divan::black_box(picture), &mut out);
        divan::black_box((stats.is_ok(), out))
    });
}

#[divan::bench(sample_count = 20)]
fn svg(bencher: Bencher) {
    run(bencher, &SvgPainter::default(), picture());
}

#[divan::bench(sample_count = 20)]
fn svg_outlined(bencher: Bencher) {
    run(bencher, &SvgPainter::default(), outlined());
}

#[divan::bench(sample_count = 20)]
fn pdf(bencher: Bencher) {
    run(bencher, &PdfPainter::default(), picture());
}

#[divan::bench(sample_count = 20)]
fn eps(bencher: Bencher) {
    run(bencher, &EpsPainter::default(), picture());
}

#[divan::bench(sample_count = 10)]
fn png(bencher: Bencher) {
    run(bencher, &PngPainter::default(), picture());
}

/// Rasterising only, without PNG encoding.
#[divan::bench(sample_count = 10)]
fn png_render_only(bencher: Bencher) {
    let painter = PngPainter::default();
    bencher.bench_local(|| divan::black_box(painter.render(divan::black_box(picture())).is_ok()));
}

/// The same document through the `svg` crate (which keeps numbers as f32).
fn svg_crate(p: &Picture) -> Vec<u8> {
    use svg::node::element::path::Data;
    use svg::node::element::{Group, Path, Rectangle};
    use svg::Document;

    let mut doc = Document::new()
        .set("width", p.width)
        .set("height", p.height)
        .set("viewBox", (0, 0, p.width, p.height))
        .add(
            Rectangle::new()
                .set("width", p.width)
                .set("height", p.height)
                .set("fill", "#ffffff"),
        );
    let mut group: Option<(u32, Group)> = None;
    for f in &p.fragments {
        if group.as_ref().is_none_or(|(o, _)| *o != f.object) {
            if let Some((_, g)) = group.take() {
                doc = doc.add(g);
            }
            let name = p
                .objects
                .get(f.object as usize)
                .cloned()
                .unwrap_or_default();
            group = Some((f.object, Group::new().set("data-name", name)));
        }
        let mut data = Data::new().move_to((f.points[0][0], f.points[0][1]));
        for q in &f.points[1..] {
            data = data.line_to((q[0], q[1]));
        }
        let c = f.fill.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
        let path = Path::new()
            .set("d", data.close())
            .set("fill", format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]));
        if let Some((o, g)) = group.take() {
            group = Some((o, g.add(path)));
        }
    }
    if let Some((_, g)) = group {
        doc = doc.add(g);
    }
    let mut out = Vec::new();
    let _ = svg::write(&mut out, &doc);
    out
}

#[divan::bench(sample_count = 10)]
fn svg_with_svg_crate(bencher: Bencher) {
    bencher.bench_local(|| divan::black_box(svg_crate(divan::black_box(picture()))));
}
