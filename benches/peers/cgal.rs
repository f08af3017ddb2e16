//! CGAL's exact kernel (Epeck) as a peer: the operands written exactly under
//! target/peers2d_cgal, the harness ../shared/tools/cgal2d run on them (the binary named by
//! `YINSET_CGAL2D`; benches/peers2d_cgal.sh builds it and runs the bench), and its CPU time of
//! the operation alone and its exact area read back from its JSON line.

use super::common::RationalRings;
use std::fmt::Write;
use std::path::PathBuf;
use std::process::Command;
use yinset::num::{Num, Rational};

/// What the harness reports for one operation.
pub struct Cgal {
    /// The best process-CPU time of the operation alone over its repetitions, in ms.
    pub time_ms: f64,
    /// The exact area of the result.
    pub area: Rational,
}

/// The harness, when `YINSET_CGAL2D` names it (else CGAL is not run).
pub fn harness() -> Option<PathBuf> {
    std::env::var_os("YINSET_CGAL2D").map(PathBuf::from)
}

/// `target/peers2d_cgal/<name>` with `text` written to it.
pub fn write(name: &str, text: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/peers2d_cgal");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    path
}

/// Rings as yin2 text (blocks of exact `p/q` coordinate lines), which the harness reads as
/// the even-odd set of all rings.
pub fn yin2(rings: &RationalRings) -> String {
    let mut s = String::new();
    for ring in rings {
        for p in ring {
            writeln!(s, "{} {}", p.x, p.y).unwrap();
        }
        s.push('\n');
    }
    s
}

/// Rings as a WKT GEOMETRYCOLLECTION of one polygon each (exact `p/q` coordinates), which the
/// harness reads as the union of the rings.
pub fn wkt_union(rings: &RationalRings) -> String {
    let polygons: Vec<String> = rings
        .iter()
        .map(|ring| {
            let pts: Vec<String> = ring
                .iter()
                .chain(ring.first())
                .map(|p| format!("{} {}", p.x, p.y))
                .collect();
            format!("POLYGON (({}))", pts.join(", "))
        })
        .collect();
    format!("GEOMETRYCOLLECTION ({})\n", polygons.join(", "))
}

/// Runs `harness op files… --reps reps` and reads its JSON line.
pub fn run(harness: &PathBuf, op: &str, files: &[PathBuf], reps: usize) -> Result<Cgal, String> {
    let out = Command::new(harness)
        .arg(op)
        .args(files)
        .args(["--reps", &reps.to_string()])
        .output()
        .map_err(|e| format!("{}: {e}", harness.display()))?;
    if !out.status.success() {
        return Err(format!(
            "{} exited with {}: {}",
            harness.display(),
            out.status,
            String::from_utf8_lossy(&out.stderr).trim()
        ));
    }
    let v: serde_json::Value = serde_json::from_slice(&out.stdout)
        .map_err(|e| format!("cgal2d output is not JSON: {e}"))?;
    let time_ms = v["time_ms"]
        .as_f64()
        .ok_or("cgal2d output without time_ms")?;
    let area = v["area_exact"]
        .as_str()
        .ok_or("cgal2d output without area_exact")?;
    let area = Rational::parse(area).map_err(|e| format!("cgal2d area {area}: {e}"))?;
    Ok(Cgal { time_ms, area })
}

/// Our exact area against CGAL's: the check printed beside our exact result.
pub fn compare(ours: Option<Rational>, cgal: &Cgal) -> String {
    match ours {
        Some(a) if a == cgal.area => "exact area = CGAL's".to_string(),
        Some(a) => format!(
            "exact area {} ≠ CGAL's {} (MISMATCH)",
            a.to_f64(),
            cgal.area.to_f64()
        ),
        None => "unbounded, CGAL's area is finite (MISMATCH)".to_string(),
    }
}
