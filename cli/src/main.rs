//! The `limn` command: render 3D polygon scenes as exact vector pictures, render the
//! built-in demo, and check vector results against image-space references.

mod args;
mod check;
mod demo;
mod output;
mod progress;
mod render;

use std::process::ExitCode;

use clap::Parser;

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
    match render::run(cli) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("limn: error: {e:#}");
            ExitCode::from(1)
        }
    }
}
