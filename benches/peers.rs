//! yinset against its peers: meet, join, complement, locate and Betti numbers,
//! exact and float, on the workloads W1–W6, with i_overlay, geo's BooleanOps and Clipper2 on the
//! same `f64` coordinates, and CGAL's exact kernel on the same values as exact fractions when
//! `YINSET_CGAL2D` names the harness of ../shared/tools/cgal2d (peers/cgal.rs). The report is
//! benches/BENCHMARKS.md.
//!
//! ```sh
//! cargo bench --bench peers               # everything (long: see BENCHMARKS.md)
//! cargo bench --bench peers -- W1/meet    # ids containing "W1/meet"
//! cargo test --bench peers                # smoke test: smallest sizes, one call each
//! bash benches/peers2d_cgal.sh            # the run of BENCHMARKS.md, with CGAL
//! ```
//!
//! Ids are `workload/operation/contender/size`. Before it is measured, every case is called once
//! untimed: that call gives the areas that are checked across contenders (printed as `# check`
//! lines) and the time of one iteration, which sets the sampling: cases over 30 s are skipped
//! (printed as `# skip`), cases over 10 s are timed by that one call only (`# single`), and
//! cases over 50 ms are measured with 10 flat samples of one iteration. After a skipped or
//! single case, larger sizes of it (and the join after its meet) are not attempted; nor is a
//! numeric size whose time, predicted from the last smaller one as growing like size^1.5
//! (W6: size², the crossings of the copies), is over 30 s. Times are the process's CPU time, all
//! threads (see peers/cpu_time.rs), with W6's `join_all` on a pool of one thread (the issue's
//! single-thread comparison; rayon's idle thread would add its waiting); CGAL's
//! (`# cgal` lines) are the harness's process CPU time of the operation alone, best of 3.
//! The data files are read from ../shared/data/2d beside the repository.

#[path = "peers/cgal.rs"]
mod cgal;
#[path = "common/mod.rs"]
mod common;
#[path = "peers/contenders.rs"]
mod contenders;
#[path = "peers/cpu_time.rs"]
mod cpu_time;

use common::{Curves, RationalRings};
use contenders::Op;
use cpu_time::{process_cpu, CpuTime};
use criterion::{BenchmarkId, Criterion, SamplingMode};
use std::collections::HashMap;
use std::fmt::Display;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::{Duration, Instant};
use yinset::kernel::Point;
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::intersect::intersections;
use yinset::yin2::{FillRule, YinSet2};

/// Cases whose single iteration takes longer are not measured.
const SKIP_OVER: Duration = Duration::from_secs(30);
/// Cases whose single iteration takes longer are not sampled: the one call is the figure
/// (printed as `# single`), and larger sizes of the case are not attempted.
const SAMPLE_OVER: Duration = Duration::from_secs(10);
/// Cases whose single iteration takes longer are measured with flat sampling.
const FLAT_OVER: Duration = Duration::from_millis(50);

/// Runs, filters and logs the cases.
struct Runner {
    c: Criterion<CpuTime>,
    /// Per `group/contender`: the one-call time of a size that was skipped, so that larger
    /// sizes (and the join, after its meet) are not attempted.
    skipped: HashMap<String, f64>,
    /// Per `group/contender`: the last numeric size measured and its one-call time in seconds.
    last: HashMap<String, (f64, f64)>,
    /// The exponent of the predicted growth of a case's time with its numeric size.
    growth: f64,
    filter: Option<String>,
    /// `cargo test --bench peers`: smallest sizes only, one call each, nothing measured.
    test_mode: bool,
}

impl Runner {
    fn new() -> Runner {
        let args: Vec<String> = std::env::args().skip(1).collect();
        let test_mode = !args.iter().any(|a| a == "--bench") || args.iter().any(|a| a == "--test");
        // The first free argument is criterion's filter; options that take a value are skipped.
        let valued = [
            "--save-baseline",
            "--baseline",
            "--load-baseline",
            "--sample-size",
            "--warm-up-time",
            "--measurement-time",
            "--nresamples",
            "--noise-threshold",
            "--confidence-level",
            "--significance-level",
            "--output-format",
            "--plotting-backend",
            "--profile-time",
            "--color",
            "--format",
        ];
        let mut filter = None;
        let mut k = 0;
        while k < args.len() {
            if valued.contains(&args[k].as_str()) {
                k += 1;
            } else if !args[k].starts_with('-') {
                filter = Some(args[k].clone());
                break;
            }
            k += 1;
        }
        Runner {
            c: Criterion::default()
                .with_measurement(CpuTime)
                .configure_from_args(),
            skipped: HashMap::new(),
            last: HashMap::new(),
            growth: 1.5,
            filter,
            test_mode,
        }
    }

    /// True if some case whose id starts with `prefix` may run (to skip building workloads).
    fn wants(&self, prefix: &str) -> bool {
        let Some(f) = &self.filter else { return true };
        if !(f.starts_with('W') || f.starts_with("L/")) {
            return true;
        }
        f.split('/')
            .zip(prefix.split('/'))
            .filter(|(a, b)| !a.is_empty() && !b.is_empty())
            .all(|(a, b)| a.starts_with(b) || b.starts_with(a))
    }

    /// True if the case `id` passes the filter.
    fn selected(&self, id: &str) -> bool {
        self.filter.as_ref().is_none_or(|f| id.contains(f.as_str()))
    }

    /// One case: `f` is called once untimed (its output goes to `check`), then measured.
    fn case<O>(
        &mut self,
        group: &str,
        contender: &str,
        size: impl Display,
        mut f: impl FnMut() -> O,
        check: impl FnOnce(&O) -> String,
    ) {
        let id = format!("{group}/{contender}/{size}");
        if !self.selected(&id) {
            return;
        }
        let key = format!("{group}/{contender}");
        let meet_key = key.replace("/join/", "/meet/");
        if let Some(t) = self.skipped.get(&key).or(self.skipped.get(&meet_key)) {
            println!("# skip {id}: not attempted (a smaller size or the meet took {t:.1} s)");
            return;
        }
        let numeric = size.to_string().parse::<f64>().ok();
        if let (Some(n), Some(&(m, t))) = (numeric, self.last.get(&key)) {
            let predicted = t * (n / m).powf(self.growth);
            if !self.test_mode && predicted > SKIP_OVER.as_secs_f64() {
                println!(
                    "# skip {id}: not attempted (predicted {predicted:.0} s from {t:.2} s at {m})"
                );
                self.skipped.insert(key, predicted);
                return;
            }
        }
        let (wall, cpu) = (Instant::now(), process_cpu());
        let out = f();
        let once = process_cpu().saturating_sub(cpu);
        if let Some(n) = numeric {
            self.last.insert(key.clone(), (n, once.as_secs_f64()));
        }
        println!(
            "# check {id}: one call {:.3} s CPU ({:.3} s wall), {}",
            once.as_secs_f64(),
            wall.elapsed().as_secs_f64(),
            check(&out)
        );
        drop(out);
        if self.test_mode {
            return;
        }
        if once > SKIP_OVER {
            println!(
                "# skip {id}: one iteration took {:.1} s CPU (> {} s)",
                once.as_secs_f64(),
                SKIP_OVER.as_secs()
            );
            self.skipped.insert(key, once.as_secs_f64());
            return;
        }
        if once > SAMPLE_OVER {
            println!(
                "# single {id}: {:.3} s CPU for the one call, not sampled (> {} s)",
                once.as_secs_f64(),
                SAMPLE_OVER.as_secs()
            );
            self.skipped.insert(key, once.as_secs_f64());
            return;
        }
        let mut g = self.c.benchmark_group(group);
        g.sample_size(10);
        if once > FLAT_OVER {
            g.sampling_mode(SamplingMode::Flat)
                .warm_up_time(Duration::from_millis(1))
                .measurement_time(once.mul_f64(11.0));
        } else {
            g.warm_up_time(Duration::from_millis(300))
                .measurement_time(Duration::from_secs(1));
        }
        g.bench_function(BenchmarkId::new(contender, size), |b| {
            b.iter(|| black_box(f()))
        });
        g.finish();
    }
}

/// The area of a Yin set, in `f64` from its rounded vertices (∞ if unbounded): a check
/// across contenders, cheap even where the exact area is a fraction of millions of digits.
fn area<N: Num>(y: &YinSet2<N>) -> f64 {
    if !y.is_bounded() {
        return f64::INFINITY;
    }
    y.curves()
        .iter()
        .map(|c| {
            let v: Vec<[f64; 2]> = c
                .vertices()
                .iter()
                .map(|p| [p.x.to_f64(), p.y.to_f64()])
                .collect();
            contenders::shoelace(&v)
        })
        .sum()
}

fn show_area(a: f64) -> String {
    format!("area {a:.12e}")
}

fn show_set<N: Num>(y: &YinSet2<N>) -> String {
    let b = y.betti();
    format!(
        "area {:.12e}, {} curves, b0 = {}, b1 = {}",
        area(y),
        y.curves().len(),
        b.components,
        b.total_holes
    )
}

/// The number I of contacts between the two operands' edges (the I of O((n + I) log n)).
fn contacts(a: &YinSet2<Float>, b: &YinSet2<Float>) -> usize {
    let edges = |y: &YinSet2<Float>| -> Vec<(Point<Float>, Point<Float>)> {
        y.curves()
            .iter()
            .flat_map(|c| c.edges().map(|(p, q)| (p.clone(), q.clone())))
            .collect()
    };
    let (ea, eb) = (edges(a), edges(b));
    let na = ea.len();
    let all: Vec<_> = ea.into_iter().chain(eb).collect();
    intersections(&all, &a.ctx(), |i, j| (i < na) != (j < na)).len()
}

/// A meet or a join, by every contender, on the curves `a` and `b` (built as Yin sets by
/// `exact` and `float`, which may fill rings instead of reading curves).
#[allow(clippy::too_many_arguments)]
fn binary(
    r: &mut Runner,
    group: &str,
    size: impl Display + Copy,
    op: Op,
    a: &Curves,
    b: &Curves,
    ea: Option<&YinSet2<Rational>>,
    eb: Option<&YinSet2<Rational>>,
    fa: &YinSet2<Float>,
    fb: &YinSet2<Float>,
    cgal_files: Option<&[PathBuf]>,
) {
    let ours = |x: &YinSet2<Float>, y: &YinSet2<Float>| match op {
        Op::Meet => x.meet(y),
        Op::Join => x.join(y),
    };
    let name = match op {
        Op::Meet => "meet",
        Op::Join => "join",
    };
    let by_cgal = cgal_files.and_then(|files| cgal_case(r, group, size, name, files));
    if let (Some(ea), Some(eb)) = (ea, eb) {
        let exact = |x: &YinSet2<Rational>, y: &YinSet2<Rational>| match op {
            Op::Meet => x.meet(y),
            Op::Join => x.join(y),
        };
        r.case(
            group,
            "exact",
            size,
            || exact(ea, eb),
            |y| checked_by_cgal(y, by_cgal.as_ref()),
        );
    }
    r.case(group, "float", size, || ours(fa, fb), show_set);
    peer(
        r,
        group,
        "i_overlay",
        size,
        contenders::i_overlay_input,
        a,
        b,
        |x, y| contenders::i_overlay_op(x, y, op),
        |s| contenders::i_overlay_area(s),
    );
    peer(
        r,
        group,
        "geo",
        size,
        contenders::geo_input,
        a,
        b,
        |x, y| contenders::geo_op(x, y, op),
        contenders::geo_area,
    );
    peer(
        r,
        group,
        "clipper2",
        size,
        contenders::clipper_input,
        a,
        b,
        |x, y| contenders::clipper_op(x, y, op),
        contenders::clipper_area,
    );
}

/// One peer's case: its input built from the curves (untimed), then `op` on it.
#[allow(clippy::too_many_arguments)]
fn peer<I, O>(
    r: &mut Runner,
    group: &str,
    name: &str,
    size: impl Display,
    input: impl Fn(&Curves) -> I,
    a: &Curves,
    b: &Curves,
    op: impl Fn(&I, &I) -> O,
    area: impl Fn(&O) -> f64,
) {
    let (ia, ib) = (input(a), input(b));
    r.case(group, name, size, || op(&ia, &ib), |o| show_area(area(o)));
}

/// The meet and the join of one workload, by every contender (see [`binary`]).
#[allow(clippy::too_many_arguments)]
fn meet_and_join(
    r: &mut Runner,
    workload: &str,
    size: impl Display + Copy,
    a: &Curves,
    b: &Curves,
    ea: Option<&YinSet2<Rational>>,
    eb: Option<&YinSet2<Rational>>,
    fa: &YinSet2<Float>,
    fb: &YinSet2<Float>,
    exact_rings: (&RationalRings, &RationalRings),
) {
    let files = cgal::harness().map(|_| {
        let file = |tag: &str, rings| {
            cgal::write(&format!("{workload}_{size}_{tag}.yin2"), &cgal::yin2(rings))
        };
        [file("a", exact_rings.0), file("b", exact_rings.1)]
    });
    for (op, name) in [(Op::Meet, "meet"), (Op::Join, "join")] {
        let group = format!("{workload}/{name}");
        binary(
            r,
            &group,
            size,
            op,
            a,
            b,
            ea,
            eb,
            fa,
            fb,
            files.as_ref().map(|f| &f[..]),
        );
    }
}

/// CGAL's case `group/cgal/size` (when the harness is named and the filter selects it): `op`
/// on `files`, best CPU time of 3 (of 1 past 1 s), printed as a `# cgal` line.
fn cgal_case(
    r: &Runner,
    group: &str,
    size: impl Display,
    op: &str,
    files: &[PathBuf],
) -> Option<cgal::Cgal> {
    let harness = cgal::harness()?;
    let id = format!("{group}/cgal/{size}");
    if !r.selected(&id) {
        return None;
    }
    let mut reps = 1;
    loop {
        match cgal::run(&harness, op, files, reps) {
            Ok(c) if reps > 1 || c.time_ms > 1000.0 || r.test_mode => {
                println!(
                    "# cgal {id}: {:.3} ms CPU (best of {reps}), area {:.12e}",
                    c.time_ms,
                    c.area.to_f64()
                );
                return Some(c);
            }
            Ok(_) => reps = 3,
            Err(e) => {
                println!("# cgal {id}: failed: {e}");
                return None;
            }
        }
    }
}

/// The check line of an exact result, with its exact area against CGAL's when CGAL ran.
fn checked_by_cgal(y: &YinSet2<Rational>, by_cgal: Option<&cgal::Cgal>) -> String {
    match by_cgal {
        Some(c) => format!("{}, {}", show_set(y), cgal::compare(y.area(), c)),
        None => show_set(y),
    }
}

/// W1: two random star-shaped polygons of n vertices each.
fn w1(r: &mut Runner) {
    let sizes: &[usize] = if r.test_mode {
        &[100]
    } else {
        &[1_000, 2_000, 10_000, 20_000, 100_000]
    };
    for &n in sizes {
        if !r.wants("W1/") {
            return;
        }
        let (a, b) = common::w1(n);
        let t = process_cpu();
        let (fa, fb) = (common::float(&a), common::float(&b));
        let tf = process_cpu() - t;
        let (ea, eb) = (common::exact(&a), common::exact(&b));
        let te = process_cpu() - t - tf;
        println!(
            "# W1 n = {n}: I = {} contacts; both operands built in {:.3} s CPU (float), {:.3} s (exact)",
            contacts(&fa, &fb),
            tf.as_secs_f64(),
            te.as_secs_f64()
        );
        let q = (common::rational_rings(&a), common::rational_rings(&b));
        meet_and_join(
            r,
            "W1",
            n,
            &a,
            &b,
            Some(&ea),
            Some(&eb),
            &fa,
            &fb,
            (&q.0, &q.1),
        );
        r.case("W1/complement", "exact", n, || ea.complement(), show_set);
        r.case("W1/complement", "float", n, || fa.complement(), show_set);
        // Betti numbers of the meet: the exact meet only where it was measured.
        let exact_meet_ok = n <= 1_000 && !r.skipped.contains_key("W1/meet/exact");
        if exact_meet_ok && r.wants("W1/betti") {
            let em = ea.meet(&eb);
            r.case("W1/betti", "exact", n, || em.betti(), |b| format!("{b:?}"));
        }
        if r.wants("W1/betti") {
            let fm = fa.meet(&fb);
            r.case("W1/betti", "float", n, || fm.betti(), |b| format!("{b:?}"));
        }
    }
}

/// Locating q random points of the bounding box in W1's first polygon of n vertices.
fn locate(r: &mut Runner) {
    let cases: &[(usize, usize)] = if r.test_mode {
        &[(1_000, 10_000)]
    } else {
        &[
            (100_000, 250_000),
            (100_000, 500_000),
            (100_000, 1_000_000),
            (50_000, 1_000_000),
        ]
    };
    for &(n, q) in cases {
        if !r.wants("L/locate") {
            return;
        }
        let (a, _) = common::w1(n);
        let pts = common::queries(q, common::bbox(&a), 7);
        let (ea, fa) = (common::exact(&a), common::float(&a));
        let (eq, fq) = (
            common::points::<Rational>(&pts),
            common::points::<Float>(&pts),
        );
        let size = format!("n{n}_q{q}");
        let count = |l: &Vec<yinset::yin2::Location>| {
            let inside = l
                .iter()
                .filter(|x| **x == yinset::yin2::Location::Inside)
                .count();
            format!("{inside} of {} inside", l.len())
        };
        // Exact location of 10^6 points costs minutes of sampling: one size only.
        if r.test_mode || q == 250_000 {
            r.case("L/locate", "exact", &size, || ea.locate(&eq), count);
        }
        r.case("L/locate", "float", &size, || fa.locate(&fq), count);
    }
}

/// W2: a k×k checkerboard met with a copy shifted by half a cell, and with a turned copy.
fn w2(r: &mut Runner) {
    let ks: &[usize] = if r.test_mode {
        &[16]
    } else {
        &[32, 45, 64, 90]
    };
    for (variant, make) in [
        ("W2shift", common::w2_shift as fn(usize) -> (Curves, Curves)),
        ("W2rotate", common::w2_rotate),
    ] {
        for &k in ks {
            let group = format!("{variant}/meet");
            if !r.wants(&group) {
                break;
            }
            let (a, b) = make(k);
            let (fa, fb) = (common::float(&a), common::float(&b));
            let (ea, eb) = (common::exact(&a), common::exact(&b));
            println!(
                "# {variant} k = {k}: n = {} + {} vertices, I = {} contacts",
                common::vertices(&a),
                common::vertices(&b),
                contacts(&fa, &fb)
            );
            binary(
                r,
                &group,
                k,
                Op::Meet,
                &a,
                &b,
                Some(&ea),
                Some(&eb),
                &fa,
                &fb,
                None,
            );
        }
    }
}

/// W3: the GIS overlay tests (subject multipolygon, clip polygon).
fn w3(r: &mut Runner) {
    for name in ["asia", "states_source"] {
        if !r.wants("W3/") {
            return;
        }
        let ((a, b), (qa, qb)) = common::w3(name);
        let (fa, fb) = (common::float_filled(&a), common::float_filled(&b));
        let (ea, eb) = (common::exact_filled(&qa), common::exact_filled(&qb));
        println!(
            "# W3 {name}: n = {} + {} vertices, I = {} contacts",
            common::vertices(&a),
            common::vertices(&b),
            contacts(&fa, &fb)
        );
        meet_and_join(
            r,
            "W3",
            name,
            &a,
            &b,
            Some(&ea),
            Some(&eb),
            &fa,
            &fb,
            (&qa, &qb),
        );
    }
}

/// W4: panda ∧ Mickey (and ∨, the panda's complement, Betti numbers).
fn w4(r: &mut Runner) {
    if !r.wants("W4/") {
        return;
    }
    let (a, b) = common::w4();
    let (fa, fb) = (common::float(&a), common::float(&b));
    let (ea, eb) = (common::exact(&a), common::exact(&b));
    println!(
        "# W4 panda, mickey: n = {} + {} vertices, I = {} contacts",
        common::vertices(&a),
        common::vertices(&b),
        contacts(&fa, &fb)
    );
    let s = "panda_mickey";
    let q = (common::rational_rings(&a), common::rational_rings(&b));
    meet_and_join(
        r,
        "W4",
        s,
        &a,
        &b,
        Some(&ea),
        Some(&eb),
        &fa,
        &fb,
        (&q.0, &q.1),
    );
    r.case(
        "W4/complement",
        "exact",
        "panda",
        || ea.complement(),
        show_set,
    );
    r.case(
        "W4/complement",
        "float",
        "panda",
        || fa.complement(),
        show_set,
    );
    let (em, fm) = (ea.meet(&eb), fa.meet(&fb));
    r.case("W4/betti", "exact", s, || em.betti(), |b| format!("{b:?}"));
    r.case("W4/betti", "float", s, || fm.betti(), |b| format!("{b:?}"));
}

/// W5: the panda met with every cell of an N×N grid over its bounding box (seed 000 §5.5,
/// IT-5), total time; the checks give the sum of the cells' areas (the panda's area). At
/// N = 256 the measured set is the 4096 cells (i, j) with i ≡ j ≡ 0 (mod 4), spread over the
/// whole grid: the total for all 65536 cells is 16 times that (every cell costs about the same,
/// a sweep over the whole panda).
fn w5(r: &mut Runner) {
    let ns: &[usize] = if r.test_mode { &[8] } else { &[64, 256] };
    for &n in ns {
        if !r.wants("W5/") {
            return;
        }
        let (panda, _) = common::w4();
        let stride = if n > 64 { 4 } else { 1 };
        let cells: Vec<Curves> = common::grid_cells(common::bbox(&panda), n)
            .into_iter()
            .enumerate()
            .filter(|(k, _)| (k / n) % stride == 0 && (k % n) % stride == 0)
            .map(|(_, c)| vec![c])
            .collect();
        let size = if stride > 1 {
            format!("{n}_every16th")
        } else {
            n.to_string()
        };
        let (ep, fp) = (common::exact(&panda), common::float(&panda));
        let ecells: Vec<_> = cells.iter().map(common::exact).collect();
        let fcells: Vec<_> = cells.iter().map(common::float).collect();
        cells_case(r, "exact", &size, &ecells, |c| ep.meet(c), area);
        cells_case(r, "float", &size, &fcells, |c| fp.meet(c), area);
        let ip = contenders::i_overlay_input(&panda);
        let meet_i = |c: &Curves| contenders::i_overlay_op(&ip, c, Op::Meet);
        cells_case(r, "i_overlay", &size, &cells, meet_i, |s| {
            contenders::i_overlay_area(s)
        });
        let gp = contenders::geo_input(&panda);
        let gcells: Vec<_> = cells.iter().map(contenders::geo_input).collect();
        let meet_g = |c: &geo::MultiPolygon<f64>| contenders::geo_op(&gp, c, Op::Meet);
        cells_case(r, "geo", &size, &gcells, meet_g, contenders::geo_area);
        let cp = contenders::clipper_input(&panda);
        let ccells: Vec<_> = cells.iter().map(contenders::clipper_input).collect();
        let meet_c =
            |c: &clipper2::Paths<contenders::Nano>| contenders::clipper_op(&cp, c, Op::Meet);
        cells_case(
            r,
            "clipper2",
            &size,
            &ccells,
            meet_c,
            contenders::clipper_area,
        );
    }
}

/// One W5 case: `meet` on every cell. When 1/64 of the cells already take more than 1/64 of
/// the skip limit, the case is skipped without the full call.
fn cells_case<C, O>(
    r: &mut Runner,
    contender: &str,
    size: &str,
    cells: &[C],
    meet: impl Fn(&C) -> O,
    area: impl Fn(&O) -> f64,
) {
    let group = "W5/meet_cells";
    let id = format!("{group}/{contender}/{size}");
    if r.filter.as_ref().is_some_and(|f| !id.contains(f.as_str())) {
        return;
    }
    let sample: Vec<&C> = cells.iter().step_by(64).collect();
    let cpu = process_cpu();
    for c in &sample {
        black_box(meet(c));
    }
    let estimate =
        process_cpu().saturating_sub(cpu).as_secs_f64() * cells.len() as f64 / sample.len() as f64;
    if !r.test_mode && estimate > SKIP_OVER.as_secs_f64() {
        println!(
            "# skip {id}: estimated {estimate:.0} s CPU for one iteration from {} cells",
            sample.len()
        );
        return;
    }
    r.case(
        group,
        contender,
        size,
        || cells.iter().map(&meet).collect::<Vec<_>>(),
        |v| show_area(v.iter().map(&area).sum()),
    );
}

/// W6: the union of 25 to 300 nearly coincident copies of a small polygon, filled
/// non-zero: ours from the rings in one fill, as `join_all` of the one-ring sets and as a fold of
/// binary joins of them, exact and float;
/// i_overlay's and Clipper2's union of the rings under the non-zero rule, geo's `unary_union`,
/// CGAL's union of the polygons.
fn w6(r: &mut Runner) {
    let sizes: &[usize] = if r.test_mode {
        &[10]
    } else {
        &[25, 50, 100, common::W6_COPIES]
    };
    r.growth = 2.0;
    for &size in sizes {
        if r.wants("W6/") {
            w6_union(r, size);
        }
    }
    r.growth = 1.5;
}

/// W6 with `size` copies.
fn w6_union(r: &mut Runner, size: usize) {
    let rings = common::w6(size);
    let exact_rings = common::rational_rings(&rings);
    let group = "W6/union";
    println!("# W6: {size} copies of {} vertices", rings[0].len());
    let by_cgal = cgal::harness().and_then(|_| {
        let file = cgal::write(&format!("W6_{size}.wkt"), &cgal::wkt_union(&exact_rings));
        cgal_case(r, group, size, "union", &[file])
    });
    let check = |y: &Result<YinSet2<Rational>, _>| match y {
        Ok(y) => checked_by_cgal(y, by_cgal.as_ref()),
        Err(e) => format!("error: {e}"),
    };
    let fill = || YinSet2::from_rings_filled(exact_rings.clone(), FillRule::NonZero);
    r.case(group, "exact_fill", size, fill, check);
    let sets: Vec<_> = rings
        .iter()
        .map(|c| common::exact(&vec![c.clone()]))
        .collect();
    // One thread, as the issue's table measures: the CPU time of rayon's second thread
    // waiting for work is not the operation's.
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    r.case(
        group,
        "exact_join_all",
        size,
        || one.install(|| YinSet2::join_all(&sets)),
        |y| checked_by_cgal(y, by_cgal.as_ref()),
    );
    let fold = || sets.iter().skip(1).fold(sets[0].clone(), |u, s| u.join(s));
    r.case(group, "exact_fold", size, fold, |y| {
        checked_by_cgal(y, by_cgal.as_ref())
    });
    let float_rings: Vec<Vec<Point<Float>>> = rings.iter().map(|c| common::points(c)).collect();
    let fill = || {
        YinSet2::from_rings_filled_with(
            float_rings.clone(),
            FillRule::NonZero,
            Tolerance::default(),
        )
        .unwrap_or_else(|e| panic!("W6 float fill: {e}"))
    };
    r.case(group, "float_fill", size, fill, show_set);
    let sets: Vec<_> = rings
        .iter()
        .map(|c| common::float(&vec![c.clone()]))
        .collect();
    r.case(
        group,
        "float_join_all",
        size,
        || one.install(|| YinSet2::join_all(&sets)),
        show_set,
    );
    let fold = || sets.iter().skip(1).fold(sets[0].clone(), |u, s| u.join(s));
    r.case(group, "float_fold", size, fold, show_set);
    let ir = contenders::i_overlay_input(&rings);
    r.case(
        group,
        "i_overlay",
        size,
        || contenders::i_overlay_union(&ir),
        |s| show_area(contenders::i_overlay_area(s)),
    );
    let gr = contenders::geo_input(&rings);
    r.case(
        group,
        "geo",
        size,
        || contenders::geo_union(&gr),
        |m| show_area(contenders::geo_area(m)),
    );
    let cr = contenders::clipper_input(&rings);
    r.case(
        group,
        "clipper2",
        size,
        || contenders::clipper_union(&cr),
        |p| show_area(contenders::clipper_area(p)),
    );
}

fn main() {
    let mut r = Runner::new();
    // Cheapest first.
    w4(&mut r);
    w3(&mut r);
    w6(&mut r);
    w2(&mut r);
    w5(&mut r);
    w1(&mut r);
    locate(&mut r);
    if !r.test_mode {
        r.c.final_summary();
    }
}
