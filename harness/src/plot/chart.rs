//! A line chart as an SVG file: measured series as solid lines with dots, the papers' series as
//! dashed lines with hollow triangles; text is plain SVG text, so no font library is needed.

use std::error::Error;
use std::ops::Range;
use std::path::Path;

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;

use super::palette::{distinct, paper_tint};
use crate::cli_error::CliError;

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

const SIZE: (u32, u32) = (960, 620);

impl Chart {
    /// Draws the chart into an SVG file at `path`.
    pub fn write_svg(&self, path: &Path) -> Result<(), CliError> {
        let spread = self.series.iter().flat_map(|s| s.spread.iter().flat_map(|&(x, low, high)| [(x, low), (x, high)]));
        let points: Vec<(f64, f64)> = self.series.iter().flat_map(|s| s.points.iter().copied()).chain(spread).collect();
        let points: Vec<(f64, f64)> = points.into_iter().filter(|(x, y)| x.is_finite() && y.is_finite()).collect();
        // Room on top for the legend: about one text line per series.
        let legend = (0.06 + 0.045 * self.series.len() as f64).min(0.5);
        let xr = axis_range(points.iter().map(|p| p.0), self.log_x, None);
        let yr = axis_range(points.iter().map(|p| p.1), self.log_y, Some(legend));
        let ticks = self.x_ticks.clone();
        let drawn = match (self.log_x, ticks.is_empty()) {
            (false, _) => self.draw_with_y(path, xr, yr),
            (true, true) => self.draw_with_y(path, xr.log_scale(), yr),
            (true, false) => self.draw_with_y(path, xr.log_scale().with_key_points(ticks), yr),
        };
        drawn.map_err(|e| CliError::failed(format!("{}: cannot draw the plot ({e})", path.display())))
    }

    fn draw_with_y<X>(&self, path: &Path, x: X, y: Range<f64>) -> Result<(), Box<dyn Error>>
    where
        X: AsRangedCoord<Value = f64>,
        X::CoordDescType: ValueFormatter<f64>,
    {
        if self.log_y { self.draw(path, x, y.log_scale()) } else { self.draw(path, x, y) }
    }

    fn draw<X, Y>(&self, path: &Path, x: X, y: Y) -> Result<(), Box<dyn Error>>
    where
        X: AsRangedCoord<Value = f64>,
        Y: AsRangedCoord<Value = f64>,
        X::CoordDescType: ValueFormatter<f64>,
        Y::CoordDescType: ValueFormatter<f64>,
    {
        let root = SVGBackend::new(path, SIZE).into_drawing_area();
        root.fill(&WHITE)?;
        let mut ctx = ChartBuilder::on(&root)
            .caption(&self.title, ("sans-serif", 22))
            .margin(20)
            .x_label_area_size(55)
            .y_label_area_size(80)
            .build_cartesian_2d(x, y)?;
        ctx.configure_mesh()
            .x_labels(6)
            .y_labels(10)
            .x_label_formatter(&tick)
            .y_label_formatter(&value_tick)
            .x_desc(self.x_label.as_str())
            .y_desc(self.y_label.as_str())
            .axis_desc_style(("sans-serif", 17))
            .label_style(("sans-serif", 14))
            .light_line_style(WHITE.mix(0.0))
            .bold_line_style(BLACK.mix(0.12))
            .draw()?;
        let wanted: Vec<RGBColor> =
            self.series.iter().map(|s| if s.paper { paper_tint(s.colour) } else { s.colour }).collect();
        for (s, colour) in self.series.iter().zip(distinct(&wanted)) {
            let line = colour.stroke_width(2);
            if s.paper {
                ctx.draw_series(DashedLineSeries::new(s.points.clone(), 8, 5, line))?;
                ctx.draw_series(s.points.iter().map(|&p| TriangleMarker::new(p, 7, line)))?
                    .label(s.label.as_str())
                    .legend(move |(px, py)| {
                        EmptyElement::at((px, py))
                            + PathElement::new(vec![(0, 0), (20, 0)], colour.stroke_width(3))
                            + TriangleMarker::new((10, 0), 6, colour.stroke_width(2))
                    });
            } else {
                ctx.draw_series(LineSeries::new(s.points.clone(), line))?
                    .label(s.label.as_str())
                    .legend(move |(px, py)| PathElement::new(vec![(px, py), (px + 20, py)], colour.stroke_width(3)));
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
        }
        ctx.configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK.mix(0.4))
            .label_font(("sans-serif", 14))
            .draw()?;
        root.present()?;
        Ok(())
    }
}

/// A tick label: integers without decimals (thousands as `k`, millions as `M`), small values with
/// up to three significant digits.
fn tick(v: &f64) -> String {
    let v = *v;
    let a = v.abs();
    if a >= 1e6 && (v / 1e6).fract() == 0.0 {
        format!("{}M", v / 1e6)
    } else if a >= 1e4 && (v / 1e3).fract() == 0.0 {
        format!("{}k", v / 1e3)
    } else if a >= 10.0 || v.fract() == 0.0 {
        format!("{v:.0}")
    } else {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    }
}

/// A y tick label: plain numbers, powers of ten beyond 10^5 or below 0.01 (`1e6`, `1e-3`).
fn value_tick(v: &f64) -> String {
    let a = v.abs();
    if a != 0.0 && !(0.01..1e5).contains(&a) {
        let e = a.log10().round();
        if (a / 10f64.powf(e) - 1.0).abs() < 1e-9 {
            return format!("{}1e{e}", if *v < 0.0 { "-" } else { "" });
        }
        return format!("{v:.1e}");
    }
    tick(v).replace('k', "000")
}

/// The axis range covering `values` with a margin: multiplicative on a log axis, additive on a
/// linear one (and reaching down to 0 for a linear y axis of positive values). A y axis is given
/// `legend_room`, the fraction of its height left free on top for the legend.
fn axis_range(values: impl Iterator<Item = f64>, log: bool, legend_room: Option<f64>) -> Range<f64> {
    let y = legend_room.is_some();
    let grow = legend_room.map_or(0.0, |f| f / (1.0 - f));
    let (lo, hi) = values
        .filter(|v| !log || *v > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if !lo.is_finite() {
        return if log { 1.0..10.0 } else { 0.0..1.0 };
    }
    if log {
        let top = hi * 1.4 * (hi * 1.4 / (lo / 1.4)).powf(grow);
        return lo / 1.4..top;
    }
    let (lo, hi) = if y { (lo.min(0.0), hi.max(0.0)) } else { (lo, hi) };
    let pad = ((hi - lo) * 0.06).max(1e-9);
    let top = hi + pad + (hi + pad - lo) * grow;
    (if y && lo == 0.0 { 0.0 } else { lo - pad })..top
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
    fn ticks_are_short() {
        assert_eq!(tick(&10.0), "10");
        assert_eq!(tick(&100_000.0), "100k");
        assert_eq!(tick(&2_000_000.0), "2M");
        assert_eq!(tick(&0.25), "0.25");
        assert_eq!(tick(&2.5), "2.5");
        assert_eq!(value_tick(&1e6), "1e6");
        assert_eq!(value_tick(&20_000.0), "20000");
        assert_eq!(value_tick(&0.001), "1e-3");
    }

    #[test]
    fn ranges_cover_the_values() {
        let r = axis_range([2.0, 8.0].into_iter(), false, Some(0.3));
        assert!(r.start == 0.0 && r.end > 8.0);
        let r = axis_range([10.0, 1000.0].into_iter(), true, None);
        assert!(r.start < 10.0 && r.end > 1000.0);
    }
}
