//! No check of the suites compares a value with itself (issue 15: a counted check of the form
//! `cells_check(.., ya, ya)` passed whatever the kernel did). Scans the Rust sources of tests/,
//! proofs/ and fuzz/ for `x == x`, `x != x`, `assert_eq!(x, x)`-style macros and the oracle
//! helpers called with the same set as result and expectation, and fails naming file and line.

use std::path::{Path, PathBuf};

/// Helpers whose last two set arguments are compared (result, expectation).
const COMPARING_HELPERS: [&str; 1] = ["cells_check("];

/// Macros whose first two arguments are compared.
const COMPARING_MACROS: [&str; 4] = [
    "assert_eq!(",
    "assert_ne!(",
    "prop_assert_eq!(",
    "prop_assert_ne!(",
];

/// The top-level comma-separated arguments of the call whose `(` is at `text[open]`.
fn arguments(text: &str, open: usize) -> Vec<String> {
    let (mut depth, mut args, mut cur) = (0i32, Vec::new(), String::new());
    for c in text[open..].chars() {
        match c {
            '(' | '[' | '{' => {
                depth += 1;
                if depth == 1 {
                    continue;
                }
            }
            ')' | ']' | '}' => {
                depth -= 1;
                if depth == 0 {
                    args.push(cur.trim().to_string());
                    return args;
                }
            }
            ',' if depth == 1 => {
                args.push(cur.trim().to_string());
                cur.clear();
                continue;
            }
            _ => {}
        }
        cur.push(c);
    }
    args
}

/// The operand of a comparison next to `at`, read backwards (`back`) or forwards: the longest
/// run of identifier, field, reference and call characters with balanced brackets.
fn operand(text: &str, at: usize, back: bool) -> String {
    let is_part = |c: char| c.is_alphanumeric() || "_.&*:".contains(c);
    let chars: Vec<char> = if back {
        text[..at].trim_end().chars().rev().collect()
    } else {
        text[at..].trim_start().chars().collect()
    };
    let (mut depth, mut out) = (0i32, String::new());
    for c in chars {
        let (opening, closing) = if back { (")]", "([") } else { ("([", ")]") };
        if opening.contains(c) {
            depth += 1;
        } else if closing.contains(c) {
            if depth == 0 {
                break;
            }
            depth -= 1;
        } else if depth == 0 && !is_part(c) {
            break;
        }
        out.push(c);
    }
    // An operand bound to a neighbour by an arithmetic or bitwise operator (`m >> p & 1 == 1`)
    // is only part of the compared expression: no comparison to judge.
    let rest: String = if back {
        text[..at]
            .trim_end()
            .chars()
            .rev()
            .skip(out.chars().count())
            .collect()
    } else {
        text[at..]
            .trim_start()
            .chars()
            .skip(out.chars().count())
            .collect()
    };
    let next: String = rest.trim_start().chars().take(2).collect();
    let bound = !next.starts_with("&&")
        && !next.starts_with("||")
        && next.starts_with(|c: char| "+-*/%&|^<>".contains(c));
    if bound {
        String::new()
    } else if back {
        out.chars().rev().collect()
    } else {
        out
    }
}

/// The self-comparisons in one source text, as (line, description).
fn tautologies(text: &str) -> Vec<(usize, String)> {
    let line_of = |at: usize| text[..at].matches('\n').count() + 1;
    let mut found = Vec::new();
    for op in [" == ", " != "] {
        for (at, _) in text.match_indices(op) {
            let (l, r) = (operand(text, at, true), operand(text, at + op.len(), false));
            if !l.is_empty() && l == r {
                found.push((line_of(at), format!("`{l}{op}{r}`")));
            }
        }
    }
    for name in COMPARING_MACROS {
        for (at, _) in text.match_indices(name) {
            let args = arguments(text, at + name.len() - 1);
            if args.len() >= 2 && args[0] == args[1] {
                found.push((line_of(at), format!("{name}{}, {}, ..)", args[0], args[1])));
            }
        }
    }
    for name in COMPARING_HELPERS {
        for (at, _) in text.match_indices(name) {
            let args = arguments(text, at + name.len() - 1);
            if let [.., y, expected, _what] = &args[..] {
                if y == expected {
                    found.push((line_of(at), format!("{name}.., {y}, {expected}, ..)")));
                }
            }
        }
    }
    found
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if path.is_dir() && !path.ends_with("target") && !path.ends_with("corpus") {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn the_detector_finds_self_comparisons_and_only_those() {
    let bad = "let ok = y == y;\nassert_eq!(a.meet(&b), a.meet(&b));\n\
               laws::cells_check(t, &cx, a, &ya, &ya, \"a\")?;\nlaw(t, L, f(x) != f(x), || s)";
    let lines: Vec<usize> = tautologies(bad).into_iter().map(|(l, _)| l).collect();
    assert_eq!(lines, vec![1, 4, 2, 3]);
    let good = "let ok = y == z;\nassert_eq!(a.meet(&b), b.meet(&a));\n\
                cells_check(t, g, p, s, &y, &expected(s), what)?;\nlet e = x.a == x.b;\n\
                let bit = m >> p & 1 == 1;\nlet odd = 1 == 1 + k % 2;";
    assert_eq!(tautologies(good), vec![]);
}

#[test]
fn no_check_compares_a_value_with_itself() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in [
        "tests",
        "proofs",
        "fuzz/src",
        "fuzz/fuzz_targets",
        "benches",
    ] {
        rust_files(&root.join(dir), &mut files);
    }
    assert!(files.len() > 20, "found only {} source files", files.len());
    let me = Path::new(file!()).file_name().unwrap();
    let found: Vec<String> = files
        .iter()
        .filter(|f| f.file_name() != Some(me))
        .flat_map(|f| {
            let text = std::fs::read_to_string(f).unwrap();
            tautologies(&text)
                .into_iter()
                .map(move |(line, what)| format!("{}:{line}: {what}", f.display()))
        })
        .collect();
    assert!(found.is_empty(), "self-comparisons:\n{}", found.join("\n"));
}
