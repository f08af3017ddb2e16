//! What a command-line user pays in 3D besides the Boolean operation (BENCHMARKS.md, *3D input
//! and output*): for each pair of OBJ files and each mode (exact `Rational`, float `Float` with
//! the default `Tolerance`), the CPU time of parsing each operand, `YinSet3::from_triangles`
//! of each, the meet alone, writing the result as OBJ, reading that text back (parse and
//! `from_triangles`), the complement of the set read back and its conversion (writing it
//! again); and the whole `yinset meet A B -o OUT` process (`--eps auto` in float mode),
//! spawned: its wall time and its CPU time (the children's rusage). Printed as a Markdown table
//! with the ratios of the targets and written to target/yin3_io.md (or `--out`).
//!
//! ```sh
//! cargo build --release && cargo bench --bench yin3_io -- [--reps R] [--quick]
//!     [--kigumi DIR] [--yinset BIN] [--tsv FILE] [--out FILE]
//! cargo bench --bench yin3_io -- --merge BEFORE.tsv AFTER.tsv [--out FILE]
//! ```
//!
//! Every time is the best of R calls (3 by default; fewer once one call takes over 2 s),
//! inputs built beforehand, outputs dropped after the clock stops. The pairs: the V3 pairs of
//! benches/yin3_work, V1 at 10⁴ and 10⁵ triangles per sphere (`--quick`: 10⁴ only, one call
//! each) and kigumi's checker ∧ text from `--kigumi DIR` or `$KIGUMI_MESHES` (a row saying so
//! when neither is given or the files are missing). `--tsv` writes the measurements one a line;
//! `--merge` prints the before/after tables of two such files (benches/yin3_io.sh). A row
//! notes where the command's output differs from the library's text of the meet.

#[allow(dead_code)] // only the clocks are used here
#[path = "peers/cpu_time.rs"]
mod cpu_time;
#[path = "yin3_work/mod.rs"]
mod work;

use cpu_time::{children_cpu, process_cpu};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};
use yinset::io::obj::{read_obj, surface_groups, write_obj};
use yinset::num::{Float, Num, Rational};
use yinset::yin3::YinSet3;

/// A call over this many ms is not repeated.
const LONG_MS: f64 = 2000.0;

/// The measured quantities, in the order of the tables: CPU ms, except the triangle counts
/// (`… tris`) and the command's wall time.
const QUANTITIES: [&str; 15] = [
    "A tris",
    "B tris",
    "R tris",
    "parse A",
    "valid A",
    "parse B",
    "valid B",
    "meet",
    "write R",
    "parse R",
    "valid R",
    "¬R",
    "convert R",
    "CLI wall",
    "CLI cpu",
];

/// The ratios of the targets: name, target, and how a row's quantities give it.
type Ratio = (&'static str, &'static str, fn(&Values) -> Option<f64>);

/// The ratios, each against its target.
const RATIOS: [Ratio; 5] = [
    ("valid/meet", "≤ 0.2", |v| {
        Some(v.get("valid A")?.max(*v.get("valid B")?) / v.get("meet")?)
    }),
    ("read/meet", "≤ 0.5", |v| {
        Some((v.get("parse R")? + v.get("valid R")?) / v.get("meet")?)
    }),
    ("CLI/meet", "≤ 1.5", |v| {
        Some(v.get("CLI cpu")? / v.get("meet")?)
    }),
    ("¬ µs/tri", "flat", |v| {
        Some(1e3 * v.get("¬R")? / v.get("R tris")?)
    }),
    ("convert µs/tri", "flat", |v| {
        Some(1e3 * v.get("convert R")? / v.get("R tris")?)
    }),
];

/// One row's quantities by name.
type Values = BTreeMap<String, f64>;

/// One pair in one mode: its quantities, or why there are none (or only some).
struct Row {
    workload: String,
    mode: String,
    values: Values,
    status: Option<String>,
}

/// Milliseconds of a duration.
fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// The best CPU ms of `op` over `reps` calls, each on a fresh input from `setup` (untimed), and
/// the last call's output (dropped by the caller, untimed).
fn best<I, T>(reps: usize, mut setup: impl FnMut() -> I, mut op: impl FnMut(I) -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..reps.max(1) {
        let input = setup();
        let t0 = process_cpu();
        let o = op(input);
        best = best.min(ms(process_cpu() - t0));
        out = Some(o);
        if best > LONG_MS {
            break;
        }
    }
    (best, out.expect("at least one call"))
}

/// The OBJ text of a 3D set, as `yinset … -o OUT.obj` writes a bounded one.
fn obj<N: Num>(set: &YinSet3<N>) -> String {
    write_obj(set.vertices(), &surface_groups(set))
}

/// Parse and `from_triangles` of OBJ text, timed apart (keys `parse X`, `valid X`, `X tris`).
fn read<N: Num>(text: &str, x: &str, reps: usize, v: &mut Values) -> Result<YinSet3<N>, String> {
    let (t, mesh) = best(reps, || (), |()| read_obj::<N>(text));
    let mesh = mesh.map_err(|e| format!("parse {x}: {e}"))?;
    v.insert(format!("parse {x}"), t);
    let (t, set) = best(
        reps,
        || (mesh.vertices.clone(), mesh.faces.clone()),
        |(p, f)| YinSet3::from_triangles(p, f),
    );
    let set = set.map_err(|e| format!("valid {x}: {e}"))?;
    v.insert(format!("valid {x}"), t);
    v.insert(format!("{x} tris"), set.triangles().len() as f64);
    Ok(set)
}

/// The best wall and CPU ms of `yinset meet A B -o OUT` (with `--eps auto` if `float`), and
/// the text it wrote.
fn cli(o: &Opts, w: &Workload, float: bool, v: &mut Values) -> Result<String, String> {
    let out = work::out_dir().join(format!("io_{}_{}.obj", w.slug, float as u8));
    let (mut wall, mut cpu) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..o.reps.max(1) {
        let mut cmd = Command::new(&o.yinset);
        cmd.arg("meet").arg(&w.a).arg(&w.b).arg("-o").arg(&out);
        if float {
            cmd.args(["--eps", "auto"]);
        }
        let (c0, t0) = (children_cpu(), Instant::now());
        let done = cmd
            .output()
            .map_err(|e| format!("{}: {e}", o.yinset.display()))?;
        (wall, cpu) = (wall.min(ms(t0.elapsed())), cpu.min(ms(children_cpu() - c0)));
        if !done.status.success() {
            let err = String::from_utf8_lossy(&done.stderr);
            let last = err.lines().rev().find(|l| !l.trim().is_empty());
            return Err(format!(
                "yinset meet: {}: {}",
                done.status,
                last.unwrap_or("")
            ));
        }
        if wall > LONG_MS {
            break;
        }
    }
    v.insert("CLI wall".into(), wall);
    v.insert("CLI cpu".into(), cpu);
    std::fs::read_to_string(&out).map_err(|e| format!("{}: {e}", out.display()))
}

/// Every quantity of one pair in backend `N`, as far as it gets (the error says where it
/// stopped).
fn measure<N: Num>(o: &Opts, w: &Workload, v: &mut Values) -> Result<(), String> {
    let text = |p: &Path| std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()));
    let a = read::<N>(&text(&w.a)?, "A", o.reps, v)?;
    let b = read::<N>(&text(&w.b)?, "B", o.reps, v)?;
    let (t, m) = best(o.reps, || (), |()| &a & &b);
    v.insert("meet".into(), t);
    drop((a, b));
    let (t, written) = best(o.reps, || (), |()| obj(&m));
    v.insert("write R".into(), t);
    let float = !N::EXACT;
    // The command must have done the work timed here: its file is the library's text.
    let same = cli(o, w, float, v)? == written;
    if m.is_empty() || m.is_full() || !m.is_bounded() {
        return Err("the meet is empty, full or unbounded: nothing to read back".into());
    }
    drop(m);
    let r = read::<N>(&written, "R", o.reps, v)?;
    let (t, c) = best(o.reps, || (), |()| !&r);
    v.insert("¬R".into(), t);
    drop(c);
    let (t, _) = best(o.reps, || (), |()| obj(&r));
    v.insert("convert R".into(), t);
    if same {
        Ok(())
    } else {
        Err("the command's output differs from the library's OBJ text of the meet".into())
    }
}

/// [`measure`] as a row, a panic included.
fn row<N: Num>(o: &Opts, w: &Workload, mode: &str) -> Row {
    let mut values = Values::new();
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        measure::<N>(o, w, &mut values)
    }));
    let status = match outcome {
        Ok(Ok(())) => None,
        Ok(Err(e)) => Some(e),
        Err(p) => Some(format!(
            "panicked: {}",
            p.downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| p.downcast_ref::<&str>().copied())
                .unwrap_or("")
        )),
    };
    eprintln!("done: {} {mode}", w.label);
    Row {
        workload: w.label.clone(),
        mode: mode.into(),
        values,
        status,
    }
}

/// A pair of operand files.
struct Workload {
    label: String,
    /// A file-name-safe name for the command's output.
    slug: String,
    a: PathBuf,
    b: PathBuf,
}

/// The pairs, and a note for each pair that is missing.
fn workloads(o: &Opts) -> (Vec<Workload>, Vec<String>) {
    let mut ws: Vec<Workload> = work::v3_files()
        .into_iter()
        .enumerate()
        .map(|(i, (label, a, b))| Workload {
            label: format!("V3 {label}"),
            slug: format!("v3_{i}"),
            a,
            b,
        })
        .collect();
    let sizes: &[usize] = if o.quick {
        &[10_000]
    } else {
        &[10_000, 100_000]
    };
    for &n in sizes {
        let m = work::sphere_m(n);
        let (a, b) = work::v1(n);
        ws.push(Workload {
            label: format!("V1 n={}", 8 * m * m),
            slug: format!("v1_{m}"),
            a: work::write(&format!("v1_a_{m}"), &a),
            b: work::write(&format!("v1_b_{m}"), &b),
        });
    }
    let mut notes = Vec::new();
    match &o.kigumi {
        None => notes.push(
            "checker ∧ text skipped: give kigumi's mesh folder as --kigumi DIR or KIGUMI_MESHES"
                .to_string(),
        ),
        Some(dir) => {
            let (a, b) = (dir.join("checker.obj"), dir.join("text.obj"));
            if a.is_file() && b.is_file() {
                ws.push(Workload {
                    label: "kigumi checker∧text".into(),
                    slug: "kigumi".into(),
                    a,
                    b,
                });
            } else {
                notes.push(format!(
                    "checker ∧ text skipped: no checker.obj and text.obj in {}",
                    dir.display()
                ));
            }
        }
    }
    (ws, notes)
}

/// Options of the run.
struct Opts {
    reps: usize,
    quick: bool,
    kigumi: Option<PathBuf>,
    yinset: PathBuf,
}

/// A quantity's cell: ms with three significant digits, a whole number (a count) in full, "–"
/// if missing.
fn cell(x: Option<f64>) -> String {
    match x {
        None => "–".into(),
        Some(x) if x >= 100.0 || x.fract() == 0.0 => format!("{x:.0}"),
        Some(x) if x >= 10.0 => format!("{x:.1}"),
        Some(x) if x >= 1.0 => format!("{x:.2}"),
        Some(x) => format!("{x:.3}"),
    }
}

/// A column's value in a row.
type Getter = Box<dyn Fn(&Values) -> Option<f64>>;

/// The columns of the one-run table: (header, value of a row).
fn all_columns() -> Vec<(String, Getter)> {
    let mut cols: Vec<(String, Getter)> = QUANTITIES
        .iter()
        .filter(|q| !matches!(**q, "parse R" | "valid R"))
        .map(|&q| {
            let get: Getter = Box::new(move |v| v.get(q).copied());
            (q.to_string(), get)
        })
        .collect();
    // Reading back is parse and from_triangles together, as the target counts it.
    let at = cols
        .iter()
        .position(|(q, _)| q == "¬R")
        .expect("¬R is a column");
    cols.insert(
        at,
        (
            "read R".into(),
            Box::new(|v| Some(v.get("parse R")? + v.get("valid R")?)),
        ),
    );
    for (name, target, f) in RATIOS {
        cols.push((format!("{name} ({target})"), Box::new(f)));
    }
    cols
}

/// The Markdown table of one run, with the notes below it.
fn table(rows: &[Row], notes: &[String]) -> String {
    let cols = all_columns();
    let mut s = String::from("| workload | mode |");
    for (h, _) in &cols {
        write!(s, " {h} |").expect("writing to a String");
    }
    s += &format!("\n|---|---|{}\n", "---:|".repeat(cols.len()));
    for r in rows {
        write!(s, "| {} | {} |", r.workload, r.mode).expect("writing to a String");
        for (_, f) in &cols {
            write!(s, " {} |", cell(f(&r.values))).expect("writing to a String");
        }
        s.push('\n');
    }
    for r in rows.iter().filter(|r| r.status.is_some()) {
        let st = r.status.as_deref().unwrap_or("");
        writeln!(s, "\n* {} {}: {st}", r.workload, r.mode).expect("writing to a String");
    }
    for n in notes {
        writeln!(s, "\n* {n}").expect("writing to a String");
    }
    s
}

/// The measurements one a line, `workload⇥mode⇥quantity⇥value` (`status` for a row's error).
fn tsv(rows: &[Row]) -> String {
    let mut s = String::new();
    for r in rows {
        for (q, x) in &r.values {
            writeln!(s, "{}\t{}\t{q}\t{x}", r.workload, r.mode).expect("writing to a String");
        }
        if let Some(st) = &r.status {
            writeln!(
                s,
                "{}\t{}\tstatus\t{}",
                r.workload,
                r.mode,
                st.replace(['\t', '\n'], " ")
            )
            .expect("writing to a String");
        }
    }
    s
}

/// The rows of a [`tsv`] file, in its order.
fn read_tsv(path: &Path) -> Vec<Row> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut rows: Vec<Row> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let f: Vec<&str> = line.splitn(4, '\t').collect();
        let [w, m, q, x] = f[..] else {
            panic!(
                "{}:{}: not workload⇥mode⇥quantity⇥value",
                path.display(),
                i + 1
            )
        };
        if !rows.last().is_some_and(|r| r.workload == w && r.mode == m) {
            rows.push(Row {
                workload: w.into(),
                mode: m.into(),
                values: Values::new(),
                status: None,
            });
        }
        let r = rows.last_mut().expect("a row was just pushed");
        if q == "status" {
            r.status = Some(x.into());
        } else {
            let x = x
                .parse()
                .unwrap_or_else(|e| panic!("{}:{}: {e}", path.display(), i + 1));
            r.values.insert(q.into(), x);
        }
    }
    rows
}

/// The before/after tables of two runs: the ratios of the targets, then every quantity.
fn merge(before: &[Row], after: &[Row]) -> String {
    let find = |rows: &'_ [Row], r: &Row| -> Option<Values> {
        rows.iter()
            .find(|b| b.workload == r.workload && b.mode == r.mode)
            .map(|b| b.values.clone())
    };
    // Every row of either run, in the after run's order, then the before run's others.
    let mut keys: Vec<&Row> = after.iter().collect();
    keys.extend(before.iter().filter(|b| find(after, b).is_none()));
    let pairs: Vec<(&Row, Values, Values)> = keys
        .iter()
        .map(|r| {
            let get = |rows| find(rows, r).unwrap_or_default();
            (*r, get(before), get(after))
        })
        .collect();
    let mut s = String::from("| workload | mode |");
    for (name, target, _) in RATIOS {
        write!(s, " {name} ({target}) before | after |").expect("writing to a String");
    }
    s += &format!("\n|---|---|{}\n", "---:|".repeat(2 * RATIOS.len()));
    for (r, b, a) in &pairs {
        write!(s, "| {} | {} |", r.workload, r.mode).expect("writing to a String");
        for (_, _, f) in RATIOS {
            write!(s, " {} | {} |", cell(f(b)), cell(f(a))).expect("writing to a String");
        }
        s.push('\n');
    }
    s += "\n| workload | mode | quantity | before | after | after/before |\n|---|---|---|---:|---:|---:|\n";
    for (r, b, a) in &pairs {
        for q in QUANTITIES {
            let (x, y) = (b.get(q).copied(), a.get(q).copied());
            let ratio = match (x, y) {
                (Some(x), Some(y)) if x > 0.0 => format!("{:.2}", y / x),
                _ => "–".into(),
            };
            writeln!(
                s,
                "| {} | {} | {q} | {} | {} | {ratio} |",
                r.workload,
                r.mode,
                cell(x),
                cell(y)
            )
            .expect("writing to a String");
        }
    }
    for (which, rows) in [("before", before), ("after", after)] {
        for r in rows.iter().filter(|r| r.status.is_some()) {
            let st = r.status.as_deref().unwrap_or("");
            writeln!(s, "\n* {which}, {} {}: {st}", r.workload, r.mode)
                .expect("writing to a String");
        }
    }
    s
}

/// Write `text` to `path`, creating its folder.
fn save(path: &Path, text: &str) {
    if let Some(d) = path.parent() {
        std::fs::create_dir_all(d).unwrap_or_else(|e| panic!("{}: {e}", d.display()));
    }
    std::fs::write(path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let get = |k: &str| work::option(&args, k);
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let out = get("--out").map_or_else(|| root.join("target/yin3_io.md"), PathBuf::from);
    if let Some(i) = args.iter().position(|a| a == "--merge") {
        let file = |k: usize| PathBuf::from(args.get(i + k).expect("--merge BEFORE.tsv AFTER.tsv"));
        let s = merge(&read_tsv(&file(1)), &read_tsv(&file(2)));
        print!("{s}");
        return save(&out, &s);
    }
    let quick = args.iter().any(|a| a == "--quick");
    let o = Opts {
        reps: get("--reps")
            .and_then(|s| s.parse().ok())
            .unwrap_or(if quick { 1 } else { 3 }),
        quick,
        kigumi: get("--kigumi")
            .map(PathBuf::from)
            .or_else(|| std::env::var_os("KIGUMI_MESHES").map(PathBuf::from)),
        yinset: get("--yinset").map_or_else(|| root.join("target/release/yinset"), PathBuf::from),
    };
    assert!(
        o.yinset.is_file(),
        "{}: no yinset binary (cargo build --release, or --yinset BIN)",
        o.yinset.display()
    );
    let (ws, notes) = workloads(&o);
    let mut rows = Vec::new();
    for w in &ws {
        rows.push(row::<Rational>(&o, w, "exact"));
        rows.push(row::<Float>(&o, w, "float"));
    }
    let s = table(&rows, &notes);
    print!("{s}");
    save(&out, &s);
    if let Some(p) = get("--tsv") {
        save(Path::new(p), &tsv(&rows));
    }
}
