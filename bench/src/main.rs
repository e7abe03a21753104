//! `limn-bench table`: what accuracy costs in time. For a fixed set of scenes, every
//! limn ordering with exact and float arithmetic, and the programs users would pick
//! instead (gl2ps's BSP and simple sorts, matplotlib's mplot3d; installed by
//! `bench/peers/install.sh`), side by side: milliseconds, primitives written, output
//! bytes, and pixels that disagree with exact ray casting outside the edge band. Every
//! SVG is rasterised the same way, without anti-aliasing.

mod effects;
mod large;
mod limn_runs;
mod lines_bench;
mod measure;
mod peers;
mod raster;
mod scenes;
mod settle;
mod shadow_costs;

use std::path::PathBuf;

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use limn_depthsort::{Arith, OrderOptions, SortMode};
use limn_zbuffer::{compare, rasterize_ids, DepthFormat, Method};

use crate::peers::Outcome;

/// Measure limn against itself and its peers.
#[derive(Debug, Parser)]
#[command(name = "limn-bench", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Cmd,
}

#[derive(Debug, Subcommand)]
enum Cmd {
    /// Print the accuracy-versus-time table (Markdown) and write it to --out.
    Table(TableArgs),
    /// Time a surface with its grid lines and a point scatter, hidden exactly, in every
    /// format (Markdown).
    Lines(lines_bench::LinesArgs),
    /// Print what each shading effect costs (Markdown): a 100k-triangle lit sphere,
    /// the effects machinery on an unlit scene against the flat-only path, SVG bytes
    /// against the shading tolerance.
    Effects(EffectsArgs),
    /// Time the large scenes (two intersecting 300×300 height fields, the 10k soups)
    /// against gl2ps's two sorts (Markdown; no rasterising).
    Large(large::LargeArgs),
}

#[derive(Debug, clap::Args)]
struct EffectsArgs {
    /// A 10k-triangle sphere instead of 100k.
    #[arg(long)]
    quick: bool,
    /// Runs per measurement (the median is reported).
    #[arg(long, default_value_t = 3)]
    runs: usize,
}

#[derive(Debug, clap::Args)]
struct TableArgs {
    /// Small scenes and three runs each (a few minutes).
    #[arg(long)]
    quick: bool,
    /// Runs per measurement (the median is reported) [default: 3 with --quick, else 5].
    #[arg(long)]
    runs: Option<usize>,
    #[command(flatten)]
    limits: peers::PeerLimits,
    /// Also write the table to this file.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// The edge band of the comparison, in pixels: 1/64 for the picture and 1/64 for the
/// rasteriser's fixed-point edges.
const BAND_PX: f64 = 1.0 / 32.0;

/// The edge band for limn's picture before writing (exact coordinates, sampled at pixel
/// centres).
const PICTURE_BAND_PX: f64 = 1.0 / 64.0;

/// Milliseconds with three significant digits.
fn ms(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else if v >= 10.0 {
        format!("{v:.1}")
    } else if v >= 1.0 {
        format!("{v:.2}")
    } else {
        format!("{v:.3}")
    }
}

// The allocator of the `limn` command (mimalloc; see the crate).
use limn_alloc as _;

fn main() -> Result<()> {
    limn_alloc::return_freed_memory();
    let a = match Cli::parse().command {
        Cmd::Table(a) => a,
        Cmd::Lines(l) => return lines_bench::run(l),
        Cmd::Large(l) => {
            print!("{}", large::run(l)?);
            return Ok(());
        }
        Cmd::Effects(e) => {
            print!("{}", effects::run(e.quick, e.runs.max(1))?);
            return Ok(());
        }
    };
    let runs = a.runs.unwrap_or(if a.quick { 3 } else { 5 });
    let peer_dir = a.limits.dir();
    let (peers, missing) = peers::find(&peer_dir);
    let work = tempfile::tempdir()?;
    let timeout = a.limits.time_bound();
    let startup = peers::startup_times(&peers, work.path(), timeout, a.limits.mem_mb)?;

    let mut out = String::new();
    out += "| scene | program | sort | arith | ms | primitives | bytes | wrong pixels |\n";
    out += "|---|---|---|---|---:|---:|---:|---:|\n";
    let mut headlines = Vec::new();
    for s in scenes::all(a.quick) {
        eprintln!("limn-bench: {}", s.name);
        let painted = limn_check::paint(&s.scene, &s.camera, &OrderOptions::default())
            .with_context(|| s.name.clone())?;
        let reference = painted.reference(&s.scene, Method::RayCast, DepthFormat::F64)?;
        let band = painted.band_with(BAND_PX);
        let (w, h) = (painted.ordered.camera.width, painted.ordered.camera.height);
        let faces = s.scene.faces.len();
        let wrong = |svg: &[u8]| -> Result<usize> {
            let shown = raster::faces_shown(svg, w, h).map_err(anyhow::Error::msg)?;
            Ok(raster::wrong_pixels(&shown, &reference, &band, faces))
        };
        let mut adaptive = [(0.0, 0); 2];
        for sort in SortMode::ALL {
            for (k, arith) in Arith::ALL.into_iter().enumerate() {
                let m = limn_runs::measure(&s, sort, arith, runs)?;
                let bad = wrong(&m.svg)?;
                let ids = rasterize_ids(&m.picture, w, h);
                let exact_band = painted.band_with(PICTURE_BAND_PX);
                let before = compare(&ids, &reference, Some(&exact_band)).mismatches_outside_band;
                if sort == SortMode::Adaptive {
                    adaptive[k] = (m.ms, bad);
                }
                out += &format!(
                    "| {} | limn | {} | {} | {} | {} | {} | {bad} ({before}) |\n",
                    s.name,
                    sort.name(),
                    arith.name(),
                    ms(m.ms),
                    m.primitives,
                    m.bytes,
                );
            }
        }
        let mut line = format!(
            "{}: limn exact {} ms, {} wrong; float {} ms ({:.2}× less), {} wrong",
            s.name,
            ms(adaptive[0].0),
            adaptive[0].1,
            ms(adaptive[1].0),
            adaptive[0].0 / adaptive[1].0,
            adaptive[1].1
        );
        if !peers.is_empty() {
            let input = work.path().join("scene.txt");
            let o = &painted.ordered;
            peers::write_projected(&s, &o.camera, o.near, o.far, &input)?;
            for (p, &start) in peers.iter().zip(&startup) {
                let cell = match peers::run(
                    p,
                    &input,
                    work.path(),
                    runs,
                    timeout,
                    a.limits.mem_mb,
                    start,
                ) {
                    Outcome::Done(m) => {
                        let bad = wrong(&m.svg)?;
                        line += &format!("; {} {} {} ms, {bad} wrong", p.name, p.sort, ms(m.ms));
                        format!("{} | {} | {} | {bad}", ms(m.ms), m.primitives, m.bytes)
                    }
                    Outcome::Timeout => {
                        line += &format!("; {} {} out of time", p.name, p.sort);
                        format!("> {} s | – | – | –", a.limits.timeout)
                    }
                    Outcome::Failed(why) => {
                        line += &format!("; {} {} failed", p.name, p.sort);
                        format!("failed: {} | – | – | –", why.replace('|', "/"))
                    }
                };
                out += &format!("| {} | {} | {} | f32 | {cell} |\n", s.name, p.name, p.sort);
            }
        }
        headlines.push(line);
    }
    let mut text = String::new();
    text += &format!(
        "Pictures {}×{}; medians of {runs} runs; limn rows: order + SVG file in process; peer rows: \
         the whole process minus its time on an empty scene; wrong pixels: the SVG rasterised \
         without anti-aliasing, outside a {BAND_PX} px band around true edges, against exact \
         ray casting (for limn, in parentheses: the picture before writing, outside a \
         {PICTURE_BAND_PX} px band; the difference is the SVG's coordinates, rounded to \
         0.01 px).\n\n",
        scenes::SIZE.0,
        scenes::SIZE.1
    );
    if !missing.is_empty() {
        text += &format!(
            "Not measured (run `bench/peers/install.sh`): {}.\n\n",
            missing.join(", ")
        );
    }
    text += &out;
    text += "\n";
    for l in &headlines {
        text += &format!("* {l}\n");
    }
    print!("{text}");
    if let Some(path) = &a.out {
        std::fs::write(path, &text).with_context(|| format!("cannot write {}", path.display()))?;
    }
    Ok(())
}
