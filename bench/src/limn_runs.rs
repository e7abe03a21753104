//! limn's own rows: every ordering with both arithmetics, rendered through limn's front
//! door (`limn::render_into`, the render the command runs) into an SVG file in this
//! process, timed as the median of several runs.

use std::borrow::Cow;
use std::fs::File;
use std::io::BufWriter;
use std::time::Instant;

use anyhow::Context;

use limn::{Input, RenderOptions, Request, SceneOptions, Silent, ViewOptions};
use limn_depthsort::{Arith, SortMode};
use limn_paint::Format;

use crate::scenes::BenchScene;

/// One measured run of a program on a scene.
pub struct Measured {
    /// Median milliseconds.
    pub ms: f64,
    /// Fragments (limn) or primitives (peers) written.
    pub primitives: usize,
    /// Output bytes.
    pub bytes: usize,
    /// The SVG.
    pub svg: Vec<u8>,
    /// The picture before writing (limn only): each fragment's outline and face.
    pub picture: Vec<(Vec<[f64; 2]>, u32)>,
}

/// Orders and writes `s` with `sort` and `arith`, `runs` times; the median time.
pub fn measure(
    s: &BenchScene,
    sort: SortMode,
    arith: Arith,
    runs: usize,
) -> anyhow::Result<Measured> {
    // The scene with its camera: copied once, outside the timed runs.
    let mut scene = s.scene.clone();
    scene.camera = Some(s.camera);
    let req = Request {
        input: Input::Scene {
            scene: Cow::Borrowed(&scene),
            settings: SceneOptions {
                size: Some((s.camera.width, s.camera.height)),
                ..SceneOptions::default()
            },
            name: s.name.clone(),
        },
        output: None,
        options: RenderOptions {
            view: ViewOptions {
                sort: Some(sort),
                arith: Some(arith),
                ..ViewOptions::default()
            },
            format: Some(Format::Svg),
            ..RenderOptions::default()
        },
    };
    let mut times = Vec::with_capacity(runs);
    let mut last = None;
    // The SVG goes to a file, as `limn render` writes it (and as the peers write theirs),
    // and is read back after the clock stops.
    let dir = tempfile::tempdir()?;
    let path = dir.path().join("limn.svg");
    for _ in 0..runs.max(1) {
        crate::settle::settle();
        let t0 = Instant::now();
        let mut file = BufWriter::new(File::create(&path)?);
        let done = limn::render_into(&req, &mut file, &mut Silent)?;
        file.into_inner().map_err(|e| e.into_error())?;
        times.push(t0.elapsed().as_secs_f64() * 1e3);
        last = Some(done);
    }
    let done = last.expect("at least one run");
    let primitives = done.ordered().map_or(0, |o| o.stats.fragments_out);
    let pic = done.picture().context("a painter's render has a picture")?;
    let svg = std::fs::read(&path)?;
    Ok(Measured {
        ms: median(&mut times),
        primitives,
        bytes: svg.len(),
        svg,
        picture: pic
            .fragments
            .iter()
            .map(|f| (f.points.clone(), f.face))
            .collect(),
    })
}

/// The median (the mean of the middle two for an even count).
pub fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        return f64::NAN;
    }
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}
