//! Where the segments of the `wang-t4` workload go: how many each rejection stage of New2, New1
//! and Liu removes, per window size and edge count.
//!
//! `cargo run --release -p clip-virtual-box --example stage_counts`

use clip_cyrus_beck::PreparedLiu;
use clip_testkit::workload::{WANG_EDGES, WangSize, wang_segments, wang_window};
use clip_virtual_box::PreparedVirtualBox;

fn main() -> Result<(), clip_core::ClipError> {
    let segments = wang_segments(10_000, 2005);
    println!("| size | edges | clipper | MEB | 45° box | virtual box | code sum | intersected | visible |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for size in WangSize::ALL {
        for edges in WANG_EDGES {
            let window = wang_window(edges, size, 2005, false);
            let mut out = Vec::new();
            for (name, rotated) in [("virtual-box", true), ("virtual-box-no45", false)] {
                let c = PreparedVirtualBox::new(&window, rotated)?.clip_batch_counted(&segments, &mut out)?;
                println!(
                    "| {} | {edges} | {name} | {} | {} | {} | {} | {} | {} |",
                    size.name(),
                    c.meb,
                    c.rotated_box,
                    c.virtual_box,
                    c.code_sum,
                    c.intersected,
                    c.visible
                );
            }
            let c = PreparedLiu::new(&window)?.clip_batch_counted(&segments, &mut out)?;
            let classified = c.segments - c.zero_length - c.bounding_box;
            println!(
                "| {} | {edges} | liu | {} | - | - | ({} no crossing) | {classified} | {} |",
                size.name(),
                c.bounding_box,
                c.no_crossing,
                c.visible
            );
        }
    }
    Ok(())
}
