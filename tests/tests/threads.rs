//! The output does not depend on the number of threads: every ordering, both arithmetics
//! and every writer give the same bytes on one thread as on two and three. The scenes
//! are large enough to take every parallel path (face preparation, candidate-pair tests
//! handed out in tasks, the probe of dense sets, the sweep broad phase, large sets split
//! on one thread and their parts ordered on the pool), and lines,
//! markers and labels hidden in parallel tasks give the same visible marks and bytes.

use glam::DVec3;
use limn_depthsort::{order, order_with_marks, Arith, OrderOptions, SortMode, VisibleMarks};
use limn_paint::{painter_for, picture, picture_with_marks, Format, Style};
use limn_scene::{shapes, Camera, Material, PointMark, Polyline, Scene, TextLabel};
use limn_tests::corpus;

/// Every writer's output for `scene`, ordered by `sort` in `arith`, on `threads` threads.
fn outputs(
    scene: &Scene,
    camera: &Camera,
    sort: SortMode,
    arith: Arith,
    threads: usize,
) -> Vec<Vec<u8>> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("thread pool");
    pool.install(|| {
        let opts = OrderOptions {
            sort,
            arith,
            ..OrderOptions::default()
        };
        let o = order(scene, camera, &opts).expect("orderable");
        let pic = picture(scene, &o, &Style::default());
        Format::ALL
            .iter()
            .map(|&f| {
                let mut out = Vec::new();
                painter_for(f).paint(&pic, &mut out).expect("painted");
                out
            })
            .collect()
    })
}

fn soup(n: usize, size: f64) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("soup", [0.7, 0.7, 0.7]));
    let o = s.add_object("soup");
    shapes::random_soup(&mut s, n, size, 3, m, o).expect("valid soup");
    s
}

fn torus() -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("torus", [0.7, 0.7, 0.7]));
    let o = s.add_object("torus");
    shapes::torus(&mut s, DVec3::ZERO, 1.0, 0.4, 40, 16, m, o).expect("valid torus");
    s
}

#[test]
fn every_writer_and_ordering_gives_the_same_bytes_on_any_number_of_threads() {
    let framed = |name: &str, s: Scene| {
        let c = Camera::framing(&s, 240, 180).expect("camera");
        (name.to_string(), s, c)
    };
    let mut scenes: Vec<(String, Scene, Camera)> = vec![
        framed("soup", soup(1500, 0.15)),
        framed("dense soup", soup(400, 0.6)),
        framed("torus", torus()),
    ];
    for case in corpus::all() {
        scenes.push((case.name.to_string(), case.scene, case.camera));
    }
    for (name, scene, camera) in &scenes {
        for sort in SortMode::ALL {
            for arith in Arith::ALL {
                let one = outputs(scene, camera, sort, arith, 1);
                for threads in [2, 3] {
                    let many = outputs(scene, camera, sort, arith, threads);
                    for (f, (a, b)) in Format::ALL.iter().zip(one.iter().zip(&many)) {
                        assert!(
                            a == b,
                            "{name}, {} {}, {}: 1 thread and {threads} differ",
                            sort.name(),
                            arith.name(),
                            f.name()
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn large_sets_split_on_every_core_give_the_same_bytes_on_any_number_of_threads() {
    // Dense enough that BSP, and the adaptive ordering (which finds cycles nearly
    // everywhere), split it on one thread and order the parts on the pool.
    let scene = soup(2600, 0.45);
    let camera = Camera::framing(&scene, 240, 180).expect("camera");
    for sort in [SortMode::Bsp, SortMode::Adaptive] {
        let stats = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("thread pool");
            let opts = OrderOptions {
                sort,
                ..OrderOptions::default()
            };
            pool.install(|| order(&scene, &camera, &opts).expect("orderable").stats)
        };
        let one = stats(1);
        assert!(one.parts_apart >= 2, "{}: {one:?}", sort.name());
        let one_bytes = outputs(&scene, &camera, sort, Arith::Exact, 1);
        for threads in [2, 3] {
            let many = outputs(&scene, &camera, sort, Arith::Exact, threads);
            for (f, (a, b)) in Format::ALL.iter().zip(one_bytes.iter().zip(&many)) {
                assert!(
                    a == b,
                    "{}, {}: 1 thread and {threads} differ",
                    sort.name(),
                    f.name()
                );
            }
        }
    }
}

/// A height field (half its faces translucent in one corner) with its grid lines, a
/// trajectory through and behind it, scattered points and labels.
fn surface_with_marks(n: usize) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("surface", [0.6, 0.7, 0.9]));
    let mut glass = Material::diffuse("glass", [0.9, 0.9, 0.9]);
    glass.opacity = 0.5;
    let g = s.add_material(glass);
    let o = s.add_object("surface");
    let at = |i: usize, j: usize| {
        let (x, z) = (
            i as f64 / n as f64 * 6.0 - 3.0,
            j as f64 / n as f64 * 6.0 - 3.0,
        );
        DVec3::new(x, x.sin() * z.cos(), z)
    };
    for i in 0..n {
        for j in 0..n {
            let mat = if i < n / 3 && j < n / 3 { g } else { m };
            let [a, b, c, d] = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            s.add_polygon(&[a, d, c], mat, o).expect("valid");
            s.add_polygon(&[a, c, b], mat, o).expect("valid");
        }
    }
    for k in 0..=n {
        s.lines
            .push(Polyline::new((0..=n).map(|j| at(k, j)).collect()));
        s.lines
            .push(Polyline::new((0..=n).map(|i| at(i, k)).collect()));
    }
    let helix = (0..200)
        .map(|k| {
            let t = k as f64 / 20.0;
            DVec3::new(2.5 * t.cos(), t / 5.0 - 1.5, 2.5 * t.sin())
        })
        .collect();
    s.lines.push(Polyline {
        head: true,
        ..Polyline::new(helix)
    });
    let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    for k in 0..600 {
        let p = DVec3::new(next() * 6.0 - 3.0, next() * 3.0 - 1.5, next() * 6.0 - 3.0);
        if k % 10 == 0 {
            s.labels.push(TextLabel::new(p, "label"));
        } else {
            s.points.push(PointMark::new(p));
        }
    }
    s
}

/// The visible marks (time left out) and every writer's bytes, on `threads` threads.
fn marks_outputs(scene: &Scene, camera: &Camera, threads: usize) -> (VisibleMarks, Vec<Vec<u8>>) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("thread pool");
    pool.install(|| {
        let (mut o, mut marks) =
            order_with_marks(scene, camera, &OrderOptions::default()).expect("orderable");
        let pic = picture_with_marks(scene, &mut o, &marks, &Style::default());
        marks.stats.ms = 0;
        let bytes = Format::ALL
            .iter()
            .map(|&f| {
                let mut out = Vec::new();
                painter_for(f).paint(&pic, &mut out).expect("painted");
                out
            })
            .collect();
        (marks, bytes)
    })
}

#[test]
fn hidden_marks_are_the_same_on_any_number_of_threads() {
    let scene = surface_with_marks(24);
    let camera = Camera::new(DVec3::new(6.0, 5.0, 8.0), DVec3::ZERO, 480, 360);
    let (one, one_bytes) = marks_outputs(&scene, &camera, 1);
    // The scene reaches every kind of mark: hidden and visible pieces, points, labels.
    let st = one.stats;
    assert!(st.hidden_pieces > 10 && st.pieces_out > 10, "{st:?}");
    assert!(
        st.markers_shown > 0 && st.markers_shown < st.markers_in,
        "{st:?}"
    );
    assert!(
        st.labels_shown > 0 && st.labels_shown < st.labels_in,
        "{st:?}"
    );
    for threads in [2, 3] {
        let (many, many_bytes) = marks_outputs(&scene, &camera, threads);
        assert_eq!(one, many, "1 thread and {threads} differ");
        for (f, (a, b)) in Format::ALL.iter().zip(one_bytes.iter().zip(&many_bytes)) {
            assert!(a == b, "{}: 1 thread and {threads} differ", f.name());
        }
    }
}
