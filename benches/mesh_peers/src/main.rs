//! `mesh_peers boolmesh meet|join A.obj B.obj [--reps N]`: one Boolean of two OBJ meshes
//! (read as f64, polygons fan-triangulated) by the pure-Rust peer boolmesh, printed as one JSON line with
//! the shape of ../shared/tools/manifold3d's: `time_ms` (best process-CPU ms of the Boolean
//! alone over the reps), `volume` and `triangles` of the result, `status` ("ok" or the peer's
//! error).

use std::time::Duration;

/// A triangle mesh read from OBJ.
struct Mesh {
    points: Vec<[f64; 3]>,
    tris: Vec<[usize; 3]>,
}

/// The `v` and `f` lines of an OBJ file (1-based or negative indices, `i/j/k` forms).
fn read_obj(path: &str) -> Result<Mesh, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut points = Vec::new();
    let mut tris = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut w = line.split_whitespace();
        match w.next() {
            Some("v") => {
                let c: Vec<f64> = w
                    .take(3)
                    .map(|s| s.parse().map_err(|e| format!("{path}:{}: {e}", n + 1)))
                    .collect::<Result<_, _>>()?;
                points.push([c[0], c[1], c[2]]);
            }
            Some("f") => {
                let ids: Vec<usize> = w
                    .map(|s| {
                        let i: i64 = s
                            .split('/')
                            .next()
                            .unwrap_or("")
                            .parse()
                            .map_err(|e| format!("{path}:{}: {e}", n + 1))?;
                        Ok(if i < 0 {
                            points.len() as i64 + i
                        } else {
                            i - 1
                        } as usize)
                    })
                    .collect::<Result<_, String>>()?;
                for k in 1..ids.len().saturating_sub(1) {
                    tris.push([ids[0], ids[k], ids[k + 1]]);
                }
            }
            _ => {}
        }
    }
    Ok(Mesh { points, tris })
}

/// The signed volume of closed triangles.
fn volume(points: &[[f64; 3]], tris: &[[usize; 3]]) -> f64 {
    tris.iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| points[v]);
            a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0])
        })
        .sum::<f64>()
        / 6.0
}

/// This process's CPU time.
fn cpu() -> Duration {
    let mut ts = libc_timespec { s: 0, ns: 0 };
    // SAFETY: clock_gettime writes one timespec into the pointer it is given.
    unsafe { clock_gettime(2, &mut ts) }; // CLOCK_PROCESS_CPUTIME_ID
    Duration::new(ts.s as u64, ts.ns as u32)
}

#[repr(C)]
struct libc_timespec {
    s: i64,
    ns: i64,
}
extern "C" {
    fn clock_gettime(clock: i32, ts: *mut libc_timespec) -> i32;
}

/// Run `op` `reps` times; the best CPU milliseconds and the last result.
fn best<T>(reps: usize, mut op: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..reps {
        let t0 = cpu();
        let r = op();
        best = best.min((cpu() - t0).as_secs_f64() * 1e3);
        last = Some(r);
    }
    (best, last.expect("reps ≥ 1"))
}

/// boolmesh: Manifold's algorithm in Rust; its constructor rejects non-manifold input.
fn boolmesh(op: &str, a: &Mesh, b: &Mesh, reps: usize) -> serde_json::Value {
    use boolmesh::prelude::*;
    let make = |m: &Mesh| {
        let pos: Vec<f64> = m.points.iter().flatten().copied().collect();
        let idx: Vec<usize> = m.tris.iter().flatten().copied().collect();
        Manifold::new(&pos, &idx)
    };
    let (x, y) = match (make(a), make(b)) {
        (Ok(x), Ok(y)) => (x, y),
        (Err(e), _) | (_, Err(e)) => {
            return serde_json::json!({"status": format!("rejected input: {e}")})
        }
    };
    let kind = || {
        if op == "join" {
            OpType::Add
        } else {
            OpType::Intersect
        }
    };
    let (ms, r) = best(reps, || compute_boolean(&x, &y, kind()));
    match r {
        Ok(m) => {
            let points: Vec<[f64; 3]> = m.ps.iter().map(|p| [p.x, p.y, p.z]).collect();
            let tails: Vec<usize> = m.hs.iter().map(|h| h.tail).collect();
            let tris: Vec<[usize; 3]> = tails.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
            serde_json::json!({"status": "ok", "time_ms": ms, "triangles": tris.len(),
                "volume": volume(&points, &tris)})
        }
        Err(e) => serde_json::json!({"status": format!("failed: {e}"), "time_ms": ms}),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: mesh_peers boolmesh meet|join A.obj B.obj [--reps N]";
    if args.len() < 5 {
        eprintln!("{usage}");
        std::process::exit(2);
    }
    let reps = args
        .iter()
        .position(|a| a == "--reps")
        .and_then(|i| args.get(i + 1)?.parse().ok())
        .unwrap_or(3);
    let (a, b) = match (read_obj(&args[3]), read_obj(&args[4])) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let out = match args[1].as_str() {
        "boolmesh" => boolmesh(&args[2], &a, &b, reps),
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    };
    println!("{out}");
}
