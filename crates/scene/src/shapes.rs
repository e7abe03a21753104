//! Generated meshes for demos, tests and benchmarks: closed, consistently oriented
//! (counter-clockwise seen from outside), except the random soup and the woven strips.

use glam::DVec3;
use std::collections::HashMap;

use crate::{Scene, SceneError};

/// Appends a closed icosphere (an icosahedron subdivided `level` times: 20·4^level
/// triangles) of the given centre and radius, with the sphere's normals as vertex normals
/// (so lit materials are Gouraud-shaded). Returns the number of faces added.
pub fn icosphere(
    scene: &mut Scene,
    centre: DVec3,
    radius: f64,
    level: u32,
    material: u32,
    object: u32,
) -> Result<usize, SceneError> {
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let mut verts: Vec<DVec3> = [
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ]
    .iter()
    .map(|p| DVec3::from(*p).normalize())
    .collect();
    let mut tris: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..level {
        let mut mid: HashMap<(u32, u32), u32> = HashMap::new();
        let mut next = Vec::with_capacity(tris.len() * 4);
        let mut midpoint = |a: u32, b: u32, verts: &mut Vec<DVec3>| -> u32 {
            let key = (a.min(b), a.max(b));
            *mid.entry(key).or_insert_with(|| {
                let p = ((verts[a as usize] + verts[b as usize]) * 0.5).normalize();
                verts.push(p);
                (verts.len() - 1) as u32
            })
        };
        for [a, b, c] in tris {
            let ab = midpoint(a, b, &mut verts);
            let bc = midpoint(b, c, &mut verts);
            let ca = midpoint(c, a, &mut verts);
            next.extend_from_slice(&[[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        tris = next;
    }
    let base = scene.vertices.len() as u32;
    let nbase = scene.normals.len() as u32;
    scene
        .vertices
        .extend(verts.iter().map(|&p| centre + p * radius));
    scene.normals.extend(verts.iter().copied());
    for [a, b, c] in &tris {
        let id = scene.add_face(&[base + a, base + b, base + c], material, object)?;
        scene.faces[id as usize].normals = Some(Box::new([nbase + a, nbase + b, nbase + c]));
    }
    Ok(tris.len())
}

/// Appends a closed UV sphere with `rings` latitude bands and `segments` longitude
/// segments, in triangles (2·segments·(rings − 1) of them). Returns the faces added.
pub fn uv_sphere(
    scene: &mut Scene,
    centre: DVec3,
    radius: f64,
    rings: u32,
    segments: u32,
    material: u32,
    object: u32,
) -> Result<usize, SceneError> {
    let rings = rings.max(2);
    let segments = segments.max(3);
    let base = scene.vertices.len() as u32;
    scene.vertices.push(centre + DVec3::Y * radius);
    for r in 1..rings {
        let phi = std::f64::consts::PI * r as f64 / rings as f64;
        for s in 0..segments {
            let th = std::f64::consts::TAU * s as f64 / segments as f64;
            let p = DVec3::new(phi.sin() * th.cos(), phi.cos(), -phi.sin() * th.sin());
            scene.vertices.push(centre + p * radius);
        }
    }
    scene.vertices.push(centre - DVec3::Y * radius);
    let bottom = base + 1 + (rings - 1) * segments;
    let ring = |r: u32, s: u32| base + 1 + (r - 1) * segments + (s % segments);
    let mut n = 0;
    for s in 0..segments {
        scene.add_face(&[base, ring(1, s), ring(1, s + 1)], material, object)?;
        scene.add_face(
            &[bottom, ring(rings - 1, s + 1), ring(rings - 1, s)],
            material,
            object,
        )?;
        n += 2;
    }
    for r in 1..rings - 1 {
        for s in 0..segments {
            let (a, b, c, d) = (
                ring(r, s),
                ring(r + 1, s),
                ring(r + 1, s + 1),
                ring(r, s + 1),
            );
            scene.add_face(&[a, b, c], material, object)?;
            scene.add_face(&[a, c, d], material, object)?;
            n += 2;
        }
    }
    Ok(n)
}

/// Appends `n` horizontal strips (material `materials[0]`) and `n` vertical ones
/// (`materials[1]`) woven over and under each other: strips one unit apart and 0.35
/// wide, each a zig-zag of flat quads with kinks 0.15 up or down at the crossings,
/// every corner moved by `offset` along each axis. An open mesh with exact degeneracies
/// (coplanar quads of parallel strips, kink lines shared by neighbouring quads) whose
/// order needs splitting: far from the origin when `offset` is large. Returns the faces
/// added (`2·n·(n + 1)`).
pub fn woven_strips(
    scene: &mut Scene,
    n: usize,
    offset: f64,
    materials: [u32; 2],
    object: u32,
) -> Result<usize, SceneError> {
    let (w, amp) = (0.35, 0.15);
    let centre = |i: usize| i as f64 - (n as f64 - 1.0) / 2.0;
    let at = |x: f64, y: f64, z: f64| DVec3::new(x + offset, y + offset, z + offset);
    // Heights of a strip at its crossings, extended half a step beyond both ends.
    let profile = |i: usize, sign: f64| -> Vec<(f64, f64)> {
        let mut pts = Vec::with_capacity(n + 2);
        let z = |j: usize| sign * amp * if (i + j).is_multiple_of(2) { 1.0 } else { -1.0 };
        pts.push((centre(0) - 0.5, 0.0));
        pts.extend((0..n).map(|j| (centre(j), z(j))));
        pts.push((centre(n - 1) + 0.5, 0.0));
        pts
    };
    let mut added = 0;
    for i in 0..n {
        let c = centre(i);
        for seg in profile(i, 1.0).windows(2) {
            let ((x0, z0), (x1, z1)) = (seg[0], seg[1]);
            let quad = [
                at(x0, c - w / 2.0, z0),
                at(x1, c - w / 2.0, z1),
                at(x1, c + w / 2.0, z1),
                at(x0, c + w / 2.0, z0),
            ];
            scene.add_polygon(&quad, materials[0], object)?;
            added += 1;
        }
        // Vertical strip i at x = c: at crossing (row j, column i) it has the opposite
        // height of horizontal strip j there.
        for seg in profile(i, -1.0).windows(2) {
            let ((y0, z0), (y1, z1)) = (seg[0], seg[1]);
            let quad = [
                at(c - w / 2.0, y0, z0),
                at(c + w / 2.0, y0, z0),
                at(c + w / 2.0, y1, z1),
                at(c - w / 2.0, y1, z1),
            ];
            scene.add_polygon(&quad, materials[1], object)?;
            added += 1;
        }
    }
    Ok(added)
}

/// Appends a closed axis-aligned box (six quads) from `lo` to `hi`, optionally rotated
/// about its centre by `rot`. Returns the faces added.
pub fn cuboid(
    scene: &mut Scene,
    lo: DVec3,
    hi: DVec3,
    rot: glam::DMat3,
    material: u32,
    object: u32,
) -> Result<usize, SceneError> {
    let c = (lo + hi) * 0.5;
    let base = scene.vertices.len() as u32;
    for i in 0..8u32 {
        let p = DVec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        );
        scene.vertices.push(c + rot * (p - c));
    }
    let quads = [
        [0, 2, 3, 1], // -z
        [4, 5, 7, 6], // +z
        [0, 1, 5, 4], // -y
        [2, 6, 7, 3], // +y
        [0, 4, 6, 2], // -x
        [1, 3, 7, 5], // +x
    ];
    for q in quads {
        scene.add_face(&q.map(|v| base + v), material, object)?;
    }
    Ok(6)
}

/// Appends a closed torus (a non-convex closed mesh) of `major` and `minor` radii around
/// the y axis, in quads. Returns the faces added.
#[allow(clippy::too_many_arguments)] // a shape generator: every number is a dimension
pub fn torus(
    scene: &mut Scene,
    centre: DVec3,
    major: f64,
    minor: f64,
    rings: u32,
    sides: u32,
    material: u32,
    object: u32,
) -> Result<usize, SceneError> {
    let (rings, sides) = (rings.max(3), sides.max(3));
    let base = scene.vertices.len() as u32;
    for r in 0..rings {
        let th = std::f64::consts::TAU * r as f64 / rings as f64;
        for s in 0..sides {
            let ph = std::f64::consts::TAU * s as f64 / sides as f64;
            let rad = major + minor * ph.cos();
            scene
                .vertices
                .push(centre + DVec3::new(rad * th.cos(), minor * ph.sin(), -rad * th.sin()));
        }
    }
    let at = |r: u32, s: u32| base + (r % rings) * sides + (s % sides);
    for r in 0..rings {
        for s in 0..sides {
            scene.add_face(
                &[at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1)],
                material,
                object,
            )?;
        }
    }
    Ok((rings * sides) as usize)
}

/// Appends `n` random triangles to `scene`: centres uniform in the cube [-1, 1]³, corners
/// within `size`/2 of the centre on each axis (a deterministic LCG seeded by `seed`;
/// slivers are redrawn). A soup for benchmarks and stress tests. Returns the faces added.
pub fn random_soup(
    scene: &mut Scene,
    n: usize,
    size: f64,
    seed: u64,
    material: u32,
    object: u32,
) -> Result<usize, SceneError> {
    let mut rng = seed;
    let mut next = move || {
        rng = rng
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((rng >> 11) as f64) / ((1u64 << 53) as f64)
    };
    let mut added = 0;
    while added < n {
        let c = DVec3::new(next(), next(), next()) * 2.0 - 1.0;
        let pts: Vec<DVec3> = (0..3)
            .map(|_| c + (DVec3::new(next(), next(), next()) - 0.5) * size)
            .collect();
        if (pts[1] - pts[0]).cross(pts[2] - pts[0]).length() > 1e-9 {
            scene.add_polygon(&pts, material, object)?;
            added += 1;
        }
    }
    Ok(added)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Material;

    fn fresh() -> (Scene, u32, u32) {
        let mut s = Scene::default();
        let m = s.add_material(Material::default_grey());
        let o = s.add_object("shape");
        (s, m, o)
    }

    fn outward(s: &Scene, centre: DVec3) -> bool {
        (0..s.faces.len() as u32).all(|f| {
            let p = s.face_points(f);
            let c = p.iter().copied().sum::<DVec3>() / p.len() as f64;
            crate::polygon_normal(&p).dot(c - centre) > 0.0
        })
    }

    #[test]
    fn soups_are_deterministic_and_open() {
        let (mut a, m, o) = fresh();
        assert_eq!(random_soup(&mut a, 50, 0.3, 7, m, o).unwrap(), 50);
        let (mut b, m, o) = fresh();
        random_soup(&mut b, 50, 0.3, 7, m, o).unwrap();
        assert_eq!(a, b);
        assert!(!a.is_closed());
        let (lo, hi) = a.bounds().unwrap();
        assert!(lo.min_element() >= -1.15 && hi.max_element() <= 1.15);
    }

    #[test]
    fn shapes_are_closed_and_face_outwards() {
        let (mut s, m, o) = fresh();
        assert_eq!(icosphere(&mut s, DVec3::ZERO, 1.0, 2, m, o).unwrap(), 320);
        assert!(s.is_closed() && outward(&s, DVec3::ZERO));
        let (mut s, m, o) = fresh();
        uv_sphere(&mut s, DVec3::ONE, 2.0, 8, 12, m, o).unwrap();
        assert!(s.is_closed() && outward(&s, DVec3::ONE));
        let (mut s, m, o) = fresh();
        cuboid(&mut s, DVec3::ZERO, DVec3::ONE, glam::DMat3::IDENTITY, m, o).unwrap();
        assert!(s.is_closed() && outward(&s, DVec3::splat(0.5)));
        let (mut s, m, o) = fresh();
        torus(&mut s, DVec3::ZERO, 2.0, 0.5, 12, 8, m, o).unwrap();
        assert!(s.is_closed());
    }
}
