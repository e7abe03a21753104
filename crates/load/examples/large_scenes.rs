//! Writes the OBJ files of the end-to-end measurements in BENCHMARKS.md into a folder:
//!
//! * `sphere100k.obj`: a closed UV sphere of 99,856 triangles (159 rings × 316
//!   segments), numbers in Rust's shortest round-trip form of f64;
//! * `sphere1m.obj`: the same sphere at 1,001,112 triangles (708 × 708);
//! * `spheres1m.obj` and `spheres1m.mtl`: 25 UV spheres of 41,472 triangles each (145
//!   rings × 144 segments, radius 1, 2.5 apart) in a 5 × 5 grid, one material each,
//!   a normal per vertex (smooth shading),
//!   1,036,800 triangles in all: an input like the glTF sample
//!   MetalRoughSpheresNoTextures (1,040,409 triangles in 25 spheres);
//! * `soup10k.obj`, `soup10k-lib.obj` and `soup10k-mtl.obj`: the same 10,000 random
//!   triangles (edges up to 0.08 in a 2 × 2 × 2 cube): without materials; with a library
//!   of 10,000 materials (`soup10k-mtl.mtl`) and one `usemtl` before all faces; with the
//!   same library and one `usemtl` per face, each naming another material;
//! * what those 10,000 `usemtl` lines cost, each file of the same size as
//!   `soup10k-mtl.obj`: `soup10k-shuf.obj` names the materials in another order (face `i`
//!   uses `m<7919·i mod 10,000>`, so that the library's order does not help);
//!   `soup10k-same.obj` names `m0` on every such line (padded with spaces to the same
//!   length); `soup10k-comment.obj` has a comment line of the same length instead.
//!
//! ```text
//! cargo run --release -p limn-load --example large_scenes -- FOLDER
//! limn render FOLDER/sphere100k.obj -o sphere100k.svg
//! ```

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use glam::DVec3;
use limn_scene::{shapes, Material, Scene};

/// How the faces of an OBJ use materials.
#[derive(Clone, Copy, PartialEq)]
enum Materials {
    /// No `mtllib`, no `usemtl`.
    None,
    /// The library, and `usemtl m0` before the first face.
    One,
    /// The library, and `usemtl m<i>` before face `i`.
    PerFace,
    /// The library, and `usemtl m<7919 i mod n>` before face `i` of `n`.
    Scattered,
    /// The library, and `usemtl m0` before each face, as long as `usemtl m<i>`.
    SameName,
    /// The library, and a comment before each face, as long as `usemtl m<i>`.
    Comments,
    /// `mtllib spheres1m.mtl`, `usemtl <name>` wherever the face's material changes,
    /// and a normal per vertex (`vn`, from the sphere's centre: smooth shading).
    Grid,
}

/// Writes the vertices and faces of `scene` as OBJ, with `mtllib soup10k-mtl.mtl` and
/// `usemtl` statements as `materials` asks.
fn write_obj(scene: &Scene, path: &Path, materials: Materials) -> std::io::Result<()> {
    let mut out = BufWriter::new(File::create(path)?);
    match materials {
        Materials::None => {}
        Materials::Grid => writeln!(out, "mtllib spheres1m.mtl")?,
        _ => writeln!(out, "mtllib soup10k-mtl.mtl")?,
    }
    if materials == Materials::One {
        writeln!(out, "usemtl m0")?;
    }
    for v in &scene.vertices {
        writeln!(out, "v {} {} {}", v.x, v.y, v.z)?;
    }
    if materials == Materials::Grid {
        for v in &scene.vertices {
            let n = (*v - sphere_centre(*v)).normalize();
            writeln!(out, "vn {} {} {}", n.x, n.y, n.z)?;
        }
    }
    let mut current = None;
    for (i, f) in scene.faces.iter().enumerate() {
        if materials == Materials::Grid && current != Some(f.material) {
            current = Some(f.material);
            writeln!(out, "usemtl {}", scene.materials[f.material as usize].name)?;
        }
        let width = format!("usemtl m{i}").len();
        match materials {
            Materials::PerFace => writeln!(out, "usemtl m{i}")?,
            Materials::Scattered => writeln!(out, "usemtl m{}", i * 7919 % scene.faces.len())?,
            Materials::SameName => writeln!(out, "{:width$}", "usemtl m0")?,
            Materials::Comments => writeln!(out, "#{}", "x".repeat(width - 1))?,
            Materials::None | Materials::One | Materials::Grid => {}
        }
        write!(out, "f")?;
        for v in &f.vertices {
            match materials {
                Materials::Grid => write!(out, " {}//{}", v + 1, v + 1)?,
                _ => write!(out, " {}", v + 1)?,
            }
        }
        writeln!(out)?;
    }
    out.flush()
}

/// A library of `n` unlit materials `m0` … `m<n-1>` of different colours.
fn write_mtl(n: usize, path: &Path) -> std::io::Result<()> {
    let mut out = BufWriter::new(File::create(path)?);
    for i in 0..n {
        let c = |k: usize| ((i * k) % 251) as f64 / 250.0;
        writeln!(out, "newmtl m{i}")?;
        writeln!(out, "Kd {} {} {}", c(7), c(31), c(101))?;
        writeln!(out, "illum 0")?;
    }
    out.flush()
}

fn sphere(rings: u32, segments: u32) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::default_grey());
    let o = s.add_object("sphere");
    shapes::uv_sphere(&mut s, DVec3::ZERO, 1.0, rings, segments, m, o).expect("valid sphere");
    s
}

/// The centre of the sphere of [`sphere_grid`] that the point `v` is on.
fn sphere_centre(v: DVec3) -> DVec3 {
    DVec3::new((v.x / 2.5).round() * 2.5, (v.y / 2.5).round() * 2.5, 0.0)
}

/// 25 spheres of `rings` × `segments` in a 5 × 5 grid in the plane z = 0, each with its
/// own material `s<i>` (written to `mtl` as a library).
fn sphere_grid(rings: u32, segments: u32, mtl: &Path) -> Result<Scene, Box<dyn std::error::Error>> {
    let mut s = Scene::default();
    let mut lib = BufWriter::new(File::create(mtl)?);
    for i in 0..25u32 {
        let (col, row) = (i % 5, i / 5);
        let mut m = Material::default_grey();
        m.name = format!("s{i}");
        let m = s.add_material(m);
        writeln!(lib, "newmtl s{i}")?;
        let kd = [
            0.2 + 0.15 * f64::from(col),
            0.3,
            0.2 + 0.15 * f64::from(row),
        ];
        writeln!(lib, "Kd {} {} {}", kd[0], kd[1], kd[2])?;
        writeln!(lib, "Ks 0.5 0.5 0.5\nNs 40\nillum 2")?;
        let o = s.add_object(&format!("sphere{i}"));
        let centre = DVec3::new(2.5 * f64::from(col), 2.5 * f64::from(row), 0.0);
        shapes::uv_sphere(&mut s, centre, 1.0, rings, segments, m, o)?;
    }
    lib.flush()?;
    Ok(s)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args()
        .nth(1)
        .ok_or("usage: large_scenes FOLDER")?;
    let dir = Path::new(&dir);
    std::fs::create_dir_all(dir)?;
    write_obj(
        &sphere(159, 316),
        &dir.join("sphere100k.obj"),
        Materials::None,
    )?;
    write_obj(
        &sphere(708, 708),
        &dir.join("sphere1m.obj"),
        Materials::None,
    )?;
    let grid = sphere_grid(145, 144, &dir.join("spheres1m.mtl"))?;
    write_obj(&grid, &dir.join("spheres1m.obj"), Materials::Grid)?;
    let mut soup = Scene::default();
    let m = soup.add_material(Material::default_grey());
    let o = soup.add_object("soup");
    shapes::random_soup(&mut soup, 10_000, 0.08, 7, m, o)?;
    write_obj(&soup, &dir.join("soup10k.obj"), Materials::None)?;
    write_obj(&soup, &dir.join("soup10k-lib.obj"), Materials::One)?;
    write_obj(&soup, &dir.join("soup10k-mtl.obj"), Materials::PerFace)?;
    write_obj(&soup, &dir.join("soup10k-shuf.obj"), Materials::Scattered)?;
    write_obj(&soup, &dir.join("soup10k-same.obj"), Materials::SameName)?;
    write_obj(&soup, &dir.join("soup10k-comment.obj"), Materials::Comments)?;
    write_mtl(soup.faces.len(), &dir.join("soup10k-mtl.mtl"))?;
    Ok(())
}
