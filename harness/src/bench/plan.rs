//! What `bench` measures: groups of cases (a workload, a window kind, case indices, sizes, ops).

use clip_core::{BoolOp, WindowKind};
use clip_testkit::workload::MapScale;

use crate::cli_error::CliError;
use crate::results_files::bench::TEXT_GROUP;

/// One group of the benchmark: a plot and a table each.
#[derive(Clone, Debug)]
pub struct Group {
    /// Name in the result files (`star`, `large-smooth`, `star-rect`, ...).
    pub label: &'static str,
    /// The clip-testkit workload the cases come from.
    pub workload: &'static str,
    /// The clip operand: the workload's own (`Any`) or a rectangle over the subject.
    pub window: WindowKind,
    /// Case indices; times are averaged over them.
    pub indices: Vec<usize>,
    /// Subject edge counts, ascending.
    pub sizes: Vec<usize>,
    /// Operations timed.
    pub ops: Vec<BoolOp>,
    /// Peak memory is measured too, under the group's first operation, at the sizes from this
    /// one on (none: not measured).
    pub memory_from: Option<usize>,
}

impl Group {
    /// Whether peak memory is measured at `size` under `op`.
    pub fn measures_memory(&self, size: usize, op: BoolOp) -> bool {
        self.memory_from.is_some_and(|from| size >= from) && self.ops.first() == Some(&op)
    }
}

impl Group {
    /// The group in words, for the sidecar.
    pub fn describe(&self) -> String {
        format!(
            "{}: workload {}, window {:?}, cases {:?}, sizes {:?}, ops {}",
            self.label,
            self.workload,
            self.window,
            self.indices,
            self.sizes,
            self.ops.iter().map(|o| o.name()).collect::<Vec<_>>().join("/")
        )
    }
}

/// The groups: `star`, `scribble`, `grid`, `holes` at 4-200 edges with three cases each;
/// `large` smooth blobs (even indices) and checkerboards (odd indices) up to 10^6 vertices (10^5
/// quick); rectangle windows over `star` and `large` smooth subjects, intersection only, where the
/// window-limited clippers join (Sutherland-Hodgman, four-state, and Clipper2's dedicated
/// rectangle clipper `clipper2-rect`, the peer to compare them with); `spiky-box` (Vatti's
/// envelope pre-filter) at the large sizes and `many-subjects` (small subjects over one clip of
/// 10^3 or 10^5 edges, 10^4 quick; times per subject; the prepared clip's case), all operations;
/// `near-coincident` (a notched star against its copy turned by a tiny angle, shifted by ulps or
/// traced a few ulps off, one case of each) at the large sizes, all operations: what robustness
/// costs where every crossing is shallow.
///
/// Then the groups that stress a sweep, sized by the edges of both operands from 10^2 to 10^6
/// (10^5 quick), peak memory from 10^4 on (`lines-net` from 10^3): `comb` (comb against comb
/// shifted half a tooth) and `comb-box` (comb against a box of 1% of its area), all four
/// operations; i_overlay's
/// performance suite under the operation it times: `nested` ⊕, `concentric` ∩, `spiral` ∪ (with
/// itself: an empty clip), `windows` −, `corrosion` −, `lines-net` ∩ (up to 3·10^3 edges: its
/// result has (edges / 8)² squares, 1.4·10^5 at 3·10^3), `checkerboard` ⊕, `not-overlap` ∪,
/// `wind-mill` −; and the world map at its three scales (10^4, 10^5, 5·10^5 edges; quick: the
/// first two): `maps-dissolve` ∪, `maps-tiles` ∩ and `maps-neighbours` −.
pub fn groups(quick: bool) -> Vec<Group> {
    let small: Vec<usize> = if quick { vec![4, 20, 100, 200] } else { vec![4, 10, 20, 40, 100, 200] };
    let large: Vec<usize> = if quick { vec![1_000, 10_000, 100_000] } else { vec![1_000, 10_000, 100_000, 1_000_000] };
    let cases: Vec<usize> = if quick { vec![0, 1] } else { vec![0, 1, 2] };
    let all = BoolOp::ALL.to_vec();
    let any = |label, workload| Group {
        label,
        workload,
        window: WindowKind::Any,
        indices: cases.clone(),
        sizes: small.clone(),
        ops: all.clone(),
        memory_from: None,
    };
    vec![
        any("star", "star"),
        any("scribble", "scribble"),
        any("grid", "grid"),
        any("holes", "holes"),
        Group {
            label: "large-smooth",
            workload: "large",
            window: WindowKind::Any,
            indices: vec![0],
            sizes: large.clone(),
            ops: all.clone(),
            memory_from: Some(0),
        },
        Group {
            label: "large-checkerboard",
            workload: "large",
            window: WindowKind::Any,
            indices: vec![1],
            sizes: large.clone(),
            ops: all.clone(),
            memory_from: Some(0),
        },
        Group {
            label: "star-rect",
            workload: "star",
            window: WindowKind::Rectangle,
            indices: cases,
            sizes: small,
            ops: vec![BoolOp::Intersection],
            memory_from: None,
        },
        Group {
            label: "spiky-box",
            workload: "spiky-box",
            window: WindowKind::Any,
            indices: vec![0],
            sizes: large.clone(),
            ops: BoolOp::ALL.to_vec(),
            memory_from: Some(0),
        },
        Group {
            label: "many-subjects",
            workload: "many-subjects",
            window: WindowKind::Any,
            // Subjects, each a case over the same clip; the sizes are the clip's edges.
            indices: (0..if quick { 16 } else { 48 }).collect(),
            // Clipper2 spends minutes per subject over a 10^5-edge lobed clip (its intersection
            // list), so quick runs stop at 10^4.
            sizes: if quick { vec![1_000, 10_000] } else { vec![1_000, 100_000] },
            ops: BoolOp::ALL.to_vec(),
            memory_from: None,
        },
        Group {
            label: "near-coincident",
            workload: "near-coincident",
            window: WindowKind::Any,
            // Index mod 3 picks the clip: turned, shifted, traced.
            indices: vec![0, 1, 2],
            sizes: large.clone(),
            ops: BoolOp::ALL.to_vec(),
            memory_from: None,
        },
        Group {
            label: "large-rect",
            workload: "large",
            window: WindowKind::Rectangle,
            indices: vec![0],
            sizes: large,
            ops: vec![BoolOp::Intersection],
            memory_from: Some(0),
        },
    ]
    .into_iter()
    .chain(sweep_groups(quick))
    .collect()
}

/// The groups that stress a sweep (see [`groups`]).
fn sweep_groups(quick: bool) -> Vec<Group> {
    let sizes: Vec<usize> =
        if quick { vec![100, 1_000, 10_000, 100_000] } else { vec![100, 1_000, 10_000, 100_000, 1_000_000] };
    let scales = if quick { &MapScale::ALL[..2] } else { &MapScale::ALL[..] };
    let map_sizes: Vec<usize> = scales.iter().map(|s| s.edges()).collect();
    let group = |label, workload, index, sizes: &[usize], ops: &[BoolOp]| Group {
        label,
        workload,
        window: WindowKind::Any,
        indices: vec![index],
        sizes: sizes.to_vec(),
        ops: ops.to_vec(),
        memory_from: Some(SWEEP_MEMORY_FROM),
    };
    use BoolOp::{Difference, Intersection, Union, Xor};
    vec![
        // Even indices of `comb` pair two combs, odd ones a comb and a box.
        group("comb", "comb", 0, &sizes, &BoolOp::ALL),
        group("comb-box", "comb", 1, &sizes, &BoolOp::ALL),
        group("nested", "nested", 0, &sizes, &[Xor]),
        group("concentric", "concentric", 0, &sizes, &[Intersection]),
        group("spiral", "spiral", 0, &sizes, &[Union]),
        group("windows", "windows", 0, &sizes, &[Difference]),
        group("corrosion", "corrosion", 0, &sizes, &[Difference]),
        // Its result has (edges / 8)² squares: 1.4·10^5 at 3·10^3 edges (i_overlay takes seconds
        // at 10^4 for 1.6·10^6 of them), so its large sizes start lower.
        Group { memory_from: Some(1_000), ..group("lines-net", "lines-net", 0, &[100, 1_000, 3_000], &[Intersection]) },
        group("checkerboard", "checkerboard", 0, &sizes, &[Xor]),
        group("not-overlap", "not-overlap", 0, &sizes, &[Union]),
        group("wind-mill", "wind-mill", 0, &sizes, &[Difference]),
        // `maps` index mod 3: a dissolve, tiles, a country minus its neighbours.
        group("maps-dissolve", "maps", 0, &map_sizes, &[Union]),
        group("maps-tiles", "maps", 1, &map_sizes, &[Intersection]),
        group("maps-neighbours", "maps", 2, &map_sizes, &[Difference]),
    ]
}

/// The smallest size at which the sweep groups measure peak memory.
const SWEEP_MEMORY_FROM: usize = 10_000;

/// The groups named in `labels` (all when none) with only the operations in `ops` (all when
/// none); groups left without an operation are dropped. Unknown names are usage errors.
pub fn select(groups: Vec<Group>, labels: &[String], ops: &[BoolOp]) -> Result<Vec<Group>, CliError> {
    if let Some(unknown) = labels.iter().find(|l| !groups.iter().any(|g| g.label == l.as_str())) {
        let valid: Vec<&str> = groups.iter().map(|g| g.label).chain([TEXT_GROUP]).collect();
        return Err(CliError::usage(format!("unknown bench group '{unknown}' (groups: {})", valid.join(", "))));
    }
    let selected: Vec<Group> = groups
        .into_iter()
        .filter(|g| labels.is_empty() || labels.iter().any(|l| l == g.label))
        .filter_map(|mut g| {
            if !ops.is_empty() {
                g.ops.retain(|o| ops.contains(o));
            }
            (!g.ops.is_empty()).then_some(g)
        })
        .collect();
    if selected.is_empty() {
        return Err(CliError::usage("nothing to bench: no selected group runs the selected operations"));
    }
    Ok(selected)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn select_keeps_the_named_groups_and_operations() {
        let picked = select(groups(true), &["scribble".to_owned(), "large-rect".to_owned()], &[BoolOp::Xor]).unwrap();
        // large-rect times intersection only, so xor leaves only scribble.
        assert_eq!(picked.iter().map(|g| g.label).collect::<Vec<_>>(), vec!["scribble"]);
        assert_eq!(picked[0].ops, vec![BoolOp::Xor]);
        assert_eq!(select(groups(true), &[], &[]).unwrap().len(), groups(true).len());
        assert!(select(groups(true), &["nope".to_owned()], &[]).is_err());
        assert!(select(groups(true), &["large-rect".to_owned()], &[BoolOp::Union]).is_err());
    }

    #[test]
    fn the_sweep_groups_are_planned_on_known_workloads() {
        use clip_testkit::workload::SWEEP_WORKLOADS;
        for quick in [true, false] {
            let all = groups(quick);
            for w in SWEEP_WORKLOADS {
                assert!(all.iter().any(|g| g.workload == *w), "no group runs {w}");
            }
            for label in ["comb-box", "maps-dissolve", "maps-tiles", "maps-neighbours"] {
                assert!(all.iter().any(|g| g.label == label), "no group {label}");
            }
            for g in all.iter().filter(|g| SWEEP_WORKLOADS.contains(&g.workload)) {
                let label = g.label;
                assert!(g.sizes.windows(2).all(|w| w[0] < w[1]), "{label}: {:?}", g.sizes);
                // Memory at the large sizes, under an operation the group runs.
                let top = *g.sizes.last().unwrap();
                assert!(g.measures_memory(top, g.ops[0]) && !g.measures_memory(100, g.ops[0]), "{label}");
                let biggest = if label == "lines-net" {
                    3_000
                } else if quick {
                    100_000
                } else {
                    1_000_000
                };
                if g.workload != "maps" {
                    assert_eq!((g.sizes[0], top), (100, biggest), "{label}");
                }
            }
            let mut labels: Vec<&str> = all.iter().map(|g| g.label).collect();
            labels.sort_unstable();
            labels.dedup();
            assert_eq!(labels.len(), all.len(), "group labels repeat");
        }
        // The old memory groups still measure every size under intersection.
        let large = groups(false).into_iter().find(|g| g.label == "large-smooth").unwrap();
        assert!(large.measures_memory(1_000, BoolOp::Intersection) && !large.measures_memory(1_000, BoolOp::Union));
    }
}
