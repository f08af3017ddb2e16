//! The shared data sets, read in place by the tests (never copied into the repository).

use std::path::PathBuf;

/// The directory `../shared/data/2d/<sub>` beside the crate; panics naming it if it is missing.
pub(crate) fn dir(sub: &str) -> PathBuf {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/data/2d")).join(sub);
    assert!(
        path.is_dir(),
        "missing test data directory {}",
        path.display()
    );
    path
}

/// Name and text of every file in [`dir`]`(sub)` whose name ends with `suffix`, sorted by name.
pub(crate) fn files(sub: &str, suffix: &str) -> Vec<(String, String)> {
    let dir = dir(sub);
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .filter_map(|entry| entry.ok()?.file_name().into_string().ok())
        .filter(|name| name.ends_with(suffix))
        .collect();
    names.sort();
    names
        .into_iter()
        .map(|name| {
            let path = dir.join(&name);
            let text = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
            (name, text)
        })
        .collect()
}
