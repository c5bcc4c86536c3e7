//! A line chart as an SVG file: measured series as solid lines with dots, the papers' series as
//! dashed lines with hollow triangles; text is plain SVG text, so no font library is needed.

use std::error::Error;
use std::ops::Range;
use std::path::Path;

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;

use super::palette::{distinct, paper_tint};
use crate::cli_error::CliError;
use crate::write::write_file;

/// One series of points.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend text.
    pub label: String,
    /// Line and marker colour.
    pub colour: RGBColor,
    /// `(x, y)` points, in x order.
    pub points: Vec<(f64, f64)>,
    /// A paper's own numbers (dashed, hollow triangles) rather than ours (solid, dots).
    pub paper: bool,
    /// Error bars: `(x, low, high)`, the 95% interval at a point (empty: none drawn).
    pub spread: Vec<(f64, f64, f64)>,
}

/// A chart: title, axis labels with units, axis scales and series.
#[derive(Clone, Debug)]
pub struct Chart {
    /// Caption above the plot.
    pub title: String,
    /// X axis description, with unit.
    pub x_label: String,
    /// Y axis description, with unit.
    pub y_label: String,
    /// Logarithmic x axis.
    pub log_x: bool,
    /// Logarithmic y axis.
    pub log_y: bool,
    /// X values to label on a logarithmic x axis (empty: plotters' own choice), e.g. the papers'
    /// edge counts; a linear axis labels itself.
    pub x_ticks: Vec<f64>,
    /// The series, drawn in order.
    pub series: Vec<Series>,
}

/// The plot area's size; the legend panel to its right is as wide as its longest label needs.
const PLOT_SIZE: (u32, u32) = (900, 620);

impl Chart {
    /// Draws the chart into an SVG file at `path`.
    pub fn write_svg(&self, path: &Path) -> Result<(), CliError> {
        let mut svg = String::new();
        self.draw_into(&mut svg)
            .map_err(|e| CliError::failed(format!("{}: cannot draw the plot ({e})", path.display())))?;
        write_file(path, &svg)
    }

    /// Draws the chart as SVG text into `svg`.
    fn draw_into(&self, svg: &mut String) -> Result<(), Box<dyn Error>> {
        let spread = self.series.iter().flat_map(|s| s.spread.iter().flat_map(|&(x, low, high)| [(x, low), (x, high)]));
        let points: Vec<(f64, f64)> = self.series.iter().flat_map(|s| s.points.iter().copied()).chain(spread).collect();
        let points: Vec<(f64, f64)> = points.into_iter().filter(|(x, y)| x.is_finite() && y.is_finite()).collect();
        let xr = axis_range(points.iter().map(|p| p.0), self.log_x, false);
        let yr = axis_range(points.iter().map(|p| p.1), self.log_y, true);
        let x_ticks = if self.x_ticks.is_empty() { log_ticks(&xr) } else { self.x_ticks.clone() };
        if self.log_x {
            self.draw_with_y(svg, xr.log_scale().with_key_points(x_ticks), yr)
        } else {
            self.draw_with_y(svg, xr, yr)
        }
    }

    fn draw_with_y<X>(&self, svg: &mut String, x: X, y: Range<f64>) -> Result<(), Box<dyn Error>>
    where
        X: AsRangedCoord<Value = f64>,
        X::CoordDescType: ValueFormatter<f64>,
    {
        if self.log_y {
            let ticks = log_ticks(&y);
            self.draw(svg, x, y.log_scale().with_key_points(ticks))
        } else {
            self.draw(svg, x, y)
        }
    }

    /// The legend panel's width: room for the swatch and the longest label.
    fn legend_width(&self) -> u32 {
        let longest = self.series.iter().map(|s| s.label.chars().count()).max().unwrap_or(0);
        (56 + 8 * longest as u32).clamp(140, 420)
    }

    fn draw<X, Y>(&self, svg: &mut String, x: X, y: Y) -> Result<(), Box<dyn Error>>
    where
        X: AsRangedCoord<Value = f64>,
        Y: AsRangedCoord<Value = f64>,
        X::CoordDescType: ValueFormatter<f64>,
        Y::CoordDescType: ValueFormatter<f64>,
    {
        let legend_width = self.legend_width();
        let root = SVGBackend::with_string(svg, (PLOT_SIZE.0 + legend_width, PLOT_SIZE.1)).into_drawing_area();
        root.fill(&WHITE)?;
        let root = root.titled(&self.title, ("sans-serif", 22))?;
        let (plot, legend) = root.split_horizontally(PLOT_SIZE.0);
        let mut ctx =
            ChartBuilder::on(&plot).margin(20).x_label_area_size(55).y_label_area_size(80).build_cartesian_2d(x, y)?;
        ctx.configure_mesh()
            .x_labels(6)
            .y_labels(10)
            .x_label_formatter(&|v| tick_label(*v))
            .y_label_formatter(&|v| tick_label(*v))
            .x_desc(self.x_label.as_str())
            .y_desc(self.y_label.as_str())
            .axis_desc_style(("sans-serif", 17))
            .label_style(("sans-serif", 14))
            .light_line_style(WHITE.mix(0.0))
            .bold_line_style(BLACK.mix(0.12))
            .draw()?;
        let wanted: Vec<RGBColor> =
            self.series.iter().map(|s| if s.paper { paper_tint(s.colour) } else { s.colour }).collect();
        for (i, (s, colour)) in self.series.iter().zip(distinct(&wanted)).enumerate() {
            let line = colour.stroke_width(2);
            if s.paper {
                ctx.draw_series(DashedLineSeries::new(s.points.clone(), 8, 5, line))?;
                ctx.draw_series(s.points.iter().map(|&p| TriangleMarker::new(p, 7, line)))?;
            } else {
                ctx.draw_series(LineSeries::new(s.points.clone(), line))?;
                ctx.draw_series(s.points.iter().map(|&p| Circle::new(p, 4, colour.filled())))?;
            }
            // Each interval as a vertical whisker through its point.
            let bar = colour.stroke_width(2);
            ctx.draw_series(
                s.spread
                    .iter()
                    .filter(|(_, low, high)| low.is_finite() && high.is_finite())
                    .map(|&(x, low, high)| PathElement::new(vec![(x, low), (x, high)], bar)),
            )?;
            // The legend entry, beside the plot so it never covers a point: a swatch 3 px wide
            // with the series' marker, and its label.
            let y = 40 + 24 * i as i32;
            legend.draw(&PathElement::new(vec![(8, y), (36, y)], colour.stroke_width(3)))?;
            if s.paper {
                legend.draw(&TriangleMarker::new((22, y), 6, colour.stroke_width(2)))?;
            } else {
                legend.draw(&Circle::new((22, y), 4, colour.filled()))?;
            }
            legend.draw(&Text::new(s.label.as_str(), (44, y - 8), ("sans-serif", 14).into_font()))?;
        }
        root.present()?;
        Ok(())
    }
}

/// The one tick-label style of every plot: three significant digits at most, thousands as `k`,
/// millions as `M`, billions as `G` (1, 10, 100, 1k, 10k, 100k, 1M; 2.5k; 0.25; 0.001).
pub fn tick_label(v: f64) -> String {
    if !v.is_finite() {
        return v.to_string();
    }
    let a = v.abs();
    let (scaled, suffix) = match a {
        a if a >= 1e9 => (v / 1e9, "G"),
        a if a >= 1e6 => (v / 1e6, "M"),
        a if a >= 1e3 => (v / 1e3, "k"),
        _ => (v, ""),
    };
    if scaled == 0.0 {
        return "0".to_owned();
    }
    let decimals = (2 - scaled.abs().log10().floor() as i32).max(0) as usize;
    let text = format!("{scaled:.decimals$}");
    let text = if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.') } else { &text };
    let text = if text == "-0" { "0" } else { text };
    format!("{text}{suffix}")
}

/// The ticks of a logarithmic axis over `range`: its powers of ten, and 2 and 5 times them (then
/// every digit) when fewer than three powers of ten fall inside.
fn log_ticks(range: &Range<f64>) -> Vec<f64> {
    let (lo, hi) = (range.start, range.end);
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return Vec::new();
    }
    let first = lo.log10().floor() as i32 - 1;
    let last = hi.log10().ceil() as i32 + 1;
    let within = |digits: &[f64]| -> Vec<f64> {
        (first..=last)
            .flat_map(|e| digits.iter().map(move |d| d * 10f64.powi(e)))
            .filter(|v| (lo..=hi).contains(v))
            .collect()
    };
    [&[1.0][..], &[1.0, 2.0, 5.0], &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]]
        .iter()
        .map(|digits| within(digits))
        .find(|ticks| ticks.len() >= 3)
        .unwrap_or_else(|| vec![lo, hi])
}

/// The axis range covering `values` with a small margin: multiplicative on a log axis (a twentieth
/// of the span's decades each side, at least 10%), additive on a linear one (and reaching down to 0
/// for a linear y axis of positive values, so bars of ratios and percentages start at zero).
fn axis_range(values: impl Iterator<Item = f64>, log: bool, y: bool) -> Range<f64> {
    let (lo, hi) = values
        .filter(|v| !log || *v > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if !lo.is_finite() {
        return if log { 1.0..10.0 } else { 0.0..1.0 };
    }
    if log {
        let margin = (hi / lo).powf(0.05).max(1.1);
        return lo / margin..hi * margin;
    }
    let (lo, hi) = if y { (lo.min(0.0), hi.max(0.0)) } else { (lo, hi) };
    let pad = ((hi - lo) * 0.05).max(1e-9);
    (if y && lo == 0.0 { 0.0 } else { lo - pad })..hi + pad
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_a_titled_svg_with_legend_text() {
        let dir = std::env::temp_dir().join(format!("clipbench-chart-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("chart.svg");
        let chart = Chart {
            title: "Test title".into(),
            x_label: "edges".into(),
            y_label: "time (µs)".into(),
            log_x: true,
            log_y: true,
            x_ticks: vec![4.0, 20.0, 200.0],
            series: vec![
                Series {
                    label: "ours".into(),
                    colour: RGBColor(1, 2, 3),
                    points: vec![(4.0, 1.0), (200.0, 50.0)],
                    paper: false,
                    spread: Vec::new(),
                },
                Series {
                    label: "paper".into(),
                    colour: RGBColor(3, 2, 1),
                    points: vec![(4.0, 2.0), (200.0, 40.0)],
                    paper: true,
                    spread: Vec::new(),
                },
            ],
        };
        chart.write_svg(&path).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        for text in ["Test title", "edges", "time (µs)", "ours", "paper"] {
            assert!(svg.contains(text), "{text} missing");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn series_of_one_colour_are_drawn_in_distinct_ones() {
        let dir = std::env::temp_dir().join(format!("clipbench-chart-colours-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("chart.svg");
        let red = RGBColor(214, 39, 40);
        let series = |label: &str, paper: bool| Series {
            label: label.into(),
            colour: red,
            points: vec![(4.0, 1.0), (200.0, 50.0)],
            paper,
            spread: vec![(4.0, 0.5, 2.0)],
        };
        let chart = Chart {
            title: "colours".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            log_x: true,
            log_y: true,
            x_ticks: Vec::new(),
            series: vec![series("ours", false), series("paper", true), series("again", false)],
        };
        chart.write_svg(&path).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        // The legend swatches, one per series, are the lines 3 px wide.
        let swatches: Vec<&str> = svg
            .split("<polyline")
            .filter(|e| e[..e.find('>').unwrap_or(e.len())].contains("stroke-width=\"3\""))
            .filter_map(|e| e.split("stroke=\"").nth(1).map(|s| &s[..7]))
            .collect();
        assert_eq!(swatches.len(), 3, "{swatches:?}");
        assert!(swatches[0] == "#D62728" && swatches[1] != swatches[0], "{swatches:?}");
        assert!(swatches[2] != swatches[0] && swatches[2] != swatches[1], "{swatches:?}");
    }

    #[test]
    fn tick_labels_have_one_style() {
        let cases = [
            (0.0, "0"),
            (1.0, "1"),
            (10.0, "10"),
            (100.0, "100"),
            (1000.0, "1k"),
            (10_000.0, "10k"),
            (100_000.0, "100k"),
            (1e6, "1M"),
            (1e7, "10M"),
            (2e9, "2G"),
            (2500.0, "2.5k"),
            (20_000.0, "20k"),
            (0.25, "0.25"),
            (2.5, "2.5"),
            (0.001, "0.001"),
            (0.1 + 0.2, "0.3"),
            (-1500.0, "-1.5k"),
            (120.0, "120"),
        ];
        for (v, text) in cases {
            assert_eq!(tick_label(v), text, "{v}");
        }
    }

    #[test]
    fn ranges_cover_the_values_with_a_small_margin() {
        let r = axis_range([2.0, 8.0].into_iter(), false, true);
        assert!(r.start == 0.0 && r.end > 8.0 && r.end < 9.0, "{r:?}");
        let r = axis_range([10.0, 1000.0].into_iter(), true, false);
        assert!(r.start < 10.0 && r.end > 1000.0 && r.end < 2000.0, "{r:?}");
    }

    #[test]
    fn log_ticks_fall_inside_and_are_never_too_few() {
        assert_eq!(log_ticks(&(2.6..3700.0)), vec![10.0, 100.0, 1000.0]);
        assert_eq!(log_ticks(&(1.5..60.0)), vec![2.0, 5.0, 10.0, 20.0, 50.0]);
        assert_eq!(log_ticks(&(1.1..1.9)), vec![1.1, 1.9]);
        let r = 0.8..1.5;
        assert!(log_ticks(&r).len() >= 2);
    }

    /// The y labels of a chart SVG: the texts right-aligned left of the plot (plotters writes
    /// `text-anchor="end"` for them).
    fn y_labels(svg: &str) -> Vec<String> {
        svg.split("<text")
            .skip(1)
            .filter(|e| e[..e.find('>').unwrap_or(0)].contains("text-anchor=\"end\""))
            .filter_map(|e| e.split('>').nth(1).and_then(|t| t.split('<').next()).map(|t| t.trim().to_owned()))
            .collect()
    }

    #[test]
    fn a_log_axis_ends_within_a_decade_of_the_data() {
        let dir = std::env::temp_dir().join(format!("clipbench-chart-range-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("chart.svg");
        // Many series, as in a bench plot: the legend must not push the axis up.
        let series = (0..12)
            .map(|i| Series {
                label: format!("clipper {i}"),
                colour: RGBColor(10 * i as u8, 0, 0),
                points: vec![(4.0, 3.0 + i as f64), (200.0, 3.2e3 - i as f64)],
                paper: false,
                spread: Vec::new(),
            })
            .collect();
        let chart = Chart {
            title: "range".into(),
            x_label: "edges".into(),
            y_label: "µs".into(),
            log_x: true,
            log_y: true,
            x_ticks: vec![4.0, 20.0, 200.0],
            series,
        };
        chart.write_svg(&path).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let labels = y_labels(&svg);
        assert_eq!(labels, ["10", "100", "1k"].map(String::from).to_vec(), "{labels:?}");
        let top = labels.iter().map(|l| l.replace('k', "000").parse::<f64>().unwrap()).fold(0.0, f64::max);
        assert!(top <= 3.2e4, "top tick {top} for data up to 3.2e3");
    }
}
