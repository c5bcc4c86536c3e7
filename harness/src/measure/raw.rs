//! Raw result files: one CSV row per measurement, written as measured and read back by `report`.

use std::path::Path;

use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::cli_error::CliError;
use crate::write::write_file;

/// One timed repetition: the row format of every timing CSV (`vatti-table3.csv`,
/// `wang-table4.csv`, `bench.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct Measurement {
    /// The workload (`vatti-t3`, `wang-t4`, `star`, ...).
    pub workload: String,
    /// Which case of the workload: a case index, or a window shape and size row (`concave-W1`).
    pub case: String,
    /// The clipper's registry name.
    pub clipper: String,
    /// What was timed: `clip`, or `fill` for the raster stage of Table 3.
    pub phase: String,
    /// Edge count (polygons) or window edge count (lines).
    pub size: usize,
    /// `intersection`, `union`, `difference`, `xor`, or `lines` for line clipping.
    pub op: String,
    /// The fill rule the operands were read under.
    pub fill_rule: String,
    /// Round number; within a round every clipper ran once, interleaved.
    pub repetition: usize,
    /// Calls timed back to back in this measurement (`time_ns` is per call).
    pub iterations: u32,
    /// Wall-clock nanoseconds per call.
    pub time_ns: f64,
    /// Whether the timed call's result passed the check (bench: the exact oracle, or its area
    /// against the exact area); empty where it was not checked (and in files written before the
    /// column existed).
    #[serde(default)]
    pub correct: Option<bool>,
}

/// Writes `rows` as CSV with a header line.
pub fn write_csv<T: Serialize>(path: &Path, rows: &[T]) -> Result<(), CliError> {
    let text = csv_text(rows).map_err(|e| CliError::failed(format!("{}: cannot write ({e})", path.display())))?;
    write_file(path, &text)
}

/// `rows` as CSV text with a header line, as [`write_csv`] writes them.
pub fn csv_text<T: Serialize>(rows: &[T]) -> Result<String, String> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    for row in rows {
        writer.serialize(row).map_err(|e| e.to_string())?;
    }
    let bytes = writer.into_inner().map_err(|e| e.to_string())?;
    String::from_utf8(bytes).map_err(|e| e.to_string())
}

/// Reads every row of a CSV written by [`write_csv`].
pub fn read_csv<T: DeserializeOwned>(path: &Path) -> Result<Vec<T>, CliError> {
    let fail = |e: &dyn std::fmt::Display| CliError::failed(format!("{}: cannot read ({e})", path.display()));
    let mut reader = csv::Reader::from_path(path).map_err(|e| fail(&e))?;
    reader.deserialize().collect::<Result<Vec<T>, _>>().map_err(|e| fail(&e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_round_trip_through_csv() {
        let dir = std::env::temp_dir().join(format!("clipbench-raw-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("rows.csv");
        let rows = vec![Measurement {
            workload: "star".into(),
            case: "0".into(),
            clipper: "vatti".into(),
            phase: "clip".into(),
            size: 20,
            op: "intersection".into(),
            fill_rule: "even-odd".into(),
            repetition: 3,
            iterations: 16,
            time_ns: 1234.5,
            correct: Some(false),
        }];
        write_csv(&path, &rows).unwrap();
        let back: Vec<Measurement> = read_csv(&path).unwrap();
        assert_eq!(back, rows);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
