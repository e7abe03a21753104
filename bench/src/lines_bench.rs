//! `limn-bench lines`: a 100 × 100 surface (20,000 triangles) with its 202 grid lines and
//! a 10,000-point scatter around it: the time to order the faces alone, to order them and
//! hide the lines and points exactly, and to write each format, with the pieces and bytes.

use std::time::Instant;

use anyhow::Result;
use glam::DVec3;
use limn_depthsort::{order, order_with_marks, OrderOptions};
use limn_paint::{painter_for, picture_with_marks, Format, Style};
use limn_scene::{Camera, MarkerShape, Material, PointMark, Polyline, Scene};

/// Options of `limn-bench lines`.
#[derive(Debug, clap::Args)]
pub struct LinesArgs {
    /// A 30 × 30 surface and 1,000 points.
    #[arg(long)]
    quick: bool,
    /// Also write the table to this file.
    #[arg(long)]
    out: Option<std::path::PathBuf>,
}

/// The surface `z = sin(x)·cos(y)` over `[−3, 3]²` in `n × n` quads split into
/// triangles, its grid lines, and `points` scatter points (deterministic) around it.
pub fn scene(n: usize, points: usize) -> (Scene, Camera) {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("surface", [0.6, 0.7, 0.9]));
    let o = s.add_object("surface");
    let at = |i: usize, j: usize| {
        let x = i as f64 / n as f64 * 6.0 - 3.0;
        let y = j as f64 / n as f64 * 6.0 - 3.0;
        DVec3::new(x, x.sin() * y.cos(), y)
    };
    let base = s.vertices.len() as u32;
    for i in 0..=n {
        for j in 0..=n {
            s.vertices.push(at(i, j));
        }
    }
    let id = |i: usize, j: usize| base + (i * (n + 1) + j) as u32;
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            s.add_face(&[a, d, c], m, o).expect("valid");
            s.add_face(&[a, c, b], m, o).expect("valid");
        }
    }
    let grid = s.add_object("grid");
    for k in 0..=n {
        for pts in [
            (0..=n).map(|j| at(k, j)).collect::<Vec<_>>(),
            (0..=n).map(|i| at(i, k)).collect(),
        ] {
            s.lines.push(Polyline {
                object: grid,
                width: 0.5,
                ..Polyline::new(pts)
            });
        }
    }
    let scatter = s.add_object("scatter");
    let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..points {
        let (u, v, w) = (next() * 6.0 - 3.0, next() * 6.0 - 3.0, next() * 3.0 - 1.5);
        s.points.push(PointMark {
            shape: MarkerShape::Dot,
            size: 2.0,
            color: [0.8, 0.1, 0.1, 1.0],
            object: scatter,
            ..PointMark::new(DVec3::new(u, w, v))
        });
    }
    let cam = Camera::new(DVec3::new(6.0, 5.0, 8.0), DVec3::ZERO, 1200, 900);
    (s, cam)
}

/// Runs the benchmark and prints the table.
pub fn run(a: LinesArgs) -> Result<()> {
    let (n, points) = if a.quick { (30, 1000) } else { (100, 10_000) };
    let (s, cam) = scene(n, points);
    let opts = OrderOptions::default();
    let t0 = Instant::now();
    let faces_only = order(&s, &cam, &opts)?;
    let t_faces = t0.elapsed().as_secs_f64() * 1e3;
    let t1 = Instant::now();
    let (mut ordered, marks) = order_with_marks(&s, &cam, &opts)?;
    let t_all = t1.elapsed().as_secs_f64() * 1e3;
    let st = marks.stats;
    let mut out = String::new();
    out += &format!(
        "{n}×{n} surface ({} triangles, {} fragments), {} grid lines ({} segments), {} points\n\n",
        s.faces.len(),
        faces_only.fragments.len(),
        st.lines,
        st.segments_in,
        st.markers_in
    );
    out += "| step | ms | count |\n|---|---:|---:|\n";
    out += &format!(
        "| order faces only | {t_faces:.0} | {} fragments |\n",
        faces_only.fragments.len()
    );
    out += &format!(
        "| order + hide lines and points | {t_all:.0} (hiding {} ms, {:.2}× the faces-only order) | {} pieces out, {} hidden, {} of {} points shown, {} exact tests |\n",
        st.ms,
        t_all / t_faces.max(1e-9),
        st.pieces_out,
        st.hidden_pieces,
        st.markers_shown,
        st.markers_in,
        st.exact_tests
    );
    let pic = picture_with_marks(&s, &mut ordered, &marks, &Style::default());
    for f in [Format::Svg, Format::Pdf, Format::Eps, Format::Png] {
        let t = Instant::now();
        let mut buf = Vec::new();
        let ps = painter_for(f).paint(&pic, &mut buf)?;
        out += &format!(
            "| write {} | {:.0} | {} bytes, {} line paths, {} markers |\n",
            f.name(),
            t.elapsed().as_secs_f64() * 1e3,
            ps.bytes,
            ps.lines,
            ps.markers
        );
    }
    print!("{out}");
    if let Some(p) = &a.out {
        std::fs::write(p, &out)?;
    }
    Ok(())
}
