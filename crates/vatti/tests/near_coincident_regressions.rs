//! Cases of the `near-coincident` workload (seed 1) that `clipbench verify` found invalid, as
//! named tests: every operation and fill rule of each, through [`Vatti`] and a prepared clip,
//! must pass the exact oracle, form included.

use clip_core::{BoolOp, FillRule, PolygonClipper, WindowKind};
use clip_oracle::polygon::{OutputRules, REGION_TOLERANCE, check_polygon_result};
use clip_testkit::workload::polygon_case;
use clip_vatti::{Vatti, VattiPrepared};

fn assert_case_passes(index: usize) {
    let case = polygon_case("near-coincident", 1, index, WindowKind::Any).expect("a workload case");
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    let clippers: [(&str, &dyn PolygonClipper); 2] = [("vatti", &Vatti), ("vatti-prepared", &VattiPrepared)];
    for (name, clipper) in clippers {
        for op in BoolOp::ALL {
            for fill in FillRule::ALL {
                let out = clipper.clip(&case.subject, &case.clip, op, fill).expect("valid input");
                let verdict = check_polygon_result(&case.subject, &case.clip, op, fill, &out, &rules);
                assert!(verdict.is_ok(), "case {index} {name} {op} {fill}: {}", verdict.unwrap_err());
            }
        }
    }
}

/// Two edges swapped at the vertex they share, in the snap fallback's sweep: the crossing's
/// quotient put the point an ulp beside the vertex (`bot.x * den / den`), and mapped back the
/// ring visited the vertex twice (difference and xor, even-odd).
#[test]
fn a_swap_at_a_shared_vertex_is_output_at_the_vertex() {
    assert_case_passes(982);
}

/// A needle's xor at 1e6: two rings met at a rounded crossing and crossed there, which no pair
/// of edges shows; the form check now looks at the passes through each shared point.
#[test]
fn rings_crossing_at_a_shared_vertex_are_caught() {
    assert_case_passes(580);
}

/// A self-crossing ring's xor: a sliver ring crossed itself between two crossings rounded 100
/// ulps apart, in an output of about 1,100 edges, above the form check's old limit of 1,024.
#[test]
fn a_sliver_crossing_itself_in_a_larger_output_is_caught() {
    assert_case_passes(768);
}
