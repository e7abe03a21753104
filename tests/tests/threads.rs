//! The output does not depend on the number of threads: every ordering, both arithmetics
//! and every writer give the same bytes on one thread as on two and three. The scenes
//! are large enough to take every parallel path (face preparation, candidate-pair tests
//! handed out in tasks, the probe of dense sets, the sweep broad phase).

use glam::DVec3;
use limn_depthsort::{order, Arith, OrderOptions, SortMode};
use limn_paint::{painter_for, picture, Format, Style};
use limn_scene::{shapes, Camera, Material, Scene};
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
