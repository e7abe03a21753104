//! `limn-bench large`: the large scenes (two intersecting 300 × 300 height fields, the
//! soups of 10,000 triangles) against gl2ps's two sorts, measured in one run: time,
//! primitives and bytes, without rasterising (the table's scenes check the pixels).

use anyhow::Result;
use limn_depthsort::{Arith, SortMode};

use crate::limn_runs;
use crate::peers::{self, Outcome};
use crate::scenes;

/// Options of `limn-bench large`.
#[derive(Debug, clap::Args)]
pub struct LargeArgs {
    /// Runs per measurement (the median is reported).
    #[arg(long, default_value_t = 3)]
    runs: usize,
    #[command(flatten)]
    limits: peers::PeerLimits,
    /// Only the scenes whose name contains this text (e.g. `soup`).
    #[arg(long)]
    only: Option<String>,
}

/// The table (Markdown): per scene, limn exact adaptive (order + SVG in this process, on
/// every core) and gl2ps's sorts (the whole process less its time on an empty scene), with
/// each peer's time over limn's.
pub fn run(a: LargeArgs) -> Result<String> {
    let dir = a.limits.dir();
    let (found, _) = peers::find(&dir);
    let gl2ps: Vec<_> = found.into_iter().filter(|p| p.name == "gl2ps").collect();
    let work = tempfile::tempdir()?;
    let timeout = a.limits.time_bound();
    let startup = peers::startup_times(&gl2ps, work.path(), timeout, a.limits.mem_mb)?;
    let mut out = format!(
        "Medians of {} runs on {} threads; limn: exact adaptive, order + SVG file in process; \
         gl2ps: the whole process less its time on an empty scene.\n\n\
         | scene | program | sort | ms | primitives | bytes | time / limn's |\n\
         |---|---|---|---:|---:|---:|---:|\n",
        a.runs.max(1),
        rayon::current_num_threads()
    );
    if gl2ps.is_empty() {
        out = format!(
            "gl2ps not found under {} (run `bench/peers/install.sh`).\n\n{out}",
            dir.display()
        );
    }
    let chosen = scenes::large()
        .into_iter()
        .filter(|s| a.only.as_ref().is_none_or(|o| s.name.contains(o.as_str())));
    for s in chosen {
        eprintln!("limn-bench: {}", s.name);
        let m = limn_runs::measure(&s, SortMode::Adaptive, Arith::Exact, a.runs)?;
        out += &format!(
            "| {} | limn | adaptive | {:.0} | {} | {} | 1 |\n",
            s.name, m.ms, m.primitives, m.bytes
        );
        if gl2ps.is_empty() {
            continue;
        }
        let ordered = limn_depthsort::order(&s.scene, &s.camera, &Default::default())?;
        let input = work.path().join("scene.txt");
        peers::write_projected(&s, &ordered.camera, ordered.near, ordered.far, &input)?;
        for (p, &start) in gl2ps.iter().zip(&startup) {
            let cell = match peers::run(
                p,
                &input,
                work.path(),
                a.runs,
                timeout,
                a.limits.mem_mb,
                start,
            ) {
                Outcome::Done(g) => format!(
                    "{:.0} | {} | {} | {:.2}",
                    g.ms,
                    g.primitives,
                    g.bytes,
                    g.ms / m.ms
                ),
                Outcome::Timeout => format!("> {} s | – | – | –", a.limits.timeout),
                Outcome::Failed(why) => format!("failed: {} | – | – | –", why.replace('|', "/")),
            };
            out += &format!("| {} | gl2ps | {} | {cell} |\n", s.name, p.sort);
        }
    }
    Ok(out)
}
