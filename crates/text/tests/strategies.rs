//! Every strategy on the `text` workload against the raster oracle, on DejaVu Sans and the 8x8
//! bitmap font, with Vatti and (on convex windows) Sutherland-Hodgman as the outline clipper.

mod common;

use clip_core::{PolygonClipper, WindowKind};
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_testkit::workload::text_case;
use clip_text::oracle::check_clipped_text;
use clip_text::{DEFAULT_TOLERANCE, Strategy, Text, TextWindow, clip_text};
use clip_vatti::Vatti;

#[test]
fn every_strategy_matches_the_masked_reference() {
    let font = common::dejavu();
    let (mut kept_strings, mut kept_glyphs, mut cut) = (0, 0, 0);
    for index in 0..60 {
        let case = text_case(3, index);
        let window = TextWindow::new(&case.window).unwrap();
        let outline = Text::outline(&font, &case.string, case.size, case.origin, DEFAULT_TOLERANCE).unwrap();
        let bitmap = Text::bitmap(&case.string, case.size, case.origin).unwrap();
        let convex = WindowKind::Convex.accepts(&case.window);
        let clippers: Vec<&dyn PolygonClipper> =
            if convex { vec![&Vatti, &SutherlandHodgman::SPLIT] } else { vec![&Vatti] };
        for text in [&outline, &bitmap] {
            for strategy in Strategy::ALL {
                for &clipper in &clippers {
                    let clipped = clip_text(text, &window, strategy, clipper).unwrap();
                    if let Err(why) = check_clipped_text(text, &window, strategy, &clipped) {
                        panic!("{} ({strategy}, {}): {why}", case.description, clipper.name());
                    }
                    match strategy {
                        Strategy::String => kept_strings += usize::from(!clipped.kept.is_empty()),
                        Strategy::Character => kept_glyphs += clipped.kept.len(),
                        Strategy::Components => cut += usize::from(clipped.kept.len() < text.len()),
                    }
                }
            }
        }
    }
    // The workload exercises every outcome: whole strings kept, single glyphs kept, glyphs cut.
    assert!(kept_strings > 0 && kept_glyphs > 0 && cut > 0, "{kept_strings} {kept_glyphs} {cut}");
}

#[test]
fn a_wrong_output_is_caught() {
    let font = common::dejavu();
    let case = text_case(3, 4);
    let window = TextWindow::new(&case.window).unwrap();
    let text = Text::outline(&font, &case.string, case.size, case.origin, DEFAULT_TOLERANCE).unwrap();
    // The whole text drawn unclipped is not what per-component clipping must give, unless the
    // window holds it all.
    let everything = clip_text(
        &text,
        &TextWindow::new(&clip_core::Polygons::from(text.bounds)).unwrap(),
        Strategy::Components,
        &Vatti,
    )
    .unwrap();
    assert!(!window.contains_box(text.bounds), "{}", case.description);
    assert!(check_clipped_text(&text, &window, Strategy::Components, &everything).is_err());
    // Keeping a glyph the window cuts is caught for the all-or-none strategies too.
    let mut chars = clip_text(&text, &window, Strategy::Character, &Vatti).unwrap();
    let cut = (0..text.len()).find(|&i| !chars.kept.contains(&i) && !text.glyphs[i].bounds.is_empty()).unwrap();
    chars.kept.push(cut);
    assert!(check_clipped_text(&text, &window, Strategy::Character, &chars).is_err());
}

/// `text` case 2070 of seed 1: the underscore, kept whole, overlaps a neighbour the window cuts.
/// Glyphs are turned counter-clockwise like the clipper's pieces, so the overlap adds up instead
/// of cancelling to a hole.
#[test]
fn a_kept_glyph_overlapping_a_clipped_one_stays_filled() {
    let font = common::dejavu();
    let case = text_case(1, 2070);
    let window = TextWindow::new(&case.window).unwrap();
    let text = Text::outline(&font, &case.string, case.size, case.origin, DEFAULT_TOLERANCE).unwrap();
    assert!(text.glyphs.iter().all(|g| !matches!(&g.shape, clip_text::Shape::Outline(p) if p.signed_area() < 0.0)));
    let clipped = clip_text(&text, &window, Strategy::Components, &Vatti).unwrap();
    check_clipped_text(&text, &window, Strategy::Components, &clipped).unwrap();
}
