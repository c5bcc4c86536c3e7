//! A batch of segments clipped on every core, the pieces in the order one thread would write them.

use clip_core::{ClipError, PreparedWindow, Segment, VisiblePiece};
use rayon::prelude::*;

/// Segments per task: large enough that a task's own buffer and the dispatch cost nothing
/// beside the clipping, small enough that the cores share the batch evenly.
const CHUNK: usize = 16_384;

/// Clips `segments` in chunks on rayon's pool and concatenates the chunks' pieces in chunk order,
/// each piece's segment index moved back to its place in the whole batch: the same output, in
/// the same order, as `prepared.clip_batch(segments, out)` on one thread.
pub fn clip_parallel(
    prepared: &dyn PreparedWindow,
    segments: &[Segment],
    out: &mut Vec<VisiblePiece>,
) -> Result<(), ClipError> {
    let parts: Vec<Result<Vec<VisiblePiece>, ClipError>> = segments
        .par_chunks(CHUNK)
        .enumerate()
        .map(|(chunk, part)| {
            let mut pieces = Vec::with_capacity(part.len());
            prepared.clip_batch(part, &mut pieces).map_err(|e| shift_error(e, chunk * CHUNK))?;
            for p in &mut pieces {
                p.segment += chunk * CHUNK;
            }
            Ok(pieces)
        })
        .collect();
    for part in parts {
        out.extend(part?);
    }
    Ok(())
}

/// An error about segment `i` of a chunk, renumbered as segment `offset + i` of the batch.
fn shift_error(e: ClipError, offset: usize) -> ClipError {
    match e {
        ClipError::NonFinite { operand, part, vertex, x, y } => {
            ClipError::NonFinite { operand, part: part + offset, vertex, x, y }
        }
        ClipError::OutOfRange { operand, part, vertex, value } => {
            ClipError::OutOfRange { operand, part: part + offset, vertex, value }
        }
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{LineClipper, Point};
    use clip_cyrus_beck::Liu;
    use clip_testkit::workload::{WangSize, wang_segments, wang_window};

    #[test]
    fn same_pieces_in_the_same_order_as_one_thread() {
        let w = wang_window(20, WangSize::W1, 3, false);
        let mut segments = wang_segments(3 * CHUNK + 17, 5);
        let prepared = Liu.prepare(&w).unwrap();
        let (mut one, mut many) = (Vec::new(), Vec::new());
        prepared.clip_batch(&segments, &mut one).unwrap();
        clip_parallel(prepared.as_ref(), &segments, &mut many).unwrap();
        assert!(!one.is_empty());
        assert_eq!(one, many);
        // A bad segment in a later chunk is named by its place in the whole batch.
        segments[2 * CHUNK + 3].b = Point::new(f64::NAN, 0.0);
        let Err(ClipError::NonFinite { part, .. }) = clip_parallel(prepared.as_ref(), &segments, &mut many) else {
            panic!("a NaN endpoint was accepted");
        };
        assert_eq!(part, 2 * CHUNK + 3);
    }
}
