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
    /// Only the scenes whose name contains this text (e.g. `soup`; the name is followed
    /// by " (", so `10k (` picks the sparse soup alone).
    #[arg(long)]
    only: Option<String>,
    /// Measure limn alone on the scene of this name and print `ms primitives bytes`: the
    /// process each of limn's rows is measured in.
    #[arg(long, hide = true)]
    limn_row: Option<String>,
}

/// limn's row for the scene `name`, measured in a process of its own (this program run
/// with `--limn-row`), as each peer is: a scene measured after another one in the same
/// process ran in the memory that one left (the 10k soup after the surfaces took 39–42 ms
/// instead of 30–34).
fn limn_row(name: &str, runs: usize) -> Result<(f64, usize, usize)> {
    let out = std::process::Command::new(std::env::current_exe()?)
        .args(["large", "--runs", &runs.to_string(), "--limn-row", name])
        .stderr(std::process::Stdio::inherit())
        .output()?;
    let text = String::from_utf8_lossy(&out.stdout);
    let fields: Vec<&str> = text.split_whitespace().collect();
    match (out.status.success(), fields.as_slice()) {
        (true, [ms, primitives, bytes]) => Ok((ms.parse()?, primitives.parse()?, bytes.parse()?)),
        _ => anyhow::bail!("limn's row of {name} failed ({}): {text}", out.status),
    }
}

/// The child's side of [`limn_row`]: builds scene `name`, measures and prints.
fn limn_row_here(name: &str, runs: usize) -> Result<String> {
    let Some((_, build)) = scenes::large().into_iter().find(|(n, _)| *n == name) else {
        anyhow::bail!("no large scene named {name}");
    };
    let m = limn_runs::measure(&build(), SortMode::Adaptive, Arith::Exact, runs)?;
    Ok(format!("{} {} {}\n", m.ms, m.primitives, m.bytes))
}

/// The table (Markdown): per scene, limn exact adaptive (order + SVG in this process, on
/// every core) and gl2ps's sorts (the whole process less its time on an empty scene), with
/// each peer's time over limn's.
pub fn run(a: LargeArgs) -> Result<String> {
    if let Some(name) = &a.limn_row {
        return limn_row_here(name, a.runs);
    }
    let dir = a.limits.dir();
    let (found, _) = peers::find(&dir);
    let gl2ps: Vec<_> = found.into_iter().filter(|p| p.name == "gl2ps").collect();
    let work = tempfile::tempdir()?;
    let timeout = a.limits.time_bound();
    let startup = peers::startup_times(&gl2ps, work.path(), timeout, a.limits.mem_mb)?;
    let mut out = format!(
        "Medians of {} runs on {} threads; limn: exact adaptive, order + SVG file in a \
         process of its own per scene; gl2ps: the whole process less its time on an empty \
         scene.\n\n\
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
    let chosen = scenes::large().into_iter().filter(|(name, _)| {
        a.only
            .as_ref()
            .is_none_or(|o| format!("{name} (").contains(o.as_str()))
    });
    for (name, build) in chosen {
        eprintln!("limn-bench: {name}");
        let (ms, primitives, bytes) = limn_row(name, a.runs)?;
        let s = build();
        out += &format!(
            "| {} | limn | adaptive | {ms:.0} | {primitives} | {bytes} | 1 |\n",
            s.name
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
                    g.ms / ms
                ),
                Outcome::Timeout => format!("> {} s | – | – | –", a.limits.timeout),
                Outcome::Failed(why) => format!("failed: {} | – | – | –", why.replace('|', "/")),
            };
            out += &format!("| {} | gl2ps | {} | {cell} |\n", s.name, p.sort);
        }
    }
    Ok(out)
}
