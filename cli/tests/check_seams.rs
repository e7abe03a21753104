//! `limn check` compares the faces of the picture `render` draws, seam flaps included
//! (`--seams PX`, 1 by default), and no flap changes its result.

mod common;

use common::{limn, put, tempdir};

/// A backdrop, a triangle and, painted after it across their shared edge, a triangle
/// whose third corner lies 10¹² px away: the crossing of a flap's far side with the edge
/// towards that corner, computed in f64, lands 10⁻⁵ px off the edge, more than the edge
/// band; at a pixel centre there unless the flap is kept inside the later triangle.
const FAR_CORNER_OBJ: &str = "\
mtllib far.mtl
v 0.0 48.0 -1.0
v 0.0 0.0 -1.0
v 64.0 0.0 -1.0
v 64.0 48.0 -1.0
v 14.0 37.82599172919788 -0.5
v 10.287359636840073 37.82599172919788 -0.5
v 12.0 46.0 -0.5
v 10.287359636840073 37.82599172919788 0.0
v 14.0 37.82599172919788 0.0
v 918496175004.0 -1407834696847.0 0.0
usemtl m0
f 1 2 3 4
usemtl m1
f 5 6 7
usemtl m2
f 8 9 10
";

const FAR_CORNER_MTL: &str = "\
newmtl m0
Kd 0.0 0.5 0.5
illum 0
newmtl m1
Kd 0.2 0.5 0.5
illum 0
newmtl m2
Kd 0.4 0.5 0.5
illum 0
";

#[test]
fn seam_flaps_change_no_pixel_limn_check_compares() {
    let d = tempdir();
    put(d.path(), "far.obj", FAR_CORNER_OBJ);
    put(d.path(), "far.mtl", FAR_CORNER_MTL);
    let view = [
        "--ortho", "48", "--eye", "32,24,10", "--target", "32,24,0", "--size", "64x48", "--near",
        "1", "--far", "20", "--quiet",
    ];
    for seams in ["0.5", "0", "2"] {
        let mut args = vec!["check", "far.obj", "--seams", seams];
        args.extend(view);
        let run = limn(d.path(), &args);
        assert_eq!(
            run.code,
            0,
            "--seams {seams}: {}{}",
            run.stderr,
            run.stdout_text()
        );
        let v: serde_json::Value = serde_json::from_slice(&run.stdout).expect("JSON");
        assert_eq!(v["mismatches_outside_band"], 0, "--seams {seams}: {v}");
        assert_eq!(v["seams"], seams.parse::<f64>().unwrap(), "{v}");
    }
    // The default is render's.
    let mut args = vec!["check", "far.obj"];
    args.extend(view);
    let run = limn(d.path(), &args);
    let v: serde_json::Value = serde_json::from_slice(&run.stdout).expect("JSON");
    assert_eq!(v["seams"], 1.0, "{v}");
}
