//! What `bench` measures: groups of cases (a workload, a window kind, case indices, sizes, ops).

use clip_core::{BoolOp, WindowKind};

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
    /// Whether peak memory is measured too.
    pub memory: bool,
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
/// 10^3 or 10^5 edges, 10^4 quick; times per subject; the prepared clip's case), all operations.
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
        memory: false,
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
            memory: true,
        },
        Group {
            label: "large-checkerboard",
            workload: "large",
            window: WindowKind::Any,
            indices: vec![1],
            sizes: large.clone(),
            ops: all,
            memory: true,
        },
        Group {
            label: "star-rect",
            workload: "star",
            window: WindowKind::Rectangle,
            indices: cases,
            sizes: small,
            ops: vec![BoolOp::Intersection],
            memory: false,
        },
        Group {
            label: "spiky-box",
            workload: "spiky-box",
            window: WindowKind::Any,
            indices: vec![0],
            sizes: large.clone(),
            ops: BoolOp::ALL.to_vec(),
            memory: true,
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
            memory: false,
        },
        Group {
            label: "large-rect",
            workload: "large",
            window: WindowKind::Rectangle,
            indices: vec![0],
            sizes: large,
            ops: vec![BoolOp::Intersection],
            memory: true,
        },
    ]
}

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
}
