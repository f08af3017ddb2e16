//! Differential test against CGAL's exact Nef polyhedra (issue 16 item 6): the exact volumes of
//! our meets, joins and differences on the shared meshes equal those of
//! ../shared/tools/cgal3d as rationals. The harness binary is found at $YINSET_CGAL3D or
//! target/cgal3d/cgal3d (.ci/run installs CGAL and builds it there); without it the test says
//! so and checks nothing.

mod common;
use common::data_file_3d;
use std::path::PathBuf;
use std::process::Command;
use yinset::io::obj::read_obj;
use yinset::num::{Num, Rational};
use yinset::yin3::YinSet3;

/// The cgal3d binary, if built.
fn cgal3d() -> Option<PathBuf> {
    let path = std::env::var_os("YINSET_CGAL3D")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/cgal3d/cgal3d"));
    path.is_file().then_some(path)
}

/// CGAL's exact volume of `op` on two data files.
fn cgal_volume(bin: &PathBuf, op: &str, a: &str, b: &str) -> Rational {
    let out = Command::new(bin)
        .args([
            op,
            data_file_3d(a).to_str().unwrap(),
            data_file_3d(b).to_str().unwrap(),
        ])
        .output()
        .expect("cgal3d runs");
    assert!(
        out.status.success(),
        "cgal3d {op} {a} {b}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON line");
    Rational::parse(json["volume_exact"].as_str().expect("volume_exact")).expect("p/q")
}

fn load(name: &str) -> YinSet3<Rational> {
    let text = std::fs::read_to_string(data_file_3d(name)).unwrap();
    let mesh = read_obj::<Rational>(&text).unwrap();
    YinSet3::from_triangles(mesh.vertices, mesh.faces).unwrap()
}

#[test]
fn exact_volumes_equal_cgal_nef_polyhedra() {
    if !common::data_available() {
        return;
    }
    let Some(bin) = cgal3d() else {
        eprintln!(
            "cgal3d not built (target/cgal3d/cgal3d or $YINSET_CGAL3D): differential test skipped"
        );
        return;
    };
    let pairs = [
        ("ballahead.obj", "ballabehind.obj"),
        ("ballmid.obj", "ballleft.obj"),
        ("ballmid.obj", "ballright.obj"),
        ("torus.obj", "innerball.obj"),
    ];
    let mut checked = 0;
    for (a, b) in pairs {
        let (x, y) = (load(a), load(b));
        let ours = [
            ("meet", &x & &y),
            ("join", &x | &y),
            ("difference", &x - &y),
        ];
        for (op, r) in ours {
            let v = r.volume().expect("bounded");
            assert_eq!(v, cgal_volume(&bin, op, a, b), "{op} {a} {b}");
            checked += 1;
        }
    }
    eprintln!("{checked} exact volumes equal CGAL's");
    assert_eq!(checked, 12);
}
