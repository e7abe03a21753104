//! Shadows end to end: only lights with `shadows = true` cast them, a light without
//! shadows changes nothing (the same bytes in every format), `--stats` lists `shadows`
//! exactly when used, every writer draws the shadowed parts, and bad values are errors
//! with file and line.

mod common;

use common::{limn, put, tempdir};

/// A ground square and a box floating over it, lit by one directional light whose
/// `shadows` line is `shadows` (empty: the key is left out).
fn scene(dir: &std::path::Path, shadows: &str) -> std::path::PathBuf {
    put(
        dir,
        "ground.obj",
        "v -3 0 3\nv 3 0 3\nv 3 0 -3\nv -3 0 -3\nf 1 2 3 4\n",
    );
    put(
        dir,
        "box.obj",
        "v -0.5 0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 1.5 -0.5\nv 0.5 1.5 -0.5\n\
         v -0.5 0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 1.5 0.5\nv 0.5 1.5 0.5\n\
         f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n",
    );
    put(
        dir,
        "s.toml",
        format!(
            "[camera]\neye = [3, 5, 6]\ntarget = [0, 0.5, 0]\n[output]\nsize = \"160x120\"\n\
             [[mesh]]\npath = \"ground.obj\"\nmaterial = {{ kd = \"#d0d0d0\", illum = 1 }}\n\
             [[mesh]]\npath = \"box.obj\"\nmaterial = {{ kd = \"#c04030\", illum = 1 }}\n\
             [[light]]\nkind = \"ambient\"\ncolor = [0.3, 0.3, 0.3]\n\
             [[light]]\nkind = \"directional\"\ndirection = [1, 2, 0.5]\n{shadows}\n"
        ),
    )
}

/// Renders `s.toml` to `out`; the statistics when `extra` asks for no `--method`.
fn render(dir: &std::path::Path, out: &str, extra: &[&str]) -> (Vec<u8>, serde_json::Value) {
    let mut args = vec!["render", "s.toml", "-o", out];
    let painter = extra.is_empty() || extra[0] != "--method";
    if painter {
        args.extend(["--stats", "stats.json"]);
    }
    args.extend(extra);
    let run = limn(dir, &args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let stats = if painter {
        serde_json::from_slice(&std::fs::read(dir.join("stats.json")).unwrap()).unwrap()
    } else {
        serde_json::Value::Null
    };
    (std::fs::read(dir.join(out)).unwrap(), stats)
}

fn has_shadows(v: &serde_json::Value) -> bool {
    v["effects"]
        .as_array()
        .unwrap()
        .iter()
        .any(|e| e == "shadows")
}

#[test]
fn a_light_without_shadows_changes_nothing() {
    let d = tempdir();
    for ext in ["svg", "pdf", "eps", "png", "tikz"] {
        let out = format!("o.{ext}");
        scene(d.path(), "");
        let (plain, v) = render(d.path(), &out, &[]);
        assert!(!has_shadows(&v));
        scene(d.path(), "shadows = false");
        let (off, v) = render(d.path(), &out, &[]);
        assert!(!has_shadows(&v));
        assert_eq!(plain, off, "{ext}: shadows = false changed the output");
        scene(d.path(), "shadows = true");
        let (on, v) = render(d.path(), &out, &[]);
        assert!(has_shadows(&v), "{v}");
        assert!(v["fragments_in_shadow"].as_u64().unwrap() > 0);
        assert_ne!(plain, on, "{ext}: the shadow is not drawn");
    }
    for method in ["zbuffer", "scanline", "warnock", "raycast"] {
        scene(d.path(), "shadows = false");
        let (off, _) = render(d.path(), "m.png", &["--method", method]);
        scene(d.path(), "");
        let (plain, _) = render(d.path(), "m.png", &["--method", method]);
        assert_eq!(plain, off, "{method}");
        scene(d.path(), "shadows = true");
        let (on, _) = render(d.path(), "m.png", &["--method", method]);
        assert_ne!(plain, on, "{method}: the shadow is not drawn");
    }
}

#[test]
fn the_shadowed_ground_is_a_fill_of_its_own() {
    let d = tempdir();
    let fills = |shadows: &str| {
        scene(d.path(), shadows);
        let (svg, _) = render(d.path(), "o.svg", &["--seams", "0"]);
        let text = String::from_utf8(svg).unwrap();
        text.match_indices("fill=\"#")
            .map(|(i, _)| text[i + 6..i + 13].to_string())
            .collect::<std::collections::BTreeSet<String>>()
    };
    let (off, on) = (fills(""), fills("shadows = true"));
    // The ground in the box's shadow is lit by the ambient light only: a colour the
    // picture without shadows does not have.
    assert!(on.len() > off.len(), "{off:?} {on:?}");
    assert!(off.is_subset(&on), "{off:?} {on:?}");
}

#[test]
fn bad_shadow_values_are_errors_with_file_and_line() {
    let d = tempdir();
    put(d.path(), "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    for (toml, line) in [
        (
            "[[mesh]]\npath = \"t.obj\"\n[[light]]\nkind = \"ambient\"\nshadows = true\n",
            5,
        ),
        (
            "[[mesh]]\npath = \"t.obj\"\n[[light]]\nkind = \"point\"\nposition = [0, 0, 3]\nshadows = \"yes\"\n",
            6,
        ),
    ] {
        put(d.path(), "bad.toml", toml);
        let run = limn(d.path(), &["render", "bad.toml", "-o", "bad.svg"]);
        assert_eq!(run.code, 1, "{}", run.stderr);
        assert!(
            run.stderr.contains(&format!("bad.toml:{line}")),
            "{}",
            run.stderr
        );
        assert!(!d.path().join("bad.svg").exists());
    }
    let run = limn(
        d.path(),
        &[
            "render",
            "t.obj",
            "-o",
            "x.png",
            "--method",
            "zbuffer",
            "--shadow-bias",
            "-1",
        ],
    );
    assert_eq!(run.code, 2, "{}", run.stderr);
}

#[test]
fn check_compares_shadows_with_the_exact_shadow_rays() {
    let d = tempdir();
    scene(d.path(), "shadows = true");
    let run = limn(d.path(), &["check", "s.toml", "--against", "raycast"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    assert_eq!(v["shadows"]["reference"], "exact shadow rays");
    assert_eq!(v["shadows"]["mismatches_outside_band"], 0);
    scene(d.path(), "");
    let run = limn(d.path(), &["check", "s.toml"]);
    let v: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    assert!(v["shadows"].is_null());
}
