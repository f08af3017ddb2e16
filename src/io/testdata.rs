//! The shared data sets, read in place by the tests (never copied into the repository): found
//! at `$YINSET_DATA`, else at `../shared/data` beside the crate. Without them the tests that
//! need them are skipped with one notice, unless `CI` is set, where they fail. (Also compiled
//! into the integration tests through `tests/common/mod.rs`.)

use std::io::Write;
use std::path::PathBuf;
use std::sync::Once;

/// The root of the shared data: `$YINSET_DATA`, else `../shared/data` beside the crate.
pub(crate) fn root() -> PathBuf {
    match std::env::var_os("YINSET_DATA") {
        Some(dir) if !dir.is_empty() => PathBuf::from(dir),
        _ => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/data"),
    }
}

/// True if the shared data is there (its `2d` and `3d` directories). If not: outside CI, one
/// notice per test process on standard error (past the test harness's capture) and false, so
/// that the calling test returns early as skipped; with `CI` set, a panic with the same notice.
pub(crate) fn available() -> bool {
    let root = root();
    if root.join("2d").is_dir() && root.join("3d").is_dir() {
        return true;
    }
    let notice = format!(
        "the shared test data is missing: no 2d/ and 3d/ under {}. The data sets (the Yin set \
         papers' panda and Mickey, the JTS and Martinez overlay suites, GIS outlines, 3D meshes; \
         see README.md, Set-up) live in the project's shared directory, read in place from \
         ../shared/data beside the repository; set YINSET_DATA=/path/to/data to read them from \
         elsewhere.",
        root.display()
    );
    if std::env::var_os("CI").is_some_and(|v| !v.is_empty()) {
        panic!("{notice} CI is set, so missing data is a failure.");
    }
    static NOTICE: Once = Once::new();
    NOTICE.call_once(|| {
        let _ = writeln!(
            std::io::stderr(),
            "\nyinset: {notice} The tests that need it pass as skipped.\n"
        );
    });
    false
}

/// The directory `<sub>` of the shared data (such as `2d/jts`); panics naming it if it is
/// missing.
pub(crate) fn dir(sub: &str) -> PathBuf {
    let path = root().join(sub);
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
