//! Measures, in one run, the cost of a vertex classification for the naive f64
//! evaluation, the float kernel and the exact kernel (with and without its filter), on
//! random, near-degenerate and one-ulp inputs, the filter's fallback rate, and splits per second.
//! Prints a Markdown table. Run with `cargo run --release -p limn-kernel --example
//! kernel_ratios`.

#[path = "../benches/common/workload.rs"]
mod workload;

use std::hint::black_box;
use std::time::Instant;

use limn_kernel::Kernel;
use workload::*;

/// Nanoseconds this thread has spent on a CPU (`CLOCK_THREAD_CPUTIME_ID`; wall-clock
/// time where there is none), so that other processes on a busy machine distort the
/// numbers less.
fn cpu_ns(start: Instant) -> f64 {
    cpu_time::ThreadTime::try_now().map_or_else(
        |_| start.elapsed().as_secs_f64() * 1e9,
        |t| t.as_duration().as_secs_f64() * 1e9,
    )
}

/// Best-of-15 time per item in nanoseconds of `f`, which processes `items` items.
fn ns_per_item(items: usize, mut f: impl FnMut() -> usize) -> f64 {
    let origin = Instant::now();
    let mut best = f64::INFINITY;
    for _ in 0..15 {
        let t = Instant::now();
        let c = cpu_ns(origin);
        let mut reps = 0;
        while t.elapsed().as_secs_f64() < 0.04 {
            black_box(f());
            reps += 1;
        }
        best = best.min((cpu_ns(origin) - c) / (reps * items) as f64);
    }
    best
}

fn main() {
    let (exact, float) = kernels();
    let unfiltered = kernels().0.without_filter();
    println!("exact kernel on the raw f64 input (no grid); float kernel epsilon 1e-9 of the box");
    println!();
    println!("| ns per vertex classification | random | near-degenerate | one ulp |");
    println!("|---|---:|---:|---:|");
    let sets = [
        ClassifySet::random(),
        ClassifySet::degenerate(),
        ClassifySet::ulp(),
    ];
    let mut rows: Vec<(String, Vec<f64>)> = Vec::new();
    let mut rates = Vec::new();
    for s in &sets {
        let before = exact.fallbacks();
        classify_exact(&exact, s);
        rates.push((exact.fallbacks() - before) as f64 / s.vertex_count as f64);
    }
    let measure = |name: &str, f: &dyn Fn(&ClassifySet) -> usize| -> (String, Vec<f64>) {
        (
            name.to_string(),
            sets.iter()
                .map(|s| ns_per_item(s.vertex_count, || f(s)))
                .collect(),
        )
    };
    rows.push(measure("naive f64 (no bound)", &|s| classify_naive(s)));
    rows.push(measure("float kernel (epsilon)", &|s| {
        classify_float(&float, s)
    }));
    rows.push(measure("exact, filtered", &|s| classify_exact(&exact, s)));
    rows.push(measure("exact, filter off", &|s| {
        classify_exact(&unfiltered, s)
    }));
    for (name, v) in &rows {
        println!("| {name} | {:.2} | {:.2} | {:.2} |", v[0], v[1], v[2]);
    }
    let ratio = |a: usize, b: usize| -> Vec<String> {
        (0..sets.len())
            .map(|i| format!("{:.2}×", rows[a].1[i] / rows[b].1[i]))
            .collect()
    };
    println!(
        "| exact filtered / float kernel | {} |",
        ratio(2, 1).join(" | ")
    );
    println!(
        "| exact filtered / exact filter off | {} |",
        ratio(2, 3).join(" | ")
    );
    let pct: Vec<String> = rates
        .iter()
        .map(|r| format!("{:.2} %", 100.0 * r))
        .collect();
    println!(
        "| filter fallbacks per vertex classified | {} |",
        pct.join(" | ")
    );
    println!();
    let s = SplitSet::new();
    let te = ns_per_item(s.exact.len(), || split_exact(&exact, &s));
    let tf = ns_per_item(s.float.len(), || split_float(&float, &s));
    println!("| splits (triangle by a plane through it) | ns per split | splits per second |");
    println!("|---|---:|---:|");
    println!("| exact kernel | {te:.1} | {:.2} M |", 1e3 / te);
    println!("| float kernel | {tf:.1} | {:.2} M |", 1e3 / tf);
    println!("| exact / float | {:.2}× | |", te / tf);
}
