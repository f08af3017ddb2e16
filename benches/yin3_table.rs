//! The 3D table of issue 19: our exact and float meet against Manifold, CGAL (corefinement and
//! Nef polyhedra) and boolmesh on the same OBJ files (benches/yin3_work), in one run, printed
//! as a Markdown table and written to target/yin3_table.md. Run by benches/yin3_peers.sh,
//! which builds the peers; a peer that is missing shows as "n/a".
//!
//! ```sh
//! cargo bench --bench yin3_table -- [--max-exact-s S] [--max-m M] [--reps R]
//! cargo bench --bench yin3_table -- --peak exact|float M   # one V1 meet, for /usr/bin/time -v
//! ```
//!
//! Our times are the best CPU time of the meet alone over R runs (operands built beforehand),
//! as the peers' `time_ms` are. V1 doubles n (m grows by √2 each step) until the exact meet
//! takes longer than S seconds (float: until m = M). A peer's row shows its exit status or
//! error instead of a time when it rejects the input or fails, and "vol≠" when its volume
//! differs from our exact one by more than 10⁻⁶ relative (a mangled result).

#[allow(dead_code)] // only the thread clock is used here
#[path = "peers/cpu_time.rs"]
mod cpu_time;
#[path = "yin3_work/mod.rs"]
mod work;

use cpu_time::thread_cpu;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use yinset::num::{Float, Num, Rational};
use yinset::yin3::YinSet3;

/// The outcome of one contender on one pair.
enum Cell {
    /// CPU milliseconds and the result's volume.
    Time(f64, f64),
    /// Why there is no time (rejected input, failure, missing peer).
    Status(String),
}

impl Cell {
    fn ms(&self) -> Option<f64> {
        match self {
            Cell::Time(ms, _) => Some(*ms),
            Cell::Status(_) => None,
        }
    }

    /// The cell's text, flagging a volume off `reference`.
    fn show(&self, reference: Option<f64>) -> String {
        match self {
            Cell::Time(ms, v) => {
                let off = reference.is_some_and(|r| (v - r).abs() > 1e-6 * r.abs().max(1e-12));
                format!(
                    "{}{}",
                    fmt_ms(*ms),
                    if off {
                        format!(" vol≠ ({v:.6})")
                    } else {
                        String::new()
                    }
                )
            }
            Cell::Status(s) => s.clone(),
        }
    }
}

/// Milliseconds with three significant digits.
fn fmt_ms(ms: f64) -> String {
    if ms >= 100.0 {
        format!("{ms:.0}")
    } else if ms >= 10.0 {
        format!("{ms:.1}")
    } else {
        format!("{ms:.2}")
    }
}

/// Options of the run.
struct Opts {
    reps: usize,
    max_exact_s: f64,
    max_m: usize,
}

/// Our meet of the files in backend `N`: best CPU ms over `reps` and (if `volume`) the
/// volume of the result, NaN otherwise.
fn ours<N: Num>(a: &Path, b: &Path, reps: usize, volume: bool) -> Cell {
    // A panic is a defect to show in the table, not a reason to lose the run.
    std::panic::catch_unwind(|| ours_unguarded::<N>(a, b, reps, volume)).unwrap_or_else(|e| {
        let msg = e
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        Cell::Status(format!(
            "panicked: {}",
            msg.chars().take(90).collect::<String>()
        ))
    })
}

/// [`ours`] without the guard.
fn ours_unguarded<N: Num>(a: &Path, b: &Path, reps: usize, volume: bool) -> Cell {
    let (x, y) = (work::load::<N>(a), work::load::<N>(b));
    let mut best = f64::INFINITY;
    let mut vol = f64::NAN;
    for _ in 0..reps {
        let t0 = thread_cpu();
        let m: YinSet3<N> = x.meet(&y);
        best = best.min((thread_cpu() - t0).as_secs_f64() * 1e3);
        if volume {
            vol = m.volume().map_or(f64::NAN, |v| v.to_f64());
        }
        if best > 2000.0 {
            break;
        }
    }
    Cell::Time(best, vol)
}

/// A path under target/.
fn target(p: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("target")
        .join(p)
}

/// A peer's meet through its harness (a JSON line with `time_ms` and `volume`), under a
/// time limit of `limit_s` seconds.
fn peer(cmd: &[&str], a: &Path, b: &Path, extra: &[&str], limit_s: u64) -> Cell {
    if !Path::new(cmd[0]).exists() {
        return Cell::Status("n/a".into());
    }
    let out = Command::new("timeout")
        .arg(limit_s.to_string())
        .args(cmd)
        .arg("meet")
        .arg(a)
        .arg(b)
        .args(extra)
        .output();
    let out = match out {
        Ok(o) => o,
        Err(e) => return Cell::Status(format!("failed to run: {e}")),
    };
    if out.status.code() == Some(124) {
        return Cell::Status(format!("> {limit_s} s"));
    }
    let json: Option<serde_json::Value> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .rev()
        .find_map(|l| serde_json::from_str(l).ok());
    let err = || {
        let e = String::from_utf8_lossy(&out.stderr);
        let last = e.lines().rev().find(|l| !l.trim().is_empty()).unwrap_or("");
        format!(
            "exit {}: {}",
            out.status.code().unwrap_or(-1),
            last.chars().take(60).collect::<String>()
        )
    };
    let Some(j) = json else {
        return Cell::Status(err());
    };
    // Manifold's harness reports each operand's status and the result's ("Error.NoError").
    let bad: Vec<String> = ["a_status", "b_status", "status"]
        .iter()
        .filter_map(|k| Some((k, j[*k].as_str()?)))
        .filter(|(_, v)| *v != "ok" && !v.ends_with("NoError"))
        .map(|(k, v)| format!("{k}: {}", v.chars().take(60).collect::<String>()))
        .collect();
    if !bad.is_empty() {
        return Cell::Status(bad.join(", "));
    }
    match (j["time_ms"].as_f64(), j["volume"].as_f64()) {
        (Some(ms), Some(v)) => Cell::Time(ms, v),
        _ => Cell::Status(err()),
    }
}

/// Every contender on one pair.
fn row(label: &str, a: &Path, b: &Path, o: &Opts, exact: bool) -> (Vec<Cell>, Option<f64>) {
    let reps = o.reps.to_string();
    let py = target("m3venv/bin/python");
    let m3 = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/tools/manifold3d/m3.py");
    let cgal = target("cgal3d/cgal3d");
    let bm = target("mesh_peers/release/mesh_peers");
    let e = if exact {
        ours::<Rational>(a, b, o.reps, true)
    } else {
        Cell::Status("skipped".into())
    };
    let f = ours::<Float>(a, b, o.reps, true);
    let reference = match (&e, &f) {
        (Cell::Time(_, v), _) => Some(*v),
        (_, Cell::Time(_, v)) => Some(*v),
        _ => None,
    };
    let cells = vec![
        e,
        f,
        peer(
            &[py.to_str().unwrap(), m3.to_str().unwrap()],
            a,
            b,
            &["--reps", &reps],
            60,
        ),
        peer(
            &[cgal.to_str().unwrap()],
            a,
            b,
            &["--engine", "corefine", "--reps", &reps],
            60,
        ),
        peer(
            &[cgal.to_str().unwrap()],
            a,
            b,
            &["--engine", "nef", "--reps", "1"],
            60,
        ),
        peer(
            &[bm.to_str().unwrap(), "boolmesh"],
            a,
            b,
            &["--reps", &reps],
            60,
        ),
    ];
    eprintln!("done: {label}");
    (cells, reference)
}

const HEAD: &str = "| workload | ours exact | ours float | Manifold | CGAL corefine | CGAL Nef | boolmesh | exact/float | exact/corefine | exact/Nef | float/Manifold |\n|---|---|---|---|---|---|---|---|---|---|---|\n";

/// One line of the table.
fn line(label: &str, cells: &[Cell], reference: Option<f64>) -> String {
    let ratio = |x: Option<f64>, y: Option<f64>| match (x, y) {
        (Some(x), Some(y)) if y > 0.0 => format!("{:.2}", x / y),
        _ => "–".into(),
    };
    let shown: Vec<String> = cells.iter().map(|c| c.show(reference)).collect();
    format!(
        "| {label} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
        shown[0],
        shown[1],
        shown[2],
        shown[3],
        shown[4],
        shown[5],
        ratio(cells[0].ms(), cells[1].ms()),
        ratio(cells[0].ms(), cells[3].ms()),
        ratio(cells[0].ms(), cells[4].ms()),
        ratio(cells[1].ms(), cells[2].ms()),
    )
}

/// Print a line of the table as soon as it is measured (the run is long), and return it.
fn say(l: String) -> String {
    print!("{l}");
    l
}

/// A V1 size n with our exact, our float and Manifold's times.
type V1Times = (usize, Option<f64>, Option<f64>, Option<f64>);

/// The octasphere sizes of V1: m = 8·√2^i, so that n = 8m² about doubles per step.
fn v1_sizes(max_m: usize) -> Vec<usize> {
    (0..)
        .map(|i| (8.0 * 2f64.sqrt().powi(i)).round() as usize)
        .take_while(|&m| m <= max_m)
        .collect()
}

/// One V1 meet at octasphere parameter `m` (for peak memory under /usr/bin/time -v).
fn peak(mode: &str, m: usize) {
    let (a, b) = work::v1(8 * m * m);
    let (pa, pb) = (
        work::write(&format!("v1_a_{m}"), &a),
        work::write(&format!("v1_b_{m}"), &b),
    );
    let cell = if mode == "exact" {
        ours::<Rational>(&pa, &pb, 1, false)
    } else {
        ours::<Float>(&pa, &pb, 1, false)
    };
    println!(
        "V1 m={m} n={} {mode} meet: {} ms",
        8 * m * m,
        cell.ms().map_or("-".into(), fmt_ms)
    );
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let get = |k: &str| {
        args.iter()
            .position(|a| a == k)
            .and_then(|i| args.get(i + 1))
    };
    if let Some(mode) = get("--peak") {
        let m = args
            .iter()
            .position(|a| a == "--peak")
            .and_then(|i| args.get(i + 2)?.parse().ok())
            .unwrap_or(64);
        return peak(mode, m);
    }
    let o = Opts {
        reps: get("--reps").and_then(|s| s.parse().ok()).unwrap_or(3),
        max_exact_s: get("--max-exact-s")
            .and_then(|s| s.parse().ok())
            .unwrap_or(60.0),
        max_m: get("--max-m").and_then(|s| s.parse().ok()).unwrap_or(128),
    };
    let mut table = say(HEAD.to_string());
    let mut v1_times: Vec<V1Times> = Vec::new();
    let mut exact = true;
    for m in v1_sizes(o.max_m) {
        let n = 8 * m * m;
        let (a, b) = work::v1(n);
        let (pa, pb) = (
            work::write(&format!("v1_a_{m}"), &a),
            work::write(&format!("v1_b_{m}"), &b),
        );
        let label = format!("V1 n={n}");
        let (cells, r) = row(&label, &pa, &pb, &o, exact);
        table += &say(line(&label, &cells, r));
        v1_times.push((n, cells[0].ms(), cells[1].ms(), cells[2].ms()));
        if cells[0].ms().is_some_and(|ms| ms > o.max_exact_s * 1e3) {
            exact = false;
        }
    }
    for k in [2, 4, 8] {
        let (g, shifted, turned) = work::v2(k);
        let pg = work::write(&format!("v2_grid_{k}"), &g);
        for (name, m) in [("shift", shifted), ("turn", turned)] {
            let label = format!("V2 {name} k={k}");
            let pm = work::write(&format!("v2_{name}_{k}"), &m);
            let (cells, r) = row(&label, &pg, &pm, &o, true);
            table += &say(line(&label, &cells, r));
        }
    }
    for (label, a, b) in work::v3_files() {
        let label = format!("V3 {label}");
        let (cells, r) = row(&label, &a, &b, &o, true);
        table += &say(line(&label, &cells, r));
    }
    let n4 = 4;
    let sphere = work::write("v4_sphere_968", &work::v4_sphere(1000));
    let mut sums: Vec<Option<f64>> = vec![Some(0.0); 6];
    let mut statuses: Vec<Option<String>> = vec![None; 6];
    for (i, cell) in work::v4_cells(n4).iter().enumerate() {
        let pc = work::write(&format!("v4_cell_{n4}_{i}"), cell);
        let (cells, _) = row(
            &format!("V4 cell {i}"),
            &sphere,
            &pc,
            &Opts { reps: 1, ..o },
            true,
        );
        for (k, c) in cells.iter().enumerate() {
            match c {
                Cell::Time(ms, _) => sums[k] = sums[k].map(|s| s + ms),
                Cell::Status(s) => {
                    sums[k] = None;
                    statuses[k].get_or_insert_with(|| format!("cell {i}: {s}"));
                }
            }
        }
    }
    let v4: Vec<Cell> = sums
        .iter()
        .zip(&statuses)
        .map(|(s, st)| match (s, st) {
            (Some(ms), _) => Cell::Time(*ms, f64::NAN),
            (None, st) => Cell::Status(st.clone().unwrap_or_default()),
        })
        .collect();
    table += &say(line(
        &format!("V4 sphere n=968, {} cells (sum)", n4 * n4 * n4),
        &v4,
        None,
    ));
    let mut scaling =
        String::from("\n| V1 n → 2n | ours exact | ours float | Manifold |\n|---|---|---|---|\n");
    for w in v1_times.windows(2) {
        let r = |x: Option<f64>, y: Option<f64>| match (x, y) {
            (Some(x), Some(y)) => format!("{:.2}", y / x),
            _ => "–".into(),
        };
        writeln!(
            scaling,
            "| {} → {} | {} | {} | {} |",
            w[0].0,
            w[1].0,
            r(w[0].1, w[1].1),
            r(w[0].2, w[1].2),
            r(w[0].3, w[1].3)
        )
        .expect("writing to a String");
    }
    table += &scaling;
    println!("{scaling}");
    let out = target("yin3_table.md");
    std::fs::write(&out, &table).unwrap_or_else(|e| panic!("{}: {e}", out.display()));
}
