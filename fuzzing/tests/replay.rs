//! Replays the committed corpus (`fuzz/corpus/<target>/`) of every target through its
//! `run` function, without libFuzzer: a panic is a regression. A target whose corpus
//! folder is missing or empty fails the test.

use std::path::Path;

use limn_fuzzing::TARGETS;

#[test]
fn every_corpus_file_of_every_target_runs() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/corpus");
    for (name, run) in TARGETS {
        let dir = root.join(name);
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("corpus folder {} is missing: {e}", dir.display()))
            .map(|e| e.expect("corpus entry").path())
            .filter(|p| p.is_file())
            .collect();
        files.sort();
        assert!(
            !files.is_empty(),
            "corpus folder {} is empty",
            dir.display()
        );
        for file in files {
            let data = std::fs::read(&file).expect("corpus file reads");
            eprintln!("{name}: {}", file.display());
            run(&data);
        }
    }
}
