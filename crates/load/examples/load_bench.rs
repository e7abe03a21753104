//! Times the loaders on generated 1M-triangle files: a binary STL, an OBJ and a binary
//! PLY of the same torus (1000 × 500 quads, each split in two triangles); or, when files
//! are named after the number of runs, on those files.
//!
//! ```text
//! cargo run --release -p limn-load --example load_bench [-- RUNS [FILE ...]]
//! ```

use std::f64::consts::TAU;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use limn_load::{load, LoadOptions};

// The allocator of the `limn` binary, so that loading is measured as `limn render`
// loads (glibc's gives memory back between loads and faults it in again).
use limn_alloc as _;

const RINGS: usize = 1000;
const SIDES: usize = 500;

fn torus() -> (Vec<[f32; 3]>, Vec<[u32; 3]>) {
    let mut v = Vec::with_capacity(RINGS * SIDES);
    for r in 0..RINGS {
        let th = TAU * r as f64 / RINGS as f64;
        for s in 0..SIDES {
            let ph = TAU * s as f64 / SIDES as f64;
            let rad = 1.0 + 0.3 * ph.cos();
            v.push([
                (rad * th.cos()) as f32,
                (0.3 * ph.sin()) as f32,
                (-rad * th.sin()) as f32,
            ]);
        }
    }
    let at = |r: usize, s: usize| ((r % RINGS) * SIDES + s % SIDES) as u32;
    let mut t = Vec::with_capacity(2 * RINGS * SIDES);
    for r in 0..RINGS {
        for s in 0..SIDES {
            let (a, b, c, d) = (at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    (v, t)
}

fn write_files(dir: &Path) -> std::io::Result<()> {
    let (v, t) = torus();
    let mut stl = std::io::BufWriter::new(std::fs::File::create(dir.join("torus.stl"))?);
    stl.write_all(&[0u8; 80])?;
    stl.write_all(&(t.len() as u32).to_le_bytes())?;
    for tri in &t {
        stl.write_all(&[0u8; 12])?;
        for &i in tri {
            for c in v[i as usize] {
                stl.write_all(&c.to_le_bytes())?;
            }
        }
        stl.write_all(&[0u8; 2])?;
    }
    stl.flush()?;
    let mut obj = std::io::BufWriter::new(std::fs::File::create(dir.join("torus.obj"))?);
    for p in &v {
        writeln!(obj, "v {} {} {}", p[0], p[1], p[2])?;
    }
    for tri in &t {
        writeln!(obj, "f {} {} {}", tri[0] + 1, tri[1] + 1, tri[2] + 1)?;
    }
    obj.flush()?;
    let mut ply = std::io::BufWriter::new(std::fs::File::create(dir.join("torus.ply"))?);
    write!(
        ply,
        "ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty float x\n\
         property float y\nproperty float z\nelement face {}\n\
         property list uchar int vertex_indices\nend_header\n",
        v.len(),
        t.len()
    )?;
    for p in &v {
        for c in p {
            ply.write_all(&c.to_le_bytes())?;
        }
    }
    for tri in &t {
        ply.write_all(&[3])?;
        for &i in tri {
            ply.write_all(&i.to_le_bytes())?;
        }
    }
    ply.flush()
}

/// Time the threads of this process have spent on a CPU (`CLOCK_PROCESS_CPUTIME_ID`:
/// finished threads included, to the nanosecond), which a busy shared machine inflates
/// less than wall time.
fn cpu_time() -> Option<Duration> {
    cpu_time::ProcessTime::try_now()
        .ok()
        .map(|t| t.as_duration())
}

/// Milliseconds, with two decimals below 100 ms (small files load in a few).
fn ms(d: Duration) -> String {
    let ms = d.as_secs_f64() * 1e3;
    if ms < 100.0 {
        format!("{ms:.2} ms")
    } else {
        format!("{ms:.0} ms")
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    limn_alloc::return_freed_memory();
    let runs: usize = std::env::args().nth(1).map_or(Ok(5), |a| a.parse())?;
    let dir = tempfile::tempdir()?;
    let named: Vec<PathBuf> = std::env::args().skip(2).map(PathBuf::from).collect();
    let files = if named.is_empty() {
        write_files(dir.path())?;
        ["torus.stl", "torus.obj", "torus.ply"]
            .map(|name| dir.path().join(name))
            .to_vec()
    } else {
        named
    };
    println!(
        "| file | size | faces | vertices | wall best | wall median | CPU best | CPU median |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    for path in files {
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        let size = std::fs::metadata(&path)?.len();
        let mut times: Vec<Duration> = Vec::new();
        let mut cpu: Vec<Duration> = Vec::new();
        let mut counts = (0, 0);
        for _ in 0..runs {
            let (t0, c0) = (Instant::now(), cpu_time());
            let scene = load(&path, &LoadOptions::default())?;
            times.push(t0.elapsed());
            if let (Some(a), Some(b)) = (c0, cpu_time()) {
                cpu.push(b.saturating_sub(a));
            }
            counts = (scene.faces.len(), scene.vertices.len());
        }
        times.sort();
        cpu.sort();
        let cpu_at = |i: usize| cpu.get(i).map_or("n/a".to_string(), |&d| ms(d));
        println!(
            "| {name} | {:.1} MB | {} | {} | {} | {} | {} | {} |",
            size as f64 / 1e6,
            counts.0,
            counts.1,
            ms(times[0]),
            ms(times[times.len() / 2]),
            cpu_at(0),
            cpu_at(cpu.len() / 2),
        );
    }
    Ok(())
}
