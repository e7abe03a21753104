//! Writing never destroys a file: links are followed, devices and FIFOs are written
//! directly, the scene's own files and read-only files are refused, replaced files keep
//! their permissions.

mod common;

use std::path::Path;

use common::{limn, put, stray_temporaries, tempdir};

const TRIANGLE_OBJ: &str = "mtllib m.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const MTL: &str = "newmtl red\nKd 1 0 0\n";
const TRIANGLE_PLY: &str = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n\
property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n\
end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

fn is_svg(bytes: &[u8]) -> bool {
    let text = String::from_utf8_lossy(bytes);
    text.contains("<svg") && text.trim_end().ends_with("</svg>")
}

fn scene(dir: &Path) {
    put(dir, "t.obj", TRIANGLE_OBJ);
    put(dir, "m.mtl", MTL);
}

#[cfg(unix)]
#[test]
fn a_symbolic_link_is_written_through_and_stays_a_link() {
    let dir = tempdir();
    scene(dir.path());
    std::fs::create_dir(dir.path().join("pictures")).unwrap();
    put(dir.path(), "pictures/real.svg", "old");
    std::os::unix::fs::symlink("pictures/real.svg", dir.path().join("link.svg")).unwrap();
    let r = limn(dir.path(), &["render", "t.obj", "-o", "link.svg", "-q"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let meta = std::fs::symlink_metadata(dir.path().join("link.svg")).unwrap();
    assert!(meta.file_type().is_symlink(), "the link was replaced");
    assert!(is_svg(
        &std::fs::read(dir.path().join("pictures/real.svg")).unwrap()
    ));
    assert!(stray_temporaries(&dir.path().join("pictures")).is_empty());
    assert!(stray_temporaries(dir.path()).is_empty());
}

#[cfg(unix)]
#[test]
fn a_dangling_link_creates_its_target() {
    let dir = tempdir();
    scene(dir.path());
    std::os::unix::fs::symlink("new.svg", dir.path().join("link.svg")).unwrap();
    let r = limn(dir.path(), &["render", "t.obj", "-o", "link.svg", "-q"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(std::fs::symlink_metadata(dir.path().join("link.svg"))
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(is_svg(&std::fs::read(dir.path().join("new.svg")).unwrap()));
}

#[cfg(unix)]
#[test]
fn dev_null_stays_a_device() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempdir();
    scene(dir.path());
    let r = limn(dir.path(), &["render", "t.obj", "-o", "/dev/null", "-q"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let meta = std::fs::metadata("/dev/null").unwrap();
    assert!(meta.file_type().is_char_device(), "/dev/null was replaced");
    assert!(stray_temporaries(Path::new("/dev")).is_empty());
}

#[cfg(unix)]
#[test]
fn a_fifo_reader_gets_the_picture() {
    let dir = tempdir();
    scene(dir.path());
    let fifo = dir.path().join("pipe.svg");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo");
    assert!(made.success());
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).unwrap())
    };
    let r = limn(dir.path(), &["render", "t.obj", "-o", "pipe.svg", "-q"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let got = reader.join().unwrap();
    assert!(is_svg(&got), "the reader got {} bytes", got.len());
    use std::os::unix::fs::FileTypeExt;
    assert!(std::fs::symlink_metadata(&fifo)
        .unwrap()
        .file_type()
        .is_fifo());
}

#[test]
fn the_input_itself_is_refused() {
    let dir = tempdir();
    put(dir.path(), "c2.ply", TRIANGLE_PLY);
    let r = limn(
        dir.path(),
        &["render", "c2.ply", "-o", "c2.ply", "--format", "svg"],
    );
    assert_ne!(r.code, 0);
    assert!(
        r.stderr.contains("refusing") && r.stderr.contains("c2.ply"),
        "{}",
        r.stderr
    );
    assert_eq!(
        std::fs::read_to_string(dir.path().join("c2.ply")).unwrap(),
        TRIANGLE_PLY
    );
    assert!(stray_temporaries(dir.path()).is_empty());
}

#[test]
fn the_material_library_is_refused() {
    let dir = tempdir();
    scene(dir.path());
    let r = limn(
        dir.path(),
        &["render", "t.obj", "-o", "m.mtl", "--format", "svg"],
    );
    assert_ne!(r.code, 0);
    assert!(r.stderr.contains("m.mtl"), "{}", r.stderr);
    assert_eq!(
        std::fs::read_to_string(dir.path().join("m.mtl")).unwrap(),
        MTL
    );
}

#[test]
fn a_scene_files_mesh_and_the_stats_file_are_protected_too() {
    let dir = tempdir();
    scene(dir.path());
    put(dir.path(), "s.toml", "[[mesh]]\npath = \"t.obj\"\n");
    let r = limn(
        dir.path(),
        &["render", "s.toml", "-o", "t.obj", "--format", "svg"],
    );
    assert_ne!(r.code, 0);
    assert!(r.stderr.contains("t.obj"), "{}", r.stderr);
    let r = limn(
        dir.path(),
        &["render", "s.toml", "-o", "x.svg", "--stats", "s.toml", "-q"],
    );
    assert_ne!(r.code, 0);
    // Refused before any work: no picture left behind either.
    assert!(!dir.path().join("x.svg").exists());
    assert_eq!(
        std::fs::read_to_string(dir.path().join("t.obj")).unwrap(),
        TRIANGLE_OBJ
    );
    assert_eq!(
        std::fs::read_to_string(dir.path().join("s.toml")).unwrap(),
        "[[mesh]]\npath = \"t.obj\"\n"
    );
}

#[cfg(unix)]
#[test]
fn a_link_to_the_input_is_refused() {
    let dir = tempdir();
    scene(dir.path());
    std::os::unix::fs::symlink("t.obj", dir.path().join("out.svg")).unwrap();
    let r = limn(dir.path(), &["render", "t.obj", "-o", "out.svg"]);
    assert_ne!(r.code, 0);
    assert_eq!(
        std::fs::read_to_string(dir.path().join("t.obj")).unwrap(),
        TRIANGLE_OBJ
    );
}

#[cfg(unix)]
#[test]
fn a_read_only_file_is_refused_and_a_writable_one_keeps_its_mode() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempdir();
    scene(dir.path());
    let ro = put(dir.path(), "ro.svg", "keep");
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o444)).unwrap();
    let r = limn(dir.path(), &["render", "t.obj", "-o", "ro.svg"]);
    assert_ne!(r.code, 0);
    assert!(r.stderr.contains("read-only"), "{}", r.stderr);
    assert_eq!(std::fs::read_to_string(&ro).unwrap(), "keep");

    let rw = put(dir.path(), "rw.svg", "old");
    std::fs::set_permissions(&rw, std::fs::Permissions::from_mode(0o600)).unwrap();
    let r = limn(dir.path(), &["render", "t.obj", "-o", "rw.svg", "-q"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(is_svg(&std::fs::read(&rw).unwrap()));
    let mode = std::fs::metadata(&rw).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600);
}
