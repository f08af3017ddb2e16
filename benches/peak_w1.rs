//! Peak memory of W1 at n = 10⁶: builds the two random star-shaped polygons
//! of benches/peers.rs (10⁶ vertices each) in float mode and meets them once; prints the CPU
//! times and the process's peak resident set (VmHWM). Run it under `/usr/bin/time -v`:
//!
//! ```sh
//! cargo bench --bench peak_w1 --no-run
//! /usr/bin/time -v target/release/deps/peak_w1-<hash> [N] [float|exact-inputs|i_overlay]
//! ```
//!
//! `float` (the default) is the measured case. `exact-inputs` only builds the two operands in
//! exact mode (the exact meet itself is out of reach at this size: see BENCHMARKS.md);
//! `i_overlay` runs the peer's intersection on the same coordinates, for comparison.

#[path = "common/mod.rs"]
mod common;

use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;
use std::hint::black_box;
use std::time::Instant;

/// The process's peak resident set so far, from /proc/self/status.
fn vm_hwm() -> String {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM"))
                .map(|l| l.split_whitespace().skip(1).collect::<Vec<_>>().join(" "))
        })
        .unwrap_or_else(|| "unknown".into())
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let n: usize = args
        .iter()
        .find_map(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let mode = args
        .iter()
        .find(|a| a.parse::<usize>().is_err())
        .map_or("float", String::as_str);
    let t = Instant::now();
    let (a, b) = common::w1(n);
    println!(
        "W1 n = {n}: curves generated in {:.2} s; peak RSS {}",
        t.elapsed().as_secs_f64(),
        vm_hwm()
    );
    match mode {
        "float" => {
            let t = Instant::now();
            let (fa, fb) = (common::float(&a), common::float(&b));
            println!(
                "float operands built in {:.2} s; peak RSS {}",
                t.elapsed().as_secs_f64(),
                vm_hwm()
            );
            let t = Instant::now();
            let m = black_box(fa.meet(&fb));
            println!(
                "float meet in {:.2} s: {} curves, {} vertices; peak RSS {}",
                t.elapsed().as_secs_f64(),
                m.curves().len(),
                m.curves().iter().map(|c| c.len()).sum::<usize>(),
                vm_hwm()
            );
        }
        "exact-inputs" => {
            let t = Instant::now();
            let (ea, eb) = (common::exact(&a), common::exact(&b));
            black_box((&ea, &eb));
            println!(
                "exact operands built in {:.2} s; peak RSS {}",
                t.elapsed().as_secs_f64(),
                vm_hwm()
            );
        }
        "i_overlay" => {
            let t = Instant::now();
            let r = black_box(a.overlay(&b, OverlayRule::Intersect, FillRule::EvenOdd));
            println!(
                "i_overlay intersection in {:.2} s: {} shapes; peak RSS {}",
                t.elapsed().as_secs_f64(),
                r.len(),
                vm_hwm()
            );
        }
        other => panic!("unknown mode {other}: float, exact-inputs or i_overlay"),
    }
}
