//! limn's pictures opened in the viewers people use: rsvg-convert for SVG, poppler's
//! pdftoppm and ghostscript for PDF. Each runs with a deadline; a viewer that is not
//! installed is skipped with a message. Their rasters are compared with limn's own PNG.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs `cmd` with a deadline of `bound`, which it must meet and exit successfully
/// within (else a panic naming `what`); `None` when the program is not installed.
pub fn run_within(mut cmd: Command, what: &str, bound: Duration) -> Option<Duration> {
    let start = Instant::now();
    let mut child = match cmd.stdout(Stdio::null()).stderr(Stdio::piped()).spawn() {
        Ok(c) => c,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            eprintln!("SKIPPED: {what} is not installed");
            return None;
        }
        Err(e) => panic!("{what}: {e}"),
    };
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            let took = start.elapsed();
            let mut err = String::new();
            if let Some(mut e) = child.stderr.take() {
                std::io::Read::read_to_string(&mut e, &mut err).unwrap();
            }
            assert!(status.success(), "{what} failed: {status}: {err}");
            eprintln!("{what}: {:.2} s", took.as_secs_f64());
            return Some(took);
        }
        if start.elapsed() > bound {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{what} took more than {} s", bound.as_secs());
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Each installed viewer's raster of `svg` (rsvg-convert) and `pdf` (pdftoppm and
/// ghostscript at 72 dpi, one pixel per point), written beside them, each within
/// `bound`: (viewer, raster).
pub fn rasters(svg: &Path, pdf: &Path, bound: Duration) -> Vec<(&'static str, PathBuf)> {
    let mut out = Vec::new();
    let rsvg = svg.with_extension("rsvg.png");
    let mut cmd = Command::new("rsvg-convert");
    cmd.arg("-o").arg(&rsvg).arg(svg);
    if run_within(cmd, &format!("rsvg-convert {}", svg.display()), bound).is_some() {
        out.push(("rsvg-convert", rsvg));
    }
    // pdftoppm adds `.png` to the name it is given.
    let stem = pdf.with_extension("poppler");
    let mut cmd = Command::new("pdftoppm");
    cmd.args(["-r", "72", "-png", "-singlefile"])
        .arg(pdf)
        .arg(&stem);
    if run_within(cmd, &format!("pdftoppm {}", pdf.display()), bound).is_some() {
        out.push(("pdftoppm", pdf.with_extension("poppler.png")));
    }
    let gs = pdf.with_extension("gs.png");
    let mut cmd = Command::new("gs");
    cmd.args([
        "-q",
        "-dSAFER",
        "-dBATCH",
        "-dNOPAUSE",
        "-sDEVICE=png16m",
        "-r72",
    ])
    .arg(format!("-sOutputFile={}", gs.display()))
    .arg(pdf);
    if run_within(cmd, &format!("ghostscript {}", pdf.display()), bound).is_some() {
        out.push(("ghostscript", gs));
    }
    out
}

/// RGBA pixels of a PNG file and its size.
pub fn load_png(path: &Path) -> (Vec<u8>, usize, usize) {
    let p = tiny_skia::Pixmap::load_png(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let (w, h) = (p.width() as usize, p.height() as usize);
    (p.data().to_vec(), w, h)
}

/// Over the pixels whose 3 × 3 neighbourhood is opaque in limn's PNG `png` (`w` × `h`,
/// RGBA; the inside of what is drawn, away from its silhouette), the share within
/// `levels` per channel of the viewer's `viewer` (composited on white, as the viewers
/// of PDF draw it), and how many pixels were compared.
pub fn agreement(png: &[u8], viewer: &[u8], w: usize, h: usize, levels: f64) -> (f64, usize) {
    let (mut agree, mut compared) = (0usize, 0usize);
    for y in 1..h.saturating_sub(1) {
        for x in 1..w.saturating_sub(1) {
            let opaque = (0..9).all(|k| png[4 * ((y + k / 3 - 1) * w + x + k % 3 - 1) + 3] == 255);
            if !opaque {
                continue;
            }
            let at = 4 * (y * w + x);
            let va = f64::from(viewer[at + 3]) / 255.0;
            let near = (0..3).all(|c| {
                let v = f64::from(viewer[at + c]) + (1.0 - va) * 255.0;
                (v - f64::from(png[at + c])).abs() <= levels
            });
            compared += 1;
            agree += usize::from(near);
        }
    }
    (agree as f64 / compared.max(1) as f64, compared)
}
