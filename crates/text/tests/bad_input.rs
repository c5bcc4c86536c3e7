//! Bad input: every kind gets its typed error, never a panic.

mod common;

use std::path::Path;

use clip_core::{ClipError, Point, Polygons, Rect, Ring};
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_text::{DEFAULT_TOLERANCE, OutlineFont, Strategy, Text, TextError, TextWindow, clip_text};

#[test]
fn a_missing_font_file_is_unreadable() {
    let e = OutlineFont::from_file(Path::new("no-such-dir/no-such-font.ttf")).unwrap_err();
    assert!(matches!(e, TextError::FontUnreadable { .. }), "{e}");
    assert!(e.to_string().contains("no-such-font.ttf"), "{e}");
}

#[test]
fn bytes_that_are_not_a_font_are_invalid() {
    let e = OutlineFont::from_bytes(b"this is not a font".to_vec(), "notes.txt").unwrap_err();
    assert!(matches!(e, TextError::FontInvalid { .. }), "{e}");
    let e = OutlineFont::from_bytes(Vec::new(), "empty.ttf").unwrap_err();
    assert!(matches!(e, TextError::FontInvalid { .. }), "{e}");
}

#[test]
fn a_character_the_font_lacks_is_named() {
    let font = common::dejavu();
    let e = Text::outline(&font, "ok\u{E000}", 20.0, Point::new(0.0, 0.0), DEFAULT_TOLERANCE).unwrap_err();
    assert!(matches!(e, TextError::MissingGlyph { ch: '\u{E000}', .. }), "{e}");
    let e = Text::bitmap("café", 16.0, Point::new(0.0, 0.0)).unwrap_err();
    assert!(matches!(e, TextError::MissingGlyph { ch: 'é', .. }), "{e}");
}

#[test]
fn empty_strings_and_bad_sizes_are_refused() {
    let font = common::dejavu();
    let o = Point::new(10.0, 10.0);
    assert!(matches!(Text::outline(&font, "", 20.0, o, DEFAULT_TOLERANCE), Err(TextError::EmptyString)));
    assert!(matches!(Text::bitmap("", 16.0, o), Err(TextError::EmptyString)));
    for size in [0.0, -3.0, f64::NAN, f64::INFINITY, 1e300] {
        assert!(
            matches!(Text::outline(&font, "a", size, o, DEFAULT_TOLERANCE), Err(TextError::BadSize { .. })),
            "{size}"
        );
        assert!(matches!(Text::bitmap("a", size, o), Err(TextError::BadSize { .. })), "{size}");
    }
    for tolerance in [0.0, -1.0, f64::NAN] {
        assert!(matches!(Text::outline(&font, "a", 20.0, o, tolerance), Err(TextError::BadTolerance { .. })));
    }
    let far = Point::new(f64::NAN, 0.0);
    assert!(matches!(Text::bitmap("a", 16.0, far), Err(TextError::BadOrigin { .. })));
}

#[test]
fn degenerate_windows_and_windows_a_clipper_refuses_are_typed() {
    let flat = Polygons::from(Ring::from(&[(0.0, 0.0), (5.0, 0.0), (10.0, 0.0)][..]));
    assert!(matches!(TextWindow::new(&flat), Err(TextError::Clip(ClipError::DegenerateWindow { .. }))));
    assert!(matches!(TextWindow::new(&Polygons::empty()), Err(TextError::Clip(ClipError::DegenerateWindow { .. }))));
    let nan = Polygons::from(Ring::from(&[(0.0, 0.0), (5.0, f64::NAN), (10.0, 3.0)][..]));
    assert!(matches!(TextWindow::new(&nan), Err(TextError::Clip(ClipError::NonFinite { .. }))));
    // A concave window is fine for Vatti but Sutherland-Hodgman refuses it, typed.
    let font = common::dejavu();
    let text = Text::outline(&font, "Hello", 30.0, Point::new(10.0, 20.0), DEFAULT_TOLERANCE).unwrap();
    let l = Polygons::from(Ring::from(
        &[(0.0, 0.0), (60.0, 0.0), (60.0, 30.0), (30.0, 30.0), (30.0, 60.0), (0.0, 60.0)][..],
    ));
    let e =
        clip_text(&text, &TextWindow::new(&l).unwrap(), Strategy::Components, &SutherlandHodgman::SPLIT).unwrap_err();
    assert!(matches!(e, TextError::Clip(ClipError::WindowNotConvex { .. })), "{e}");
    // A window away from the text clips everything off, whatever the strategy.
    let away = TextWindow::new(&Polygons::from(Rect::new(500.0, 500.0, 600.0, 600.0))).unwrap();
    for strategy in Strategy::ALL {
        let out = clip_text(&text, &away, strategy, &SutherlandHodgman::SPLIT).unwrap();
        assert!(out.kept.is_empty() && out.polygons.is_empty() && out.pixels.is_empty(), "{strategy}");
    }
}

#[test]
fn dejavu_has_quadratic_outlines_flattened_within_the_tolerance() {
    let font = common::dejavu();
    assert_eq!(font.units_per_em(), 2048);
    let coarse = Text::outline(&font, "O", 200.0, Point::new(20.0, 60.0), 1.0).unwrap();
    let fine = Text::outline(&font, "O", 200.0, Point::new(20.0, 60.0), 0.01).unwrap();
    let count = |t: &Text| t.outlines().vertex_count();
    assert!(count(&fine) > 3 * count(&coarse), "{} vs {}", count(&fine), count(&coarse));
    // The two flattenings enclose nearly the same area: both within their tolerance of the curve.
    let (a, b) = (coarse.outlines().signed_area().abs(), fine.outlines().signed_area().abs());
    let perimeter: f64 = fine.outlines().edges().map(|e| e.a.distance(e.b)).sum();
    assert!((a - b).abs() <= 1.0 * perimeter, "{a} vs {b}");
}
