//! The bench judges what it times: every clipper's result on every case is checked before its
//! time counts. The exact oracle where its area sweep is affordable; past that, the result's form
//! (exact and O(n log n) on every input, so always checked for conventional output) and its area
//! against the exact area of the answer (one sweep of the operands, shared by every clipper);
//! past that too (combs of 10^5 edges and more), the form and the oracle's exact sample points,
//! which are linear in the edges and say so.

use std::collections::BTreeMap;

use clip_core::{BoolOp, FillRule, Polygons};
use clip_oracle::polygon::{
    OutputRules, check_polygon_samples, check_valid_output, region_area, region_area_work, tolerance,
};
use clip_testkit::workload::PolygonCase;

use crate::checks::polygon_oracle_under;
use crate::registry::PolygonEntry;

/// The most edge-slab pairs one area sweep may visit (about a second): the full oracle sweeps the
/// operands and the result together, the area check sweeps the operands alone.
pub const CHECK_WORK: u64 = 100_000_000;

/// How one timed result was judged.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// It passed the oracle, or its area matched the exact area.
    Right,
    /// Only the oracle's sample points were affordable, and it passed them.
    RightAtSamples,
    /// It failed: why.
    Wrong(String),
    /// No check was affordable (a bridged result too costly to measure): why.
    Unchecked(String),
}

impl Verdict {
    /// The `correct` column of bench.csv: empty when unchecked.
    pub fn column(&self) -> Option<bool> {
        match self {
            Verdict::Right | Verdict::RightAtSamples => Some(true),
            Verdict::Wrong(_) => Some(false),
            Verdict::Unchecked(_) => None,
        }
    }
}

/// Judges results on the cases of one size, remembering each exact area it measured so every
/// clipper's result on the same case, operation and rule is held to one sweep.
#[derive(Default)]
pub struct Judge {
    exact_areas: BTreeMap<(usize, BoolOp, FillRule), Option<f64>>,
    /// Per case: whether its subject passed the exact form check, which decides how a clipper
    /// conventional only for conventional subjects is read (split Sutherland-Hodgman).
    subject_conventional: BTreeMap<usize, bool>,
}

impl Judge {
    /// The verdict on `output`, `entry`'s result of case number `slot` under `op` and `fill`.
    pub fn judge(
        &mut self,
        entry: &PolygonEntry,
        slot: usize,
        case: &PolygonCase,
        op: BoolOp,
        fill: FillRule,
        output: &Polygons,
    ) -> Verdict {
        let (subject, clip) = (&case.subject, &case.clip);
        let rules = self.output_rules(entry, slot, subject, fill);
        let operands = [(subject, fill), (clip, fill)];
        let full = [(subject, fill), (clip, fill), (output, rules.output_fill)];
        if region_area_work(&full) <= CHECK_WORK {
            return match polygon_oracle_under(&rules, subject, clip, op, fill, output) {
                Ok(_) => Verdict::Right,
                Err(why) => Verdict::Wrong(why.to_string()),
            };
        }
        if rules.conventional
            && let Err(why) = check_valid_output(output)
        {
            return Verdict::Wrong(why.to_string());
        }
        let exact = *self.exact_areas.entry((slot, op, fill)).or_insert_with(|| {
            (region_area_work(&operands) <= CHECK_WORK).then(|| region_area(&operands, |i| op.apply(i[0], i[1])))
        });
        let Some(exact) = exact else {
            return match check_polygon_samples(subject, clip, op, fill, output, &rules) {
                Ok(()) => Verdict::RightAtSamples,
                Err(why) => Verdict::Wrong(why.to_string()),
            };
        };
        let area = if rules.conventional {
            output.signed_area()
        } else if region_area_work(&[(output, rules.output_fill)]) <= CHECK_WORK {
            region_area(&[(output, rules.output_fill)], |i| i[0])
        } else {
            return Verdict::Unchecked(format!(
                "the result's area (read under {}) would take over {CHECK_WORK} edge-slab pairs to measure",
                rules.output_fill.name()
            ));
        };
        let tol = tolerance(subject, clip, rules.relative_tolerance);
        if (area - exact).abs() <= tol {
            Verdict::Right
        } else {
            Verdict::Wrong(format!("result area {area:e} against the exact {exact:e} (tolerance {tol:e})"))
        }
    }

    /// How `entry`'s output on case `slot` is read ([`crate::checks::output_rules`]), with the
    /// subject's form checked once per case.
    fn output_rules(&mut self, entry: &PolygonEntry, slot: usize, subject: &Polygons, fill: FillRule) -> OutputRules {
        let known = &mut self.subject_conventional;
        let conventional = || *known.entry(slot).or_insert_with(|| check_valid_output(subject).is_ok());
        OutputRules::for_form_given(entry.clipper.capabilities().output, conventional, fill, entry.tolerance)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::registry;
    use clip_core::Rect;

    fn case(subject: Rect, clip: Rect) -> PolygonCase {
        PolygonCase {
            workload: "test",
            seed: 1,
            index: 0,
            subject: Polygons::from(subject),
            clip: Polygons::from(clip),
            description: String::new(),
        }
    }

    #[test]
    fn a_right_result_passes_a_wrong_or_empty_one_fails() {
        let registry = registry();
        let vatti = registry.find_polygon("vatti").unwrap();
        let k = case(Rect::new(0.0, 0.0, 2.0, 2.0), Rect::new(1.0, 1.0, 3.0, 3.0));
        let right = Polygons::from(Rect::new(1.0, 1.0, 2.0, 2.0));
        let mut judge = Judge::default();
        let (op, fill) = (BoolOp::Intersection, FillRule::EvenOdd);
        assert_eq!(judge.judge(vatti, 0, &k, op, fill, &right), Verdict::Right);
        let square = Polygons::from(Rect::new(0.0, 0.0, 1000.0, 1000.0));
        assert!(matches!(judge.judge(vatti, 0, &k, op, fill, &square), Verdict::Wrong(_)));
        assert!(matches!(judge.judge(vatti, 0, &k, op, fill, &Polygons::default()), Verdict::Wrong(_)));
        assert_eq!(Verdict::Unchecked(String::new()).column(), None);
    }

    /// 12 000 bars 10^6 wide, 2 apart, inside a box: every long edge shares its height with
    /// thousands (a pairwise form check was quadratic here; the sweep is not).
    fn bars_in_a_box() -> PolygonCase {
        let bars: Vec<_> =
            (0..12_000).map(|i| Rect::new(0.0, 2.0 * i as f64, 1e6, 2.0 * i as f64 + 1.0).to_ring()).collect();
        PolygonCase {
            workload: "test",
            seed: 1,
            index: 0,
            subject: Polygons::new(bars),
            clip: Polygons::from(Rect::new(-1.0, -1.0, 1e6 + 1.0, 24_001.0)),
            description: String::new(),
        }
    }

    #[test]
    fn split_sutherland_hodgman_is_read_by_its_subjects_form_checked_once_per_case() {
        // Split Sutherland-Hodgman is conventional only for a conventional subject, so judging it
        // asks for the subject's form (the bench once spent an hour on spiky-box's subject at 10^6
        // with a pairwise check).
        let k = bars_in_a_box();
        let (op, fill) = (BoolOp::Intersection, FillRule::EvenOdd);
        let registry = registry();
        let sh = registry.find_polygon(clip_sutherland_hodgman::SPLIT_NAME).unwrap();
        let mut judge = Judge::default();
        assert_eq!(judge.judge(sh, 0, &k, op, fill, &k.subject), Verdict::Right);
        assert_eq!(judge.subject_conventional.get(&0), Some(&true));
        let fewer = Polygons::new(k.subject.rings[1..].to_vec());
        assert!(matches!(judge.judge(sh, 0, &k, op, fill, &fewer), Verdict::Wrong(_)));
        // A subject that crosses itself reads the result by region under the input's rule.
        let bow = Polygons::new(vec![clip_core::Ring::new(vec![
            clip_core::Point::new(0.0, 0.0),
            clip_core::Point::new(2.0, 2.0),
            clip_core::Point::new(2.0, 0.0),
            clip_core::Point::new(0.0, 2.0),
        ])]);
        let crossed =
            PolygonCase { subject: bow, ..case(Rect::new(0.0, 0.0, 1.0, 1.0), Rect::new(-1.0, -1.0, 3.0, 3.0)) };
        let _ = judge.judge(sh, 1, &crossed, op, fill, &crossed.subject);
        assert_eq!(judge.subject_conventional.get(&1), Some(&false));
    }

    #[test]
    fn past_the_area_sweep_the_sample_points_still_catch_a_liar() {
        use clip_core::{Point, Ring};
        // A comb of 20 000 teeth: a level line crosses every tooth, so every sweep is quadratic.
        let teeth = 20_000;
        let mut comb: Vec<Point> = (0..teeth)
            .flat_map(|i| [Point::new(2.0 * i as f64, 1.0 + i as f64), Point::new(2.0 * i as f64 + 1.0, 0.0)])
            .collect();
        comb.extend([Point::new(2.0 * teeth as f64, -1.0), Point::new(0.0, -1.0)]);
        comb.reverse(); // counter-clockwise: an outer, as conventional output has it
        let k = PolygonCase {
            workload: "test",
            seed: 1,
            index: 0,
            subject: Polygons::new(vec![Ring::new(comb)]),
            clip: Polygons::from(Rect::new(-1.0, -2.0, 2.0 * teeth as f64 + 1.0, teeth as f64 + 2.0)),
            description: String::new(),
        };
        let (op, fill) = (BoolOp::Intersection, FillRule::EvenOdd);
        assert!(region_area_work(&[(&k.subject, fill), (&k.clip, fill)]) > CHECK_WORK);
        let registry = registry();
        let vatti = registry.find_polygon("vatti").unwrap();
        let mut judge = Judge::default();
        // The box holds the comb: the comb is the answer.
        assert_eq!(judge.judge(vatti, 0, &k, op, fill, &k.subject), Verdict::RightAtSamples);
        let square = Polygons::from(Rect::new(0.0, 0.0, 1000.0, 1000.0));
        assert!(matches!(judge.judge(vatti, 0, &k, op, fill, &square), Verdict::Wrong(_)));
        assert!(matches!(judge.judge(vatti, 0, &k, op, fill, &Polygons::default()), Verdict::Wrong(_)));
        // The comb twice covers the same points once under the non-zero reading, but its edges
        // overlap: the form check, affordable on every input, catches it.
        let twice = Polygons::new([k.subject.rings.clone(), k.subject.rings.clone()].concat());
        match judge.judge(vatti, 0, &k, op, fill, &twice) {
            Verdict::Wrong(why) => assert!(why.contains("invalid output"), "{why}"),
            other => panic!("{other:?}"),
        }
    }
}
