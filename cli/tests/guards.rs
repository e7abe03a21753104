//! `--max-fragments`: runaway splitting stops with an error naming the flag, and no
//! output file; `--stats` says how close a run came.

mod common;

use common::{limn, put, stray_temporaries, tempdir};

/// `n` large triangles in a unit cube from a fixed linear congruential sequence.
fn dense_soup(n: usize) -> String {
    let mut x: u64 = 12345;
    let mut next = move || {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut s = String::new();
    for i in 0..n {
        for _ in 0..3 {
            s += &format!("v {} {} {}\n", next(), next(), next());
        }
        s += &format!("f {} {} {}\n", 3 * i + 1, 3 * i + 2, 3 * i + 3);
    }
    s
}

#[test]
fn runaway_splitting_stops_with_the_flag_named_and_no_output() {
    let dir = tempdir();
    put(dir.path(), "soup.obj", dense_soup(300));
    let r = limn(
        dir.path(),
        &[
            "render",
            "soup.obj",
            "-o",
            "soup.svg",
            "--max-fragments",
            "2000",
        ],
    );
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("--max-fragments") && r.stderr.contains("more than 2000 fragments"),
        "{}",
        r.stderr
    );
    assert!(!dir.path().join("soup.svg").exists());
    assert!(stray_temporaries(dir.path()).is_empty());

    let r = limn(
        dir.path(),
        &[
            "render", "soup.obj", "-o", "soup.svg", "--stats", "s.json", "-q",
        ],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("s.json")).unwrap()).unwrap();
    let made = s["fragments_made"].as_u64().unwrap();
    assert!(made > 2000, "{s}");
    assert_eq!(s["fragment_limit"], 300 * 50 + 200_000);
}
