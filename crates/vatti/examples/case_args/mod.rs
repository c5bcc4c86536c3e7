//! The command line shared by the profiling examples: which bench case to clip.

use clip_core::{BoolOp, PolygonClipper, WindowKind};
use clip_testkit::workload::{PolygonCase, polygon_case_sized};
use clip_vatti::{FixedSweep, Sweep, Vatti};

/// One bench case and how often to clip it.
pub struct CaseArgs {
    /// What the case is, for the printout.
    pub label: String,
    pub case: PolygonCase,
    pub op: BoolOp,
    pub repetitions: usize,
    /// Input vertices of both operands.
    pub vertices: usize,
    /// The sweep asked for (`scanbeam` or `events`), or `None` for `Vatti`'s own choice.
    pub sweep: Option<Sweep>,
}

/// Reads `WORKLOAD EDGES OP REPETITIONS [INDEX] [rect] [scanbeam|events]` (seed 1, as the
/// bench).
pub fn parse(usage: &str) -> Result<CaseArgs, String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 4 {
        return Err(format!("usage: {usage} WORKLOAD EDGES OP REPETITIONS [INDEX] [rect] [scanbeam|events]"));
    }
    let edges: usize = args[1].parse().map_err(|_| format!("bad EDGES '{}'", args[1]))?;
    let op: BoolOp = args[2].parse().map_err(|e| format!("{e}"))?;
    let repetitions: usize = args[3].parse().map_err(|_| format!("bad REPETITIONS '{}'", args[3]))?;
    let index = args.get(4).and_then(|s| s.parse().ok()).unwrap_or(0);
    let rect = args.iter().any(|a| a == "rect");
    let sweep = args.iter().find_map(|a| match a.as_str() {
        "scanbeam" => Some(Sweep::Scanbeam),
        "events" => Some(Sweep::Events),
        _ => None,
    });
    let window = if rect { WindowKind::Rectangle } else { WindowKind::Any };
    let case = polygon_case_sized(&args[0], 1, index, edges, window).map_err(|e| e.to_string())?;
    let vertices = [&case.subject, &case.clip].iter().flat_map(|p| &p.rings).map(|r| r.points.len()).sum();
    let label = format!("{} {edges} {} case {index}{}", args[0], op.name(), if rect { " rect" } else { "" });
    Ok(CaseArgs { label, case, op, repetitions, vertices, sweep })
}

impl CaseArgs {
    /// The clipper to run: [`Vatti`], or its sweep fixed when one was asked for.
    pub fn clipper(&self) -> Box<dyn PolygonClipper> {
        match self.sweep {
            Some(s) => Box::new(FixedSweep(s)),
            None => Box::new(Vatti),
        }
    }
}
