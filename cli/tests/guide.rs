//! The examples of README.md and of the user guide (`docs/*.md`) run as written.
//!
//! Each page is worked through in a fresh temporary folder holding a copy of the
//! repository's `docs/` folder, in the page's order:
//!
//! * a fenced block whose info string names a file (```` ```toml file=scene.toml ````) is
//!   written there under that name; a TOML one is a scene file and is also rendered;
//! * in a ```` ```sh ```` block, every line that calls `limn` (or `cargo run --release --`,
//!   the same command built from the clone) is run with the folder as the current
//!   folder and must succeed; other lines (`cargo test`, `pip`, …) are left to the
//!   suites that own them.
//!
//! Blocks of other kinds (```` ```text ````, ```` ```toml ```` without a file name,
//! ```` ```python ````, ```` ```rust ````) are not run here: the Python examples belong to
//! the Python suite, the Rust one to `tests/tests/readme_example.rs`. The relative links
//! of the pages must lead to files that exist, and a link's `#anchor` into a Markdown
//! file to one of its headings.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The repository's root folder.
fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("cli/ has a parent folder")
        .to_path_buf()
}

/// README.md and every `docs/*.md`, in name order.
fn pages() -> Vec<PathBuf> {
    let mut docs: Vec<PathBuf> = std::fs::read_dir(repo().join("docs"))
        .expect("docs/ is readable")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    let mut all = vec![repo().join("README.md")];
    all.extend(docs);
    all
}

/// A fenced code block: its info string, its text and the line of its opening fence.
struct Block {
    info: String,
    body: String,
    line: usize,
}

/// The fenced blocks of a Markdown text (fences of three backticks at the start of a
/// line).
fn blocks(text: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut open: Option<Block> = None;
    for (i, line) in text.lines().enumerate() {
        if let Some(b) = open.as_mut() {
            if line.trim_end() == "```" {
                out.push(open.take().unwrap());
            } else {
                b.body.push_str(line);
                b.body.push('\n');
            }
        } else if let Some(info) = line.strip_prefix("```") {
            open = Some(Block {
                info: info.trim().to_string(),
                body: String::new(),
                line: i + 1,
            });
        }
    }
    assert!(open.is_none(), "a fenced block is not closed");
    out
}

/// The language of a block and the file it names (`file=NAME`), if any.
fn kind(info: &str) -> (&str, Option<&str>) {
    let mut parts = info.split_whitespace();
    let lang = parts.next().unwrap_or("");
    let file = parts.find_map(|p| p.strip_prefix("file="));
    (lang, file)
}

/// A command line split into words as a POSIX shell splits it: blanks separate words,
/// single and double quotes group, a backslash escapes the next character, and a `#`
/// starting a word begins a comment. Anything a plain command does not need (pipes,
/// redirections, variables) is refused, so the guide keeps to what runs here.
fn words(line: &str) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    let mut word: Option<String> = None;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            ' ' | '\t' => {
                out.extend(word.take());
            }
            '#' if word.is_none() => break,
            '\'' => {
                let w = word.get_or_insert_with(String::new);
                loop {
                    match chars.next() {
                        Some('\'') => break,
                        Some(ch) => w.push(ch),
                        None => return Err("unclosed single quote".into()),
                    }
                }
            }
            '"' => {
                let w = word.get_or_insert_with(String::new);
                loop {
                    match chars.next() {
                        Some('"') => break,
                        Some('\\') => w.extend(chars.next()),
                        Some('$' | '`') => return Err("expansion inside quotes".into()),
                        Some(ch) => w.push(ch),
                        None => return Err("unclosed double quote".into()),
                    }
                }
            }
            '\\' => word.get_or_insert_with(String::new).extend(chars.next()),
            '|' | '&' | ';' | '<' | '>' | '$' | '`' | '(' | ')' | '*' | '?' => {
                return Err(format!("`{c}` needs a shell"));
            }
            _ => word.get_or_insert_with(String::new).push(c),
        }
    }
    out.extend(word);
    Ok(out)
}

/// The `limn` arguments of a command line of an `sh` block, or `None` for a line that
/// is not a `limn` command.
fn limn_args(line: &str) -> Result<Option<Vec<String>>, String> {
    let w = words(line)?;
    let rest = match w.first().map(String::as_str) {
        Some("limn") => &w[1..],
        Some("cargo") if w.len() >= 4 && w[1] == "run" && w[2] == "--release" && w[3] == "--" => {
            &w[4..]
        }
        _ => return Ok(None),
    };
    Ok(Some(rest.to_vec()))
}

/// Copies the folder `from` into `to`, recursively.
fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let e = e.unwrap();
        let target = to.join(e.file_name());
        if e.file_type().unwrap().is_dir() {
            copy_dir(&e.path(), &target);
        } else {
            std::fs::copy(e.path(), target).unwrap();
        }
    }
}

/// Runs `limn ARGS` in `dir`; an error message when it does not succeed.
fn run(dir: &Path, args: &[String]) -> Result<(), String> {
    let out = Command::new(env!("CARGO_BIN_EXE_limn"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .map_err(|e| format!("cannot run limn: {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        // `limn check` says on standard output where pixels disagree.
        Err(format!(
            "exit status {:?}: {}\n{}",
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).trim(),
            String::from_utf8_lossy(&out.stdout).trim()
        ))
    }
}

/// What running the examples of the pages did.
#[derive(Default)]
struct Tally {
    commands: usize,
    scene_files: usize,
    files_written: usize,
    failures: Vec<String>,
}

/// Works through one page in a fresh folder.
fn run_page(page: &Path, tally: &mut Tally) {
    let name = page.strip_prefix(repo()).unwrap().display().to_string();
    let text = std::fs::read_to_string(page).unwrap();
    let dir = tempfile::tempdir().expect("a temporary folder");
    copy_dir(&repo().join("docs"), &dir.path().join("docs"));
    for b in blocks(&text) {
        let (lang, file) = kind(&b.info);
        if let Some(file) = file {
            assert!(
                !file.contains('/') && !file.contains(".."),
                "{name}:{}: a file block names a file of the folder itself",
                b.line
            );
            std::fs::write(dir.path().join(file), &b.body).unwrap();
            tally.files_written += 1;
            if lang == "toml" {
                let stem = file.trim_end_matches(".toml");
                let args: Vec<String> = ["render", file, "-o", &format!("{stem}-as-given.svg")]
                    .iter()
                    .map(|s| s.to_string())
                    .chain(["--quiet".to_string()])
                    .collect();
                tally.scene_files += 1;
                if let Err(e) = run(dir.path(), &args) {
                    tally
                        .failures
                        .push(format!("{name}:{}: scene file {file}: {e}", b.line));
                }
            }
        }
        if lang != "sh" {
            continue;
        }
        for (k, line) in b.body.lines().enumerate() {
            let at = b.line + 1 + k;
            match limn_args(line) {
                Err(e) => tally.failures.push(format!("{name}:{at}: {e}: {line}")),
                Ok(None) => {}
                Ok(Some(args)) => {
                    tally.commands += 1;
                    if let Err(e) = run(dir.path(), &args) {
                        tally.failures.push(format!("{name}:{at}: `{line}`: {e}"));
                    }
                }
            }
        }
    }
}

#[test]
fn every_command_of_the_readme_and_the_guide_runs() {
    let mut tally = Tally::default();
    let pages = pages();
    for page in &pages {
        run_page(page, &mut tally);
    }
    println!(
        "guide: {} commands run, {} scene files rendered, {} files written, from {} pages",
        tally.commands,
        tally.scene_files,
        tally.files_written,
        pages.len()
    );
    assert!(
        tally.failures.is_empty(),
        "examples that failed:\n{}",
        tally.failures.join("\n")
    );
    // A change in how blocks are marked must not make the examples silently vanish.
    assert!(
        tally.commands >= 50,
        "only {} commands found",
        tally.commands
    );
    assert!(
        tally.scene_files >= 3,
        "only {} scene files",
        tally.scene_files
    );
}

/// The test command README.md gives newcomers is the one continuous integration runs.
#[test]
fn the_readme_test_command_is_the_one_ci_runs() {
    let readme = std::fs::read_to_string(repo().join("README.md")).unwrap();
    let quick: Vec<String> = blocks(&readme)
        .into_iter()
        .filter(|b| kind(&b.info).0 == "sh")
        .flat_map(|b| b.body.lines().map(str::to_string).collect::<Vec<_>>())
        .collect();
    assert!(quick
        .iter()
        .any(|l| l.trim() == "cargo run --release -- demo"));
    assert!(quick.iter().any(|l| l.trim() == "cargo test --workspace"));
    let ci = std::fs::read_to_string(repo().join(".ci/run")).unwrap();
    assert!(
        ci.lines().any(|l| l.trim() == "cargo test --workspace"),
        ".ci/run no longer runs `cargo test --workspace`: update README.md with it"
    );
}

/// GitHub's anchor of a heading: lower case, punctuation dropped, blanks as hyphens.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || *c == ' ' || *c == '-' || *c == '_')
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a Markdown file's headings (outside fenced blocks).
fn anchors(text: &str) -> Vec<String> {
    let mut fenced = false;
    let mut out = Vec::new();
    for line in text.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
        } else if !fenced && line.starts_with('#') {
            out.push(slug(line.trim_start_matches('#')));
        }
    }
    out
}

/// The targets of the inline links `[text](target)` of a Markdown text, outside fenced
/// blocks.
fn links(text: &str) -> Vec<String> {
    let mut fenced = false;
    let mut out = Vec::new();
    for line in text.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        let mut rest = line;
        while let Some(i) = rest.find("](") {
            let after = &rest[i + 2..];
            let Some(j) = after.find(')') else { break };
            out.push(after[..j].to_string());
            rest = &after[j..];
        }
    }
    out
}

#[test]
fn the_links_of_the_readme_and_the_guide_lead_somewhere() {
    let mut broken = Vec::new();
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        let folder = page.parent().unwrap();
        for target in links(&text) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let (file, anchor) = match target.split_once('#') {
                Some((f, a)) => (f, Some(a)),
                None => (target.as_str(), None),
            };
            let path = if file.is_empty() {
                page.clone()
            } else {
                folder.join(file)
            };
            let shown = format!("{}: {target}", page.display());
            if !path.exists() {
                broken.push(format!("{shown} (no such file)"));
                continue;
            }
            if let Some(a) = anchor {
                if path.extension().is_some_and(|x| x == "md") {
                    let text = std::fs::read_to_string(&path).unwrap();
                    if !anchors(&text).iter().any(|h| h == a) {
                        broken.push(format!("{shown} (no such heading)"));
                    }
                }
            }
        }
    }
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

#[test]
fn command_lines_are_split_as_a_shell_splits_them() {
    assert_eq!(
        words("limn render a.obj --background '#f0f0f0' # a comment").unwrap(),
        ["limn", "render", "a.obj", "--background", "#f0f0f0"]
    );
    assert_eq!(
        words(r#"limn render "a b.obj" -o x\ y.svg"#).unwrap(),
        ["limn", "render", "a b.obj", "-o", "x y.svg"]
    );
    assert!(words("limn render a.obj | wc").is_err());
    assert_eq!(
        limn_args("cargo run --release -- demo").unwrap(),
        Some(vec!["demo".to_string()])
    );
    assert_eq!(limn_args("cargo test --workspace").unwrap(), None);
    assert_eq!(
        slug("Seam flaps: seamless output, exact picture"),
        "seam-flaps-seamless-output-exact-picture"
    );
    assert_eq!(
        slug("Exactness and `limn check`"),
        "exactness-and-limn-check"
    );
}
