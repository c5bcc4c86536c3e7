//! One bench case clipped many times, for `perf record` and `valgrind --tool=callgrind`.
//!
//! ```sh
//! cargo build --release -p clip-vatti --example profile_case
//! target/release/examples/profile_case scribble 200 intersection 2000
//! valgrind --tool=callgrind target/release/examples/profile_case large 100000 xor 1
//! ```
//!
//! Arguments: workload (a clip-testkit workload; `large` case 0 is the bench's `large-smooth`,
//! case 1 `large-checkerboard`), subject edges, operation, repetitions, then optionally the case
//! index (default 0), `rect` for a rectangle window and `scanbeam` or `events` to fix the sweep;
//! seed 1 and even-odd, as in the bench.
//! Allocations are counted by the `alloc_case` example, so this binary runs on the plain
//! system allocator, as the bench does.

mod case_args;

use std::hint::black_box;
use std::process::ExitCode;
use std::time::Instant;

use clip_core::FillRule;

fn main() -> ExitCode {
    let a = match case_args::parse("profile_case") {
        Ok(a) => a,
        Err(e) => {
            eprintln!("profile_case: {e}");
            return ExitCode::FAILURE;
        }
    };
    let (s, c) = (&a.case.subject, &a.case.clip);
    let clipper = a.clipper();
    let out = match clipper.clip(s, c, a.op, FillRule::EvenOdd) {
        Ok(out) => out,
        Err(e) => {
            eprintln!("profile_case: {e}");
            return ExitCode::FAILURE;
        }
    };
    let out_vertices: usize = out.rings.iter().map(|r| r.points.len()).sum();
    let start = Instant::now();
    for _ in 0..a.repetitions {
        black_box(clipper.clip(black_box(s), c, a.op, FillRule::EvenOdd).ok());
    }
    let per_call = start.elapsed().as_secs_f64() / a.repetitions.max(1) as f64;
    println!(
        "{}: {} input vertices, {out_vertices} output vertices in {} rings; {:.1} µs per call over {}",
        a.label,
        a.vertices,
        out.rings.len(),
        per_call * 1e6,
        a.repetitions
    );
    ExitCode::SUCCESS
}
