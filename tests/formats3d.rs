//! The 3D mesh formats (issue 18 item 2): every shared mesh of ../shared/data/3d converted from
//! OBJ to STL, OFF and PLY and read back with the same exact corners; Yin sets written in each
//! format and read back equal (==) to themselves, bounded, with a cavity, and unbounded; binary
//! STL only for 32-bit float coordinates.

mod common;
use common::data_file_3d;
use yinset::io::mesh::Mesh;
use yinset::io::obj::{read_obj, write_obj};
use yinset::io::off::{read_off, write_off};
use yinset::io::ply::{read_ply, write_ply};
use yinset::io::stl::{read_stl, write_stl_ascii, write_stl_binary};
use yinset::kernel::Point3;
use yinset::num::Rational;
use yinset::yin3::YinSet3;

type Y = YinSet3<Rational>;

/// The shared meshes, by the data README's table.
const SHARED: [&str; 12] = [
    "Rabbit_Lowpoly_2.obj",
    "ballabehind.obj",
    "ballahead.obj",
    "ballconnecttorus.obj",
    "ballleft.obj",
    "ballmid.obj",
    "ballright.obj",
    "heart.obj",
    "innerball.obj",
    "teddy.obj",
    "torus.obj",
    "torusbig.obj",
];

/// The OBJ mesh of a shared file.
fn shared_mesh(name: &str) -> Mesh<Rational> {
    let path = data_file_3d(name);
    let text = std::fs::read_to_string(&path).expect("readable data file");
    read_obj(&text).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Each face of `mesh` as its corner points.
fn corners(mesh: &Mesh<Rational>) -> Vec<Vec<Point3<Rational>>> {
    mesh.faces
        .iter()
        .map(|f| f.iter().map(|&i| mesh.vertices[i].clone()).collect())
        .collect()
}

/// A writer of triangles and the reader of its output.
type Codec = (
    &'static str,
    fn(&[Point3<Rational>], &[[usize; 3]]) -> Vec<u8>,
    fn(&[u8]) -> Mesh<Rational>,
);

/// The text formats' writers and readers (binary STL is tested on its own: it holds only
/// `f32` coordinates).
fn codecs() -> [Codec; 4] {
    fn text(bytes: &[u8]) -> &str {
        std::str::from_utf8(bytes).expect("a text format")
    }
    [
        (
            "stl",
            |v, t| write_stl_ascii(v, t).into_bytes(),
            |b| read_stl(b).expect("written STL reads"),
        ),
        (
            "off",
            |v, t| write_off(v, t).into_bytes(),
            |b| read_off(text(b)).expect("written OFF reads"),
        ),
        (
            "ply",
            |v, t| write_ply(v, t).into_bytes(),
            |b| read_ply(b).expect("written PLY reads"),
        ),
        (
            "obj",
            |v, t| write_obj(v, &[("all".to_string(), t.to_vec())]).into_bytes(),
            |b| read_obj(text(b)).expect("written OBJ reads"),
        ),
    ]
}

#[test]
fn shared_meshes_convert_between_formats_exactly() {
    if !common::data_available() {
        return;
    }
    for name in SHARED {
        let mesh = shared_mesh(name);
        let triangles: Vec<[usize; 3]> = mesh
            .faces
            .iter()
            .map(|f| {
                <[usize; 3]>::try_from(f.as_slice())
                    .unwrap_or_else(|_| panic!("{name}: a face of {} corners", f.len()))
            })
            .collect();
        let want = corners(&mesh);
        for (format, write, read) in codecs() {
            let back = read(&write(&mesh.vertices, &triangles));
            assert_eq!(corners(&back), want, "{name} through {format}");
            assert_eq!(back.faces.len(), back.face_lines.len(), "{name}");
        }
        // The data's decimals (such as 2.707107) are no 32-bit floats: binary STL refuses them
        // rather than round.
        let e = write_stl_binary(&mesh.vertices, &triangles).unwrap_err();
        assert!(e.to_string().contains("write ASCII STL"), "{name}: {e}");
    }
}

/// The Yin set bounded by `mesh`.
fn set(mesh: Mesh<Rational>) -> Y {
    YinSet3::from_triangles(mesh.vertices, mesh.faces).expect("a Yin set")
}

/// The cube [lo, hi]³.
fn cube(lo: i64, hi: i64) -> Y {
    YinSet3::cuboid(&Point3::int(lo, lo, lo), &Point3::int(hi, hi, hi)).expect("a box")
}

#[test]
fn sets_round_trip_through_every_format() {
    if !common::data_available() {
        return;
    }
    let hollow = &cube(0, 3) - &cube(1, 2);
    let torus = set(shared_mesh("torus.obj"));
    let cavity = &torus - &set(shared_mesh("innerball.obj"));
    assert_eq!(cavity.surfaces().len(), 2);
    for (label, y) in [
        ("hollow cube", hollow.clone()),
        ("outside of the hollow cube", hollow.complement()),
        ("torus minus innerball", cavity.clone()),
    ] {
        for (format, write, read) in codecs() {
            let back = set(read(&write(y.vertices(), y.triangles())));
            assert_eq!(back, y, "{label} through {format}");
            assert_eq!(
                back.is_bounded(),
                y.is_bounded(),
                "{label} through {format}"
            );
        }
    }
    // Integer coordinates are 32-bit floats: binary STL holds the hollow cube exactly.
    let bytes = write_stl_binary(hollow.vertices(), hollow.triangles()).unwrap();
    assert_eq!(bytes.len(), 84 + 50 * hollow.triangles().len());
    assert_eq!(set(read_stl(&bytes).unwrap()), hollow);
    let outside = hollow.complement();
    let bytes = write_stl_binary(outside.vertices(), outside.triangles()).unwrap();
    assert_eq!(set(read_stl(&bytes).unwrap()), outside);
    // Not so the torus's decimals.
    assert!(write_stl_binary(cavity.vertices(), cavity.triangles()).is_err());
}

/// Small files of every reader: ASCII and binary STL, OFF, ASCII and binary PLY, OBJ.
fn small_files() -> Vec<(&'static str, Vec<u8>)> {
    let hollow = &cube(0, 3) - &cube(1, 2);
    let (v, t) = (hollow.vertices(), hollow.triangles());
    let mut files: Vec<(&'static str, Vec<u8>)> = codecs()
        .into_iter()
        .map(|(format, write, _)| (format, write(v, t)))
        .collect();
    files.push(("stl-binary", write_stl_binary(v, t).unwrap()));
    let mut ply = b"ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n\
        property float y\nproperty float z\nelement face 1\nproperty list uchar ushort vertex_index\n\
        end_header\n"
        .to_vec();
    for x in [0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
        ply.extend(x.to_be_bytes());
    }
    ply.push(3);
    for i in [0u16, 1, 2] {
        ply.extend(i.to_be_bytes());
    }
    files.push(("ply-binary", ply));
    files
}

/// Every reader on `bytes`; none may panic (errors are fine).
fn read_all(bytes: &[u8]) {
    let _ = read_stl::<Rational>(bytes);
    let _ = read_ply::<Rational>(bytes);
    if let Ok(text) = std::str::from_utf8(bytes) {
        let _ = read_off::<Rational>(text);
        let _ = read_obj::<Rational>(text);
    }
}

/// The mesh in `bytes` read by the reader of `format` (a name of [`small_files`]), or its error.
fn read_as(format: &str, bytes: &[u8]) -> Result<Mesh<Rational>, String> {
    let text = || std::str::from_utf8(bytes).map_err(|e| e.to_string());
    match format {
        "stl" | "stl-binary" => read_stl(bytes).map_err(|e| e.to_string()),
        "ply" | "ply-binary" => read_ply(bytes).map_err(|e| e.to_string()),
        "off" => read_off(text()?).map_err(|e| e.to_string()),
        _ => read_obj(text()?).map_err(|e| e.to_string()),
    }
}

#[test]
fn a_byte_order_mark_is_ignored_by_every_reader() {
    for (format, bytes) in small_files() {
        if format == "stl-binary" {
            continue; // binary STL is told by its size, and has no text to mark
        }
        let marked = [&b"\xEF\xBB\xBF"[..], &bytes[..]].concat();
        let plain = read_as(format, &bytes).unwrap();
        assert!(!plain.faces.is_empty(), "{format}");
        assert_eq!(read_as(format, &marked), Ok(plain), "{format}");
    }
}

#[test]
fn ascii_stl_without_its_solid_line_is_named_as_such() {
    let (_, stl) = &small_files()[0];
    let text = std::str::from_utf8(stl).unwrap();
    let headless = &text[text.find('\n').unwrap() + 1..];
    let e = read_as("stl", headless.as_bytes()).unwrap_err();
    assert!(
        e.contains("an ASCII STL file begins with `solid`, this one with `facet`")
            && e.contains("begin it with a line `solid NAME`")
            && e.starts_with("line 1, column 3:"),
        "{e}"
    );
    let e = read_as("stl", b"0 0\n1 0\n0 1\n").unwrap_err();
    assert!(
        e.contains("this one with `0`, and it is not a binary STL either"),
        "{e}"
    );
    assert!(read_as("stl", b"")
        .unwrap_err()
        .contains("the file is empty"));
}

#[test]
fn obj_text_without_vertices_or_faces_is_empty_only_if_it_says_nothing() {
    for nothing in [
        "",
        "\n\n",
        "# yinset: the empty set (no boundary)\n",
        "\u{feff}# c\n",
    ] {
        let mesh = read_as("obj", nothing.as_bytes()).unwrap();
        assert!(
            mesh.vertices.is_empty() && mesh.faces.is_empty(),
            "{nothing:?}"
        );
    }
    for (other, at) in [
        ("0 0\n1 0\n0 1\n", "line 1, column 1: `0`"),
        ("# a box\no box\ng side\n", "line 2, column 1: `o`"),
        (
            "POLYGON ((0 0, 1 0, 0 1, 0 0))",
            "line 1, column 1: `POLYGON`",
        ),
    ] {
        let e = read_as("obj", other.as_bytes()).unwrap_err();
        assert!(
            e.starts_with(at) && e.contains("no vertex (`v`) or face (`f`) lines"),
            "{e}"
        );
    }
}

#[test]
fn damaged_files_are_errors_not_panics() {
    for (format, bytes) in small_files() {
        // The undamaged file reads in its own format.
        let mesh = read_as(format, &bytes).unwrap();
        assert!(!mesh.faces.is_empty(), "{format}");
        // Every truncation, and every byte replaced by a few others (in steps, to stay fast).
        let step = (bytes.len() / 400).max(1);
        for cut in (0..bytes.len()).step_by(step) {
            read_all(&bytes[..cut]);
        }
        for at in (0..bytes.len()).step_by(step) {
            for b in [0u8, b' ', b'\n', b'9', b'-', b'/', 0xff] {
                let mut damaged = bytes.clone();
                damaged[at] = b;
                read_all(&damaged);
            }
        }
    }
}
