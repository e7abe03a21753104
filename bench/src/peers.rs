//! The programs users would pick instead, run as separate processes on the scene as
//! limn projects it (`bench/peers/README.md` gives the exchange format), each capped in
//! time and memory.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use limn_scene::Camera;

use crate::limn_runs::{median, Measured};
use crate::scenes::{face_colour, BenchScene};

/// A peer program.
#[derive(Debug, Clone)]
pub struct Peer {
    /// Its name in the table.
    pub name: &'static str,
    /// Its sort, as the table names it.
    pub sort: &'static str,
    /// The command, before the input and output paths.
    pub command: Vec<String>,
}

/// How a peer run ended.
pub enum Outcome {
    /// It wrote a picture.
    Done(Measured),
    /// It ran out of time.
    Timeout,
    /// It failed (out of memory, a crash): the first line of what it said.
    Failed(String),
}

/// The peers found under `dir` (`bench/peers/`): gl2ps's two sorts when its driver is
/// built, matplotlib when Python can import it. Missing ones are named in the second
/// list with what would install them.
pub fn find(dir: &Path) -> (Vec<Peer>, Vec<String>) {
    let mut peers = Vec::new();
    let mut missing = Vec::new();
    let driver = dir.join("gl2ps_driver");
    if driver.is_file() {
        for (sort, arg) in [("bsp", "bsp"), ("simple", "simple")] {
            peers.push(Peer {
                name: "gl2ps",
                sort,
                command: vec![driver.display().to_string(), arg.into()],
            });
        }
    } else {
        missing.push(format!("gl2ps ({} not built)", driver.display()));
    }
    let script = dir.join("mpl_driver.py");
    let has_mpl = Command::new("python3")
        .args(["-c", "import matplotlib"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if has_mpl && script.is_file() {
        peers.push(Peer {
            name: "matplotlib",
            sort: "mplot3d",
            command: vec!["python3".into(), script.display().to_string()],
        });
    } else {
        missing.push("matplotlib (not importable by python3)".into());
    }
    (peers, missing)
}

/// Writes the scene, projected by `camera` with `near` and `far`, in the exchange
/// format; faces with a corner at or behind the eye's plane are left out (none in the
/// table's scenes).
pub fn write_projected(
    s: &BenchScene,
    camera: &Camera,
    near: f64,
    far: f64,
    out: &Path,
) -> std::io::Result<()> {
    let vp = camera.view_projection(near, far);
    let mut text = String::new();
    let mut polys = Vec::new();
    for (i, f) in s.scene.faces.iter().enumerate() {
        let mut line = String::new();
        let c = face_colour(i);
        line += &format!("{} {} {} {}", c[0], c[1], c[2], f.vertices.len());
        let mut ok = true;
        for &v in &f.vertices {
            let p = camera.project_with(&vp, s.scene.vertices[v as usize]);
            ok &= p.w > 0.0 && p.x.is_finite() && p.y.is_finite();
            line += &format!(" {:e} {:e} {:e}", p.x, p.y, p.z);
        }
        if ok {
            polys.push(line);
        }
    }
    text += &format!(
        "limn-projected 1\n{} {}\n{}\n",
        camera.width,
        camera.height,
        polys.len()
    );
    for p in polys {
        text += &p;
        text.push('\n');
    }
    std::fs::File::create(out)?.write_all(text.as_bytes())
}

/// How the peers are found and bounded (options shared by the commands that run them).
#[derive(Debug, clap::Args)]
pub struct PeerLimits {
    /// Folder of the peer drivers [default: bench/peers of this crate].
    #[arg(long)]
    peers: Option<PathBuf>,
    /// Seconds a peer may take on one scene before it is reported as out of time.
    #[arg(long, default_value_t = 60)]
    pub timeout: u64,
    /// Memory a peer may use, in MB, before it is reported as out of memory.
    #[arg(long, default_value_t = 4096)]
    pub mem_mb: u64,
}

impl PeerLimits {
    /// The folder of the peer drivers.
    pub fn dir(&self) -> PathBuf {
        self.peers
            .clone()
            .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("peers"))
    }

    /// The time bound of one peer on one scene.
    pub fn time_bound(&self) -> Duration {
        Duration::from_secs(self.timeout)
    }
}

/// Each peer's start-up (process, interpreter, imports): its median time on an empty
/// scene written in `dir` (0 when it fails there), taken off its times so that they
/// measure the drawing.
pub fn startup_times(
    peers: &[Peer],
    dir: &Path,
    timeout: Duration,
    mem_mb: u64,
) -> std::io::Result<Vec<f64>> {
    let empty = dir.join("empty.txt");
    std::fs::write(&empty, "limn-projected 1\n16 16\n0\n")?;
    Ok(peers
        .iter()
        .map(|p| match run(p, &empty, dir, 3, timeout, mem_mb, 0.0) {
            Outcome::Done(m) => m.ms,
            _ => 0.0,
        })
        .collect())
}

/// Runs `peer` on `input`, `runs` times, each capped at `timeout` and `mem_mb`; the
/// median wall time minus `startup` (the peer's time on an empty scene).
pub fn run(
    peer: &Peer,
    input: &Path,
    dir: &Path,
    runs: usize,
    timeout: Duration,
    mem_mb: u64,
    startup: f64,
) -> Outcome {
    let out: PathBuf = dir.join(format!("{}-{}.svg", peer.name, peer.sort));
    let mut times = Vec::new();
    let mut primitives = 0;
    for _ in 0..runs.max(1) {
        let _ = std::fs::remove_file(&out);
        match once(peer, input, &out, timeout, mem_mb) {
            Ok((ms, n)) => {
                times.push((ms - startup).max(0.0));
                primitives = n;
            }
            Err(o) => return o,
        }
    }
    match std::fs::read(&out) {
        Ok(svg) => Outcome::Done(Measured {
            ms: median(&mut times),
            primitives,
            bytes: svg.len(),
            svg,
            picture: Vec::new(),
        }),
        Err(e) => Outcome::Failed(format!("no output: {e}")),
    }
}

/// One run: wall milliseconds and the primitives the peer reports.
fn once(
    peer: &Peer,
    input: &Path,
    out: &Path,
    timeout: Duration,
    mem_mb: u64,
) -> Result<(f64, usize), Outcome> {
    let mut line = format!("ulimit -v {} && exec", mem_mb * 1024);
    for a in &peer.command {
        line += &format!(" '{a}'");
    }
    line += &format!(" '{}' '{}'", input.display(), out.display());
    crate::settle::settle();
    let t0 = Instant::now();
    let mut child = Command::new("sh")
        .args(["-c", &line])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| Outcome::Failed(e.to_string()))?;
    loop {
        match child.try_wait() {
            Ok(Some(_)) => break,
            Ok(None) if t0.elapsed() > timeout => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(Outcome::Timeout);
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => return Err(Outcome::Failed(e.to_string())),
        }
    }
    let ms = t0.elapsed().as_secs_f64() * 1e3;
    let output = child
        .wait_with_output()
        .map_err(|e| Outcome::Failed(e.to_string()))?;
    if !output.status.success() {
        let err = String::from_utf8_lossy(&output.stderr);
        let status = match output.status.code() {
            Some(c) => format!("exit status {c}"),
            None => "killed by a signal".to_string(),
        };
        let first = match err.lines().find(|l| !l.trim().is_empty()) {
            Some(l) => format!("{status}: {}", l.trim()),
            None => format!("{status}, nothing said (out of memory under the {mem_mb} MB cap?)"),
        };
        return Err(Outcome::Failed(first));
    }
    let text = String::from_utf8_lossy(&output.stdout);
    let n = text
        .lines()
        .find_map(|l| l.strip_prefix("primitives "))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(0);
    Ok((ms, n))
}
