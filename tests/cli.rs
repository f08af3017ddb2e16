//! The `yinset` binary end to end: every subcommand, panda ∧ Mickey, pipelines, and malformed
//! input (each a message naming what and where, a non-zero exit status, no panic).

use assert_cmd::Command;
use predicates::prelude::*;
use predicates::str::contains;
use serde_json::Value;
use std::path::{Path, PathBuf};
use tempfile::TempDir;
use yinset::io::yin2_text::{self, Yin2Text};
use yinset::num::{Num, Rational};
use yinset::yin2::YinSet2;

/// The binary under test.
fn yinset() -> Command {
    Command::new(env!("CARGO_BIN_EXE_yinset"))
}

/// A scratch directory for one test.
fn scratch() -> TempDir {
    tempfile::tempdir().expect("a temporary directory")
}

/// Write `text` to `name` in `dir`; its path.
fn file(dir: &TempDir, name: &str, text: &str) -> PathBuf {
    let path = dir.path().join(name);
    std::fs::write(&path, text).expect("write a scratch file");
    path
}

#[path = "../src/io/testdata.rs"]
#[allow(dead_code)]
mod testdata;

/// The curve files of the shared data's `2d/<shape>` concatenated with blank lines, in `dir`.
fn shared_shape(dir: &TempDir, shape: &str) -> PathBuf {
    let src = testdata::dir(&format!("2d/{shape}"));
    let mut names: Vec<PathBuf> = std::fs::read_dir(&src)
        .unwrap_or_else(|e| panic!("missing test data {}: {e}", src.display()))
        .map(|e| e.expect("a directory entry").path())
        .collect();
    names.sort();
    let texts: Vec<String> = names
        .iter()
        .map(|p| std::fs::read_to_string(p).expect("a curve file"))
        .collect();
    file(dir, &format!("{shape}.txt"), &texts.join("\n"))
}

/// The Yin set in a yin2 text (the command's output), read by the library.
fn parse(text: &str) -> YinSet2<Rational> {
    match yin2_text::read(text).expect("yin2 output parses") {
        Yin2Text::Plane => YinSet2::full(),
        Yin2Text::Curves(curves) if curves.is_empty() => YinSet2::empty(),
        Yin2Text::Curves(curves) => YinSet2::from_curves(curves).expect("the output is a Yin set"),
    }
}

/// Run with `args` (and `stdin`), expect success; standard output.
fn ok(args: &[&str], stdin: &str) -> String {
    let out = yinset().args(args).write_stdin(stdin).assert().success();
    String::from_utf8(out.get_output().stdout.clone()).expect("UTF-8 output")
}

/// Run with `args`, expect exit status `code` and a message on stderr containing each of
/// `needles`, and no panic.
fn fails(args: &[&str], stdin: &str, code: i32, needles: &[&str]) {
    let mut assert = yinset()
        .args(args)
        .write_stdin(stdin)
        .assert()
        .code(code)
        .stderr(contains("panicked").not());
    for needle in needles {
        assert = assert.stderr(contains(*needle));
    }
}

/// A path as `&str`.
fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

/// A 4×4 square with a triangular hole touching its bottom edge at (2, 0).
const FRAME: &str = "0 0\n4 0\n4 4\n0 4\n0 0\n\n2 0\n1 2\n3 2\n";
/// A bar overlapping FRAME's right side.
const BAR: &str = "3 1\n6 1\n6 3\n3 3\n";

#[test]
fn no_arguments_runs_the_demo() {
    let out = ok(&[], "");
    assert!(out.contains("check (A')' == A: true"), "{out}");
    assert_eq!(ok(&["demo"], ""), out);
}

#[test]
fn boolean_operations_agree_with_the_library() {
    let dir = scratch();
    let (a, b) = (file(&dir, "a.txt", FRAME), file(&dir, "b.yin2", BAR));
    let (ya, yb) = (parse(FRAME), parse(BAR));
    let cases = [
        ("meet", &ya & &yb),
        ("join", &ya | &yb),
        ("difference", &ya - &yb),
        ("xor", &ya ^ &yb),
    ];
    for (op, want) in cases {
        assert_eq!(parse(&ok(&[op, s(&a), s(&b)], "")), want, "{op}");
    }
    // Complement reads standard input and writes the unbounded result as yin2.
    let outside = ok(&["complement", "-"], FRAME);
    assert_eq!(parse(&outside), !&ya);
    assert_eq!(parse(&ok(&["complement", "-"], &outside)), ya);
}

#[test]
fn empty_and_whole_plane_survive_a_pipeline() {
    let dir = scratch();
    let a = file(&dir, "a.txt", FRAME);
    let empty = ok(&["difference", s(&a), s(&a)], "");
    assert!(parse(&empty).is_empty(), "{empty}");
    let full = ok(&["complement", "-"], &empty);
    assert!(parse(&full).is_full(), "{full}");
    let info: Value = serde_json::from_str(&ok(&["info", "-"], &full)).unwrap();
    assert_eq!(
        (info["set"].as_str(), info["bounded"].as_bool()),
        (Some("full"), Some(false))
    );
}

#[test]
fn panda_meet_mickey_is_exact() {
    if !testdata::available() {
        return;
    }
    let dir = scratch();
    let (panda, mickey) = (shared_shape(&dir, "panda"), shared_shape(&dir, "mickey"));
    let pm = dir.path().join("pm.txt");
    let out = ok(&["meet", s(&panda), s(&mickey), "-o", s(&pm)], "");
    assert_eq!(out, "", "the result goes to the file");
    let text = std::fs::read_to_string(&pm).unwrap();
    assert!(
        text.lines().any(|l| l.contains('/')),
        "exact rationals are written"
    );
    let read = |p: &Path| parse(&std::fs::read_to_string(p).unwrap());
    assert_eq!(read(&pm), &read(&panda) & &read(&mickey));
    // |P ∧ M| + |P ∨ M| = |P| + |M| exactly, from the areas `info` prints.
    let area = |p: &Path| {
        let info: Value = serde_json::from_str(&ok(&["info", s(p)], "")).unwrap();
        Rational::parse(info["area"]["exact"].as_str().unwrap()).unwrap()
    };
    let pj = dir.path().join("pj.txt");
    ok(&["join", s(&panda), s(&mickey), "-o", s(&pj)], "");
    assert_eq!(area(&pm) + area(&pj), area(&panda) + area(&mickey));
    let svg = dir.path().join("pm.svg");
    ok(
        &["render", s(&panda), s(&mickey), s(&pm), "-o", s(&svg)],
        "",
    );
    let svg = std::fs::read_to_string(svg).unwrap();
    assert!(svg.contains("pm.txt") && svg.contains("stroke-dasharray"));
}

#[test]
fn info_reports_topology_area_and_box() {
    let info: Value = serde_json::from_str(&ok(&["info", "-"], FRAME)).unwrap();
    assert_eq!(info["betti"]["components"], 1);
    assert_eq!(info["betti"]["holes"], serde_json::json!([1]));
    assert_eq!(info["area"]["exact"], "14");
    assert_eq!(info["area"]["float"], 14.0);
    assert_eq!(info["hasse"][1]["parent"], 0);
    assert_eq!(info["hasse"][1]["orientation"], "negative");
    assert_eq!(info["bbox"]["max"][1]["exact"], "4");
    assert_eq!(
        (info["curves"].clone(), info["exact"].clone()),
        (2.into(), true.into())
    );
}

#[test]
fn locate_classifies_points_from_stdin() {
    let dir = scratch();
    let a = file(&dir, "a.txt", FRAME);
    // One output line per input line: blank and comment lines give empty lines.
    let out = ok(
        &["locate", s(&a)],
        "# x y\n1/2 1/2\n\n2 1\n2 0\n  \n9 9\n\n",
    );
    assert_eq!(out, "\ninside\n\noutside\nboundary\n\noutside\n\n");
    let points = file(&dir, "p.txt", "3.5 3.5\n");
    assert_eq!(ok(&["locate", "-", s(&points)], FRAME), "inside\n");
}

#[test]
fn render_draws_holes_dashed_and_touching_points() {
    let svg = ok(&["render", "-"], FRAME);
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert_eq!(
        svg.matches("stroke-dasharray").count(),
        1,
        "one negative curve"
    );
    assert_eq!(
        svg.matches("<circle").count(),
        1,
        "the hole touches at (2, 0)"
    );
}

#[test]
fn validate_accepts_and_explains() {
    let out = ok(&["validate", "-"], FRAME);
    assert!(
        out.contains("is a Yin set") && out.contains("b0 = 1"),
        "{out}"
    );
    let crossing = "0 0\n2 0\n2 2\n0 2\n\n1 1\n3 1\n3 3\n1 3\n";
    fails(
        &["validate", "-"],
        crossing,
        1,
        &["standard input is not a Yin set", "cross"],
    );
}

#[test]
fn convert_round_trips_through_wkt_and_geojson() {
    let dir = scratch();
    let a = file(&dir, "a.txt", FRAME);
    let wkt = ok(&["convert", s(&a), "--to", "wkt"], "");
    assert!(wkt.starts_with("MULTIPOLYGON (((0 0, 2 0, 4 0"), "{wkt}");
    let json = dir.path().join("a.geojson");
    ok(&["convert", "--from", "wkt", "-", "-o", s(&json)], &wkt);
    let back = ok(&["convert", s(&json)], "");
    assert_eq!(parse(&back), parse(FRAME));
    // Polygons in any orientation are turned exterior-ccw, holes-cw.
    let cw = "POLYGON ((0 0, 0 4, 4 4, 4 0, 0 0), (2 0, 3 2, 1 2, 2 0))";
    assert_eq!(
        parse(&ok(&["convert", "--from", "wkt", "-"], cw)),
        parse(FRAME)
    );
}

#[test]
fn float_mode_with_eps() {
    let dir = scratch();
    let (a, b) = (file(&dir, "a.txt", FRAME), file(&dir, "b.txt", BAR));
    let out = ok(
        &["meet", s(&a), s(&b), "--eps", "1e-9", "--to", "geojson"],
        "",
    );
    let json: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json["type"], "MultiPolygon");
    let info: Value = serde_json::from_str(&ok(&["info", "-", "--eps", "1e-9"], FRAME)).unwrap();
    assert_eq!(
        (info["exact"].clone(), info["area"]["float"].clone()),
        (false.into(), 14.0.into())
    );
}

#[test]
fn axioms_pass_and_report() {
    yinset()
        .args(["axioms", "4", "--seed", "5"])
        .assert()
        .success()
        .stdout(contains(
            "4 random triples × 9 laws, seed 5: 36 passed, 0 failed",
        ));
}

#[test]
fn parse_errors_give_line_and_column() {
    let dir = scratch();
    let bad = file(&dir, "bad.txt", "0 0\n1 0\n1 x\n");
    fails(
        &["info", s(&bad)],
        "",
        1,
        &["bad.txt", "line 3, column 3", "`x` is not a number"],
    );
    let wkt = file(&dir, "bad.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 0)");
    fails(&["convert", s(&wkt)], "", 1, &["bad.wkt", "line 1, column"]);
    let json = file(
        &dir,
        "bad.geojson",
        "{\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1]]]}",
    );
    fails(&["convert", s(&json)], "", 1, &["bad.geojson", "line 1"]);
    fails(
        &["locate", "-", "-"],
        "",
        2,
        &["standard input", "only once"],
    );
    let points = file(&dir, "pts.txt", "0 0\n1 2 3\n");
    fails(&["locate", s(&bad), s(&points)], "", 1, &["line 3"]);
    let set = file(&dir, "set.txt", FRAME);
    fails(
        &["locate", s(&set), s(&points)],
        "",
        1,
        &["pts.txt", "line 2, column 5"],
    );
}

#[test]
fn invalid_sets_are_explained_in_the_input_terms() {
    let wkt = "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((1 1, 3 1, 3 3, 1 3, 1 1)))";
    fails(
        &["info", "--from", "wkt", "-"],
        wkt,
        1,
        &["not a Yin set", "curve 1 is polygon 1's exterior ring"],
    );
    fails(
        &["validate", "-"],
        "0 0\n1 0\n",
        1,
        &["curve 0", "at least 3"],
    );
}

#[test]
fn unreadable_files_and_unknown_formats() {
    let dir = scratch();
    let missing = dir.path().join("missing.txt");
    fails(
        &["info", s(&missing)],
        "",
        1,
        &["cannot read", "missing.txt"],
    );
    fails(&["info", s(dir.path())], "", 2, &["--from"]);
    let dat = file(&dir, "a.dat", FRAME);
    fails(&["info", s(&dat)], "", 2, &["a.dat", "--from"]);
    assert!(ok(&["info", "--from", "yin2", s(&dat)], "").contains("\"betti\""));
    let unwritable = dir.path().join("no/such/dir/out.txt");
    fails(
        &["convert", "-", "-o", s(&unwritable)],
        FRAME,
        1,
        &["cannot write", "out.txt"],
    );
}

#[test]
fn conflicting_or_wrong_options_are_usage_errors() {
    let dir = scratch();
    let a = file(&dir, "a.txt", FRAME);
    fails(
        &["convert", s(&a), "--to", "wkt", "-o", "x.geojson"],
        "",
        2,
        &["conflicting options"],
    );
    fails(&["convert", s(&a), "-o", "x.out"], "", 2, &["--to"]);
    fails(&["meet", "-", "-"], FRAME, 2, &["only once"]);
    fails(
        &["info", s(&a), "--eps", "0"],
        "",
        2,
        &["--eps", "greater than 0"],
    );
    fails(
        &["info", s(&a), "--eps", "-1e-9"],
        "",
        2,
        &["--eps", "greater than 0"],
    );
    fails(&["info", s(&a), "--to", "wkt"], "", 2, &["--to"]);
    fails(&["axioms", "--eps", "1e-9"], "", 2, &["--eps"]);
    fails(&["meet", s(&a)], "", 2, &["<B>"]);
    fails(&["frobnicate"], "", 2, &["frobnicate"]);
}

#[test]
fn unbounded_sets_are_not_written_as_polygons() {
    fails(
        &["complement", "-", "--to", "wkt"],
        FRAME,
        1,
        &["unbounded", "--to yin2"],
    );
    fails(
        &["complement", "-", "-o", "out.geojson"],
        FRAME,
        1,
        &["unbounded", "GeoJSON"],
    );
}

#[test]
fn fill_rules_take_polygon_soup() {
    let overlap = "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((1 1, 3 1, 3 3, 1 3, 1 1)))";
    fails(
        &["info", "--from", "wkt", "-"],
        overlap,
        1,
        &["not a Yin set", "--fill nonzero"],
    );
    let info = |args: &[&str], input: &str| -> Value {
        serde_json::from_str(&ok(args, input)).expect("JSON")
    };
    let union = info(
        &["info", "--from", "wkt", "--fill", "nonzero", "-"],
        overlap,
    );
    assert_eq!(union["area"]["exact"], "7");
    let xor = info(
        &["info", "--from", "wkt", "--fill", "evenodd", "-"],
        overlap,
    );
    assert_eq!(xor["area"]["exact"], "6");
    assert_eq!(xor["betti"]["components"], 2);
    // A self-intersecting ring, in WKT and as a yin2 curve: a bow-tie of two triangles.
    let bow = "POLYGON ((0 0, 2 2, 2 0, 0 2, 0 0))";
    let wkt = info(&["info", "--from", "wkt", "--fill", "nonzero", "-"], bow);
    let yin2 = info(&["info", "--fill", "nonzero", "-"], "0 0\n2 2\n2 0\n0 2\n");
    for y in [wkt, yin2] {
        assert_eq!(
            (y["area"]["exact"].clone(), y["betti"]["components"].clone()),
            ("2".into(), 2.into())
        );
    }
    // Filled sets go on through the other subcommands.
    let out = ok(
        &[
            "convert", "--from", "wkt", "--fill", "nonzero", "-", "--to", "wkt",
        ],
        overlap,
    );
    assert!(
        out.starts_with("MULTIPOLYGON (((0 0, 2 0, 2 1, 3 1, 3 3, 1 3, 1 2, 0 2, 0 0)))"),
        "{out}"
    );
}

#[test]
fn large_inputs_keep_pipes_clean() {
    // A zigzag-bottomed strip of 10 005 vertices: past the spinner's threshold, but standard
    // error is not a terminal here, so nothing is drawn.
    let n = 10_002;
    let mut text: String = (0..=n).map(|i| format!("{i} {}\n", i % 2)).collect();
    text.push_str(&format!("{n} 10\n0 10\n"));
    let out = yinset()
        .args(["info", "-"])
        .write_stdin(text)
        .assert()
        .success()
        .stderr("");
    let info: Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
    assert_eq!(info["vertices"], 10_005);
}

#[test]
fn byte_order_marks_are_accepted_in_all_three_formats() {
    let dir = scratch();
    let inputs = [
        ("a.txt", "0 0\n4 0\n0 4\n"),
        ("a.wkt", "POLYGON ((0 0, 4 0, 0 4, 0 0))"),
        (
            "a.geojson",
            r#"{"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [0, 4], [0, 0]]]}"#,
        ),
    ];
    for (name, text) in inputs {
        let path = file(&dir, name, &format!("\u{feff}{text}"));
        let info: Value = serde_json::from_str(&ok(&["info", s(&path)], "")).unwrap();
        assert_eq!(info["area"]["exact"], "8", "{name}: {info}");
    }
}

#[test]
fn long_numbers_and_large_inputs_are_refused_up_front() {
    let dir = scratch();
    let long = format!("0 0\n1 0\n0 0.{}\n", "3".repeat(20_000));
    fails(
        &["info", "-"],
        &long,
        1,
        &[
            "standard input: line 3, column 5",
            "20000 digits in a row, more than the limit of 10000 (--max-digits)",
        ],
    );
    let info: Value =
        serde_json::from_str(&ok(&["info", "-", "--max-digits", "20000"], &long)).expect("JSON");
    assert_eq!(info["curves"], 1);
    let points = file(&dir, "p.txt", &format!("1 {}\n", "1".repeat(50)));
    fails(
        &["locate", "-", s(&points), "--max-digits", "49"],
        FRAME,
        1,
        &["line 1, column 3", "50 digits"],
    );
    // A file is refused by its length, before it is read; /dev/zero after the limit.
    let a = file(&dir, "a.txt", FRAME);
    fails(
        &["info", s(&a), "--max-bytes", "10"],
        "",
        1,
        &[
            "`",
            "a.txt` is larger than 10 bytes, the limit of --max-bytes",
        ],
    );
    fails(
        &["locate", s(&a), "/dev/zero", "--max-bytes", "1000000"],
        "",
        1,
        &["`/dev/zero` is larger than 1000000 bytes"],
    );
}

#[test]
fn the_whole_plane_is_a_statement_and_curves_may_not_follow_it() {
    let full = ok(&["complement", "-"], "");
    assert!(full.starts_with("plane\n"), "{full}");
    assert!(parse(&full).is_full());
    fails(
        &["info", "-"],
        &format!("{full}\n{FRAME}"),
        1,
        &[
            "line 4, column 1",
            "(`plane` on line 1) is followed by curves",
        ],
    );
    // The old comment is a comment: it reads as the empty set.
    let info: Value = serde_json::from_str(&ok(
        &["info", "-"],
        "# yinset: the whole plane (no boundary curves)\n",
    ))
    .unwrap();
    assert_eq!(info["set"], "empty");
}

#[test]
fn polygonal_only_drops_points_and_lines() {
    let json = r#"{"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"name": "a well"}, "geometry": {"type": "Point", "coordinates": [1, 1]}},
        {"type": "Feature", "properties": null, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [0, 4], [0, 0]]]}}]}"#;
    fails(
        &["info", "--from", "geojson", "-"],
        json,
        1,
        &["`Point` is not polygonal"],
    );
    let wkt =
        "GEOMETRYCOLLECTION (POINT (1 1), LINESTRING (0 0, 1 1), POLYGON ((0 0, 4 0, 0 4, 0 0)))";
    fails(
        &["info", "--from", "wkt", "-"],
        wkt,
        1,
        &["`POINT` is not polygonal"],
    );
    for (from, text) in [("geojson", json), ("wkt", wkt)] {
        let out = ok(&["info", "--from", from, "--polygonal-only", "-"], text);
        let info: Value = serde_json::from_str(&out).unwrap();
        assert_eq!(info["area"]["exact"], "8", "{from}: {info}");
    }
}

#[test]
fn render_writes_png_for_png_names_and_refuses_other_extensions() {
    let dir = scratch();
    let png = dir.path().join("frame.png");
    ok(&["render", "-", "-o", s(&png)], FRAME);
    let bytes = std::fs::read(&png).unwrap();
    assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "not a PNG");
    let image = resvg::tiny_skia::Pixmap::decode_png(&bytes).unwrap();
    // The SVG of the same picture says where the picture's coordinates are: viewBox = x,
    // -y_max, width, height, in units of the larger side of the sets' box (FRAME's: 4).
    let svg = ok(&["render", "-"], FRAME);
    let view: Vec<f64> = svg
        .split("viewBox=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .split(' ')
        .map(|t| t.parse().unwrap())
        .collect();
    assert_eq!(image.width(), 800);
    let scale = 800.0 / view[2];
    let colour = |x: f64, y: f64| {
        let (x, y) = (x / 4.0, y / 4.0);
        let (px, py) = ((x - view[0]) * scale, (-y - view[1]) * scale);
        let p = image.pixel(px as u32, py as u32).unwrap();
        (p.red(), p.green(), p.blue())
    };
    let (r, _, b) = colour(0.5, 3.5);
    assert!(b > r + 40, "inside the frame: {:?}", colour(0.5, 3.5));
    assert_eq!(colour(2.0, 1.0), (255, 255, 255), "the hole is white");
    for bad in ["frame.pdf", "frame"] {
        fails(
            &["render", "-", "-o", s(&dir.path().join(bad))],
            FRAME,
            2,
            &[
                "render cannot write",
                "use the extension .svg or .png (2D sets)",
            ],
        );
        assert!(!dir.path().join(bad).exists(), "{bad} written");
    }
}

#[test]
fn wkb_round_trips_binary_and_hex_and_is_told_apart_from_yin2() {
    let dir = scratch();
    let a = file(&dir, "a.txt", FRAME);
    let wkb = dir.path().join("a.wkb");
    ok(&["convert", s(&a), "-o", s(&wkb)], "");
    let bytes = std::fs::read(&wkb).unwrap();
    // Little-endian MultiPolygon (type 6) of one polygon.
    assert_eq!(&bytes[..9], &[1, 6, 0, 0, 0, 1, 0, 0, 0]);
    assert_eq!(parse(&ok(&["convert", s(&wkb)], "")), parse(FRAME));
    // Hex: to standard output; read back from standard input without --from, and from a
    // .wkb file holding hex digits.
    let hex = ok(&["convert", s(&a), "--to", "wkb-hex"], "");
    assert!(
        hex.starts_with("010600000001000000") && hex.ends_with('\n'),
        "{hex}"
    );
    assert_eq!(parse(&ok(&["convert", "-"], &hex)), parse(FRAME));
    let hex_file = file(&dir, "h.wkb", &hex.to_lowercase());
    assert_eq!(parse(&ok(&["convert", s(&hex_file)], "")), parse(FRAME));
    // A yin2 text of hex-looking numbers is still yin2.
    assert_eq!(
        parse(&ok(&["convert", "-"], "0 0\n10 0\n0 10\n"))
            .curves()
            .len(),
        1
    );
}

#[test]
fn malformed_wkb_is_refused_at_its_byte() {
    let dir = scratch();
    let a = file(&dir, "a.txt", FRAME);
    let hex = ok(&["convert", s(&a), "--to", "wkb-hex"], "");
    let cut = &hex.trim()[..hex.trim().len() - 6];
    fails(
        &["info", "--from", "wkb-hex", "-"],
        cut,
        1,
        // Bytes 0–17 the headers, 18 the exterior's count, 22–117 its 6 points, 118 the hole's.
        &["standard input: wkb-hex: byte 118: truncated: 4 points need at least 64 bytes, 61 remain"],
    );
    fails(
        &["info", "-"],
        "0103",
        1,
        &["byte 1: truncated: the geometry type needs 4 bytes, 1 remain"],
    );
    fails(
        &["info", "--from", "wkb-hex", "-"],
        "01 003",
        1,
        &["` ` (character 3 of the text) is not a hex digit"],
    );
    // A point is not polygonal, but is dropped with --polygonal-only.
    let point = "0101000000000000000000F03F000000000000F03F";
    fails(
        &["info", "-"],
        point,
        1,
        &["byte 1: a Point is not polygonal"],
    );
    let collection = format!("010700000002000000{point}{}", &hex.trim()[18..]);
    let info: Value =
        serde_json::from_str(&ok(&["info", "--polygonal-only", "-"], &collection)).unwrap();
    assert_eq!(info["area"]["exact"], "14", "{info}");
    // WKB holds f64s: --exact refuses 1/3 instead of rounding it.
    let third = file(&dir, "t.txt", "0 0\n1/3 0\n0 1\n");
    fails(
        &["convert", s(&third), "--to", "wkb", "--exact"],
        "",
        1,
        &[
            "cannot write the result as WKB: the coordinate 1/3 of vertex",
            "is not an f64",
        ],
    );
    let rounded = ok(&["convert", s(&third), "--to", "wkb-hex"], "");
    assert_eq!(rounded.trim().len(), 2 * (9 + 9 + 4 + 4 * 16));
}

/// Float-mode areas are the exact areas of the `f64` vertices: the square of side 2⁹⁹⁶ (about
/// 6.7·10²⁹⁹) has its exact area (beyond `f64`: `float` is null, never infinite or NaN), the
/// square of side 2⁻⁹⁹⁶ its exact area (below `f64`: `float` is 0), both labelled exact
/// because they are (both sides are grid points, so float mode keeps the corners).
#[test]
fn float_areas_are_exact_beyond_the_range_of_f64() {
    for (k, eps, float) in [(996, "1e290", Value::Null), (-996, "1e-310", 0.0.into())] {
        let side = Rational::from_float(2f64.powi(k)).unwrap();
        let square = format!("0 0\n{side} 0\n{side} {side}\n0 {side}\n");
        let info: Value = serde_json::from_str(&ok(&["info", "-", "--eps", eps], &square)).unwrap();
        assert_eq!(
            info["area"]["exact"],
            (side.clone() * side).to_string(),
            "side 2^{k}"
        );
        assert_eq!(info["area"]["float"], float, "side 2^{k}");
    }
}

/// Two 10 m squares in UTM coordinates (as the GIS cases of the JTS suites): at 4.6·10⁶ the
/// finest grid is 2⁻²⁸ (4.6·10⁶ < 2²³ = 2⁵¹ · 2⁻²⁸), so ε = 10⁻⁹ is refused.
const UTM: &str = "MULTIPOLYGON (((500000 4649776, 500010 4649776, 500010 4649786, 500000 4649786, 500000 4649776)))";
/// A square overlapping UTM's by 5 × 5.
const UTM_B: &str =
    "POLYGON ((500005 4649781, 500015 4649781, 500015 4649791, 500005 4649791, 500005 4649781))";

/// An ε too fine for the coordinates blames the tolerance, not the input, names the finest that
/// works and offers `--eps auto`; auto then works, and its ε is the documented default:
/// 10⁻¹⁰ × the side 10, raised to the finest grid 2⁻²⁸ ≈ 3.7·10⁻⁹ (so 1.9·10⁻⁹ off an edge is
/// on the boundary, 9.3·10⁻⁹ off is not).
#[test]
fn eps_auto_takes_the_default_tolerance_where_a_given_one_is_too_fine() {
    let dir = scratch();
    let (a, b) = (file(&dir, "a.wkt", UTM), file(&dir, "b.wkt", UTM_B));
    let refused = yinset()
        .args(["meet", s(&a), s(&b), "--eps", "1e-9"])
        .assert()
        .code(1);
    let message = String::from_utf8(refused.get_output().stderr.clone()).unwrap();
    for needle in [
        "a.wkt` cannot be read with this tolerance",
        "tolerance 1e-9 is too fine",
        "3.725290298461914e-9",
        "--eps auto",
    ] {
        assert!(message.contains(needle), "{needle}: {message}");
    }
    assert!(!message.contains("not a Yin set"), "{message}");
    let meet = ok(&["meet", s(&a), s(&b), "--eps", "auto", "--to", "wkt"], "");
    let info: Value =
        serde_json::from_str(&ok(&["info", "-", "--from", "wkt", "--eps", "auto"], &meet)).unwrap();
    assert_eq!(info["exact"], false);
    assert_eq!(info["area"]["float"], 25.0);
    let points = "500005 4649776.000000002\n500005 4649776.00000001\n";
    assert_eq!(
        ok(&["locate", s(&a), "-", "--eps", "auto"], points),
        "boundary\ninside\n"
    );
    assert_eq!(ok(&["locate", s(&a), "-"], points), "inside\ninside\n");
    fails(
        &["info", s(&a), "--eps", "Auto"],
        "",
        2,
        &["not a number or auto"],
    );
}

/// Vertices that differ in the input but are one `f64` are said to coincide once rounded, not
/// merely called a repeated vertex; a vertex repeated in the input gets no such note.
#[test]
fn vertices_merged_by_rounding_to_f64_are_named_as_such() {
    let note = "differ in the input but coincide once rounded to the nearest f64s";
    let merged =
        "POLYGON ((0 0, 1 0, 1 1, 1.00000000000000000001 1.00000000000000000001, 0 1, 0 0))";
    fails(
        &["info", "-", "--from", "wkt", "--eps", "1e-9"],
        merged,
        1,
        &[
            "curve 0, vertex 3: repeats the previous vertex (1, 1)",
            note,
        ],
    );
    // Exactly, the same text is a Yin set (a pentagon with a vertex 10⁻²⁰ off (1, 1) on the
    // diagonal).
    let info: Value = serde_json::from_str(&ok(&["info", "-", "--from", "wkt"], merged)).unwrap();
    assert_eq!(info["vertices"], 5);
    let repeated = "POLYGON ((0 0, 1 0, 1 1, 1 1, 0 1, 0 0))";
    yinset()
        .args(["info", "-", "--from", "wkt", "--eps", "1e-9"])
        .write_stdin(repeated)
        .assert()
        .code(1)
        .stderr(contains("repeats the previous vertex").and(contains(note).not()));
    // A yin2 triangle whose last vertex rounds to its first: two vertices are left.
    fails(
        &["info", "-", "--eps", "1e-9"],
        "1 1\n2 1\n1.00000000000000000001 1.00000000000000000001\n",
        1,
        &["curve 0: 2 vertices", note],
    );
}

/// The PNG of `render` says what the SVG says: each label's line, right of its swatch, and the
/// key's line have dark pixels (the words, in a bitmap font), the margin left of the swatches
/// none. Two squares in [0, 10]²: 800 pixels over the window's 11 units, the legend's unit is
/// 10 / 400, so 800 / 11 · 0.025 pixels per legend unit.
#[test]
fn the_png_legend_names_the_layers() {
    let dir = scratch();
    let a = file(&dir, "first.txt", "0 0\n10 0\n10 10\n0 10\n");
    let b = file(&dir, "second.txt", "2 2\n8 2\n8 8\n2 8\n");
    let png = dir.path().join("x.png");
    ok(&["render", s(&a), s(&b), "-o", s(&png)], "");
    let bytes = std::fs::read(&png).unwrap();
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .expect("a valid PNG");
    let mut buf = vec![0; reader.output_buffer_size().expect("a buffer size")];
    let info = reader.next_frame(&mut buf).expect("a PNG frame");
    assert_eq!((info.color_type, info.width), (png::ColorType::Rgba, 800));
    let scale = 800.0 / 11.0 * 0.025;
    let dark = |x: [f64; 2], y: [f64; 2]| {
        let px = |v: f64| (v * scale) as usize;
        let mut n = 0;
        for j in px(y[0])..px(y[1]) {
            for i in px(x[0])..px(x[1]) {
                let p = &buf[4 * (j * info.width as usize + i)..][..3];
                n += usize::from(p.iter().all(|&c| c < 128));
            }
        }
        n
    };
    // Label k on the baseline 21 + 18k from x = 28, glyphs 8.4 high and 6 wide.
    for k in 0..2 {
        let y = 21.0 + 18.0 * k as f64;
        let n = dark([28.0, 28.0 + 6.0 * 10.0], [y - 8.4, y]);
        assert!(n > 40, "label {k}: {n} dark pixels");
    }
    // The key to the line styles: 80 characters of 5 units on the baseline 60.
    assert!(dark([10.0, 410.0], [53.0, 60.0]) > 200);
    assert_eq!(dark([0.0, 9.0], [0.0, 60.0]), 0);
}

/// FRAME (the square [0, 4]² with a triangular hole touching its bottom) with each coordinate
/// c written `lo + c·scale` exactly, as decimals.
fn frame_at(lo: &str, scale: &str) -> String {
    let q = |t: &str| Rational::parse(t).unwrap();
    let (lo, scale) = (q(lo), q(scale));
    FRAME
        .lines()
        .map(|line| {
            let words: Vec<String> = line
                .split_whitespace()
                .map(|c| (lo.clone() + q(c) * scale.clone()).to_string())
                .collect();
            words.join(" ") + "\n"
        })
        .collect()
}

#[test]
fn pictures_of_sets_beyond_f64_are_those_of_the_same_sets_at_unit_scale() {
    let dir = scratch();
    let mut pictures = Vec::new();
    let ten400 = format!("1{}", "0".repeat(400));
    let tenth400 = format!("1/{ten400}");
    for (name, lo, scale) in [
        ("unit", "0", "1"),
        ("big", "0", ten400.as_str()),
        ("tiny", "0", tenth400.as_str()),
        ("far", ten400.as_str(), "1"),
    ] {
        let sub = dir.path().join(name);
        std::fs::create_dir(&sub).unwrap();
        let set = sub.join("frame.txt");
        std::fs::write(&set, frame_at(lo, scale)).unwrap();
        let (svg, png) = (sub.join("frame.svg"), sub.join("frame.png"));
        ok(&["render", s(&set), "-o", s(&svg)], "");
        ok(&["render", s(&set), "-o", s(&png)], "");
        let text = std::fs::read_to_string(&svg).unwrap();
        assert!(
            !text.contains("inf") && !text.contains("NaN"),
            "{name}: {text}"
        );
        pictures.push((name, text, std::fs::read(&png).unwrap()));
    }
    let (_, unit_svg, unit_png) = &pictures[0];
    assert_eq!(unit_svg.matches("<circle").count(), 1, "{unit_svg}");
    for (name, svg, png) in &pictures[1..] {
        assert_eq!(svg, unit_svg, "{name}");
        assert!(png == unit_png, "{name}: another PNG");
    }
}

#[test]
fn writers_refuse_sets_their_f64s_cannot_hold_naming_the_vertex() {
    let dir = scratch();
    let tiny = file(&dir, "tiny.txt", "0 0\n1e-400 0\n1e-400 1e-400\n0 1e-400\n");
    for (to, format) in [("wkt", "WKT"), ("geojson", "GeoJSON"), ("wkb-hex", "WKB")] {
        fails(
            &["convert", s(&tiny), "--to", to],
            "",
            1,
            &[
                &format!("cannot write the result as {format}: rounded to the nearest f64s"),
                "curve 0, vertex 1: repeats the previous vertex (0, 0)",
                "vertex 1 of polygon 0's exterior ring is (1/1",
                "--exact",
            ],
        );
    }
    // Written exactly instead, it reads back as itself.
    let exact = ok(&["convert", s(&tiny), "--to", "wkt", "--exact"], "");
    let back = ok(&["convert", "--from", "wkt", "-"], &exact);
    assert_eq!(
        parse(&back),
        parse(&std::fs::read_to_string(&tiny).unwrap())
    );
    // Beyond the range of f64: the coordinate and its vertex.
    let huge = file(&dir, "huge.txt", "0 0\n1e400 0\n0 1\n");
    fails(
        &["convert", s(&huge), "--to", "geojson"],
        "",
        1,
        &[
            "of vertex 1 (1",
            "of polygon 0's exterior ring is beyond the range of f64",
        ],
    );
    // A coordinate whose nearest f64 is another nonzero value is written as that f64.
    let third = file(&dir, "third.txt", "0 0\n1/3 0\n0 1/3\n");
    assert_eq!(
        ok(&["convert", s(&third), "--to", "wkt"], ""),
        "MULTIPOLYGON (((0 0, 0.3333333333333333 0, 0 0.3333333333333333, 0 0)))\n"
    );
}

#[test]
fn ogc_rings_must_be_closed_in_wkt_geojson_and_wkb() {
    fails(
        &["info", "--from", "wkt", "-"],
        "POLYGON ((0 0, 4 0, 0 4))",
        1,
        &[
            "line 1, column 10",
            "a ring of 3 points is not closed: its last point is not its first",
        ],
    );
    fails(
        &["info", "--from", "geojson", "-"],
        r#"{"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [0, 4]]]}"#,
        1,
        &["`coordinates[0]`: a ring of 3 points is not closed"],
    );
    // The same ring as WKB hex (little-endian Polygon of one ring of 3 points).
    let hex = "01030000000100000003000000000000000000000000000000000000000000000000001040000000000000000000000000000000000000000000001040";
    fails(
        &["info", "--from", "wkb-hex", "-"],
        hex,
        1,
        &["byte 9: a ring of 3 points is not closed"],
    );
}

#[test]
fn binary_wkb_on_standard_input_without_from_gets_a_hint() {
    let dir = scratch();
    let a = file(&dir, "a.txt", FRAME);
    let wkb = dir.path().join("a.wkb");
    ok(&["convert", s(&a), "-o", s(&wkb)], "");
    let bytes = std::fs::read(&wkb).unwrap();
    yinset()
        .args(["info", "-"])
        .write_stdin(bytes.clone())
        .assert()
        .code(1)
        .stderr(contains("standard input").and(contains("looks like binary WKB: give --from wkb")));
    let info: Value = serde_json::from_str(
        &String::from_utf8(
            yinset()
                .args(["info", "--from", "wkb", "-"])
                .write_stdin(bytes)
                .assert()
                .success()
                .get_output()
                .stdout
                .clone(),
        )
        .unwrap(),
    )
    .unwrap();
    assert_eq!(info["area"]["exact"], "14", "{info}");
}
