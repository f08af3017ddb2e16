//! The 3D table of BENCHMARKS.md: our exact and float meet against Manifold, CGAL (corefinement and
//! Nef polyhedra), boolmesh and kigumi on the same OBJ files (benches/yin3_work, and kigumi's
//! checker ∧ text and plate − (checker ∧ text) from `$KIGUMI_MESHES` when set), in one run,
//! printed as a Markdown table and
//! written to target/yin3_table.md. Run by benches/yin3_peers.sh, which builds the peers; a
//! peer that is missing shows as "n/a".
//!
//! ```sh
//! cargo bench --bench yin3_table -- [--max-exact-s S] [--max-float-s F] [--max-m M] [--reps R]
//! cargo bench --bench yin3_table -- --peak exact|float M   # one V1 meet, for /usr/bin/time -v
//! ```
//!
//! Our times are the best CPU time of the meet alone over R runs (operands built beforehand),
//! as the peers' `time_ms` are. V1 doubles n (m grows by √2 each step) until the exact meet
//! takes longer than S seconds, our float past F seconds, a peer past its time limit (V1 stops at
//! m = M or when both of ours have stopped). A peer's row shows its exit status or
//! error instead of a time when it rejects the input or fails, and "vol≠" when its volume
//! differs from our exact one by more than 10⁻⁶ relative (a mangled result). Our float cell is
//! flagged "vol≠" when its volume differs from our exact one by more than the bound of 3D
//! float mode, ε·A (ε the default tolerance of the pair, A the boundary area of the operands
//! plus the result's); each row's difference and bound are printed after the table.

#[allow(dead_code)] // only the thread clock is used here
#[path = "peers/cpu_time.rs"]
mod cpu_time;
#[path = "yin3_work/mod.rs"]
mod work;

use cpu_time::process_cpu;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use yinset::io::obj::{surface_groups, write_obj};
use yinset::num::{Float, Num, Rational, Tolerance};
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

    /// The cell's text, flagging a volume more than `tol` off `reference`.
    fn show(&self, reference: Option<f64>, tol: f64) -> String {
        match self {
            Cell::Time(ms, v) => {
                let off = reference.is_some_and(|r| (v - r).abs() > tol);
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

/// The bound of 3D float mode on |vol F − vol E| for our float meet F of the files against the
/// exact E:
/// vol(F △ E) ≤ ε·A, ε the default tolerance of the pair's bounding box, A the boundary area
/// of both operands plus the result's, at most twice the operands' (the meet's boundary lies
/// on theirs).
fn float_bound(a: &Path, b: &Path) -> f64 {
    let (ma, mb) = (work::read_f64(a), work::read_f64(b));
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    let mut area = 0.0;
    for m in [&ma, &mb] {
        for p in &m.points {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        for t in &m.tris {
            let [p, q, r] = t.map(|i| m.points[i]);
            let (u, v) = (
                [0, 1, 2].map(|k| q[k] - p[k]),
                [0, 1, 2].map(|k| r[k] - p[k]),
            );
            let c = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            area += (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt() / 2.0;
        }
    }
    let span = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
    let magnitude = lo.iter().chain(&hi).fold(0.0f64, |m, x| m.max(x.abs()));
    let eps = Tolerance::default()
        .resolve(span, magnitude)
        .map_or(f64::NAN, |t| t.eps());
    eps * 2.0 * area
}

/// Options of the run.
struct Opts {
    reps: usize,
    max_exact_s: f64,
    max_float_s: f64,
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
        let t0 = process_cpu();
        let m: YinSet3<N> = x.meet(&y);
        best = best.min((process_cpu() - t0).as_secs_f64() * 1e3);
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
        let mut last = e
            .lines()
            .rev()
            .find(|l| !l.trim().is_empty())
            .unwrap_or("")
            .to_string();
        // The files' directory would fill the cell: name them by their file names.
        for p in [a, b] {
            if let (Some(full), Some(name)) = (p.to_str(), p.file_name().and_then(|n| n.to_str())) {
                last = last.replace(full, name);
            }
        }
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
    // CGAL's harness prints `volume` to six significant digits (a 10⁻⁶ check would flag it)
    // and `volume_exact` as p/q: the exact one is read where there is one.
    let volume = j["volume_exact"]
        .as_str()
        .and_then(|s| s.parse::<BigRational>().ok())
        .and_then(|q| q.to_f64())
        .or(j["volume"].as_f64());
    match (j["time_ms"].as_f64(), volume) {
        (Some(ms), Some(v)) => Cell::Time(ms, v),
        _ => Cell::Status(err()),
    }
}

/// A row's results: the contenders' cells, the reference volume (ours exact, else ours
/// float) and the float bound ε·A on our float volume's difference from it.
struct Row {
    cells: Vec<Cell>,
    reference: Option<f64>,
    float_bound: f64,
}

/// Every contender on one pair; `run[k]` says whether contender k (the table's order) runs
/// (V1 drops a contender past its limit at a smaller n).
fn row(label: &str, a: &Path, b: &Path, o: &Opts, run: [bool; CONTENDERS]) -> Row {
    let reps = o.reps.to_string();
    let py = target("m3venv/bin/python");
    let m3 = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/tools/manifold3d/m3.py");
    let cgal = target("cgal3d/cgal3d");
    let bm = target("mesh_peers/release/mesh_peers");
    let kigumi = target("kigumi3d/kigumi3d");
    let skipped = || Cell::Status("skipped (over its limit at a smaller n)".into());
    let e = if run[0] {
        ours::<Rational>(a, b, o.reps, true)
    } else {
        skipped()
    };
    let f = if run[1] {
        ours::<Float>(a, b, o.reps, true)
    } else {
        skipped()
    };
    let reference = match (&e, &f) {
        (Cell::Time(_, v), _) => Some(*v),
        (_, Cell::Time(_, v)) => Some(*v),
        _ => None,
    };
    let peers: [(Vec<&str>, Vec<&str>); CONTENDERS - 2] = [
        (
            vec![py.to_str().unwrap(), m3.to_str().unwrap()],
            vec!["--reps", &reps],
        ),
        (
            vec![cgal.to_str().unwrap()],
            vec!["--engine", "corefine", "--reps", &reps],
        ),
        (
            vec![cgal.to_str().unwrap()],
            vec!["--engine", "nef", "--reps", "1"],
        ),
        (
            vec![bm.to_str().unwrap(), "boolmesh"],
            vec!["--reps", &reps],
        ),
        (vec![kigumi.to_str().unwrap()], vec!["--reps", &reps]),
    ];
    let mut cells = vec![e, f];
    cells.extend(peers.iter().zip(&run[2..]).map(|((cmd, extra), &go)| {
        if go {
            peer(cmd, a, b, extra, PEER_LIMIT_S)
        } else {
            skipped()
        }
    }));
    eprintln!("done: {label}");
    Row {
        cells,
        reference,
        float_bound: float_bound(a, b),
    }
}

/// Ours exact and float, Manifold, CGAL corefine, CGAL Nef, boolmesh, kigumi: the table's
/// columns.
const CONTENDERS: usize = 7;

/// A peer's time limit per call, seconds.
const PEER_LIMIT_S: u64 = 60;

const HEAD: &str = "| workload | ours exact | ours float | Manifold | CGAL corefine | CGAL Nef | boolmesh | kigumi | float/exact | exact/kigumi | exact/corefine | exact/Nef | float/Manifold |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";

/// Our float volume's difference from our exact one and the float bound ε·A on it, when both
/// ran.
fn float_gap(r: &Row) -> Option<(f64, f64)> {
    match (&r.cells[0], &r.cells[1]) {
        (Cell::Time(_, e), Cell::Time(_, f)) => Some(((f - e).abs(), r.float_bound)),
        _ => None,
    }
}

/// A line of the float check: the difference, the bound and whether it holds.
fn gap_line(label: &str, gap: Option<(f64, f64)>) -> String {
    match gap {
        Some((d, b)) => format!(
            "| {label} | {d:.3e} | {b:.3e} | {} |\n",
            if d <= b { "yes" } else { "**no**" }
        ),
        None => format!("| {label} | – | – | – |\n"),
    }
}

/// The float check's line for a row.
fn check(label: &str, r: &Row) -> String {
    gap_line(label, float_gap(r))
}

/// One line of the table.
fn line(label: &str, r: &Row) -> String {
    let cells = &r.cells;
    let ratio = |x: Option<f64>, y: Option<f64>| match (x, y) {
        (Some(x), Some(y)) if y > 0.0 => format!("{:.2}", x / y),
        _ => "–".into(),
    };
    let shown: Vec<String> = cells
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let tol = match (i, r.reference) {
                (1, _) => r.float_bound,
                (_, Some(v)) => 1e-6 * v.abs().max(1e-12),
                _ => 0.0,
            };
            c.show(r.reference, tol)
        })
        .collect();
    format!(
        "| {label} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
        shown[0],
        shown[1],
        shown[2],
        shown[3],
        shown[4],
        shown[5],
        shown[6],
        ratio(cells[1].ms(), cells[0].ms()),
        ratio(cells[0].ms(), cells[6].ms()),
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
    let get = |k: &str| work::option(&args, k);
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
        max_float_s: get("--max-float-s")
            .and_then(|s| s.parse().ok())
            .unwrap_or(f64::INFINITY),
        max_m: get("--max-m").and_then(|s| s.parse().ok()).unwrap_or(128),
    };
    let mut table = say(HEAD.to_string());
    let mut v1_times: Vec<V1Times> = Vec::new();
    let mut checks = String::from(
        "\n| workload | \\|V float − V exact\\| | bound ε·A | within |\n|---|---|---|---|\n",
    );
    let mut run = [true; CONTENDERS];
    for m in v1_sizes(o.max_m) {
        let n = 8 * m * m;
        let (a, b) = work::v1(n);
        let (pa, pb) = (
            work::write(&format!("v1_a_{m}"), &a),
            work::write(&format!("v1_b_{m}"), &b),
        );
        let label = format!("V1 n={n}");
        let r = row(&label, &pa, &pb, &o, run);
        table += &say(line(&label, &r));
        checks += &check(&label, &r);
        v1_times.push((n, r.cells[0].ms(), r.cells[1].ms(), r.cells[2].ms()));
        run[0] &= !r.cells[0].ms().is_some_and(|ms| ms > o.max_exact_s * 1e3);
        run[1] &= !r.cells[1].ms().is_some_and(|ms| ms > o.max_float_s * 1e3);
        for (go, c) in run.iter_mut().zip(&r.cells).skip(2) {
            *go &= !matches!(c, Cell::Status(s) if s.starts_with("> "));
        }
        if !run[0] && !run[1] {
            break;
        }
    }
    for k in [2, 4, 8] {
        let (g, shifted, turned) = work::v2(k);
        let pg = work::write(&format!("v2_grid_{k}"), &g);
        for (name, m) in [("shift", shifted), ("turn", turned)] {
            let label = format!("V2 {name} k={k}");
            let pm = work::write(&format!("v2_{name}_{k}"), &m);
            let r = row(&label, &pg, &pm, &o, [true; CONTENDERS]);
            table += &say(line(&label, &r));
            checks += &check(&label, &r);
        }
    }
    for (label, a, b) in work::v3_files() {
        let label = format!("V3 {label}");
        let r = row(&label, &a, &b, &o, [true; CONTENDERS]);
        table += &say(line(&label, &r));
        checks += &check(&label, &r);
    }
    // kigumi's own non-manifold benchmark (meshes/checker.obj, text.obj and plate.obj of its
    // repository).
    if let Some(dir) = std::env::var_os("KIGUMI_MESHES").map(PathBuf::from) {
        let label = "V5 kigumi's checker ∧ text";
        let (a, b) = (dir.join("checker.obj"), dir.join("text.obj"));
        let r = row(label, &a, &b, &o, [true; CONTENDERS]);
        table += &say(line(label, &r));
        checks += &check(label, &r);
        // The chain's second step: the plate minus that result, as the meet of the plate with
        // the exact complement of our exact checker ∧ text (written exactly: `p/q`, which only
        // ours and kigumi read; float mode reads each coordinate's nearest f64).
        let label = "V5 plate − (checker ∧ text)";
        let ct = work::load::<Rational>(&a).meet(&work::load::<Rational>(&b));
        let ict = ct.complement();
        let pi = work::out_dir().join("v5_not_checker_text.obj");
        std::fs::write(&pi, write_obj(ict.vertices(), &surface_groups(&ict)))
            .expect("the complement's OBJ file");
        let r = row(label, &dir.join("plate.obj"), &pi, &o, [true; CONTENDERS]);
        table += &say(line(label, &r));
        checks += &check(label, &r);
    }
    let n4 = 4;
    let sphere = work::write("v4_sphere_968", &work::v4_sphere(1000));
    let mut sums: Vec<Option<f64>> = vec![Some(0.0); CONTENDERS];
    let mut statuses: Vec<Option<String>> = vec![None; CONTENDERS];
    let mut v4_gap = (0.0, 0.0);
    for (i, cell) in work::v4_cells(n4).iter().enumerate() {
        let pc = work::write(&format!("v4_cell_{n4}_{i}"), cell);
        let r = row(
            &format!("V4 cell {i}"),
            &sphere,
            &pc,
            &Opts { reps: 1, ..o },
            [true; CONTENDERS],
        );
        if let Some((d, b)) = float_gap(&r) {
            v4_gap = (v4_gap.0 + d, v4_gap.1 + b);
        }
        for (k, c) in r.cells.iter().enumerate() {
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
    let v4_label = format!("V4 sphere n=968, {} cells (sum)", n4 * n4 * n4);
    table += &say(line(
        &v4_label,
        &Row {
            cells: v4,
            reference: None,
            float_bound: f64::NAN,
        },
    ));
    checks += &gap_line(&v4_label, Some(v4_gap));
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
    table += &checks;
    println!("{checks}");
    println!("{scaling}");
    let out = target("yin3_table.md");
    std::fs::write(&out, &table).unwrap_or_else(|e| panic!("{}: {e}", out.display()));
}
