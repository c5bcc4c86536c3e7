//! SVG pictures of a fuzz input and what the clippers made of it, for regression files.

use clip_core::{Polygons, VisiblePiece};
use clip_testkit::case_record::{lines_svg, polygons_svg_with_fill};

use crate::{Outcome, lines, vatti, windows};

/// The picture of `data` decoded as target `target`'s input: the operands (or window and
/// segments) and, where the check passes, each result. `None` when the bytes do not decode to a
/// geometric case (too short, or a target without geometry).
pub fn picture(target: &str, data: &[u8]) -> Option<String> {
    match target {
        "vatti" => {
            let case = vatti::decode(data)?;
            let outcome = vatti::check(&case).unwrap_or(Outcome::Refused);
            Some(polygons_picture(&case.subject, &case.clip, case.fill, &outcome))
        }
        "window_clippers" => {
            let case = windows::decode(data)?;
            let outcome = windows::check(&case).unwrap_or(Outcome::Refused);
            Some(polygons_picture(&case.subject, &case.window, case.fill, &outcome))
        }
        "line_clippers" => {
            let case = lines::decode(data)?;
            let outputs = match lines::check(&case) {
                Ok(Outcome::Lines(outputs)) => outputs,
                _ => Vec::new(),
            };
            let named: Vec<(&str, &[VisiblePiece])> = outputs.iter().map(|(n, p)| (*n, p.as_slice())).collect();
            Some(lines_svg(&case.window, &case.segments, &named))
        }
        _ => None,
    }
}

fn polygons_picture(subject: &Polygons, clip: &Polygons, fill: clip_core::FillRule, outcome: &Outcome) -> String {
    let outputs: Vec<(&str, &Polygons)> = match outcome {
        Outcome::Polygons(outputs) => outputs.iter().map(|(n, p)| (*n, p)).collect(),
        _ => Vec::new(),
    };
    polygons_svg_with_fill(subject, clip, fill, &outputs)
}
