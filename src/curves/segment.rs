//! Finding the segment `[t_i, t_{i+1}]` that contains a time: binary search, or a cursor that
//! remembers where the previous sample fell.

/// Index `i` of the segment `[times[i], times[i+1])` that contains `t`, by binary search.
/// ```text
/// i = (number of keys with t_k ≤ t) − 1,   clamped to [0, N − 2]
/// ```
/// `times` must be strictly increasing (a [`Track`](super::Track) guarantees it). A time before
/// the first key gives 0, a time at or after the last key gives `N − 2` (the last segment), so
/// `times[i]` and `times[i + 1]` are always valid indices when `N ≥ 2`. At a key time exactly,
/// `t = t_k`, the segment that *starts* at `t_k` is returned (except at the last key). With
/// fewer than two keys, or a NaN `t`, the answer is 0. Cost: `O(log N)` comparisons.
///
/// Reference solution of the "find the segment" exercise. Lesson: keyframes and splines.
pub fn find_segment(times: &[f32], t: f32) -> usize {
    let last_segment = times.len().saturating_sub(2);
    // `partition_point` counts the keys with `t_k ≤ t` because the times are sorted.
    let keys_at_or_before = times.partition_point(|&t_k| t_k <= t);
    keys_at_or_before.saturating_sub(1).min(last_segment)
}

/// How many segments a [`Cursor`] walks, forwards or backwards, before giving up and doing a
/// binary search. Consecutive frames usually stay in the same segment or move to the next one.
const CURSOR_MAX_WALK: usize = 4;

/// Remembers the segment of the previous sample, so that sampling a track at increasing (or
/// slowly changing) times costs `O(1)` per sample instead of a binary search.
///
/// A cursor holds only an index: keep one per track you sample (it is `Copy`), and
/// start it with [`Cursor::new`]. It always answers exactly what [`find_segment`] answers; only
/// the cost differs. Using a cursor with a different track than before is allowed: the first
/// lookup then just falls back to a binary search.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Cursor {
    segment: usize,
}

impl Cursor {
    /// A cursor at the first segment.
    pub const fn new() -> Self {
        Self { segment: 0 }
    }

    /// The segment found by the last call to [`Cursor::find`].
    pub const fn segment(&self) -> usize {
        self.segment
    }

    /// Same result as [`find_segment`]`(times, t)`: checks the remembered segment, walks up to a
    /// few segments forwards or backwards, and only then does a binary search.
    pub fn find(&mut self, times: &[f32], t: f32) -> usize {
        if times.len() < 2 {
            self.segment = 0;
            return 0;
        }
        let last_segment = times.len() - 2;
        let mut i = self.segment.min(last_segment);
        for _ in 0..=CURSOR_MAX_WALK {
            // A NaN time walks back to segment 0, as `find_segment` answers.
            if t < times[i] || t.is_nan() {
                if i == 0 {
                    self.segment = 0;
                    return 0;
                }
                i -= 1;
            } else if i == last_segment || t < times[i + 1] {
                self.segment = i;
                return i;
            } else {
                i += 1;
            }
        }
        self.segment = find_segment(times, t);
        self.segment
    }
}
