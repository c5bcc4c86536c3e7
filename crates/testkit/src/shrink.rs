//! Shrinks a failing case to a smaller one that still fails the same way: deterministic, bounded
//! work.
//!
//! The caller says how a case fails (`None` when it passes); a smaller candidate is kept only when
//! it fails as the original does, so a hang never shrinks to a crash, nor a wrong answer to a
//! refusal. Greedy passes, repeated while any of them helps: drop whole rings (or segments), drop runs
//! of vertices (halves first, down to single vertices), then snap every coordinate to the
//! coarsest grid of spacing `2^k` (from 1024 down to 2^-20) on which the case still fails. A
//! candidate that is not valid input (a ring left with fewer than 3 distinct points, an empty
//! window) is never tried. At most [`MAX_TRIES`] calls of the predicate are made, and with a
//! [`ShrinkLimit`] time none is begun after it runs out: a predicate that runs an external clipper
//! until a time-out (a hang) can take that long on every call.

use std::time::{Duration, Instant};

use clip_core::{Operand, Point, Polygons, Ring, Segment, validate_polygons, validate_window};

/// The most times a shrinker calls its predicate.
pub const MAX_TRIES: usize = 2000;

/// How much work a shrinker may do: at most `tries` predicate calls, none begun after `time`
/// has passed since it started (a call under way is not cut short).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShrinkLimit {
    /// The most predicate calls, the first (does the original fail?) included.
    pub tries: usize,
    /// The time after which no call is begun; `None` for none.
    pub time: Option<Duration>,
}

impl Default for ShrinkLimit {
    /// [`MAX_TRIES`] calls and no time limit: the result depends on the case alone.
    fn default() -> ShrinkLimit {
        ShrinkLimit { tries: MAX_TRIES, time: None }
    }
}

/// Why a shrinker stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShrinkEnd {
    /// No candidate it tries is smaller and still fails alike (or the original does not fail).
    Smallest,
    /// It made its [`ShrinkLimit::tries`] calls.
    OutOfTries,
    /// Its [`ShrinkLimit::time`] ran out.
    OutOfTime,
}

/// Counts predicate calls and time against a [`ShrinkLimit`].
struct Budget {
    tries: usize,
    until: Option<Instant>,
    end: ShrinkEnd,
}

impl Budget {
    fn new(limit: ShrinkLimit) -> Budget {
        let until = limit.time.and_then(|t| Instant::now().checked_add(t));
        Budget { tries: limit.tries, until, end: ShrinkEnd::Smallest }
    }

    fn take(&mut self) -> bool {
        if self.tries == 0 {
            self.end = ShrinkEnd::OutOfTries;
            return false;
        }
        if self.until.is_some_and(|until| Instant::now() >= until) {
            self.end = ShrinkEnd::OutOfTime;
            return false;
        }
        self.tries -= 1;
        true
    }

    fn spent(&self) -> bool {
        self.end != ShrinkEnd::Smallest
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
    shrink_polygons_within(subject, clip, ShrinkLimit::default(), failure).0
}

/// [`shrink_polygons`] within `limit`, and why it stopped.
pub fn shrink_polygons_within<F: PartialEq>(
    subject: &Polygons,
    clip: &Polygons,
    limit: ShrinkLimit,
    failure: impl FnMut(&Polygons, &Polygons) -> Option<F>,
) -> ((Polygons, Polygons), ShrinkEnd) {
    let mut budget = Budget::new(limit);
    if !budget.take() {
        return ((subject.clone(), clip.clone()), budget.end);
    }
    let Some(mut still_fails) = failing_alike((subject, clip), failure) else {
        return ((subject.clone(), clip.clone()), ShrinkEnd::Smallest);
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
        if size(&best) >= size_before || budget.spent() {
            return ((best[0].clone(), best[1].clone()), budget.end);
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
    shrink_segments_within(window, segments, ShrinkLimit::default(), failure).0
}

/// [`shrink_segments`] within `limit`, and why it stopped.
pub fn shrink_segments_within<F: PartialEq>(
    window: &Polygons,
    segments: &[Segment],
    limit: ShrinkLimit,
    failure: impl FnMut(&Polygons, &[Segment]) -> Option<F>,
) -> ((Polygons, Vec<Segment>), ShrinkEnd) {
    let mut budget = Budget::new(limit);
    if !budget.take() {
        return ((window.clone(), segments.to_vec()), budget.end);
    }
    let Some(mut still_fails) = failing_alike((window, segments), failure) else {
        return ((window.clone(), segments.to_vec()), ShrinkEnd::Smallest);
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
        if size_after >= size_before || budget.spent() {
            return (best, budget.end);
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
