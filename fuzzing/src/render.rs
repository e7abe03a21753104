//! A whole render through limn's front door: the input is a TOML scene file, then
//! (after the first NUL byte, if any) the bytes of the OBJ mesh `m.obj` beside it; the
//! scene's own `[output]` settings choose format, style and the rest. `limn::render`
//! either writes a complete, non-empty picture or returns a typed error with a message
//! and leaves no file behind; it never panics.

use limn::{Input, RenderOptions, Request, Silent};

/// Most fragments a case may make: fuzzing looks for wrong answers, not slow ones.
const MAX_FRAGMENTS: usize = 20_000;

/// Renders the scene of `data` to a fresh folder and checks what was left there.
pub fn run(data: &[u8]) {
    let (head, tail) = crate::split_nul(data);
    // A failure to make the folder is the machine's, not limn's: skip the case.
    let Ok(dir) = tempfile::tempdir() else {
        return;
    };
    let scene = dir.path().join("s.toml");
    if std::fs::write(&scene, head).is_err() {
        return;
    }
    if let Some(tail) = tail {
        if std::fs::write(dir.path().join("m.obj"), tail).is_err() {
            return;
        }
    }
    let mut options = RenderOptions::default();
    options.view.max_fragments = Some(MAX_FRAGMENTS);
    options.view.size = Some((64, 48));
    let req = Request {
        input: Input::File(scene.clone()),
        output: None,
        options,
    };
    let files = |dir: &std::path::Path| -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .map(|r| {
                r.filter_map(|e| e.ok())
                    .map(|e| e.file_name().to_string_lossy().into_owned())
                    .collect()
            })
            .unwrap_or_default();
        v.sort();
        v
    };
    let before = files(dir.path());
    match limn::render(&req, &mut Silent) {
        Ok(done) => {
            let len = std::fs::metadata(&done.output)
                .map(|m| m.len())
                .unwrap_or(0);
            assert!(len > 0, "a render reported success but wrote nothing");
            assert_eq!(
                std::fs::read(&scene).ok().as_deref(),
                Some(head),
                "the render changed its input"
            );
        }
        Err(e) => {
            assert!(!e.message().is_empty(), "an error without a message");
            assert_eq!(
                files(dir.path()),
                before,
                "a failed render left a file: {e}"
            );
        }
    }
}
