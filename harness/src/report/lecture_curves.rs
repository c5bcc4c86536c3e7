//! The lecture's curve clipping from its raw CSVs: the share of objects each preliminary test
//! settled, ns per object with the tests on and off and by the polygon routes, their ratios, a
//! plot against radius, and the Fig. 6-27 picture.

use super::derived::Derived;
use super::markdown::{header, num, table};
use super::provenance_line::provenance_line;
use super::results_folder::ResultsFolder;
use crate::cli_error::CliError;
use crate::measure::raw::read_csv;
use crate::measure::timing::median;
use crate::plot::chart::{Chart, Series};
use crate::plot::palette::clipper_colour;
use crate::results_files::lecture_curves::{
    CSV, CurveStageRecord, CurveTiming, FIGURE_6_27, FLATTEN_GEO, FLATTEN_VATTI, META, STAGES_CSV, WITH_TESTS,
    WITHOUT_TESTS,
};
use std::collections::BTreeMap;

/// The plot of ns per object against radius.
pub const PLOT: &str = "lecture-curves.svg";

/// The stages in the table's order, with their column titles.
const STAGES: [(&str, &str); 5] = [
    ("box-accept", "box accept %"),
    ("box-reject", "box reject %"),
    ("quadrants", "quadrants %"),
    ("octants", "octants %"),
    ("equations", "equations %"),
];

/// The timed columns: method, phase.
const TIMED: [(&str, &str); 6] = [
    (WITH_TESTS, "outline"),
    (WITHOUT_TESTS, "outline"),
    (WITH_TESTS, "filled"),
    (WITHOUT_TESTS, "filled"),
    (FLATTEN_VATTI, "filled"),
    (FLATTEN_GEO, "filled"),
];

/// One workload and window: stage shares and ns per object for each of [`TIMED`].
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// `circles` or `ellipses`.
    pub workload: String,
    /// `rectangle` or `polygon`.
    pub window: String,
    /// Objects over all bins.
    pub objects: usize,
    /// Percent of the objects each of [`STAGES`] settled.
    pub shares: [f64; 5],
    /// ns per object for each of [`TIMED`] (NaN where not measured): each bin's median, weighted
    /// by the bin's objects.
    pub ns: [f64; 6],
}

impl Row {
    /// Percent of objects settled without any equation.
    pub fn settled(&self) -> f64 {
        100.0 - self.shares[4]
    }

    /// `ns[a] / ns[b]`.
    pub fn ratio(&self, a: usize, b: usize) -> f64 {
        self.ns[a] / self.ns[b]
    }
}

type Key = (String, String);

/// (workload and window, radius bin's low end as bits, method, phase).
type BatchKey = (Key, u64, String, String);

/// Median ns per object of each (workload, window, bin, method, phase).
fn medians(timings: &[CurveTiming]) -> BTreeMap<BatchKey, (f64, usize)> {
    let mut all: BTreeMap<BatchKey, (Vec<f64>, usize)> = BTreeMap::new();
    for t in timings {
        let key = ((t.workload.clone(), t.window.clone()), t.radius_lo.to_bits(), t.method.clone(), t.phase.clone());
        let entry = all.entry(key).or_insert_with(|| (Vec::new(), t.objects));
        entry.0.push(t.ns_per_object);
    }
    all.into_iter().map(|(k, (v, n))| (k, (median(&v), n))).collect()
}

/// Computes the rows from the raw timings and stage records.
pub fn rows(timings: &[CurveTiming], stages: &[CurveStageRecord]) -> Vec<Row> {
    let med = medians(timings);
    let mut keys: Vec<Key> = stages.iter().map(|s| (s.workload.clone(), s.window.clone())).collect();
    keys.dedup();
    keys.sort();
    keys.dedup();
    keys.into_iter()
        .map(|key| {
            let here: Vec<&CurveStageRecord> =
                stages.iter().filter(|s| s.workload == key.0 && s.window == key.1).collect();
            let mut bins: Vec<(u64, usize)> = here.iter().map(|s| (s.radius_lo.to_bits(), s.of)).collect();
            bins.sort_unstable();
            bins.dedup();
            let objects: usize = bins.iter().map(|b| b.1).sum();
            let shares = STAGES.map(|(stage, _)| {
                let n: usize = here.iter().filter(|s| s.stage == stage).map(|s| s.objects).sum();
                n as f64 * 100.0 / objects.max(1) as f64
            });
            let ns = TIMED.map(|(method, phase)| {
                let mut total = 0.0;
                let mut counted = 0;
                for &(bin, n) in &bins {
                    if let Some(&(m, _)) = med.get(&(key.clone(), bin, method.to_owned(), phase.to_owned())) {
                        total += m * n as f64;
                        counted += n;
                    }
                }
                if counted == objects && objects > 0 { total / objects as f64 } else { f64::NAN }
            });
            Row { workload: key.0, window: key.1, objects, shares, ns }
        })
        .collect()
}

/// The main table: shares and times per workload and window.
pub fn markdown_table(rows: &[Row]) -> String {
    let mut head = header(&["Workload", "Window", "Objects"]);
    head.extend(STAGES.iter().map(|(_, t)| (*t).to_owned()));
    head.extend(header(&[
        "outline ns, tests on",
        "outline ns, tests off",
        "off / on",
        "filled ns, tests on",
        "filled ns, tests off",
        "off / on",
        "flatten+vatti ns",
        "vatti / on",
        "flatten+geo ns",
        "geo / on",
    ]));
    let body = rows
        .iter()
        .map(|r| {
            let mut cells = vec![r.workload.clone(), r.window.clone(), r.objects.to_string()];
            cells.extend(r.shares.iter().map(|s| num(*s, 1)));
            cells.extend([
                num(r.ns[0], 0),
                num(r.ns[1], 0),
                format!("**{}**", num(r.ratio(1, 0), 2)),
                num(r.ns[2], 0),
                num(r.ns[3], 0),
                format!("**{}**", num(r.ratio(3, 2), 2)),
                num(r.ns[4], 0),
                format!("**{}**", num(r.ratio(4, 2), 1)),
                num(r.ns[5], 0),
                num(r.ratio(5, 2), 1),
            ]);
            cells
        })
        .collect::<Vec<_>>();
    table(&head, &body)
}

/// Per radius bin, for one workload and window: share settled by the tests and the ratios.
pub fn bins_table(timings: &[CurveTiming], stages: &[CurveStageRecord], workload: &str, window: &str) -> String {
    let med = medians(timings);
    let key = (workload.to_owned(), window.to_owned());
    let mut bins: Vec<(f64, f64, usize)> = stages
        .iter()
        .filter(|s| s.workload == workload && s.window == window)
        .map(|s| (s.radius_lo, s.radius_hi, s.of))
        .collect();
    bins.dedup();
    let head = header(&[
        "Radius",
        "Objects",
        "settled by the tests %",
        "outline off / on",
        "filled off / on",
        "flatten+vatti / filled on",
    ]);
    let body = bins
        .iter()
        .map(|&(lo, hi, of)| {
            let settled: usize = stages
                .iter()
                .filter(|s| s.workload == workload && s.window == window && s.radius_lo == lo && s.stage != "equations")
                .map(|s| s.objects)
                .sum();
            let t = |method: &str, phase: &str| {
                med.get(&(key.clone(), lo.to_bits(), method.to_owned(), phase.to_owned())).map_or(f64::NAN, |m| m.0)
            };
            vec![
                format!("{lo}-{hi}"),
                of.to_string(),
                num(settled as f64 * 100.0 / of.max(1) as f64, 1),
                num(t(WITHOUT_TESTS, "outline") / t(WITH_TESTS, "outline"), 2),
                num(t(WITHOUT_TESTS, "filled") / t(WITH_TESTS, "filled"), 2),
                num(t(FLATTEN_VATTI, "filled") / t(WITH_TESTS, "filled"), 1),
            ]
        })
        .collect::<Vec<_>>();
    table(&head, &body)
}

/// ns per object against radius (each bin at its geometric middle) for one workload and window.
pub fn chart(timings: &[CurveTiming], workload: &str, window: &str) -> Chart {
    let med = medians(timings);
    let key = (workload.to_owned(), window.to_owned());
    let mut bins: Vec<(f64, f64)> = timings
        .iter()
        .filter(|t| t.workload == workload && t.window == window)
        .map(|t| (t.radius_lo, t.radius_hi))
        .collect();
    bins.sort_by(|a, b| a.0.total_cmp(&b.0));
    bins.dedup();
    let series = TIMED
        .iter()
        .map(|&(method, phase)| {
            let label = format!("{method} ({phase})");
            // The routes take their clipper's colour; outlines a lighter shade of their clipper's.
            let colour_name = match (method, phase) {
                (FLATTEN_VATTI, _) => "vatti".to_owned(),
                (FLATTEN_GEO, _) => "geo".to_owned(),
                (_, "outline") => format!("{method}-outline"),
                _ => method.to_owned(),
            };
            let points = bins
                .iter()
                .filter_map(|&(lo, hi)| {
                    let m = med.get(&(key.clone(), lo.to_bits(), method.to_owned(), phase.to_owned()))?;
                    Some(((lo * hi).sqrt(), m.0))
                })
                .collect();
            Series { label, colour: clipper_colour(&colour_name), points, paper: false, spread: Vec::new() }
        })
        .collect();
    Chart {
        title: format!("Curve clipping, {workload} against a {window} window: what the preliminary tests save"),
        x_label: "long radius (window 300-800 wide)".to_owned(),
        y_label: "ns per object (median)".to_owned(),
        log_x: true,
        log_y: true,
        x_ticks: Vec::new(),
        series,
    }
}

/// A short reading, every statement computed from the rows.
pub fn reading(rows: &[Row]) -> String {
    let mut text = String::new();
    for r in rows {
        text.push_str(&format!(
            "- {} against a {} window: the tests settle {}% of the objects without any equation; without them the \
             outline clip takes {}x as long and the filled clip {}x; flatten+vatti takes {}x the filled \
             clip's time{}.\n",
            r.workload,
            r.window,
            num(r.settled(), 1),
            num(r.ratio(1, 0), 2),
            num(r.ratio(3, 2), 2),
            num(r.ratio(4, 2), 1),
            if r.ns[5].is_nan() { String::new() } else { format!(", flatten+geo {}x", num(r.ratio(5, 2), 1)) }
        ));
    }
    text
}

/// The section and its plot; `None` when the folder holds no curve results.
pub fn derive(folder: &ResultsFolder) -> Result<Option<Derived>, CliError> {
    let csv = folder.join(CSV);
    if !csv.exists() {
        return Ok(None);
    }
    let timings: Vec<CurveTiming> = read_csv(&csv)?;
    let stages: Vec<CurveStageRecord> = read_csv(&folder.join(STAGES_CSV))?;
    let rows = rows(&timings, &stages);
    let (provenance, notes) = provenance_line(&folder.join(META))?;
    let param = |k: &str| provenance.parameters.get(k).and_then(serde_json::Value::as_u64).unwrap_or(0);
    let figure = if folder.join(FIGURE_6_27).exists() {
        format!(
            "### Fig. 6-27: a filled circle clipped by a rectangle\n\n![Fig. 6-27 redrawn]({FIGURE_6_27})\n\n\
             Drawn by `clipbench reproduce lecture` from the clipper's region (SVG elliptical arcs, not a \
             flattening): green is the clipped filled circle, red its visible arcs, dashed the circle as given.\n\n"
        )
    } else {
        String::new()
    };
    let body = format!(
        "The lecture notes (*Computer Graphics, Lecture 17: Polygon Clipping*) test a curved object's bounding \
         rectangle against the window first (keep or drop it whole), then for a circle the extents of its quadrants \
         and octants, for an ellipse its quadrants, and solve the curve-line equations only for what survives; \
         against a polygon window, the bounding rectangles first. `clip-curve` does exactly that (`curve`) or goes \
         straight to the equations (`curve-no-tests`); the polygon route flattens the ellipse and clips the polygon \
         with Vatti or geo. Workloads `circles` and `ellipses`: {} cases per workload and window, {} objects each \
         (whole circles and ellipses only), long radius 5-600 in a 1000 x 1000 frame. Times are ns per object: per \
         radius bin the median over {} interleaved rounds (geo: {}), weighted by the bin's objects. Ratios above 1 \
         are what the tests (or the exact clipper) save. A stage's share counts the objects it settled whole; the \
         four quadrant boxes of a whole circle or ellipse tile its bounding box, so once that box overlaps the \
         window some quadrant box does too, and quadrants alone never settle a whole curve: they settle quadrants, \
         cutting down what the octants and the equations see.\n\n{}\n{}\n\
         ### Circles against a rectangle, by radius\n\n{}\n![ns per object against radius]({PLOT})\n\n\
         ### Circles against a concave window with holes, by radius\n\n{}\n{figure}{}\n",
        param("cases_per_workload_and_window"),
        param("objects_per_case"),
        param("repetitions"),
        param("geo_repetitions"),
        markdown_table(&rows),
        reading(&rows),
        bins_table(&timings, &stages, "circles", "rectangle"),
        bins_table(&timings, &stages, "circles", "polygon"),
        notes
    );
    Ok(Some(Derived::new(body).with_plot(PLOT, chart(&timings, "circles", "rectangle"))))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn t(method: &str, phase: &str, rep: usize, ns: f64) -> CurveTiming {
        CurveTiming {
            workload: "circles".into(),
            window: "rectangle".into(),
            radius_lo: 5.0,
            radius_hi: 15.0,
            method: method.into(),
            phase: phase.into(),
            objects: 10,
            repetition: rep,
            iterations: 1,
            ns_per_object: ns,
        }
    }

    fn s(stage: &str, n: usize) -> CurveStageRecord {
        CurveStageRecord {
            workload: "circles".into(),
            window: "rectangle".into(),
            radius_lo: 5.0,
            radius_hi: 15.0,
            stage: stage.into(),
            objects: n,
            of: 10,
        }
    }

    #[test]
    fn ratios_come_from_the_medians_and_shares_from_the_counts() {
        let timings = vec![
            t(WITH_TESTS, "outline", 0, 10.0),
            t(WITH_TESTS, "outline", 1, 10.0),
            t(WITH_TESTS, "outline", 2, 900.0),
            t(WITHOUT_TESTS, "outline", 0, 30.0),
            t(WITH_TESTS, "filled", 0, 20.0),
            t(WITHOUT_TESTS, "filled", 0, 50.0),
            t(FLATTEN_VATTI, "filled", 0, 2000.0),
        ];
        let stages =
            vec![s("box-accept", 2), s("box-reject", 5), s("quadrants", 0), s("octants", 1), s("equations", 2)];
        let rows = rows(&timings, &stages);
        assert_eq!(rows.len(), 1);
        assert_eq!(rows[0].shares, [20.0, 50.0, 0.0, 10.0, 20.0]);
        assert_eq!(rows[0].ratio(1, 0), 3.0);
        assert_eq!(rows[0].ratio(4, 2), 100.0);
        assert!(rows[0].ns[5].is_nan());
        let reading = reading(&rows);
        assert!(reading.contains("settle 80.0%") && reading.contains("outline clip takes 3.00x"), "{reading}");
        assert!(reading.contains("flatten+vatti takes 100.0x"), "{reading}");
    }
}
