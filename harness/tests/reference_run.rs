//! The committed reference run (`scripts/reference-run.sh`): every result in results/ measured at
//! one git revision, from committed code, so the revision REPORT.md states names what measured
//! every figure.

use std::collections::BTreeSet;
use std::path::Path;

use clipbench::report::revisions::of_folder;

#[test]
fn every_committed_result_names_one_revision() {
    let results = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("results");
    let revisions = of_folder(&results).unwrap();
    assert!(!revisions.is_empty(), "no .meta.json sidecar in {}", results.display());
    let distinct: BTreeSet<&str> = revisions.values().map(String::as_str).collect();
    assert_eq!(distinct.len(), 1, "results/ holds more than one revision: {revisions:#?}");
    let revision = distinct.first().copied().unwrap_or_default();
    assert!(
        !revision.ends_with("+dirty") && revision != "unknown",
        "results/ was measured at {revision}, which no commit names"
    );
}

/// The atlas (`scripts/atlas.sh`) judges the external clippers on every polygon workload: a
/// workload added to clip-testkit without the script would be missing from REPORT.md's atlas.
#[test]
fn the_atlas_script_runs_every_polygon_workload() {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("scripts").join("atlas.sh");
    let text = std::fs::read_to_string(&script).unwrap();
    let list = text.split("\nworkloads=(").nth(1).and_then(|rest| rest.split(')').next());
    let listed: BTreeSet<&str> = list.expect("atlas.sh sets workloads=(...)").split_whitespace().collect();
    let polygon: BTreeSet<&str> = clip_testkit::workload::POLYGON_WORKLOADS.iter().copied().collect();
    assert_eq!(listed, polygon, "scripts/atlas.sh's workloads differ from POLYGON_WORKLOADS");
}
