//! Markdown tables and number formats shared by the report sections.

use crate::measure::interval::Interval;

/// A markdown table: a header row and body rows, every cell already formatted.
pub fn table(header: &[String], rows: &[Vec<String>]) -> String {
    let line = |cells: &[String]| format!("| {} |\n", cells.join(" | "));
    let mut text = line(header);
    let rule: Vec<String> =
        header.iter().enumerate().map(|(i, _)| if i == 0 { "---".to_owned() } else { "---:".to_owned() }).collect();
    text.push_str(&line(&rule));
    for row in rows {
        text.push_str(&line(row));
    }
    text
}

/// Owned header cells from string slices.
pub fn header(cells: &[&str]) -> Vec<String> {
    cells.iter().map(|c| (*c).to_owned()).collect()
}

/// A number with `decimals` decimals, or "n/a" for NaN.
pub fn num(value: f64, decimals: usize) -> String {
    if value.is_nan() { "n/a".to_owned() } else { format!("{value:.decimals$}") }
}

/// A time given in nanoseconds, in the unit that keeps three significant figures readable.
pub fn duration_ns(ns: f64) -> String {
    if ns.is_nan() {
        "n/a".to_owned()
    } else if ns >= 1e9 {
        format!("{:.2} s", ns / 1e9)
    } else if ns >= 1e6 {
        format!("{:.2} ms", ns / 1e6)
    } else if ns >= 1e3 {
        format!("{:.1} µs", ns / 1e3)
    } else {
        format!("{ns:.0} ns")
    }
}

/// A figure with its interval, `0.82 (0.79-0.85)`, or "n/a".
pub fn num_interval(i: &Interval, decimals: usize) -> String {
    if i.estimate.is_nan() {
        "n/a".to_owned()
    } else {
        // A dash between negative ends reads as a minus: `-5.0 (-7.0 to -3.0)`.
        let to = if i.low < 0.0 || i.high < 0.0 { " to " } else { "-" };
        format!("{} ({}{to}{})", num(i.estimate, decimals), num(i.low, decimals), num(i.high, decimals))
    }
}

/// A time in nanoseconds with its interval in the estimate's unit, `1.5 µs (1.4-1.7)`.
pub fn duration_interval_ns(i: &Interval) -> String {
    let shown = duration_ns(i.estimate);
    let Some((_, unit)) = shown.split_once(' ') else { return shown };
    let scale = match unit {
        "s" => 1e9,
        "ms" => 1e6,
        "µs" => 1e3,
        _ => 1.0,
    };
    let decimals = if unit == "µs" {
        1
    } else if unit == "ns" {
        0
    } else {
        2
    };
    format!("{shown} ({}-{})", num(i.low / scale, decimals), num(i.high / scale, decimals))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_and_numbers() {
        let t = table(&header(&["a", "b"]), &[vec!["1".into(), "2".into()]]);
        assert_eq!(t, "| a | b |\n| --- | ---: |\n| 1 | 2 |\n");
        assert_eq!(num(f64::NAN, 2), "n/a");
        assert_eq!(num(1.234, 2), "1.23");
        assert_eq!(duration_ns(1_500.0), "1.5 µs");
        assert_eq!(duration_ns(2_340_000.0), "2.34 ms");
        assert_eq!(duration_ns(12.0), "12 ns");
        let i = Interval { estimate: 0.82, low: 0.79, high: 0.851 };
        assert_eq!(num_interval(&i, 2), "0.82 (0.79-0.85)");
        assert_eq!(duration_interval_ns(&i.scaled(2e3)), "1.6 µs (1.6-1.7)");
        assert_eq!(num_interval(&Interval::exact(f64::NAN), 2), "n/a");
    }
}
