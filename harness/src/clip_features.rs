//! `clipbench clip` on a GeoJSON Feature or FeatureCollection subject: each feature clipped on its
//! own against the clip operand, its `id` and `properties` kept, and the features written back
//! (as ogr2ogr's `-clipsrc` and mapshaper's `-clip` do); a feature with a null geometry is written
//! back as it is. Clipping the features' union instead would lose which part came from which
//! feature, and where features overlap, even-odd would cut holes no feature has.

use clip_core::{BoolOp, FillRule, Operand, Polygons, Segment, VisiblePiece, validate_polygons, validate_segments};
use clip_testkit::case_record::{lines_svg, polygons_svg, polygons_to_wkt, segments_to_wkt};
use geo::{LineString, MultiLineString, MultiPolygon};

use crate::cli_error::{CliError, InputError};
use crate::console;
use crate::read::Features;
use crate::registry::{LineEntry, PolygonEntry};
use crate::write::OutputFormat;

/// A feature's clipped geometry: polygons or visible pieces; none for a null geometry.
enum Clipped {
    Polygons(Polygons),
    Pieces(Vec<Segment>, Vec<VisiblePiece>),
    Null,
}

/// The clipper the features go through: polygons or line strings, as they hold.
pub enum FeatureClipper<'a> {
    /// A polygon clipper, with the operation and fill rule.
    Polygon(&'a PolygonEntry, BoolOp, FillRule),
    /// A line clipper.
    Line(&'a LineEntry),
}

/// Clips every feature of `features` (read from `subject`) against `clip`, and returns the output
/// text in `format`: GeoJSON features (WKT and SVG get their geometries, without properties, said
/// in a note).
pub fn clip_features(
    clipper: FeatureClipper<'_>,
    subject: &std::path::Path,
    features: &Features,
    clip: &Polygons,
    format: OutputFormat,
) -> Result<String, CliError> {
    let name = match &clipper {
        FeatureClipper::Polygon(e, ..) => e.clipper.name(),
        FeatureClipper::Line(e) => e.clipper.name(),
    };
    let prepared = match &clipper {
        FeatureClipper::Line(e) => Some(e.clipper.prepare(clip).map_err(|e| CliError::usage(e.to_string()))?),
        FeatureClipper::Polygon(..) => None,
    };
    let mut clipped = Vec::with_capacity(features.features.len());
    for f in &features.features {
        let Some(shapes) = &f.shapes else {
            clipped.push(Clipped::Null);
            continue;
        };
        let at = |e: clip_core::ClipError| InputError::new(subject, format!("{}: {e}", f.place));
        clipped.push(match (&clipper, &prepared) {
            (FeatureClipper::Line(_), Some(window)) => {
                validate_segments(&shapes.segments).map_err(at)?;
                let mut pieces = Vec::new();
                window.clip_batch(&shapes.segments, &mut pieces).map_err(|e| CliError::usage(e.to_string()))?;
                Clipped::Pieces(shapes.segments.clone(), pieces)
            }
            (FeatureClipper::Polygon(entry, op, fill), _) => {
                let polygons = shapes.polygons();
                validate_polygons(&polygons, Operand::Subject).map_err(at)?;
                let result =
                    entry.clipper.clip(&polygons, clip, *op, *fill).map_err(|e| CliError::usage(e.to_string()))?;
                Clipped::Polygons(result)
            }
            (FeatureClipper::Line(_), None) => Clipped::Null,
        });
    }
    if format != OutputFormat::GeoJson {
        console::note(format_args!(
            "{}: the features' ids and properties are not written to {}: write .geojson to keep them",
            subject.display(),
            if format == OutputFormat::Wkt { "WKT" } else { "a picture" }
        ));
    }
    Ok(match format {
        OutputFormat::GeoJson => geojson_features(features, &clipped) + "\n",
        OutputFormat::Wkt => {
            let members: Vec<String> = clipped
                .iter()
                .map(|c| match c {
                    Clipped::Polygons(p) => polygons_to_wkt(p, true),
                    Clipped::Pieces(_, pieces) => segments_to_wkt(&pieces.iter().map(|p| p.piece).collect::<Vec<_>>()),
                    Clipped::Null => "GEOMETRYCOLLECTION EMPTY".to_owned(),
                })
                .collect();
            if members.is_empty() {
                "GEOMETRYCOLLECTION EMPTY\n".to_owned()
            } else {
                format!("GEOMETRYCOLLECTION ({})\n", members.join(", "))
            }
        }
        OutputFormat::Svg => picture(name, features, &clipped, clip),
    })
}

/// The features back as GeoJSON, each with its id and properties and its clipped geometry.
fn geojson_features(features: &Features, clipped: &[Clipped]) -> String {
    let out: Vec<geojson::Feature> = features
        .features
        .iter()
        .zip(clipped)
        .map(|(f, c)| geojson::Feature {
            bbox: None,
            geometry: match c {
                Clipped::Polygons(p) => {
                    Some(geojson::Geometry::new(geojson::GeometryValue::from(&MultiPolygon::from(p))))
                }
                Clipped::Pieces(_, pieces) => {
                    let lines =
                        MultiLineString(pieces.iter().map(|p| LineString::from(vec![p.piece.a, p.piece.b])).collect());
                    Some(geojson::Geometry::new(geojson::GeometryValue::from(&lines)))
                }
                Clipped::Null => None,
            },
            id: f.id.clone(),
            properties: f.properties.clone(),
            foreign_members: None,
        })
        .collect();
    if features.collection {
        geojson::FeatureCollection { bbox: None, features: out, foreign_members: None }.to_string()
    } else {
        out.into_iter().next().map(|f| f.to_string()).unwrap_or_default()
    }
}

/// Every feature's inputs and result in one picture.
fn picture(clipper: &str, features: &Features, clipped: &[Clipped], clip: &Polygons) -> String {
    let shapes = features.features.iter().filter_map(|f| f.shapes.as_ref());
    if features.line_strings {
        let segments: Vec<Segment> = shapes.flat_map(|s| s.segments.iter().copied()).collect();
        let mut pieces = Vec::new();
        let mut offset = 0;
        for c in clipped {
            if let Clipped::Pieces(own, p) = c {
                pieces.extend(p.iter().map(|p| VisiblePiece { segment: p.segment + offset, piece: p.piece }));
                offset += own.len();
            }
        }
        lines_svg(clip, &segments, &[(clipper, &pieces)])
    } else {
        let subject = Polygons::new(shapes.flat_map(|s| s.rings.iter().cloned()).collect());
        let result = Polygons::new(
            clipped
                .iter()
                .filter_map(|c| if let Clipped::Polygons(p) = c { Some(p.rings.iter().cloned()) } else { None })
                .flatten()
                .collect(),
        );
        polygons_svg(&subject, clip, &[(clipper, &result)])
    }
}
