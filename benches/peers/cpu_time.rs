//! Criterion measurement of the process's CPU time (`CLOCK_PROCESS_CPUTIME_ID`, all its
//! threads) instead of wall time: the machine is shared, and the CPU time is the figure that
//! other processes disturb least. All threads, because our n-ary operations and cuts run on
//! rayon's pool: the benchmarking thread's own CPU time would not see that work.

use criterion::measurement::{Measurement, ValueFormatter};
use criterion::Throughput;
use std::time::Duration;

#[repr(C)]
struct Timespec {
    tv_sec: i64,
    tv_nsec: i64,
}

extern "C" {
    fn clock_gettime(clock: i32, tp: *mut Timespec) -> i32;
}

/// Linux's clock id of the calling process's CPU time.
const CLOCK_PROCESS_CPUTIME_ID: i32 = 2;

/// The process's CPU time so far, over all its threads.
pub fn process_cpu() -> Duration {
    let mut t = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `clock_gettime` writes one `struct timespec` (two 64-bit fields on x86_64 and
    // aarch64 Linux) to a valid pointer and reads nothing else.
    let rc = unsafe { clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    assert_eq!(rc, 0, "clock_gettime(CLOCK_PROCESS_CPUTIME_ID) failed");
    Duration::new(t.tv_sec as u64, t.tv_nsec as u32)
}

/// The process's CPU time, in nanoseconds like criterion's wall time.
pub struct CpuTime;

impl Measurement for CpuTime {
    type Intermediate = Duration;
    type Value = Duration;

    fn start(&self) -> Duration {
        process_cpu()
    }
    fn end(&self, start: Duration) -> Duration {
        process_cpu().saturating_sub(start)
    }
    fn add(&self, a: &Duration, b: &Duration) -> Duration {
        *a + *b
    }
    fn zero(&self) -> Duration {
        Duration::ZERO
    }
    fn to_f64(&self, v: &Duration) -> f64 {
        v.as_nanos() as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        &Nanoseconds
    }
}

/// Formats nanoseconds as ns, µs, ms or s.
struct Nanoseconds;

impl ValueFormatter for Nanoseconds {
    fn scale_values(&self, ns: f64, values: &mut [f64]) -> &'static str {
        let (factor, unit) = if ns < 1e3 {
            (1.0, "ns")
        } else if ns < 1e6 {
            (1e-3, "µs")
        } else if ns < 1e9 {
            (1e-6, "ms")
        } else {
            (1e-9, "s")
        };
        for v in values {
            *v *= factor;
        }
        unit
    }

    fn scale_throughputs(&self, ns: f64, t: &Throughput, values: &mut [f64]) -> &'static str {
        let per = match t {
            Throughput::Bytes(n) | Throughput::BytesDecimal(n) | Throughput::Elements(n) => {
                *n as f64
            }
        };
        for v in values {
            *v = per * 1e9 / *v;
        }
        let _ = ns;
        "per s"
    }

    fn scale_for_machines(&self, _values: &mut [f64]) -> &'static str {
        "ns"
    }
}

#[repr(C)]
struct Timeval {
    tv_sec: i64,
    tv_usec: i64,
}

/// Linux's `struct rusage`: the user and system times, then 14 counters of `long`.
#[repr(C)]
struct Rusage {
    ru_utime: Timeval,
    ru_stime: Timeval,
    #[allow(dead_code)] // written by getrusage, not read here
    counters: [i64; 14],
}

extern "C" {
    fn getrusage(who: i32, usage: *mut Rusage) -> i32;
}

/// Linux's `RUSAGE_CHILDREN`: the children of the calling process that have been waited for.
const RUSAGE_CHILDREN: i32 = -1;

/// The CPU time (user and system) of this process's waited-for children so far.
#[allow(dead_code)] // only the benches that spawn processes use it
pub fn children_cpu() -> Duration {
    let zero = || Timeval {
        tv_sec: 0,
        tv_usec: 0,
    };
    let mut r = Rusage {
        ru_utime: zero(),
        ru_stime: zero(),
        counters: [0; 14],
    };
    // SAFETY: `getrusage` writes one `struct rusage` (two `struct timeval` of two 64-bit fields
    // and 14 `long`s on x86_64 and aarch64 Linux) to a valid pointer and reads nothing else.
    let rc = unsafe { getrusage(RUSAGE_CHILDREN, &mut r) };
    assert_eq!(rc, 0, "getrusage(RUSAGE_CHILDREN) failed");
    let d = |t: &Timeval| Duration::new(t.tv_sec as u64, 1000 * t.tv_usec as u32);
    d(&r.ru_utime) + d(&r.ru_stime)
}
