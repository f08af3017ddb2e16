//! The `yinset` binary on 3D sets (OBJ, STL, OFF, PLY files): the Boolean operations, `info`,
//! `validate`, `locate`, `convert` between the formats and `render` (PNG, HTML), pipelines
//! through standard input, 0̂ and 1̂, invalid meshes named by their lines, faces or bytes, usage
//! errors (float mode, mixed dimensions), and the shared 3D data.

use assert_cmd::Command;
use predicates::prelude::*;
use predicates::str::contains;
use serde_json::Value;
use std::path::{Path, PathBuf};
use tempfile::TempDir;
use yinset::io::obj::read_obj;
use yinset::kernel::Point3;
use yinset::num::Rational;
use yinset::yin3::{shapes, YinSet3};

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

/// A path as a command-line argument.
fn s(p: &Path) -> &str {
    p.to_str().expect("a UTF-8 path")
}

#[path = "../src/io/testdata.rs"]
#[allow(dead_code)]
mod testdata;

/// A file of the shared data's `3d` directory; panics naming it if it is missing.
fn shared(name: &str) -> PathBuf {
    let path = testdata::root().join("3d").join(name);
    assert!(path.is_file(), "test data missing: {}", path.display());
    path
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

/// The `info` JSON of `args`.
fn info(args: &[&str], stdin: &str) -> Value {
    serde_json::from_str(&ok(args, stdin)).expect("info prints JSON")
}

/// Run with `args`, expect success; standard output as bytes.
fn ok_bytes(args: &[&str]) -> Vec<u8> {
    let out = yinset().args(args).assert().success();
    out.get_output().stdout.clone()
}

/// The 3D Yin set in an OBJ text (the command's output), read by the library.
fn parse(text: &str) -> YinSet3<Rational> {
    let mesh = read_obj(text).expect("OBJ output parses");
    if mesh.faces.is_empty() {
        return if text.contains("# yinset: the whole space (no boundary)") {
            YinSet3::full()
        } else {
            YinSet3::empty()
        };
    }
    YinSet3::from_triangles(mesh.vertices, mesh.faces).expect("the output is a Yin set")
}

/// The OBJ text of the box [lo, hi] (coordinates as written), faces as quads with normals out;
/// `inward` turns them in, for a cavity.
fn cuboid(lo: [&str; 3], hi: [&str; 3], inward: bool) -> String {
    let mut text = String::new();
    for i in 0..8 {
        let c = |k: usize| if i >> k & 1 == 0 { lo[k] } else { hi[k] };
        text += &format!("v {} {} {}\n", c(0), c(1), c(2));
    }
    // The faces of the library's own box; negative indices count back from its 8 vertices.
    let (_, faces) = shapes::cuboid(&Point3::<Rational>::int(0, 0, 0), &Point3::int(1, 1, 1));
    for mut face in faces {
        if inward {
            face.reverse();
        }
        let f: Vec<String> = face.iter().map(|&v| (v as i64 - 8).to_string()).collect();
        text += &format!("f {}\n", f.join(" "));
    }
    text
}

/// The box [0, 2]³.
fn box_a() -> String {
    cuboid(["0", "0", "0"], ["2", "2", "2"], false)
}

/// The box [1, 3] × [1, 3] × [0.1, 2.1]: its meet with [`box_a`] has volume 1 · 1 · 1.9.
fn box_b() -> String {
    cuboid(["1", "1", "0.1"], ["3", "3", "2.1"], false)
}

/// The two boxes as files `a.obj` and `b.obj` in `dir`.
fn two_boxes(dir: &TempDir) -> (PathBuf, PathBuf) {
    (file(dir, "a.obj", &box_a()), file(dir, "b.obj", &box_b()))
}

#[test]
fn meet_and_join_have_exact_volumes() {
    let dir = scratch();
    let (a, b) = two_boxes(&dir);
    let meet = dir.path().join("m.obj");
    ok(&["meet", s(&a), s(&b), "-o", s(&meet)], "");
    let m = info(&["info", s(&meet)], "");
    assert_eq!(m["dimension"], 3);
    assert_eq!(m["volume"]["exact"], "19/10", "0.1 is read exactly");
    assert_eq!((m["b0"].clone(), m["b1"].clone()), (1.into(), 0.into()));
    let j = info(
        &["info", "--from", "obj", "-"],
        &ok(&["join", s(&a), s(&b)], ""),
    );
    assert_eq!(j["volume"]["exact"], "141/10");
    assert_eq!(j["volume"]["float"], 14.1);
    let d = parse(&ok(&["difference", s(&a), s(&b)], ""));
    assert_eq!(d.volume(), Some(Rational::new(61.into(), 10.into())));
    let x = parse(&ok(&["xor", s(&a), s(&b)], ""));
    assert_eq!(x.volume(), Some(Rational::new(122.into(), 10.into())));
    assert_eq!(x.betti().b0, 2);
}

#[test]
fn meet_output_reads_back_through_standard_input() {
    let dir = scratch();
    let (a, b) = two_boxes(&dir);
    let out = ok(&["meet", s(&a), s(&b)], "");
    assert!(out.starts_with("# yinset\n") && out.contains("\no surface_0_positive\n"));
    let back = info(&["info", "--from", "obj", "-"], &out);
    assert_eq!(back["volume"]["exact"], "19/10");
    // Standard input takes the format of the other operand, OBJ.
    let again = parse(&ok(&["meet", s(&a), "-"], &box_b()));
    assert_eq!(again, parse(&out));
    let summary = ok(&["validate", "--from", "obj", "-"], &out);
    assert!(
        summary.starts_with("standard input is a Yin set: 1 surfaces, b0 = 1, b1 = 0, b2 = 0"),
        "{summary}"
    );
    // Without --from, a lone standard input is yin2, and the error says what to do.
    fails(&["info", "-"], &out, 1, &["--from obj"]);
}

#[test]
fn complement_twice_is_the_identity() {
    let dir = scratch();
    let (a, _) = two_boxes(&dir);
    let outside = ok(&["complement", s(&a)], "");
    assert!(
        outside.starts_with("# yinset: the set is unbounded"),
        "{outside}"
    );
    assert!(outside.contains("o surface_0_negative"), "{outside}");
    let o = info(&["info", "--from", "obj", "-"], &outside);
    assert_eq!(
        (o["bounded"].clone(), o["volume"].clone(), o["b2"].clone()),
        (false.into(), Value::Null, 1.into())
    );
    let back = ok(&["complement", "--from", "obj", "-"], &outside);
    assert_eq!(parse(&back), parse(&box_a()));
}

#[test]
fn empty_and_whole_space_survive_a_pipeline() {
    let dir = scratch();
    let (a, _) = two_boxes(&dir);
    let empty = ok(&["difference", s(&a), s(&a)], "");
    assert_eq!(empty, "# yinset: the empty set (no boundary)\n");
    let full = ok(&["complement", "--from", "obj", "-"], &empty);
    assert_eq!(full, "# yinset: the whole space (no boundary)\n");
    let f = info(&["info", "--from", "obj", "-"], &full);
    assert_eq!(
        (f["set"].clone(), f["bounded"].clone(), f["b0"].clone()),
        ("full".into(), false.into(), 1.into())
    );
    let e = info(&["info", "--from", "obj", "-"], &empty);
    assert_eq!(
        (e["set"].clone(), e["volume"]["exact"].clone()),
        ("empty".into(), "0".into())
    );
    let full_file = file(&dir, "full.obj", &full);
    assert_eq!(
        ok(&["meet", s(&a), s(&full_file)], ""),
        ok(&["convert", s(&a)], "")
    );
}

#[test]
fn info_reports_cavities_surfaces_and_box() {
    let dir = scratch();
    let hollow = cuboid(["0", "0", "0"], ["3", "3", "3"], false)
        + &cuboid(["1", "1", "1"], ["2", "2", "2"], true);
    let h = file(&dir, "hollow.obj", &hollow);
    let r = info(&["info", s(&h)], "");
    assert_eq!(
        (r["b0"].clone(), r["b1"].clone(), r["b2"].clone()),
        (1.into(), 0.into(), 1.into())
    );
    assert_eq!(r["volume"]["exact"], "26");
    assert_eq!(r["surfaces"][0]["positive"], true);
    assert_eq!(r["surfaces"][1]["positive"], false);
    assert_eq!(r["surfaces"][1]["parent"], 0);
    assert_eq!(r["surfaces"][0]["genus"], 0);
    assert_eq!(
        r["atoms"],
        serde_json::json!([{ "outer": 0, "inner": [1] }])
    );
    assert_eq!(r["bbox"]["max"][2]["exact"], "3");
    assert_eq!(
        (r["vertices"].clone(), r["triangles"].clone()),
        (16.into(), 24.into())
    );
    let out = ok(&["validate", s(&h)], "");
    assert!(
        out.contains("`") && out.contains("hollow.obj` is a Yin set: 2 surfaces"),
        "{out}"
    );
    assert!(out.contains("b2 = 1, volume 26"), "{out}");
}

#[test]
fn locate_takes_xyz_lines() {
    let dir = scratch();
    let (a, _) = two_boxes(&dir);
    let out = ok(&["locate", s(&a)], "# x y z\n1 1 1\n2 1/2 1\n5 5 5\n");
    assert_eq!(
        out, "\ninside\nboundary\noutside\n",
        "one line per input line"
    );
    fails(&["locate", s(&a)], "1 1\n", 1, &["line 1", "3 numbers"]);
}

#[test]
fn invalid_meshes_are_explained_with_their_obj_lines() {
    let dir = scratch();
    // The box without its top face: open along four edges.
    let open: String = box_a()
        .lines()
        .filter(|l| *l != "f -4 -3 -1 -2")
        .map(|l| l.to_string() + "\n")
        .collect();
    assert_eq!(open.lines().count(), 13);
    let o = file(&dir, "open.obj", &open);
    fails(
        &["validate", s(&o)],
        "",
        1,
        &["`", "open.obj` is not a Yin set", "open", "is on line"],
    );
    fails(&["meet", s(&o), s(&o)], "", 1, &["not a Yin set"]);
    fails(
        &["info", "--from", "obj", "-"],
        "v 0 0 0\nv 1 0 0\nf 1 2 3\n",
        1,
        &["line 3", "out of range"],
    );
}

/// 3D float mode (`--eps`): 0.1 is the nearest f64, so the meet's volume is 1.9 to within
/// rounding, and the written result reads back as a valid exact set.
#[test]
fn float_mode_meets_meshes() {
    let dir = scratch();
    let (a, b) = two_boxes(&dir);
    let meet = dir.path().join("m.obj");
    ok(&["meet", s(&a), s(&b), "--eps", "1e-9", "-o", s(&meet)], "");
    let m = info(&["info", s(&meet)], "");
    let v = m["volume"]["float"].as_f64().unwrap();
    assert!((v - 1.9).abs() < 1e-12, "volume {v}");
    let f = info(&["info", s(&meet), "--eps", "1e-9"], "");
    assert_eq!(f["b0"], 1);
    let out = ok(&["validate", s(&meet)], "");
    assert!(out.contains("is a Yin set"), "{out}");
}

#[test]
fn usage_errors_of_3d_input() {
    let dir = scratch();
    let (a, b) = two_boxes(&dir);
    let t = file(&dir, "t.txt", "0 0\n1 0\n0 1\n");
    fails(
        &["join", s(&t), s(&a)],
        "",
        2,
        &["2D", "3D", "t.txt", "a.obj"],
    );
    fails(&["meet", s(&a), s(&b), "--to", "wkt"], "", 2, &["obj"]);
    fails(&["complement", s(&a), "-o", "x.txt"], "", 2, &["3D"]);
    fails(&["convert", s(&t), "--to", "obj"], "", 2, &["2D"]);
    fails(&["render", s(&a)], "", 2, &["-o FILE.png"]);
    fails(&["render", s(&a), "-o", "a.svg"], "", 2, &["PNG", "HTML"]);
    fails(&["render", s(&a), "-o", "a.gif"], "", 2, &["a.gif", ".png"]);
    fails(
        &["render", s(&a), "-o", "a.png", "--view", "1"],
        "",
        2,
        &["AZIMUTH,ELEVATION"],
    );
    fails(
        &["render", s(&a), "-o", "a.html", "--size", "99"],
        "",
        2,
        &["--size"],
    );
    let t2 = file(&dir, "t2.txt", "0 0\n1 0\n0 1\n");
    fails(
        &["render", s(&t2), "-o", "t.html"],
        "",
        2,
        &["2D sets are drawn as SVG or PNG"],
    );
    fails(&["render", s(&t2), "--view", "0,0"], "", 2, &["--view"]);
    fails(&["info", s(&a), "--fill", "nonzero"], "", 2, &["--fill"]);
}

#[test]
fn shared_ball_info() {
    if !testdata::available() {
        return;
    }
    let ball = shared("ballahead.obj");
    let r = info(&["info", s(&ball)], "");
    assert_eq!(r["dimension"], 3);
    assert_eq!(
        (r["b0"].clone(), r["b1"].clone(), r["b2"].clone()),
        (1.into(), 0.into(), 0.into())
    );
    assert_eq!(r["bounded"], true);
    assert_eq!(r["surfaces"].as_array().map(Vec::len), Some(1));
    assert_eq!(r["triangles"], 48);
    let volume = r["volume"]["float"].as_f64().expect("a bounded volume");
    assert!(volume > 0.0, "{volume}");
    assert!(
        r["volume"]["exact"]
            .as_str()
            .is_some_and(|v| v.contains('/')),
        "{r}"
    );
}

#[test]
fn shared_teddy_is_rejected_naming_crossing_faces_and_lines() {
    if !testdata::available() {
        return;
    }
    let teddy = shared("teddy.obj");
    fails(
        &["validate", s(&teddy)],
        "",
        1,
        &[
            "teddy.obj` is not a Yin set",
            "faces",
            "cross",
            "is on line",
        ],
    );
}

/// The hollow cube [0, 3]³ − [1, 2]³ as `hollow.obj` in `dir`.
fn hollow_cube(dir: &TempDir) -> PathBuf {
    let hollow = cuboid(["0", "0", "0"], ["3", "3", "3"], false)
        + &cuboid(["1", "1", "1"], ["2", "2", "2"], true);
    file(dir, "hollow.obj", &hollow)
}

#[test]
fn convert_between_all_3d_formats() {
    let dir = scratch();
    let h = hollow_cube(&dir);
    let want = parse(&ok(&["convert", s(&h)], ""));
    for (name, to) in [
        ("h.stl", None),
        ("h.off", None),
        ("h.ply", None),
        ("hb.stl", Some("stl-binary")),
        ("h.dat", Some("ply")),
    ] {
        let out = dir.path().join(name);
        let mut args = vec!["convert", s(&h), "-o", s(&out)];
        args.extend(to.iter().flat_map(|t| ["--to", *t]));
        ok(&args, "");
        // Back to OBJ by extension (or --from for the unknown extension), equal as sets.
        let from: Vec<&str> = to
            .filter(|_| name.ends_with(".dat"))
            .map_or(vec![], |t| vec!["--from", t]);
        let back = ok(&[&["convert", s(&out)][..], &from].concat(), "");
        assert_eq!(parse(&back), want, "{name}");
        let r = info(&[&["info", s(&out)][..], &from].concat(), "");
        assert_eq!(r["volume"]["exact"], "26", "{name}");
        assert_eq!(r["b2"], 1, "{name}");
    }
    let bin = std::fs::read(dir.path().join("hb.stl")).unwrap();
    assert_eq!(bin.len(), 84 + 50 * 24, "binary STL of 24 triangles");
    // Standard input in another format, and operands of different 3D formats.
    let off = std::fs::read_to_string(dir.path().join("h.off")).unwrap();
    let r = info(&["info", "--from", "off", "-"], &off);
    assert_eq!(r["volume"]["exact"], "26");
    let (a, b) = two_boxes(&dir);
    let b_ply = dir.path().join("b.ply");
    ok(&["convert", s(&b), "-o", s(&b_ply)], "");
    let m = ok(&["meet", s(&a), s(&b_ply)], "");
    assert_eq!(
        parse(&m).volume().map(|v| v.to_string()),
        Some("19/10".into())
    );
}

#[test]
fn conversions_that_cannot_be_exact_or_complete_are_refused() {
    let dir = scratch();
    let (_, b) = two_boxes(&dir);
    let out = dir.path().join("b.stl");
    fails(
        &["convert", s(&b), "-o", s(&out), "--to", "stl-binary"],
        "",
        1,
        &["binary STL holds 32-bit floats", "0.1", "write ASCII STL"],
    );
    // The whole space in a mesh format is an error of the input (1), as the whole plane in a
    // polygon format is, not of usage (2).
    let full = format!("{}\n", "# yinset: the whole space (no boundary)");
    for to in ["off", "stl", "stl-binary", "ply"] {
        fails(
            &["convert", "--from", "obj", "-", "--to", to],
            &full,
            1,
            &["whole space", "--to obj"],
        );
    }
    fails(
        &["convert", s(&b), "--to", "wkt"],
        "",
        2,
        &["obj, stl, stl-binary, off or ply"],
    );
    fails(
        &["convert", s(&b), "-o", "x.obj", "--to", "stl"],
        "",
        2,
        &["conflicting"],
    );
}

#[test]
fn malformed_mesh_files_are_named_with_line_face_or_byte() {
    let dir = scratch();
    let off = file(
        &dir,
        "bad.off",
        "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 7\n3 2 0 3\n",
    );
    fails(
        &["info", s(&off)],
        "",
        1,
        &[
            "bad.off",
            "line 9, column 7",
            "vertex index 7 is out of range",
        ],
    );
    let ply = file(
        &dir,
        "bad.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
         property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\
         0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n",
    );
    fails(
        &["validate", s(&ply)],
        "",
        1,
        &["bad.ply", "line 11, column 3", "`zero` is not a number"],
    );
    let stl = file(
        &dir,
        "bad.stl",
        "solid s\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n\
         endloop\n endfacet\nendsolid s\n",
    );
    fails(
        &["info", s(&stl)],
        "",
        1,
        &["bad.stl", "line 6", "a facet needs at least 3 vertices"],
    );
    // A binary STL cut inside its second facet.
    let h = hollow_cube(&dir);
    let bin = dir.path().join("h.stl");
    ok(&["convert", s(&h), "-o", s(&bin), "--to", "stl-binary"], "");
    let bytes = std::fs::read(&bin).unwrap();
    let cut = dir.path().join("cut.stl");
    std::fs::write(&cut, &bytes[..84 + 50 + 20]).unwrap();
    fails(
        &["info", s(&cut)],
        "",
        1,
        &[
            "cut.stl",
            "byte 154",
            "truncated binary STL",
            "24 facets",
            "inside facet 1",
        ],
    );
    // Well-formed files whose faces do not bound a Yin set: the face and its line.
    let open = file(
        &dir,
        "open.off",
        "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n",
    );
    fails(
        &["validate", s(&open)],
        "",
        1,
        &["open.off` is not a Yin set", "is on line"],
    );
}

/// The decoded `(width, height, rgb)` of PNG `bytes`.
fn decode_png(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .expect("a valid PNG");
    let mut rgb = vec![0; reader.output_buffer_size().expect("a buffer size")];
    let info = reader.next_frame(&mut rgb).expect("a PNG frame");
    assert_eq!(info.color_type, png::ColorType::Rgb);
    (info.width, info.height, rgb)
}

/// The numbers of warm (orange: a cavity) and cool (blue: an outer surface) pixels of `rgb`.
fn warm_and_cool(rgb: &[u8]) -> (usize, usize) {
    let px = || rgb.chunks(3).map(|p| (i32::from(p[0]), i32::from(p[2])));
    (
        px().filter(|(r, b)| r > &(b + 15)).count(),
        px().filter(|(r, b)| b > &(r + 15)).count(),
    )
}

#[test]
fn render_draws_cavities_in_their_own_colour() {
    let dir = scratch();
    let h = hollow_cube(&dir);
    let png = dir.path().join("h.png");
    ok(&["render", s(&h), "-o", s(&png), "--size", "120"], "");
    let (w, ht, rgb) = decode_png(&std::fs::read(&png).unwrap());
    assert_eq!((w, ht), (120, 120));
    let (warm, cool) = warm_and_cool(&rgb);
    assert!(warm > 100 && cool > 100, "warm {warm}, cool {cool}");
    // A box without a cavity has no warm pixel; from another view the picture differs.
    let (a, _) = two_boxes(&dir);
    let pa = dir.path().join("a.png");
    ok(&["render", s(&a), "-o", s(&pa), "--size", "64"], "");
    let (_, _, box_rgb) = decode_png(&std::fs::read(&pa).unwrap());
    let (warm, cool) = warm_and_cool(&box_rgb);
    assert!(warm == 0 && cool > 100, "warm {warm}, cool {cool}");
    ok(
        &[
            "render",
            s(&a),
            "-o",
            s(&pa),
            "--size",
            "64",
            "--view",
            "10,-40",
        ],
        "",
    );
    let (_, _, turned) = decode_png(&std::fs::read(&pa).unwrap());
    assert_ne!(turned, box_rgb);
    // The complement (unbounded) is drawn by its one negatively oriented surface: warm only.
    let out = file(&dir, "out.obj", &ok(&["complement", s(&a)], ""));
    ok(&["render", s(&out), "-o", s(&pa), "--size", "64"], "");
    let (warm, cool) = warm_and_cool(&decode_png(&std::fs::read(&pa).unwrap()).2);
    assert!(warm > 100 && cool == 0, "warm {warm}, cool {cool}");
    // The HTML page holds every triangle with its orientation, and loads nothing.
    let html = dir.path().join("h.html");
    ok(&["render", s(&h), "-o", s(&html), "--view", "30,20"], "");
    let page = std::fs::read_to_string(&html).unwrap();
    let flags = page
        .split("\"s\": [")
        .nth(1)
        .and_then(|t| t.split(']').next())
        .unwrap();
    assert_eq!(flags.split(',').filter(|f| *f == "1").count(), 12);
    assert_eq!(flags.split(',').filter(|f| *f == "0").count(), 12);
    assert!(page.contains("const VIEW = [30, 20];") && page.contains("hollow.obj"));
    assert!(!page.contains("http"), "the page loads nothing");
    // The whole space has no surface to draw.
    fails(
        &["render", "--from", "obj", "-", "-o", s(&png)],
        "# yinset: the whole space (no boundary)\n",
        2,
        &["standard input is the whole space"],
    );
    // With -o, nothing goes to standard output.
    assert!(ok_bytes(&["render", s(&h), "-o", s(&png)]).is_empty());
}

/// Float-mode volumes are the exact volumes of the `f64` vertices, labelled exact only when
/// they are: a cube of side 2 at 10⁹ has volume 8 (not 0), one at 10¹⁵ of side 64 has 262144,
/// and [10³⁰⁰, 3·10³⁰⁰]³ has its exact volume (beyond `f64`: `float` is null, never NaN).
#[test]
fn float_volumes_are_exact_far_out_and_beyond_f64() {
    let dir = scratch();
    for (lo, hi, volume) in [
        ("1000000000", "1000000002", "8"),
        ("30000000000", "30000000002", "8"),
        ("1000000000000000", "1000000000000064", "262144"),
    ] {
        let c = file(&dir, "c.obj", &cuboid([lo; 3], [hi; 3], false));
        let r = info(&["info", s(&c), "--eps", "1"], "");
        assert_eq!(r["volume"]["exact"], volume, "cube at {lo}");
        assert_eq!(
            r["volume"]["float"],
            volume.parse::<f64>().unwrap(),
            "cube at {lo}"
        );
    }
    let c = file(&dir, "c.obj", &cuboid(["1e300"; 3], ["3e300"; 3], false));
    let r = info(&["info", s(&c), "--eps", "1e290"], "");
    let side = Rational::from_float(3e300).unwrap() - Rational::from_float(1e300).unwrap();
    let exact = side.clone() * side.clone() * side;
    assert_eq!(r["volume"]["exact"], exact.to_string());
    assert_eq!(r["volume"]["float"], Value::Null);
}

/// 3D `locate --eps` is on the boundary within Euclidean distance ε of a face, as in 2D: near
/// [0, 2]³'s faces, edges and corners with ε = 0.5, the distances worked by hand — a point 0.45
/// off in each coordinate is 0.45·√3 ≈ 0.78 from the corner (outside), 0.28 off each is 0.485
/// (boundary); 0.3 and 0.4 off two coordinates are 0.42 and 0.57 from an edge; 0.49 and 0.51
/// off a face, outside and inside.
#[test]
fn locate_eps_is_the_euclidean_distance_to_the_boundary() {
    let dir = scratch();
    let cube = file(&dir, "cube.obj", &box_a());
    let cases = [
        ("2.45 2.45 2.45", "outside"),
        ("-0.45 -0.45 -0.45", "outside"),
        ("2.28 2.28 2.28", "boundary"),
        ("-0.28 2.28 -0.28", "boundary"),
        ("2.3 2.3 1", "boundary"),
        ("2.4 2.4 1", "outside"),
        ("1 -0.4 -0.4", "outside"),
        ("1 -0.3 2.3", "boundary"),
        ("2.49 1 1", "boundary"),
        ("2.51 1 1", "outside"),
        ("1.51 1 1", "boundary"),
        ("1.49 1 1", "inside"),
        ("1 1 1", "inside"),
    ];
    let points: String = cases.iter().map(|(p, _)| format!("{p}\n")).collect();
    let want: String = cases.iter().map(|(_, w)| format!("{w}\n")).collect();
    assert_eq!(
        ok(&["locate", s(&cube), "-", "--eps", "0.5"], &points),
        want
    );
}

/// `--eps auto` in 3D: the default tolerance, 10⁻¹⁰ × the side 2 rounded down to 2⁻³³
/// ≈ 1.16·10⁻¹⁰, so a point 10⁻¹⁰ off a face is on the boundary and 2·10⁻¹⁰ off is not; an ε
/// too fine for the coordinates is refused naming ε, not the input, in scientific notation.
#[test]
fn eps_auto_and_too_fine_eps_in_3d() {
    let dir = scratch();
    let cube = file(&dir, "cube.obj", &box_a());
    let points = "2.0000000001 1 1\n2.0000000002 1 1\n1 1.9999999999 1\n1 1.9999999998 1\n";
    assert_eq!(
        ok(&["locate", s(&cube), "-", "--eps", "auto"], points),
        "boundary\noutside\nboundary\ninside\n"
    );
    let j = info(&["info", s(&cube), "--eps", "auto"], "");
    assert_eq!(
        (j["exact"].clone(), j["b0"].clone()),
        (false.into(), 1.into())
    );
    let refused = yinset()
        .args(["info", s(&cube), "--eps", "1e-300"])
        .assert()
        .code(1);
    let message = String::from_utf8(refused.get_output().stderr.clone()).unwrap();
    for needle in [
        "cube.obj` cannot be read with this tolerance",
        "tolerance 1e-300 is too fine",
        "the smallest usable is 8.881784197001252e-16",
        "--eps 8.881784197001252e-16 or more, or --eps auto",
    ] {
        assert!(message.contains(needle), "{needle}: {message}");
    }
    assert!(
        !message.contains("not a Yin set") && !message.contains("0.000000"),
        "{message}"
    );
}

/// Points in 3D float-mode messages are the nearest f64s, in scientific notation where very
/// small, marked `≈` where the exact point (a crossing of faces) is not one; exact mode names
/// the exact point.
#[test]
fn float_mode_messages_show_points_as_f64s() {
    let dir = scratch();
    // Two tetrahedra whose faces cross, at scale 10⁻³⁰⁰ (and at scale 1).
    let tetrahedra = |unit: &str| {
        let v = [
            "0 0 0", "3 0.1 0", "0 3 0.3", "0.2 0 3", "1 1 -1", "4 1.3 -1", "1 4 -0.7", "1.1 1 2",
        ];
        let mut text = String::new();
        for p in v {
            let scaled: Vec<String> = p.split(' ').map(|x| format!("{x}{unit}")).collect();
            text += &format!("v {}\n", scaled.join(" "));
        }
        text + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 5 7 6\nf 5 6 8\nf 5 8 7\nf 6 7 8\n"
    };
    let tiny = file(&dir, "tiny.obj", &tetrahedra("e-300"));
    let refused = yinset()
        .args(["validate", s(&tiny), "--eps", "1e-310"])
        .assert()
        .code(1);
    let message = String::from_utf8(refused.get_output().stderr.clone()).unwrap();
    assert!(
        message.contains("cross each other")
            && message.contains("through ≈ (")
            && message.contains("e-300"),
        "{message}"
    );
    let point = message
        .split("through ")
        .nth(1)
        .and_then(|t| t.split(')').next());
    assert!(
        point.is_some_and(|p| !p.contains('/') && p.len() < 80),
        "{message}"
    );
    let unit = file(&dir, "unit.obj", &tetrahedra(""));
    fails(
        &["validate", s(&unit)],
        "",
        1,
        &["through (9330/9001, 1, 869/9001)"],
    );
}
#[test]
fn files_without_a_mesh_are_errors_while_the_empty_set_reads_back() {
    let dir = scratch();
    let (a, _) = two_boxes(&dir);
    // A yin2 text named .obj has no OBJ lines: an error, not the empty set.
    let sq = file(&dir, "sq.obj", "0 0\n1 0\n1 1\n0 1\n");
    fails(
        &["info", s(&sq)],
        "",
        1,
        &[
            "sq.obj",
            "line 1, column 1",
            "no vertex (`v`) or face (`f`) lines",
        ],
    );
    // Vertices without faces bound nothing, in every format.
    let cloud = file(&dir, "cloud.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    fails(
        &["info", s(&cloud)],
        "",
        1,
        &["cloud.off", "3 vertices but no faces"],
    );
    // The empty set written in each 3D format reads back as the empty set.
    for ext in ["obj", "stl", "off", "ply"] {
        let out = dir.path().join(format!("e.{ext}"));
        ok(&["difference", s(&a), s(&a), "-o", s(&out)], "");
        let e = info(&["info", s(&out)], "");
        assert_eq!(e["set"], "empty", "{ext}");
    }
}

#[test]
fn from_may_not_contradict_an_operand_extension() {
    let dir = scratch();
    let sq = file(&dir, "sq.txt", "0 0\n1 0\n1 1\n0 1\n");
    fails(
        &["meet", s(&sq), "-", "--from", "obj"],
        &box_a(),
        2,
        &[
            "conflicting options: --from obj but",
            "sq.txt",
            "the extension of yin2",
        ],
    );
    // Without an extension, or on standard input, --from says the format.
    let box_file = file(&dir, "box", &box_a());
    let v = info(&["info", "--from", "obj", s(&box_file)], "");
    assert_eq!(v["volume"]["exact"], "8");
    let (a, _) = two_boxes(&dir);
    let v = info(&["info", "--from", "obj", s(&a)], "");
    assert_eq!(v["volume"]["exact"], "8");
}

#[test]
fn a_byte_order_mark_is_ignored_in_every_3d_format() {
    let dir = scratch();
    let h = hollow_cube(&dir);
    let want = info(&["info", s(&h)], "");
    for ext in ["obj", "stl", "off", "ply"] {
        let plain = dir.path().join(format!("p.{ext}"));
        ok(&["convert", s(&h), "-o", s(&plain)], "");
        let text = std::fs::read_to_string(&plain).unwrap();
        let marked = file(&dir, &format!("m.{ext}"), &format!("\u{feff}{text}"));
        assert_eq!(info(&["info", s(&marked)], ""), want, "{ext}");
    }
    // An ASCII STL without its `solid` line is named as such, not as a truncated binary STL.
    let stl = std::fs::read_to_string(dir.path().join("p.stl")).unwrap();
    let headless = file(&dir, "headless.stl", &stl[stl.find('\n').unwrap() + 1..]);
    fails(
        &["info", s(&headless)],
        "",
        1,
        &["headless.stl", "begins with `solid`, this one with `facet`"],
    );
}

#[test]
fn pictures_of_sets_beyond_f64_are_those_of_the_same_sets_at_unit_scale() {
    let dir = scratch();
    // The hollow box [0, 3]³ − [1, 2]³ scaled by 10^±400 and moved by 10^400: no coordinate
    // has an f64 (or a nonzero one), yet each is drawn as the unit-scale box is.
    let box_text = |outer: [&str; 2], inner: [&str; 2]| {
        cuboid([outer[0]; 3], [outer[1]; 3], false) + &cuboid([inner[0]; 3], [inner[1]; 3], true)
    };
    let cases = [
        ("unit", box_text(["0", "3"], ["1", "2"])),
        ("big", box_text(["0", "3e400"], ["1e400", "2e400"])),
        ("tiny", box_text(["0", "3e-400"], ["1e-400", "2e-400"])),
        (
            "far",
            box_text(
                [
                    format!("1{}", "0".repeat(400)).as_str(),
                    format!("1{}3", "0".repeat(399)).as_str(),
                ],
                [
                    format!("1{}1", "0".repeat(399)).as_str(),
                    format!("1{}2", "0".repeat(399)).as_str(),
                ],
            ),
        ),
    ];
    let mut pictures = Vec::new();
    for (name, text) in &cases {
        let sub = dir.path().join(name);
        std::fs::create_dir(&sub).unwrap();
        let obj = sub.join("h.obj");
        std::fs::write(&obj, text).unwrap();
        let (png, html) = (sub.join("h.png"), sub.join("h.html"));
        ok(&["render", s(&obj), "-o", s(&png), "--size", "64"], "");
        ok(&["render", s(&obj), "-o", s(&html)], "");
        let page = std::fs::read_to_string(&html).unwrap();
        let data = page
            .split("const DATA = ")
            .nth(1)
            .unwrap()
            .split(';')
            .next()
            .unwrap();
        assert!(
            !data.contains("Infinity") && !data.contains("NaN"),
            "{name}: {data}"
        );
        pictures.push((std::fs::read(&png).unwrap(), page));
    }
    let (warm, cool) = warm_and_cool(&decode_png(&pictures[0].0).2);
    assert!(warm > 50 && cool > 50, "warm {warm}, cool {cool}");
    for (k, (name, _)) in cases.iter().enumerate().skip(1) {
        assert!(pictures[k] == pictures[0], "{name} is drawn otherwise");
    }
}
