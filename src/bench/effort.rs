//! What `--quick` changes in the bench, in one value: every number a full run and a
//! quick one differ by. The run picks [`BenchEffort::FULL`] or [`BenchEffort::QUICK`]
//! once and hands it to each part; what `--quick` measures besides (fewer settings,
//! only the contrast after caching) is said by `method_settings`.

/// The bench's numbers that `--quick` changes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BenchEffort {
    /// Rounds that interleave a view's cases, each preparing the method anew (see
    /// `result::Rounds`).
    pub rounds: usize,
    /// Frames timed per round, after the warm-up (`run::WARMUP_FRAMES`).
    pub frames_per_round: usize,
    /// Points per scaling series.
    pub scaling_points: usize,
    /// Frames timed per point and method of a scaling series, after its warm-up.
    pub scaling_frames: usize,
    /// The last point of the `glyph-count` series, in glyphs.
    pub glyph_count_up_to: f64,
    /// The last point of the `px-per-em` series.
    pub px_per_em_up_to: f64,
    /// Frames per camera path in the "In motion" section.
    pub motion_frames: usize,
}

impl BenchEffort {
    /// The full run: 3 rounds of 7 frames (21 in all, as `render --stats` times); 11
    /// points a series (the px/em series then falls on the powers of two) up to 30 000
    /// glyphs and 4 096 px/em, 5 frames timed at each (at 30 000 glyphs or 4 096 px/em
    /// a frame of the slowest methods takes seconds on a software GPU, and the fitted
    /// slope pools the points); 16 frames per camera path.
    pub const FULL: BenchEffort = BenchEffort {
        rounds: 3,
        frames_per_round: 7,
        scaling_points: 11,
        scaling_frames: 5,
        glyph_count_up_to: 30_000.0,
        px_per_em_up_to: 4096.0,
        motion_frames: 16,
    };

    /// `--quick`: three rounds of three frames each after the full run's warm-up. On
    /// lavapipe the first frames after a method is prepared run slow on the small
    /// scenes (the atlas on `rotated`: 4.1–4.3 ms for the three frames after one
    /// warm-up frame, 2.5 ms after), and a median of three such frames measured the
    /// warm-up, not the method. One round measured whatever load the machine had while
    /// each case ran: three one-round runs of the same build put `winding` on `rotated`
    /// at 1.32×, 2.16× and 3.04× the atlas (a slow spell of a few seconds covering one
    /// case's frames). The scaling series: 3 points, 2 frames timed at each, stopping
    /// at about a tenth of the pixels (3 000 glyphs, 256 px/em) so they stay a run of
    /// seconds; 8 frames per camera path.
    pub const QUICK: BenchEffort = BenchEffort {
        rounds: 3,
        frames_per_round: 3,
        scaling_points: 3,
        scaling_frames: 2,
        glyph_count_up_to: 3_000.0,
        px_per_em_up_to: 256.0,
        motion_frames: 8,
    };

    /// [`BenchEffort::QUICK`] with `quick`, else [`BenchEffort::FULL`].
    pub fn of(quick: bool) -> BenchEffort {
        if quick {
            BenchEffort::QUICK
        } else {
            BenchEffort::FULL
        }
    }
}
