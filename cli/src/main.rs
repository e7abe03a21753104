//! The `limn` command: render 3D polygon scenes as exact vector pictures, render the
//! built-in demo, and check vector results against image-space references.

mod args;
mod check;
mod demo;
mod losses;
mod output;
mod progress;
mod raster;
mod render;
mod setup;
mod stats;

use std::process::ExitCode;

use clap::Parser;

/// The allocator: ordering and composing make and free millions of small vectors
/// on both cores, where mimalloc's per-thread heaps cost less than the system
/// allocator's (BENCHMARKS.md, "Allocator").
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    let cli = match args::Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            // Usage errors exit with status 2; --help and --version with 0.
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    if let Err(e) = cli.check_conflicts() {
        let _ = e.print();
        return ExitCode::from(2);
    }
    if let Some(n) = cli.threads {
        // Only fails when a pool already exists, which nothing here creates before.
        if let Err(e) = rayon::ThreadPoolBuilder::new()
            .num_threads(usize::from(n))
            .build_global()
        {
            eprintln!("limn: error: cannot start {n} threads: {e}");
            return ExitCode::from(1);
        }
    }
    let run = match cli.command {
        args::Command::Render(a) => render::render(a),
        args::Command::Demo(a) => demo::run(a),
        args::Command::Check(a) => check::check(a),
    };
    match run {
        Ok(code) => code,
        Err(e) => {
            eprintln!("limn: error: {}", message(&e));
            ExitCode::from(1)
        }
    }
}

/// The error and its causes on one line, `: `-separated, leaving out a cause whose text
/// the message already contains (many errors repeat their source in their own text).
fn message(e: &anyhow::Error) -> String {
    let mut out = String::new();
    for cause in e.chain() {
        let s = cause.to_string();
        if out.contains(&s) {
            continue;
        }
        if !out.is_empty() {
            out.push_str(": ");
        }
        out.push_str(&s);
    }
    out
}

#[cfg(test)]
mod tests {
    use anyhow::Context;

    #[test]
    fn causes_repeated_in_the_message_are_left_out() {
        let inner = std::io::Error::other("disk on fire");
        let e = Err::<(), _>(inner)
            .context("a.obj:3: disk on fire")
            .unwrap_err();
        assert_eq!(super::message(&e), "a.obj:3: disk on fire");
        let e = Err::<(), _>(std::io::Error::other("disk on fire"))
            .context("cannot write out.svg")
            .unwrap_err();
        assert_eq!(super::message(&e), "cannot write out.svg: disk on fire");
    }
}
