//! Fig. 6-24 redrawn: a concave polygon clipped by Sutherland-Hodgman with its bridge, and by the split mode without.

use std::path::Path;

use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons, Rect, Ring};
use clip_oracle::polygon::bridge_count_along;
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_testkit::case_record::polygons_svg;

use crate::cli_error::CliError;
use crate::results_files::lecture_sh::FIGURES;
use crate::write::write_file;

/// The notes' Fig. 6-24 in spirit: a concave polygon with two prongs rising through the top of
/// the window, and a dent between them, so its part inside the window falls into two pieces.
pub fn subject_and_window() -> (Polygons, Polygons) {
    let subject = Ring::from(
        &[(1.0, 1.0), (9.0, 1.0), (9.0, 9.0), (7.0, 9.0), (6.0, 4.0), (4.0, 4.0), (3.0, 9.0), (1.0, 9.0)][..],
    );
    (Polygons::from(subject), Polygons::from(Rect::new(0.0, 5.0, 10.0, 8.0)))
}

/// Writes both pictures; the split one must hold no bridge and the plain one at least one.
pub fn write(out: &Path) -> Result<(), CliError> {
    let (subject, window) = subject_and_window();
    let run = |c: SutherlandHodgman| {
        c.clip(&subject, &window, BoolOp::Intersection, FillRule::NonZero)
            .map_err(|e| CliError::failed(format!("Fig. 6-24: {e}")))
    };
    let (plain, split) = (run(SutherlandHodgman::default())?, run(SutherlandHodgman::SPLIT)?);
    let (bridges_plain, bridges_split) =
        (bridge_count_along(&plain, &window, 0.0), bridge_count_along(&split, &window, 0.0));
    if bridges_plain == 0 || bridges_split != 0 || split.rings.len() != 2 {
        return Err(CliError::failed(format!(
            "Fig. 6-24: expected a bridge from sutherland-hodgman ({bridges_plain}) and two rings without one from the split mode ({} rings, {bridges_split} bridges)",
            split.rings.len()
        )));
    }
    for ((file, _), (name, output)) in
        FIGURES.iter().zip([("sutherland-hodgman", &plain), ("sutherland-hodgman-split", &split)])
    {
        write_file(&out.join(file), &polygons_svg(&subject, &window, &[(name, output)]))?;
    }
    Ok(())
}
