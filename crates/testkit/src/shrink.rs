//! Shrinks a failing case to a smaller one that still fails the same way: deterministic, bounded
//! work.
//!
//! The caller says how a case fails (`None` when it passes); a smaller candidate is kept only when
//! it fails as the original does, so a hang never shrinks to a crash, nor a wrong answer to a
//! refusal. Greedy passes, repeated while any of them helps: drop whole rings (or segments), drop runs
//! of vertices (halves first, down to single vertices), then snap every coordinate to the
//! coarsest grid of spacing `2^k` (from 1024 down to 2^-20) on which the case still fails. A
//! candidate that is not valid input (a ring left with fewer than 3 distinct points, an empty
//! window) is never tried. At most [`MAX_TRIES`] calls of the predicate are made.

use clip_core::{Operand, Point, Polygons, Ring, Segment, validate_polygons, validate_window};

/// The most times a shrinker calls its predicate.
pub const MAX_TRIES: usize = 2000;

/// Counts predicate calls against [`MAX_TRIES`].
struct Budget(usize);

impl Budget {
    fn take(&mut self) -> bool {
        if self.0 == 0 {
            return false;
        }
        self.0 -= 1;
        true
    }
}

/// `failure` as a predicate: true for a case that fails the way the original does. `None` when the
/// original does not fail (then nothing smaller is kept).
fn failing_alike<A: ?Sized, B: ?Sized, F: PartialEq>(
    original: (&A, &B),
    mut failure: impl FnMut(&A, &B) -> Option<F>,
) -> Option<impl FnMut(&A, &B) -> bool> {
    let found = failure(original.0, original.1)?;
    Some(move |a: &A, b: &B| failure(a, b).is_some_and(|f| f == found))
}

/// Reduces a failing polygon case while it fails as it does now: `failure(subject, clip)` says
/// how a case fails (`None` when it passes). Returns the smallest case found that fails the same
/// way (the input itself if none smaller does, or if it does not fail).
pub fn shrink_polygons<F: PartialEq>(
    subject: &Polygons,
    clip: &Polygons,
    failure: impl FnMut(&Polygons, &Polygons) -> Option<F>,
) -> (Polygons, Polygons) {
    let mut budget = Budget(MAX_TRIES);
    budget.take();
    let Some(mut still_fails) = failing_alike((subject, clip), failure) else {
        return (subject.clone(), clip.clone());
    };
    let mut best = [subject.clone(), clip.clone()];
    let valid = |p: &[Polygons; 2]| {
        validate_polygons(&p[0], Operand::Subject).is_ok() && validate_polygons(&p[1], Operand::Clip).is_ok()
    };
    let mut attempt = |candidate: [Polygons; 2], best: &mut [Polygons; 2], budget: &mut Budget| {
        if candidate != *best && valid(&candidate) && budget.take() && still_fails(&candidate[0], &candidate[1]) {
            *best = candidate;
            true
        } else {
            false
        }
    };
    loop {
        let size_before = size(&best);
        for operand in 0..2 {
            let mut r = best[operand].rings.len();
            while r > 0 {
                r -= 1;
                let mut c = best.clone();
                c[operand].rings.remove(r);
                attempt(c, &mut best, &mut budget);
            }
        }
        for operand in 0..2 {
            for r in 0..best[operand].rings.len() {
                let mut chunk = best[operand].rings[r].len() / 2;
                while chunk >= 1 {
                    let mut start = 0;
                    while start + chunk <= best[operand].rings[r].len() && best[operand].rings[r].len() - chunk >= 3 {
                        let mut c = best.clone();
                        c[operand].rings[r].points.drain(start..start + chunk);
                        if !attempt(c, &mut best, &mut budget) {
                            start += chunk;
                        }
                    }
                    chunk /= 2;
                }
            }
        }
        for spacing in grid_spacings() {
            let c = [snap_polygons(&best[0], spacing), snap_polygons(&best[1], spacing)];
            if c == best || attempt(c, &mut best, &mut budget) {
                break;
            }
        }
        if size(&best) >= size_before || budget.0 == 0 {
            return (best[0].clone(), best[1].clone());
        }
    }
}

/// Reduces a failing line case while it fails as it does now (`failure(window, segments)`, as
/// for [`shrink_polygons`]): drops segments, window rings and window vertices, then snaps
/// coordinates.
pub fn shrink_segments<F: PartialEq>(
    window: &Polygons,
    segments: &[Segment],
    failure: impl FnMut(&Polygons, &[Segment]) -> Option<F>,
) -> (Polygons, Vec<Segment>) {
    let mut budget = Budget(MAX_TRIES);
    budget.take();
    let Some(mut still_fails) = failing_alike((window, segments), failure) else {
        return (window.clone(), segments.to_vec());
    };
    let mut best = (window.clone(), segments.to_vec());
    let mut attempt = |c: (Polygons, Vec<Segment>), best: &mut (Polygons, Vec<Segment>), budget: &mut Budget| {
        if c != *best && validate_window(&c.0).is_ok() && budget.take() && still_fails(&c.0, &c.1) {
            *best = c;
            true
        } else {
            false
        }
    };
    loop {
        let size_before = best.0.vertex_count() + best.0.rings.len() + best.1.len();
        let mut chunk = best.1.len().div_ceil(2);
        while chunk >= 1 {
            let mut start = 0;
            while start < best.1.len() && best.1.len() > 1 {
                let mut c = best.clone();
                let end = (start + chunk).min(c.1.len());
                c.1.drain(start..end);
                if c.1.is_empty() || !attempt(c, &mut best, &mut budget) {
                    start += chunk;
                }
            }
            chunk /= 2;
        }
        let mut r = best.0.rings.len();
        while r > 0 {
            r -= 1;
            let mut c = best.clone();
            c.0.rings.remove(r);
            attempt(c, &mut best, &mut budget);
        }
        for r in 0..best.0.rings.len() {
            let mut chunk = best.0.rings[r].len() / 2;
            while chunk >= 1 {
                let mut start = 0;
                while start + chunk <= best.0.rings[r].len() && best.0.rings[r].len() - chunk >= 3 {
                    let mut c = best.clone();
                    c.0.rings[r].points.drain(start..start + chunk);
                    if !attempt(c, &mut best, &mut budget) {
                        start += chunk;
                    }
                }
                chunk /= 2;
            }
        }
        for spacing in grid_spacings() {
            let snap = |p: Point| snap_point(p, spacing);
            let c =
                (snap_polygons(&best.0, spacing), best.1.iter().map(|s| Segment::new(snap(s.a), snap(s.b))).collect());
            if c == best || attempt(c, &mut best, &mut budget) {
                break;
            }
        }
        let size_after = best.0.vertex_count() + best.0.rings.len() + best.1.len();
        if size_after >= size_before || budget.0 == 0 {
            return best;
        }
    }
}

fn size(p: &[Polygons; 2]) -> usize {
    p.iter().map(|q| q.vertex_count() + q.rings.len()).sum()
}

/// Grid spacings from coarse to fine: 2^10 down to 2^-20.
fn grid_spacings() -> impl Iterator<Item = f64> {
    (-20..=10).rev().map(|k| 2f64.powi(k))
}

fn snap_point(p: Point, spacing: f64) -> Point {
    Point::new((p.x / spacing).round() * spacing, (p.y / spacing).round() * spacing)
}

/// Every vertex snapped to the grid, consecutive repeats removed.
fn snap_polygons(p: &Polygons, spacing: f64) -> Polygons {
    Polygons::new(
        p.rings
            .iter()
            .map(|r| Ring::new(r.points.iter().map(|&q| snap_point(q, spacing)).collect()).without_repeats())
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Rect;

    #[test]
    fn spacings_run_coarse_to_fine() {
        let s: Vec<f64> = grid_spacings().collect();
        assert_eq!((s[0], s[10], *s.last().unwrap()), (1024.0, 1.0, 2f64.powi(-20)));
    }

    #[test]
    fn snapping_removes_repeats() {
        let r = Polygons::from(Ring::from(&[(0.1, 0.1), (0.2, 0.1), (5.0, 0.0), (5.0, 5.0)][..]));
        assert_eq!(snap_polygons(&r, 1.0).rings[0].len(), 3);
        assert_eq!(
            snap_polygons(&Polygons::from(Rect::new(0.3, 0.3, 2.6, 2.6)), 1.0),
            Polygons::from(Rect::new(0.0, 0.0, 3.0, 3.0))
        );
    }
}
