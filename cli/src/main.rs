//! The `limn` command: render 3D polygon scenes as exact vector pictures, render the
//! built-in demo, and check vector results against image-space references. Argument
//! parsing and messages over the `limn` library, which does the work.

mod args;
mod progress;
mod terminal;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use limn::{Input, Rendered, Request};

use crate::terminal::Terminal;

// The allocator (mimalloc; see the crate).
use limn_alloc as _;

/// Exit status when `check` finds mismatches outside the edge band.
const MISMATCH: u8 = 3;

fn main() -> ExitCode {
    limn_alloc::return_freed_memory();
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
        args::Command::Render(a) => render(
            &Request {
                input: Input::File(a.input.clone()),
                output: a.output.clone(),
                options: a.options(),
            },
            a.view.quiet,
        ),
        args::Command::Demo(a) => {
            let output = a
                .output
                .clone()
                .unwrap_or_else(|| PathBuf::from("demo.svg"));
            match limn::demo::request(output, a.outline, a.stats.clone()) {
                Ok(req) => render(&req, a.quiet),
                Err(e) => Err(e),
            }
        }
        args::Command::Check(a) => check(&a),
    };
    match run {
        Ok(code) => code,
        Err(e) => {
            eprintln!("limn: error: {}", e.message());
            ExitCode::from(1)
        }
    }
}

/// Runs a render and says what it wrote.
fn render(req: &Request<'_>, quiet: bool) -> Result<ExitCode, limn::Error> {
    let mut term = Terminal::start(quiet);
    let done: Rendered<'_> = limn::render(req, &mut term)?;
    term.finish();
    if !quiet && done.output.as_os_str() != "-" {
        match &done.stats {
            Some(s) => eprintln!(
                "limn: wrote {} ({} faces, {} fragments, {} splits, {:.0} ms)",
                done.output.display(),
                s.faces_in,
                s.fragments_out,
                s.splits,
                s.ms.total
            ),
            None => eprintln!(
                "limn: wrote {} ({})",
                done.output.display(),
                done.method.name()
            ),
        }
    }
    // The process ends after this: freeing the scene, the order and the picture one
    // allocation at a time (millions on large scenes) takes longer than the system takes
    // to reclaim the whole process.
    std::mem::forget(done);
    Ok(ExitCode::SUCCESS)
}

/// Runs `limn check`: the report on standard output (or to `--stats`), status 3 when the
/// pictures disagree.
fn check(a: &args::CheckArgs) -> Result<ExitCode, limn::Error> {
    let mut term = Terminal::start(a.view.quiet);
    let report = limn::check(&Input::File(a.input.clone()), &a.options(), &mut term)?;
    term.finish();
    if a.view.stats.is_none() {
        print!("{}", report.to_json_text());
    }
    if report.agrees() {
        return Ok(ExitCode::SUCCESS);
    }
    if !a.view.quiet {
        for f in &report.failures {
            eprintln!("limn: {f}");
        }
    }
    Ok(ExitCode::from(MISMATCH))
}
