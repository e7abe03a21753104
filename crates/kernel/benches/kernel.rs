//! Kernel benchmarks: classification (naive f64, float kernel, exact with and without the
//! filter) on random, near-degenerate and one-ulp inputs, and splitting. Each iteration processes
//! a whole workload; divide by its size (printed by the `kernel_ratios` example, which
//! also reports the per-operation ratios and fallback rates of one run).

#[path = "common/workload.rs"]
mod workload;

use divan::{black_box, Bencher};
use workload::*;

fn main() {
    divan::main();
}

#[divan::bench(args = ["random", "degenerate", "ulp"])]
fn classify_naive_f64(b: Bencher, set: &str) {
    let s = ClassifySet::named(set);
    b.counter(divan::counter::ItemsCount::new(s.vertex_count))
        .bench(|| classify_naive(black_box(&s)));
}

#[divan::bench(args = ["random", "degenerate", "ulp"])]
fn classify_float_kernel(b: Bencher, set: &str) {
    let s = ClassifySet::named(set);
    let (_, f) = kernels();
    b.counter(divan::counter::ItemsCount::new(s.vertex_count))
        .bench(|| classify_float(&f, black_box(&s)));
}

#[divan::bench(args = ["random", "degenerate", "ulp"])]
fn classify_exact_filtered(b: Bencher, set: &str) {
    let s = ClassifySet::named(set);
    let (e, _) = kernels();
    b.counter(divan::counter::ItemsCount::new(s.vertex_count))
        .bench(|| classify_exact(&e, black_box(&s)));
}

#[divan::bench(args = ["random", "degenerate", "ulp"])]
fn classify_exact_unfiltered(b: Bencher, set: &str) {
    let s = ClassifySet::named(set);
    let e = kernels().0.without_filter();
    b.counter(divan::counter::ItemsCount::new(s.vertex_count))
        .bench(|| classify_exact(&e, black_box(&s)));
}

#[divan::bench]
fn split_exact_kernel(b: Bencher) {
    let s = SplitSet::new();
    let (e, _) = kernels();
    b.counter(divan::counter::ItemsCount::new(s.exact.len()))
        .bench(|| split_exact(&e, black_box(&s)));
}

#[divan::bench]
fn split_float_kernel(b: Bencher) {
    let s = SplitSet::new();
    let (_, f) = kernels();
    b.counter(divan::counter::ItemsCount::new(s.float.len()))
        .bench(|| split_float(&f, black_box(&s)));
}
