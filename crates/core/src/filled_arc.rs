//! A filled arc: an elliptic arc closed by two radii (a sector) or by its chord (a segment).

use core::f64::consts::PI;
use core::fmt;
use core::str::FromStr;

use crate::predicates::orient;
use crate::{BoundaryPiece, CurveRegion, Ellipse, EllipseArc, Location, Point, Rect, Segment, UnknownName};

/// How an arc is closed into a filled region.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ArcFill {
    /// The arc and the two radii from its ends to the centre (a pie slice).
    Sector,
    /// The arc and the chord between its ends (a circular or elliptic segment).
    Chord,
}

impl ArcFill {
    /// Both kinds.
    pub const ALL: [ArcFill; 2] = [ArcFill::Sector, ArcFill::Chord];

    /// `sector` or `chord`.
    pub fn name(self) -> &'static str {
        match self {
            ArcFill::Sector => "sector",
            ArcFill::Chord => "chord",
        }
    }
}

impl fmt::Display for ArcFill {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for ArcFill {
    type Err = UnknownName;

    fn from_str(s: &str) -> Result<ArcFill, UnknownName> {
        ArcFill::ALL.into_iter().find(|k| k.name().eq_ignore_ascii_case(s)).ok_or_else(|| UnknownName {
            what: "arc fill",
            given: s.to_owned(),
            valid: "sector, chord",
        })
    }
}

/// A filled arc: the region bounded by `arc` (counter-clockwise) and its closing sides. A whole
/// ellipse (sweep 2π) is the filled ellipse under either fill. Every `FilledArc` is usable: the
/// arc was validated when it was built ([`EllipseArc::new`] refuses empty or non-finite sweeps).
///
/// The region is the ellipse cut by a half-plane (chord: the side of the line through the arc's
/// ends that holds the arc) or by a wedge at the centre (sector: convex for sweeps up to π,
/// the union of two half-planes beyond), which is how [`FilledArc::locate_closing`] decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilledArc {
    arc: EllipseArc,
    fill: ArcFill,
}

impl FilledArc {
    /// The arc closed by `fill`.
    pub fn new(arc: EllipseArc, fill: ArcFill) -> FilledArc {
        FilledArc { arc, fill }
    }

    /// The whole filled ellipse.
    pub fn whole(ellipse: Ellipse) -> FilledArc {
        FilledArc { arc: EllipseArc::full(ellipse), fill: ArcFill::Sector }
    }

    /// The arc.
    #[inline]
    pub fn arc(&self) -> &EllipseArc {
        &self.arc
    }

    /// How it is closed.
    #[inline]
    pub fn fill(&self) -> ArcFill {
        self.fill
    }

    /// The ellipse the arc lies on.
    #[inline]
    pub fn ellipse(&self) -> &Ellipse {
        self.arc.ellipse()
    }

    /// True for a whole ellipse (no closing side).
    #[inline]
    pub fn is_whole(&self) -> bool {
        self.arc.is_closed()
    }

    /// The closing sides, walked with the region on their left: for a sector the radius from the
    /// arc's end to the centre and the one from the centre to its start, for a chord the chord
    /// from end to start; none for a whole ellipse.
    pub fn closing_segments(&self) -> Vec<Segment> {
        if self.is_whole() {
            return Vec::new();
        }
        let e = self.ellipse();
        let (s, t) = (e.point_at(self.arc.start()), e.point_at(self.arc.end()));
        match self.fill {
            ArcFill::Sector => vec![Segment::new(t, e.center()), Segment::new(e.center(), s)],
            ArcFill::Chord => vec![Segment::new(t, s)],
        }
    }

    /// The exact area: `rx ry sweep / 2` for a sector, `rx ry (sweep - sin sweep) / 2` for a
    /// segment (the affine image of the circular formulas), `π rx ry` for a whole ellipse.
    pub fn area(&self) -> f64 {
        let (rx, ry) = self.ellipse().radii();
        let sweep = self.arc.sweep();
        if self.is_whole() {
            return PI * rx * ry;
        }
        match self.fill {
            ArcFill::Sector => 0.5 * rx * ry * sweep,
            ArcFill::Chord => 0.5 * rx * ry * (sweep - sweep.sin()),
        }
    }

    /// The bounding box: the arc's, with the centre for a sector (the chord's ends are the arc's).
    pub fn bounds(&self) -> Rect {
        let b = self.arc.bounds();
        match self.fill {
            ArcFill::Sector if !self.is_whole() => b.including(self.ellipse().center()),
            _ => b,
        }
    }

    /// The unclipped region: one loop, the arc then the closing sides.
    pub fn region(&self) -> CurveRegion {
        let mut lp = vec![BoundaryPiece::Arc { from: self.arc.start(), to: self.arc.end() }];
        lp.extend(self.closing_segments().into_iter().map(BoundaryPiece::Segment));
        CurveRegion { ellipse: *self.ellipse(), loops: vec![lp] }
    }

    /// Where `p` lies against the closing sides' half-plane (chord) or wedge (sector), ignoring
    /// the ellipse: exact orientation tests against the rounded ends of the arc. The whole plane
    /// for a whole ellipse.
    pub fn locate_closing(&self, p: Point) -> Location {
        if self.is_whole() {
            return Location::Inside;
        }
        let e = self.ellipse();
        let (s, t, c) = (e.point_at(self.arc.start()), e.point_at(self.arc.end()), e.center());
        match self.fill {
            ArcFill::Chord => match orient(t, s, p).sign() {
                1 => Location::Inside,
                0 => Location::Boundary,
                _ => Location::Outside,
            },
            ArcFill::Sector => {
                // Left of centre → start, and right of centre → end.
                let (a, b) = (orient(c, s, p).sign(), -orient(c, t, p).sign());
                let (inside, outside) = if self.arc.sweep() <= PI {
                    (a > 0 && b > 0, a < 0 || b < 0)
                } else {
                    (a > 0 || b > 0, a < 0 && b < 0)
                };
                if inside {
                    Location::Inside
                } else if outside {
                    Location::Outside
                } else {
                    Location::Boundary
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::{FRAC_PI_2, TAU};

    fn quarter(fill: ArcFill) -> FilledArc {
        let e = Ellipse::circle(Point::ZERO, 2.0).unwrap();
        FilledArc::new(EllipseArc::new(e, 0.0, FRAC_PI_2).unwrap(), fill)
    }

    #[test]
    fn areas_are_the_sector_and_segment_formulas_and_the_loops_agree() {
        let s = quarter(ArcFill::Sector);
        assert!((s.area() - PI).abs() < 1e-15);
        assert!((s.region().area() - s.area()).abs() < 1e-14);
        let c = quarter(ArcFill::Chord);
        assert!((c.area() - (PI - 2.0)).abs() < 1e-15);
        assert!((c.region().area() - c.area()).abs() < 1e-14);
        // A reflex sector and segment of a rotated ellipse: Green's theorem on the loop.
        let e = Ellipse::new(Point::new(3.0, -1.0), 4.0, 1.5, 0.7).unwrap();
        let arc = EllipseArc::new(e, 5.0, 4.5).unwrap();
        for fill in ArcFill::ALL {
            let f = FilledArc::new(arc, fill);
            assert!((f.region().area() - f.area()).abs() < 1e-12, "{fill}");
        }
        assert!((FilledArc::whole(e).area() - 6.0 * PI).abs() < 1e-12);
        assert!(FilledArc::new(EllipseArc::new(e, 1.0, TAU).unwrap(), ArcFill::Chord).closing_segments().is_empty());
    }

    #[test]
    fn closing_sides_locate_points() {
        let s = quarter(ArcFill::Sector);
        assert_eq!(s.locate_closing(Point::new(1.0, 1.0)), Location::Inside);
        assert_eq!(s.locate_closing(Point::new(1.0, 0.0)), Location::Boundary);
        assert_eq!(s.locate_closing(Point::new(-1.0, 1.0)), Location::Outside);
        let c = quarter(ArcFill::Chord);
        assert_eq!(c.locate_closing(Point::new(1.5, 1.5)), Location::Inside);
        assert_eq!(c.locate_closing(Point::new(0.5, 0.5)), Location::Outside);
        // Three quarters: the wedge is the union of two half-planes.
        let e = Ellipse::circle(Point::ZERO, 2.0).unwrap();
        let big = FilledArc::new(EllipseArc::new(e, 0.0, 1.5 * PI).unwrap(), ArcFill::Sector);
        assert_eq!(big.locate_closing(Point::new(-1.0, -1.0)), Location::Inside);
        assert_eq!(big.locate_closing(Point::new(1.0, -1.0)), Location::Outside);
        assert_eq!(big.locate_closing(Point::new(-1.0, 0.0)), Location::Inside);
        assert_eq!(big.bounds(), big.arc().bounds());
        assert!(s.bounds().contains(Point::ZERO));
    }

    #[test]
    fn fills_parse_by_name() {
        assert_eq!("Chord".parse::<ArcFill>().unwrap(), ArcFill::Chord);
        assert!("pie".parse::<ArcFill>().is_err());
    }
}
