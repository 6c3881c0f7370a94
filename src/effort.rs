//! What `--quick` means, in one place: the plain numbers a full run and a quick one
//! measure with, side by side. The command line picks [`Effort::FULL`] or
//! [`Effort::QUICK`] once per command; the modules read the numbers from the one picked
//! and never choose with an `if quick` of their own.

/// How much a run measures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Effort {
    /// The flag that picks this effort as a report's command line writes it: `""` or
    /// `" --quick"`.
    pub flag: &'static str,
    /// The stability sweep's sub-pixel offsets (x, y), in pixels, each seen at every
    /// rotation of [`Effort::sweep_rotations_deg`].
    pub sweep_offsets: &'static [(f64, f64)],
    /// The stability sweep's rotations, degrees.
    pub sweep_rotations_deg: &'static [f64],
    /// A hard case seen through a full turn is seen every this many degrees besides.
    pub sweep_full_turn_step_deg: f64,
    /// Whether the sweep also runs the cameras where the full sweep found each method
    /// worst (`data/worst-cameras.csv`): a grid too coarse to contain them.
    pub sweep_reruns_worst_cameras: bool,
    /// Frames each hard case drifts through in the stability run's motion stage.
    pub stability_motion_frames: usize,
    /// `bench`: every bench setting of each method's row, and after caching each
    /// method's default; or only the settings its row marks for `--quick`, and after
    /// caching only the peers' and the contrast's (`bench::method_settings`).
    pub bench_every_setting: bool,
    /// `bench`: rounds that interleave a view's cases, each preparing the method anew
    /// (`bench::result::Rounds`).
    pub bench_rounds: usize,
    /// `bench`: frames timed per round, after the warm-up (`bench::run::WARMUP_FRAMES`).
    pub bench_frames_per_round: usize,
    /// `bench`: seconds a case whose ratios are not settled is timed for, over its
    /// rounds, before the run reports it unsettled (`bench::settle`).
    pub bench_settle_cap_s: f64,
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
    /// A full run: the sweep at 16 sub-pixel offsets (a 4×4 grid of 1/4 px) × 0°, 1°,
    /// 45° and 89.9° (and every 30° for a full turn), whose grid is where every listed
    /// worst camera was found.
    pub const FULL: Effort = Effort {
        flag: "",
        sweep_offsets: &[
            (0.0, 0.0),
            (0.25, 0.0),
            (0.5, 0.0),
            (0.75, 0.0),
            (0.0, 0.25),
            (0.25, 0.25),
            (0.5, 0.25),
            (0.75, 0.25),
            (0.0, 0.5),
            (0.25, 0.5),
            (0.5, 0.5),
            (0.75, 0.5),
            (0.0, 0.75),
            (0.25, 0.75),
            (0.5, 0.75),
            (0.75, 0.75),
        ],
        sweep_rotations_deg: &[0.0, 1.0, 45.0, 89.9],
        sweep_full_turn_step_deg: 30.0,
        sweep_reruns_worst_cameras: false,
        stability_motion_frames: 16,
        bench_every_setting: true,
        bench_rounds: 5,
        bench_frames_per_round: 7,
        bench_settle_cap_s: 30.0,
        bench_scaling_points: 11,
        bench_scaling_frames: 5,
        bench_glyph_count_up_to: 30_000.0,
        bench_px_per_em_up_to: 4096.0,
        bench_motion_frames: 16,
    };

    /// `--quick`, the CI size: the sweep at 4 offsets (one per row and column of the
    /// full grid) × 0° and 45° (every 90° for a full turn) plus the listed worst
    /// cameras; the bench at a few frames, its scaling series stopping at about a tenth
    /// of the pixels, so a run takes minutes.
    ///
    /// The bench's three rounds of three frames come after the full run's warm-up. On
    /// lavapipe the first frames after a method is prepared run slow on the small
    /// scenes (the atlas on `rotated`: 4.1–4.3 ms for the three frames after one
    /// warm-up frame, 2.5 ms after), and a median of three such frames measured the
    /// warm-up, not the method. One round measured whatever load the machine had while
    /// each case ran: three one-round runs of the same build put `winding` on `rotated`
    /// at 1.32×, 2.16× and 3.04× the atlas (a slow spell of a few seconds covering one
    /// case's frames).
    pub const QUICK: Effort = Effort {
        flag: " --quick",
        sweep_offsets: &[(0.0, 0.0), (0.25, 0.5), (0.5, 0.75), (0.75, 0.25)],
        sweep_rotations_deg: &[0.0, 45.0],
        sweep_full_turn_step_deg: 90.0,
        sweep_reruns_worst_cameras: true,
        stability_motion_frames: 8,
        bench_every_setting: false,
        bench_rounds: 3,
        bench_frames_per_round: 3,
        bench_settle_cap_s: 25.0,
        bench_scaling_points: 3,
        bench_scaling_frames: 2,
        bench_glyph_count_up_to: 3_000.0,
        bench_px_per_em_up_to: 256.0,
        bench_motion_frames: 8,
    };

    /// [`Effort::QUICK`] when `quick`, else [`Effort::FULL`]: what a `--quick` flag
    /// picks.
    pub fn of(quick: bool) -> Effort {
        if quick { Effort::QUICK } else { Effort::FULL }
    }
}
