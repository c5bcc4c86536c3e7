//! The curve oracle catches wrong answers and passes hand-worked right ones.

use core::f64::consts::{FRAC_PI_2, PI, TAU};

use clip_core::{ArcFill, BoundaryPiece, CurveRegion, Ellipse, EllipseArc, FilledArc, Point, Polygons, Rect, Segment};
use clip_oracle::curve::{
    CurveFailure, check_filled_region, check_identities, check_region, check_visible, ellipse_side, filled_arc_side,
};

fn square() -> Polygons {
    Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0))
}

#[test]
fn visible_intervals_right_and_wrong() {
    // A circle centred on the right edge: visible from π/2 to 3π/2.
    let e = Ellipse::circle(Point::new(10.0, 5.0), 2.0).unwrap();
    let arc = EllipseArc::full(e);
    assert_eq!(check_visible(&square(), &arc, &[(FRAC_PI_2, 1.5 * PI)]), Ok(()));
    // The other half: samples disagree.
    let wrong = check_visible(&square(), &arc, &[(1.5 * PI, 2.5 * PI)]);
    assert!(matches!(wrong, Err(CurveFailure::WrongSample { .. })), "{wrong:?}");
    // A closed ellipse's interval must start within the first turn.
    let wrong = check_visible(&square(), &arc, &[(FRAC_PI_2 + TAU, 1.5 * PI + TAU)]);
    assert!(matches!(wrong, Err(CurveFailure::BadIntervals(_))), "{wrong:?}");
    // An end moved off the boundary by 1e-5.
    let wrong = check_visible(&square(), &arc, &[(FRAC_PI_2 + 1e-5, 1.5 * PI)]);
    assert!(matches!(wrong, Err(CurveFailure::EndOffBoundary { .. })), "{wrong:?}");
    // Unmerged or reversed intervals.
    let wrong = check_visible(&square(), &arc, &[(FRAC_PI_2, PI), (PI, 1.5 * PI)]);
    assert!(matches!(wrong, Err(CurveFailure::BadIntervals(_))), "{wrong:?}");
}

#[test]
fn regions_right_and_wrong() {
    let e = Ellipse::circle(Point::new(10.0, 5.0), 2.0).unwrap();
    let half = CurveRegion {
        ellipse: e,
        loops: vec![vec![
            BoundaryPiece::Arc { from: FRAC_PI_2, to: 1.5 * PI },
            BoundaryPiece::Segment(Segment::new(Point::new(10.0, 3.0), Point::new(10.0, 7.0))),
        ]],
    };
    assert_eq!(check_region(&square(), &half), Ok(()));
    let wrong = check_region(&square(), &CurveRegion::whole(e));
    assert!(matches!(wrong, Err(CurveFailure::WrongPoint { expected: false, .. })), "{wrong:?}");
    let open = CurveRegion { ellipse: e, loops: vec![vec![BoundaryPiece::Arc { from: FRAC_PI_2, to: 1.5 * PI }]] };
    assert!(matches!(check_region(&square(), &open), Err(CurveFailure::BadLoop(_))));
    // Areas and spans: the half disc and the other half add up; a wrong area does not.
    assert_eq!(
        check_identities(
            &EllipseArc::full(e),
            &[(0.0, PI)],
            &[(PI, TAU)],
            Some((&FilledArc::whole(e), 2.0 * PI, 2.0 * PI))
        ),
        Ok(())
    );
    assert!(
        check_identities(
            &EllipseArc::full(e),
            &[(0.0, PI)],
            &[(PI, TAU)],
            Some((&FilledArc::whole(e), 2.0 * PI, 2.1 * PI))
        )
        .is_err()
    );
    assert!(check_identities(&EllipseArc::full(e), &[(0.0, PI)], &[(PI + 1e-4, TAU)], None).is_err());
}

#[test]
fn point_in_ellipse_abstains_near_the_curve() {
    let e = Ellipse::new(Point::new(1.0, 1.0), 4.0, 1.0, 0.5).unwrap();
    assert_eq!(ellipse_side(&e, Point::new(1.0, 1.0), 1e-6), Some(true));
    assert_eq!(ellipse_side(&e, Point::new(10.0, 1.0), 1e-6), Some(false));
    let on = e.point_at(0.3);
    assert_eq!(ellipse_side(&e, on, 1e-6), None);
    let (s, c) = 0.5f64.sin_cos();
    // 1e-3 outside along the long axis: decided with a small margin, not with a large one.
    let out = Point::new(1.0 + 4.001 * c, 1.0 + 4.001 * s);
    assert_eq!(ellipse_side(&e, out, 1e-6), Some(false));
    assert_eq!(ellipse_side(&e, out, 1e-2), None);
}

#[test]
fn filled_arcs_are_judged_by_their_closing_sides() {
    // The quarter disc x, y >= 0 of radius 4 about (5, 5), wholly inside the square.
    let e = Ellipse::circle(Point::new(5.0, 5.0), 4.0).unwrap();
    let quarter = EllipseArc::new(e, 0.0, FRAC_PI_2).unwrap();
    let sector = FilledArc::new(quarter, ArcFill::Sector);
    let chord = FilledArc::new(quarter, ArcFill::Chord);
    assert_eq!(filled_arc_side(&sector, Point::new(6.0, 6.0), 1e-9), Some(true));
    assert_eq!(filled_arc_side(&chord, Point::new(6.0, 6.0), 1e-9), Some(false));
    assert_eq!(filled_arc_side(&sector, Point::new(4.0, 6.0), 1e-9), Some(false));
    assert_eq!(filled_arc_side(&sector, Point::new(5.0, 6.0), 1e-9), None);
    assert_eq!(check_filled_region(&square(), &sector, &sector.region()), Ok(()));
    assert_eq!(check_filled_region(&square(), &chord, &chord.region()), Ok(()));
    // The sector's loop given as the chord's answer, and the whole disc as the sector's: wrong.
    assert!(matches!(
        check_filled_region(&square(), &chord, &sector.region()),
        Err(CurveFailure::WrongPoint { expected: false, .. })
    ));
    assert!(matches!(
        check_filled_region(&square(), &sector, &CurveRegion::whole(e)),
        Err(CurveFailure::WrongPoint { expected: false, .. })
    ));
    // Areas split between a window and its complement add up to the sector's, not the disc's.
    let a = 4.0 * PI;
    assert_eq!(check_identities(&quarter, &[(0.0, FRAC_PI_2)], &[], Some((&sector, a, 0.0))), Ok(()));
    assert!(check_identities(&quarter, &[(0.0, FRAC_PI_2)], &[], Some((&chord, a, 0.0))).is_err());
}
