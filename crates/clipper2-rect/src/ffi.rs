//! The crate's only unsafe code: Clipper2's C rectangle clip (`clipper2c-sys`) behind a safe call.
//!
//! `clipper2c-sys` 0.2 compiles and links all of Clipper2's C layer, rectangle clipping
//! included, but its generated bindings leave the rectangle functions and `ClipperRect64` out,
//! so the two used here are declared below from `clipper2c/include/clipper2c.h` and `types.h`.
//!
//! Memory follows the C layer's model: every C++ object lives in a buffer from
//! `clipper_allocate`, is built there by a constructor (placement new) and is released by the
//! matching `clipper_delete_*`, which runs the destructor and frees the buffer. [`OwnedPaths`]
//! pairs each `Paths64` with its delete, so nothing leaks on any path out of a function.

use std::ffi::{c_int, c_void};

use clipper2c_sys::{
    ClipperClipType_INTERSECTION, ClipperClipper64, ClipperFillRule_EVEN_ODD, ClipperPaths64, ClipperPoint64,
    clipper_allocate, clipper_clipper64, clipper_clipper64_add_clip, clipper_clipper64_add_open_subject,
    clipper_clipper64_execute, clipper_clipper64_size, clipper_delete_clipper64, clipper_delete_path64,
    clipper_delete_paths64, clipper_path64_of_points, clipper_path64_size, clipper_paths64, clipper_paths64_add_path,
    clipper_paths64_get_point, clipper_paths64_length, clipper_paths64_path_length, clipper_paths64_size,
};

/// A point on Clipper2's integer grid, `[x, y]`.
pub type GridPoint = [i64; 2];

/// Clipper2's `Rect64` as `types.h` declares it (`struct ClipperRect64`): the C layer
/// reinterprets a pointer to it as a `Clipper2Lib::Rect64`, the same four `int64_t` in the same
/// order. Clipper2 names the smaller y `top`; `RectClip` treats `bottom <= top` or
/// `right <= left` as empty.
#[repr(C)]
struct ClipperRect64 {
    left: i64,
    top: i64,
    right: i64,
    bottom: i64,
}

unsafe extern "C" {
    /// `RectClip(rect, paths)`: each path of `paths` clipped to `rect` on its own, built in `mem`.
    fn clipper_paths64_rect_clip(
        mem: *mut c_void,
        rect: *mut ClipperRect64,
        paths: *mut ClipperPaths64,
    ) -> *mut ClipperPaths64;

    /// `RectClipLines(rect, paths)`: each open path of `paths` clipped to `rect`, built in `mem`.
    fn clipper_paths64_rect_clip_lines(
        mem: *mut c_void,
        rect: *mut ClipperRect64,
        paths: *mut ClipperPaths64,
    ) -> *mut ClipperPaths64;
}

/// The signature both rectangle clips share.
type RectClipFn = unsafe extern "C" fn(*mut c_void, *mut ClipperRect64, *mut ClipperPaths64) -> *mut ClipperPaths64;

/// A grid rectangle: `min` and `max` corners, each `[x, y]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct GridRect {
    /// Lower-left corner.
    pub min: GridPoint,
    /// Upper-right corner.
    pub max: GridPoint,
}

/// Clipper2's `RectClip` on `paths` (closed paths; each clipped on its own). `None` when a count
/// does not fit the C layer's `int` indices.
pub(crate) fn rect_clip(rect: GridRect, paths: &[Vec<GridPoint>]) -> Option<Vec<Vec<GridPoint>>> {
    run(clipper_paths64_rect_clip, rect, paths)
}

/// Clipper2's `RectClipLines` on `paths` (open paths): the pieces inside `rect`. `None` as for
/// [`rect_clip`].
pub(crate) fn rect_clip_lines(rect: GridRect, paths: &[Vec<GridPoint>]) -> Option<Vec<Vec<GridPoint>>> {
    run(clipper_paths64_rect_clip_lines, rect, paths)
}

/// Copies `paths` to the C++ side, runs `clip` on them and copies the result back.
fn run(clip: RectClipFn, rect: GridRect, paths: &[Vec<GridPoint>]) -> Option<Vec<Vec<GridPoint>>> {
    let input = OwnedPaths::from_paths(paths);
    let mut c_rect = ClipperRect64 { left: rect.min[0], top: rect.min[1], right: rect.max[0], bottom: rect.max[1] };
    // SAFETY: `clipper_allocate` returns a buffer of `clipper_paths64_size()` bytes (C++
    // `operator new`, which throws rather than return null), and `clip` (one of the two
    // functions declared above) builds its result `Paths64` in it. `c_rect` has `Rect64`'s
    // layout and outlives the call; `input.0` is a live `Paths64` that the call only reads.
    // `OwnedPaths` takes ownership of the result at once.
    let output = OwnedPaths(unsafe {
        let mem = clipper_allocate(clipper_paths64_size());
        clip(mem, &mut c_rect, input.0)
    });
    output.read()
}

/// Clipper2's general engine (`Clipper64`) on open paths, one call per segment: for each of
/// `segments`, `AddClip(window)`, `AddOpenSubject({segment})` and `Execute(Intersection,
/// EvenOdd)` on a fresh `Clipper64`, and the open paths it returns (the segment's parts inside
/// the window). `None` when Clipper2 reports a failure or a count does not fit the C layer's
/// `int` indices.
pub(crate) fn open_intersections(
    window: &[Vec<GridPoint>],
    segments: &[[GridPoint; 2]],
) -> Option<Vec<Vec<Vec<GridPoint>>>> {
    let window = OwnedPaths::from_paths(window);
    let mut all = Vec::with_capacity(segments.len());
    for segment in segments {
        let subject = OwnedPaths::from_paths(&[segment.to_vec()]);
        let closed = OwnedPaths::empty();
        let open = OwnedPaths::empty();
        // SAFETY: a fresh buffer of `clipper_clipper64_size()` bytes with a `Clipper64` built in
        // it, deleted by `OwnedClipper`'s drop. `add_clip` and `add_open_subject` copy the live
        // `Paths64` they are given; `execute` writes into the two live, owned `Paths64`.
        let done = unsafe {
            let clipper = OwnedClipper(clipper_clipper64(clipper_allocate(clipper_clipper64_size())));
            clipper_clipper64_add_clip(clipper.0, window.0);
            clipper_clipper64_add_open_subject(clipper.0, subject.0);
            clipper_clipper64_execute(
                clipper.0,
                ClipperClipType_INTERSECTION,
                ClipperFillRule_EVEN_ODD,
                closed.0,
                open.0,
            )
        };
        if done == 0 {
            return None;
        }
        all.push(open.read()?);
    }
    Some(all)
}

/// A `Clipper64` this side owns, deleted (destructor and buffer) when dropped.
struct OwnedClipper(*mut ClipperClipper64);

impl Drop for OwnedClipper {
    fn drop(&mut self) {
        // SAFETY: `self.0` came from the `Clipper64` constructor in a `clipper_allocate` buffer and
        // is deleted only here, once.
        unsafe { clipper_delete_clipper64(self.0) }
    }
}

/// A `Paths64` this side owns, deleted (destructor and buffer) when dropped.
struct OwnedPaths(*mut ClipperPaths64);

impl OwnedPaths {
    /// An empty `Paths64` on the C++ side.
    fn empty() -> OwnedPaths {
        // SAFETY: a fresh buffer of `clipper_paths64_size()` bytes from `clipper_allocate`,
        // an empty `Paths64` built in it; `OwnedPaths` deletes it with `clipper_delete_paths64`.
        OwnedPaths(unsafe { clipper_paths64(clipper_allocate(clipper_paths64_size())) })
    }

    /// A copy of `paths` on the C++ side.
    fn from_paths(paths: &[Vec<GridPoint>]) -> OwnedPaths {
        let owned = OwnedPaths::empty();
        for path in paths {
            let mut points: Vec<ClipperPoint64> = path.iter().map(|&[x, y]| ClipperPoint64 { x, y }).collect();
            // SAFETY: `points` is `points.len()` initialised `ClipperPoint64` (layout of
            // `Point64`: two `int64_t`), which the `Path64` constructor copies. The path is built
            // in its own `clipper_allocate` buffer, copied into `owned` by `add_path` and then
            // deleted with its matching `clipper_delete_path64`; nothing keeps a pointer to it.
            unsafe {
                let path = clipper_path64_of_points(
                    clipper_allocate(clipper_path64_size()),
                    points.as_mut_ptr(),
                    points.len(),
                );
                clipper_paths64_add_path(owned.0, path);
                clipper_delete_path64(path);
            }
        }
        owned
    }

    /// The paths' points, or `None` if a count exceeds the C `int` the accessors index with.
    fn read(&self) -> Option<Vec<Vec<GridPoint>>> {
        // SAFETY: `self.0` is a live `Paths64` (owned until drop).
        let len = unsafe { clipper_paths64_length(self.0) };
        let mut paths = Vec::with_capacity(len);
        for i in 0..len {
            let i = c_int::try_from(i).ok()?;
            // SAFETY: `i` < the number of paths, checked just above.
            let path_len = unsafe { clipper_paths64_path_length(self.0, i) };
            let mut path = Vec::with_capacity(path_len);
            for j in 0..path_len {
                let j = c_int::try_from(j).ok()?;
                // SAFETY: `i` indexes a path and `j` < that path's length.
                let point = unsafe { clipper_paths64_get_point(self.0, i, j) };
                path.push([point.x, point.y]);
            }
            paths.push(path);
        }
        Some(paths)
    }
}

impl Drop for OwnedPaths {
    fn drop(&mut self) {
        // SAFETY: `self.0` came from a `Paths64` constructor in a `clipper_allocate` buffer and
        // is deleted only here, once.
        unsafe { clipper_delete_paths64(self.0) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const RECT: GridRect = GridRect { min: [0, 0], max: [10, 10] };

    fn area2(path: &[GridPoint]) -> i64 {
        (0..path.len())
            .map(|i| {
                let ([x0, y0], [x1, y1]) = (path[i], path[(i + 1) % path.len()]);
                x0 * y1 - x1 * y0
            })
            .sum()
    }

    #[test]
    fn a_square_over_a_corner_keeps_the_overlap_and_its_orientation() {
        let ccw = vec![[5, 5], [15, 5], [15, 15], [5, 15]];
        let out = rect_clip(RECT, std::slice::from_ref(&ccw)).unwrap();
        assert_eq!(out.len(), 1, "{out:?}");
        assert_eq!(area2(&out[0]), 2 * 25);
        let cw: Vec<GridPoint> = ccw.into_iter().rev().collect();
        let out = rect_clip(RECT, &[cw]).unwrap();
        assert_eq!(area2(&out[0]), -2 * 25);
    }

    #[test]
    fn paths_outside_inside_and_around() {
        let outside = vec![[20, 20], [30, 20], [30, 30]];
        let inside = vec![[1, 1], [2, 1], [2, 2]];
        let around = vec![[-5, -5], [15, -5], [15, 15], [-5, 15]];
        let out = rect_clip(RECT, &[outside, inside.clone(), around]).unwrap();
        assert_eq!(out.len(), 2, "{out:?}");
        assert_eq!(out[0], inside);
        assert_eq!(area2(&out[1]), 2 * 100);
        assert!(rect_clip(RECT, &[]).unwrap().is_empty());
    }

    #[test]
    fn a_line_through_the_rectangle_keeps_the_inside_piece() {
        let out = rect_clip_lines(RECT, &[vec![[-5, 5], [15, 5]]]).unwrap();
        assert_eq!(out, vec![vec![[0, 5], [10, 5]]]);
    }

    #[test]
    fn clipper2_drops_a_line_along_a_side_that_leaves_the_rectangle() {
        // The part on the bottom side is visible by docs/DESIGN.md's closed-set rule; RectClipLines
        // keeps a line lying wholly on a side but not this one (a peer difference, not rounding:
        // these are Clipper2's own integers).
        assert_eq!(rect_clip_lines(RECT, &[vec![[2, 0], [8, 0]]]).unwrap(), vec![vec![[2, 0], [8, 0]]]);
        assert!(rect_clip_lines(RECT, &[vec![[2, 0], [15, 0]]]).unwrap().is_empty());
    }

    #[test]
    fn open_paths_keep_their_parts_inside_a_concave_window() {
        // A U: the segment crosses both arms and passes over the notch.
        let u = vec![[0, 0], [30, 0], [30, 30], [20, 30], [20, 10], [10, 10], [10, 30], [0, 30]];
        let out = open_intersections(&[u], &[[[-10, 20], [40, 20]], [[-10, 40], [40, 40]]]).unwrap();
        assert_eq!(out.len(), 2);
        let mut pieces: Vec<(i64, i64)> = out[0].iter().map(|p| (p[0][0].min(p[1][0]), p[0][0].max(p[1][0]))).collect();
        pieces.sort_unstable();
        assert_eq!(pieces, vec![(0, 10), (20, 30)]);
        assert!(out[1].is_empty());
    }

    #[test]
    fn an_empty_rectangle_clips_everything_away() {
        let flat = GridRect { min: [0, 0], max: [10, 0] };
        assert!(rect_clip(flat, &[vec![[-5, -5], [15, -5], [15, 15]]]).unwrap().is_empty());
    }
}
