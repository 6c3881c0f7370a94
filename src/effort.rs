//! What `--quick` means, in one place: every number a full run and a quick one differ
//! by, in one value. A subcommand picks [`Effort::FULL`] or [`Effort::QUICK`] once and
//! hands it to each part. What `--quick` measures besides in the bench (fewer
//! settings, only the contrast after caching) is said by `bench::method_settings`.

/// The numbers `--quick` changes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Effort {
    /// `bench`: rounds that interleave a view's cases, each preparing the method anew
    /// (`bench::result::Rounds`).
    pub bench_rounds: usize,
    /// `bench`: frames timed per round, after the warm-up (`bench::run::WARMUP_FRAMES`).
    pub bench_frames_per_round: usize,
    /// `bench`: points per scaling series.
    pub bench_scaling_points: usize,
    /// `bench`: frames timed per point and method of a scaling series, after its
    /// warm-up.
    pub bench_scaling_frames: usize,
    /// `bench`: the last point of the `glyph-count` series, in glyphs.
    pub bench_glyph_count_up_to: f64,
    /// `bench`: the last point of the `px-per-em` series.
    pub bench_px_per_em_up_to: f64,
    /// `bench`: frames per camera path in the "In motion" section.
    pub bench_motion_frames: usize,
}

impl Effort {
    /// The full run. `bench`: 3 rounds of 7 frames (21 in all, as `render --stats`
    /// times); 11 points a series (the px/em series then falls on the powers of two) up to 30 000
    /// glyphs and 4 096 px/em, 5 frames timed at each (at 30 000 glyphs or 4 096 px/em
    /// a frame of the slowest methods takes seconds on a software GPU, and the fitted
    /// slope pools the points); 16 frames per camera path.
    pub const FULL: Effort = Effort {
        bench_rounds: 3,
        bench_frames_per_round: 7,
        bench_scaling_points: 11,
        bench_scaling_frames: 5,
        bench_glyph_count_up_to: 30_000.0,
        bench_px_per_em_up_to: 4096.0,
        bench_motion_frames: 16,
    };

    /// `--quick`. `bench`: three rounds of three frames each after the full run's warm-up. On
    /// lavapipe the first frames after a method is prepared run slow on the small
    /// scenes (the atlas on `rotated`: 4.1–4.3 ms for the three frames after one
    /// warm-up frame, 2.5 ms after), and a median of three such frames measured the
    /// warm-up, not the method. One round measured whatever load the machine had while
    /// each case ran: three one-round runs of the same build put `winding` on `rotated`
    /// at 1.32×, 2.16× and 3.04× the atlas (a slow spell of a few seconds covering one
    /// case's frames). The scaling series: 3 points, 2 frames timed at each, stopping
    /// at about a tenth of the pixels (3 000 glyphs, 256 px/em) so they stay a run of
    /// seconds; 8 frames per camera path.
    pub const QUICK: Effort = Effort {
        bench_rounds: 3,
        bench_frames_per_round: 3,
        bench_scaling_points: 3,
        bench_scaling_frames: 2,
        bench_glyph_count_up_to: 3_000.0,
        bench_px_per_em_up_to: 256.0,
        bench_motion_frames: 8,
    };

    /// [`Effort::QUICK`] with `quick`, else [`Effort::FULL`].
    pub fn of(quick: bool) -> Effort {
        if quick { Effort::QUICK } else { Effort::FULL }
    }
}
