//! The registry: every clipper the harness knows, one line each, with where it comes from.
//!
//! To add a clipper, add its crate to harness/Cargo.toml and one line to [`registry`]:
//! `.polygon(Origin::Ours, REGION_TOLERANCE, clip_vatti::Vatti)` for a polygon
//! clipper, `.line(Origin::Ours, LINE_TOLERANCE, ...)` for a line clipper (its tolerance is on the
//! parameter `t` of piece end points). Its name, operations,
//! fill rules and windows come from its own `name()` and `capabilities()`, so every command runs
//! it only where it applies. Curve clippers (`.curve(...)`) take any window and run on the curve
//! workloads.

use std::sync::Arc;

use clip_core::{LineClipper, PolygonClipper};
use clip_curve::CurveClipper;
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_line_index::LineIndex;
use clip_oracle::polygon::{GEO_TOLERANCE, REGION_TOLERANCE};
use clip_peers::{
    Clipper1Clipper, Clipper2Clipper, Clipper2OpenLines, Clipper2RectClipper, Clipper2RectLines, Clipper2RustClipper,
    GeoClipper, GeoLineClipper, GeosClipper, IOverlayClipper,
};
use clip_rect_four_state::FourState;
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_vatti::{FixedSweep, Sweep, Vatti, VattiPrepared};
use clip_virtual_box::VirtualBox;

use crate::cli_error::CliError;
use crate::measure::own_time::OwnTime;
use crate::measure::peak_memory::OwnProcessMemory;

/// Tolerance of our exact line clippers on the parameter `t` of piece end points.
pub const LINE_TOLERANCE: f64 = 1e-9;

/// Every registered clipper.
pub fn registry() -> Registry {
    Registry::default()
        .polygon(Origin::Ours, REGION_TOLERANCE, Vatti)
        .polygon(Origin::Ours, REGION_TOLERANCE, VattiPrepared)
        .polygon(Origin::Ours, REGION_TOLERANCE, FixedSweep(Sweep::Scanbeam))
        .polygon(Origin::Ours, REGION_TOLERANCE, SutherlandHodgman::default())
        .polygon(Origin::Ours, REGION_TOLERANCE, SutherlandHodgman::SPLIT)
        .polygon(Origin::Ours, REGION_TOLERANCE, FourState)
        .line(Origin::Ours, LINE_TOLERANCE, CyrusBeck)
        .line(Origin::Ours, LINE_TOLERANCE, Liu)
        .line(Origin::Ours, LINE_TOLERANCE, VirtualBox::NEW2)
        .line(Origin::Ours, LINE_TOLERANCE, VirtualBox::NEW1)
        .line(Origin::Ours, LINE_TOLERANCE, LineIndex)
        .curve(Origin::Ours, CurveClipper::WITH_TESTS)
        .curve(Origin::Ours, CurveClipper::WITHOUT_TESTS)
        .polygon(Origin::Peer, GEO_TOLERANCE, GeoClipper::new())
        .line(Origin::Peer, GEO_TOLERANCE, GeoLineClipper::new())
        .polygon(Origin::Peer, GEO_TOLERANCE, Clipper2Clipper::new())
        .polygon(Origin::Peer, GEO_TOLERANCE, Clipper2RectClipper)
        .line(Origin::Peer, GEO_TOLERANCE, Clipper2RectLines)
        .line(Origin::Peer, GEO_TOLERANCE, Clipper2OpenLines)
        .polygon(Origin::Peer, GEO_TOLERANCE, GeosClipper::new())
        .polygon(Origin::Peer, GEO_TOLERANCE, IOverlayClipper::new())
        .polygon(Origin::Peer, GEO_TOLERANCE, Clipper1Clipper::new())
        .polygon(Origin::Peer, GEO_TOLERANCE, Clipper2RustClipper::new())
}

/// Where a clipper comes from, which decides whether its failures fail a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Origin {
    /// One of this project's algorithm crates: its failures fail a run.
    Ours,
    /// A library we compare against (`geo`, Clipper2, GEOS, ...): failures are reported only.
    Peer,
    /// An external clipper process (`--external`): a peer, failures reported only.
    External,
    /// An external clipper under `--strict`: its failures fail a run like ours.
    Strict,
}

impl Origin {
    /// True when a failure of a clipper of this origin fails the run.
    pub fn fails_run(self) -> bool {
        matches!(self, Origin::Ours | Origin::Strict)
    }

    /// `ours`, `peer`, `external` or `strict`, as summaries print it.
    pub fn label(self) -> &'static str {
        match self {
            Origin::Ours => "ours",
            Origin::Peer => "peer",
            Origin::External => "external",
            Origin::Strict => "strict",
        }
    }
}

/// A registered polygon clipper.
pub struct PolygonEntry {
    /// The clipper.
    pub clipper: Box<dyn PolygonClipper>,
    /// Ours or a peer.
    pub origin: Origin,
    /// Relative area tolerance its output is checked with (see `clip_oracle::polygon`).
    pub tolerance: f64,
    /// For an external clipper, the times it reports for itself (bench shows them beside the
    /// round trip).
    pub own_time: Option<Arc<OwnTime>>,
    /// For an external clipper, its peak memory for one call, measured in its own process (bench
    /// reads it for the large groups).
    pub own_memory: Option<Arc<dyn OwnProcessMemory>>,
    /// For an external clipper, the command-line options that register it again (a replay
    /// command needs them).
    pub external: Option<String>,
    /// For an external clipper, the `name` its handshake gave: the library and its version, as
    /// the process found them (result files record it).
    pub handshake: Option<String>,
}

/// A registered line clipper.
pub struct LineEntry {
    /// The clipper.
    pub clipper: Box<dyn LineClipper>,
    /// Ours or a peer.
    pub origin: Origin,
    /// Tolerance on the parameter `t` of piece end points.
    pub tolerance: f64,
    /// For an external clipper, the command-line options that register it again.
    pub external: Option<String>,
}

/// A registered curve clipper (circles, ellipses, arcs; any window, read even-odd).
pub struct CurveEntry {
    /// The clipper.
    pub clipper: CurveClipper,
    /// Ours or a peer.
    pub origin: Origin,
}

/// The polygon, line and curve clippers, in registration order (a name may be both polygon and
/// line: `geo`).
#[derive(Default)]
pub struct Registry {
    /// Polygon clippers.
    pub polygon: Vec<PolygonEntry>,
    /// Line clippers.
    pub line: Vec<LineEntry>,
    /// Curve clippers.
    pub curve: Vec<CurveEntry>,
}

impl Registry {
    /// Adds a polygon clipper.
    pub fn polygon(mut self, origin: Origin, tolerance: f64, clipper: impl PolygonClipper + 'static) -> Registry {
        self.polygon.push(PolygonEntry {
            clipper: Box::new(clipper),
            origin,
            tolerance,
            own_time: None,
            own_memory: None,
            external: None,
            handshake: None,
        });
        self
    }

    /// Adds a line clipper.
    pub fn line(mut self, origin: Origin, tolerance: f64, clipper: impl LineClipper + 'static) -> Registry {
        self.line.push(LineEntry { clipper: Box::new(clipper), origin, tolerance, external: None });
        self
    }

    /// Adds a curve clipper.
    pub fn curve(mut self, origin: Origin, clipper: CurveClipper) -> Registry {
        self.curve.push(CurveEntry { clipper, origin });
        self
    }

    /// Every name, each once, in registration order.
    pub fn names(&self) -> Vec<&'static str> {
        let mut names: Vec<&'static str> = Vec::new();
        let all = self
            .polygon
            .iter()
            .map(|e| e.clipper.name())
            .chain(self.line.iter().map(|e| e.clipper.name()))
            .chain(self.curve.iter().map(|e| e.clipper.name()));
        for name in all {
            if !names.contains(&name) {
                names.push(name);
            }
        }
        names
    }

    /// The polygon clipper called `name`.
    pub fn find_polygon(&self, name: &str) -> Option<&PolygonEntry> {
        self.polygon.iter().find(|e| e.clipper.name() == name)
    }

    /// The line clipper called `name`.
    pub fn find_line(&self, name: &str) -> Option<&LineEntry> {
        self.line.iter().find(|e| e.clipper.name() == name)
    }

    /// The options that register the named clippers that are external (each once, in the order
    /// named): what a command replaying their case needs beside its own arguments.
    pub fn external_options(&self, names: &[&str]) -> Vec<String> {
        let mut options: Vec<String> = Vec::new();
        for name in names {
            let polygon = self.find_polygon(name).and_then(|e| e.external.clone());
            if let Some(option) = polygon.or_else(|| self.find_line(name).and_then(|e| e.external.clone()))
                && !options.contains(&option)
            {
                options.push(option);
            }
        }
        options
    }

    /// Keeps only the named clippers (all of them when `names` is empty) and every external one
    /// (naming it on the command line selected it); an unknown name is a usage error listing the
    /// valid ones.
    pub fn select(mut self, names: &[String]) -> Result<Registry, CliError> {
        if names.is_empty() {
            return Ok(self);
        }
        let valid = self.names();
        if let Some(unknown) = names.iter().find(|n| !valid.contains(&n.as_str())) {
            return Err(unknown_clipper(unknown, &valid));
        }
        let external = |o: Origin| matches!(o, Origin::External | Origin::Strict);
        self.polygon.retain(|e| external(e.origin) || names.iter().any(|n| n == e.clipper.name()));
        self.line.retain(|e| external(e.origin) || names.iter().any(|n| n == e.clipper.name()));
        self.curve.retain(|e| names.iter().any(|n| n == e.clipper.name()));
        Ok(self)
    }
}

/// The usage error for a clipper name that is not registered.
pub fn unknown_clipper(given: &str, valid: &[&str]) -> CliError {
    CliError::usage(format!("unknown clipper '{given}' (registered: {})", valid.join(", ")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_select_keeps_both_kinds() {
        let names = registry().names();
        assert!(names.contains(&"geo") && names.contains(&"clipper2"), "{names:?}");
        assert!(names.iter().enumerate().all(|(i, n)| !names[..i].contains(n)), "{names:?}");
        let geo = registry().select(&["geo".to_owned()]).unwrap();
        assert_eq!(geo.polygon.len(), 1);
        assert_eq!(geo.line.len(), 1);
        let rect = registry().select(&["clipper2-rect".to_owned()]).unwrap();
        assert_eq!((rect.polygon.len(), rect.line.len()), (1, 1));
        let curve = registry().select(&["curve-no-tests".to_owned()]).unwrap();
        assert_eq!((curve.polygon.len(), curve.line.len(), curve.curve.len()), (0, 0, 1));
        assert!(!curve.curve[0].clipper.preliminary_tests);
    }

    #[test]
    fn unknown_name_lists_the_valid_ones() {
        let Err(e) = registry().select(&["vati".to_owned()]) else { panic!("accepted an unknown name") };
        assert_eq!(e.code, 2);
        assert!(
            e.message.contains("'vati'") && e.message.contains("geo") && e.message.contains("clipper2"),
            "{}",
            e.message
        );
    }
}
