//! Allocations and peak heap of one clip of a bench case, counted by `dhat`'s allocator.
//!
//! ```sh
//! cargo run --release -p clip-vatti --example alloc_case -- large 1000000 intersection 1
//! ```
//!
//! Arguments as for the `profile_case` example. Prints the allocations of one call (the mean over
//! the repetitions), allocations per input vertex and the peak of live heap bytes during the
//! calls above what was live before them.

mod case_args;

use std::process::ExitCode;

use clip_core::FillRule;

#[global_allocator]
static ALLOC: dhat::Alloc = dhat::Alloc;

fn main() -> ExitCode {
    let a = match case_args::parse("alloc_case") {
        Ok(a) => a,
        Err(e) => {
            eprintln!("alloc_case: {e}");
            return ExitCode::FAILURE;
        }
    };
    let _profiler = dhat::Profiler::builder().testing().build();
    let before = dhat::HeapStats::get();
    let clipper = a.clipper();
    let out = clipper.clip(&a.case.subject, &a.case.clip, a.op, FillRule::EvenOdd);
    for _ in 1..a.repetitions {
        drop(clipper.clip(&a.case.subject, &a.case.clip, a.op, FillRule::EvenOdd));
    }
    let after = dhat::HeapStats::get();
    let out = match out {
        Ok(out) => out,
        Err(e) => {
            eprintln!("alloc_case: {e}");
            return ExitCode::FAILURE;
        }
    };
    let allocations = (after.total_blocks - before.total_blocks) as f64 / a.repetitions.max(1) as f64;
    let out_vertices: usize = out.rings.iter().map(|r| r.points.len()).sum();
    println!(
        "{}: {} input vertices, {out_vertices} output vertices; {allocations:.1} allocations per call ({:.3} per input vertex), \
         peak heap {:.1} KiB above the inputs, output {:.1} KiB",
        a.label,
        a.vertices,
        allocations / a.vertices as f64,
        (after.max_bytes - before.curr_bytes) as f64 / 1024.0,
        (after.curr_bytes - before.curr_bytes) as f64 / 1024.0,
    );
    ExitCode::SUCCESS
}
