//! Effects on demand end to end: an unlit scene writes no shading objects and lists no
//! effects; Phong, Gouraud and fog are listed when asked and show in every writer;
//! fog colours by hand.

mod common;

use common::{limn, put, tempdir, TRIANGLE_OBJ};

fn ok(dir: &std::path::Path, args: &[&str]) -> serde_json::Value {
    let mut args = args.to_vec();
    args.extend(["--stats", "-"]);
    let run = limn(dir, &args);
    assert_eq!(run.code, 0, "limn {args:?}: {}", run.stderr);
    serde_json::from_slice(&run.stdout).unwrap()
}

fn effects(v: &serde_json::Value) -> Vec<String> {
    v["effects"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_str().unwrap().to_string())
        .collect()
}

/// A glossy octahedron-like cap: four triangles around an apex with vertex normals.
const CAP_OBJ: &str = "mtllib m.mtl\nusemtl shiny\n\
v 0 0 1\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\n\
vn 0 0 1\nvn 1 0 0.2\nvn 0 1 0.2\nvn -1 0 0.2\nvn 0 -1 0.2\n\
f 1//1 2//2 3//3\nf 1//1 3//3 4//4\nf 1//1 4//4 5//5\nf 1//1 5//5 2//2\n";
const SHINY_MTL: &str =
    "newmtl shiny\nKa 0.1 0.1 0.1\nKd 0.7 0.3 0.2\nKs 0.8 0.8 0.8\nNs 40\nillum 2\n";

#[test]
fn an_unlit_scene_writes_no_shading_and_lists_no_effects() {
    let d = tempdir();
    put(d.path(), "c.mtl", "newmtl blue\nillum 0\nKd 0.2 0.4 0.6\n");
    put(
        d.path(),
        "a.obj",
        format!("mtllib c.mtl\nusemtl blue\n{TRIANGLE_OBJ}"),
    );
    for shading in [None, Some("phong")] {
        for ext in ["svg", "pdf", "eps", "png"] {
            let out = format!("out.{ext}");
            let mut args = vec!["render", "a.obj", "-o", &out];
            if let Some(s) = shading {
                args.extend(["--shading", s]);
            }
            let v = ok(d.path(), &args);
            assert!(effects(&v).is_empty(), "{v}");
            let bytes = std::fs::read(d.path().join(&out)).unwrap();
            let text = String::from_utf8_lossy(&bytes);
            for marker in ["linearGradient", "<image", "/Shading", "shfill", "/Image"] {
                assert!(!text.contains(marker), "{ext}: {marker}");
            }
        }
    }
}

#[test]
fn smooth_shading_is_listed_and_written_as_asked() {
    let d = tempdir();
    put(d.path(), "m.mtl", SHINY_MTL);
    put(d.path(), "cap.obj", CAP_OBJ);
    let eye = ["--eye", "0,0,5", "--target", "0,0,0", "--size", "200x200"];
    let run = |shading: &str, out: &str| {
        let mut args = vec!["render", "cap.obj", "-o", out, "--shading", shading];
        args.extend(eye);
        let v = ok(d.path(), &args);
        let bytes = std::fs::read(d.path().join(out)).unwrap();
        (effects(&v), String::from_utf8_lossy(&bytes).into_owned())
    };
    let (e, pdf) = run("gouraud", "g.pdf");
    assert!(e.contains(&"gouraud".to_string()) && !e.contains(&"phong".to_string()));
    let gouraud_meshes = pdf.matches("/ShadingType 4").count();
    assert_eq!(gouraud_meshes, 4, "one mesh per face");
    let (e, pdf) = run("phong", "p.pdf");
    assert!(e.contains(&"phong".to_string()) && !e.contains(&"gouraud".to_string()));
    assert_eq!(pdf.matches("/ShadingType 4").count(), 4);
    assert!(pdf.len() > 2 * std::fs::metadata(d.path().join("g.pdf")).unwrap().len() as usize);
    let (e, eps) = run("phong", "p.eps");
    assert!(e.contains(&"phong".to_string()));
    assert!(eps.contains("shfill"));
    let (_, svg) = run("gouraud", "g.svg");
    let (_, flat) = run("flat", "f.svg");
    assert!(!flat.contains("<linearGradient"));
    assert!(
        svg.contains("<linearGradient")
            || svg.matches("<path").count() > 2 * flat.matches("<path").count(),
        "{svg}"
    );
    let (e, _) = run("flat", "f.pdf");
    assert!(!e.iter().any(|x| x == "gouraud" || x == "phong"), "{e:?}");
}

#[test]
fn fog_colours_by_hand() {
    let d = tempdir();
    put(
        d.path(),
        "g.mtl",
        "newmtl grey\nKa 0 0 0\nKd 0.5 0.5 0.5\nillum 1\n",
    );
    put(
        d.path(),
        "t.obj",
        "mtllib g.mtl\nusemtl grey\nv -1 -1 0\nv 2 -1 0\nv -1 2 0\nf 1 2 3\n",
    );
    // Centroid at the origin, 4 from the eye, facing the headlight: diffuse 0.5.
    let scene = |fog: &str| {
        format!(
            "[camera]\neye = [0, 0, 4]\ntarget = [0, 0, 0]\n[output]\nsize = [100, 100]\n\
             [[mesh]]\npath = \"t.obj\"\n{fog}"
        )
    };
    put(d.path(), "plain.toml", scene(""));
    put(
        d.path(),
        "fog.toml",
        scene("[fog]\ncolor = [1, 0, 0]\nstart = 2\nend = 6\n"),
    );
    put(
        d.path(),
        "exp.toml",
        scene("[fog]\ncolor = [0, 0, 1]\nmode = \"exponential\"\ndensity = 0.25\n"),
    );
    let v = ok(d.path(), &["render", "plain.toml", "-o", "plain.svg"]);
    assert!(!effects(&v).contains(&"fog".to_string()));
    let svg = std::fs::read_to_string(d.path().join("plain.svg")).unwrap();
    assert!(svg.contains("fill=\"#808080\""), "{svg}");
    // Linear: half-way from 2 to 6, so half grey, half red: (0.75, 0.25, 0.25).
    let v = ok(d.path(), &["render", "fog.toml", "-o", "fog.svg"]);
    assert!(effects(&v).contains(&"fog".to_string()), "{v}");
    let svg = std::fs::read_to_string(d.path().join("fog.svg")).unwrap();
    assert!(svg.contains("fill=\"#bf4040\""), "{svg}");
    // Exponential: exp(-0.25 · 4) = 0.3679 of the grey, the rest blue.
    ok(d.path(), &["render", "exp.toml", "-o", "exp.svg"]);
    let svg = std::fs::read_to_string(d.path().join("exp.svg")).unwrap();
    let k = (-1.0f64).exp();
    let r = (0.5 * k * 255.0).round() as u8;
    let b = ((0.5 * k + 1.0 - k) * 255.0).round() as u8;
    let want = format!("fill=\"#{r:02x}{r:02x}{b:02x}\"");
    assert!(svg.contains(&want), "{want} in {svg}");
}
