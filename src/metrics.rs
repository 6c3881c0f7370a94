//! Error of a coverage image against the reference: the figures every test, the bench
//! and the app quote.

use serde::Serialize;

use crate::Error;
use crate::coverage::CoverageImage;

/// Error figures over a whole frame, and over its edge pixels alone.
///
/// A pixel whose value is not finite or lies outside [0, 1] (in the image or the
/// reference) is invalid: it counts as an error of 1 in the means and the percentile,
/// as an infinite error in `max` (so it breaks every bound), and among the pixels over
/// 0.25 and 0.5. Nothing is clamped before it is checked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct ErrorStats {
    /// Mean absolute error, in 1/255.
    pub mae_255: f64,
    /// Root-mean-square error, in 1/255.
    pub rmse_255: f64,
    /// The 99th percentile of the absolute error over all pixels, in 1/255: on a page
    /// most pixels are blank and exact, so it says how much of the ink is badly off.
    pub p99_255: f64,
    /// Largest absolute error, as coverage (0..1).
    pub max: f64,
    /// Where the largest error is (x, y).
    pub worst_pixel: (u32, u32),
    pub pixels_over_025: usize,
    pub pixels_over_05: usize,
    pub pixels: usize,
    /// Pixels whose value is not finite or outside [0, 1].
    pub invalid_pixels: usize,
    /// The same figures over the edge pixels only: where the reference or the image is
    /// strictly between 0 and 1, or where they differ. A frame is mostly blank and
    /// exact; averaged over it, rare full-pixel artifacts vanish, over the edges not.
    pub edge: EdgeError,
}

/// Error over the edge pixels of a frame (see [`ErrorStats::edge`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct EdgeError {
    pub pixels: usize,
    /// Mean absolute error over the edge pixels, in 1/255.
    pub mae_255: f64,
    pub max: f64,
    pub pixels_over_025: usize,
    pub pixels_over_05: usize,
}

/// Whether `v` is a coverage value at all.
fn is_valid(v: f32) -> bool {
    (0.0..=1.0).contains(&v)
}

/// Compares `image` with `reference` pixel by pixel.
pub fn compare(image: &CoverageImage, reference: &CoverageImage) -> Result<ErrorStats, Error> {
    if (image.width, image.height) != (reference.width, reference.height) {
        return Err(Error::Input(format!(
            "cannot compare a {}x{} image with a {}x{} reference",
            image.width, image.height, reference.width, reference.height
        )));
    }
    let mut stats = ErrorStats {
        pixels: image.data.len(),
        ..Default::default()
    };
    let (mut sum, mut sum_sq, mut edge_sum) = (0.0, 0.0, 0.0);
    let mut errors = Vec::with_capacity(image.data.len());
    for (i, (&a, &b)) in image.data.iter().zip(&reference.data).enumerate() {
        let valid = is_valid(a) && is_valid(b);
        // An invalid value is as far off as coverage can be in the means, and beyond
        // any bound in the maximum.
        let (e, worst) = if valid {
            let e = (f64::from(a) - f64::from(b)).abs();
            (e, e)
        } else {
            stats.invalid_pixels += 1;
            (1.0, f64::INFINITY)
        };
        errors.push(e);
        sum += e;
        sum_sq += e * e;
        stats.pixels_over_025 += usize::from(worst > 0.25);
        stats.pixels_over_05 += usize::from(worst > 0.5);
        if worst > stats.max {
            stats.max = worst;
            stats.worst_pixel = (
                (i % image.width as usize) as u32,
                (i / image.width as usize) as u32,
            );
        }
        let partial = |v: f32| v > 0.0 && v < 1.0;
        if !valid || partial(a) || partial(b) || a != b {
            let edge = &mut stats.edge;
            edge.pixels += 1;
            edge_sum += e;
            edge.max = edge.max.max(worst);
            edge.pixels_over_025 += usize::from(worst > 0.25);
            edge.pixels_over_05 += usize::from(worst > 0.5);
        }
    }
    let n = stats.pixels.max(1) as f64;
    stats.mae_255 = sum / n * 255.0;
    stats.rmse_255 = (sum_sq / n).sqrt() * 255.0;
    stats.p99_255 = percentile(&mut errors, 0.99) * 255.0;
    stats.edge.mae_255 = edge_sum / stats.edge.pixels.max(1) as f64 * 255.0;
    Ok(stats)
}

/// A change of a pixel's error between two frames above this counts as a flicker a
/// reader can see: a tenth of the way from white to black.
pub const TEMPORAL_THRESHOLD: f64 = 0.1;

/// What a method does between two frames of moving text that the reference does not:
/// per pixel, the method's change of coverage less the reference's, Δm − Δr (which is
/// also the change of its error, e₁ − e₀).
///
/// - A method exact in each frame scores 0, and so does any change that is right,
///   however large: an edge sweeping across a pixel changes it by the reference's amount.
/// - A constant bias that moves with the text (a blur) scores little: its error moves
///   by the step, so Δe is the step times the bias's slope.
/// - A method that snaps (an atlas's sub-pixel phases, a heuristic that flips) scores
///   the jump less the reference's smooth change, in the frames where it jumps: hence
///   the maximum and the worst frame pair beside the mean.
/// - It does not see an error that stays put while the text moves (the same wrong
///   value in two frames): that is the still-frame error's business, quoted beside it.
///
/// Invalid values (not finite or outside [0, 1]) in any of the four images count as a
/// change of 1 in the means, an infinite one in `max`, and among the pixels over the
/// threshold.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct TemporalError {
    /// Mean |Δm − Δr| over the frame, in 1/255.
    pub mae_255: f64,
    /// Largest |Δm − Δr|, as coverage.
    pub max: f64,
    pub worst_pixel: (u32, u32),
    /// Pixels with |Δm − Δr| over [`TEMPORAL_THRESHOLD`].
    pub pixels_over: usize,
    pub pixels: usize,
    pub invalid_pixels: usize,
    /// The same over the pixels that are edge pixels (see [`ErrorStats::edge`]) in
    /// either frame.
    pub edge: TemporalEdge,
}

/// [`TemporalError`] over edge pixels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct TemporalEdge {
    pub pixels: usize,
    pub mae_255: f64,
    pub max: f64,
    pub pixels_over: usize,
}

/// The temporal error between frames 0 and 1 of a method (`image`) and of the
/// reference.
pub fn temporal(
    image: [&CoverageImage; 2],
    reference: [&CoverageImage; 2],
) -> Result<TemporalError, Error> {
    let size = (image[0].width, image[0].height);
    for other in [image[1], reference[0], reference[1]] {
        if (other.width, other.height) != size {
            return Err(Error::Input(format!(
                "cannot compare frames of {}x{} and {}x{} pixels",
                size.0, size.1, other.width, other.height
            )));
        }
    }
    let mut stats = TemporalError {
        pixels: image[0].data.len(),
        ..Default::default()
    };
    let (mut sum, mut edge_sum) = (0.0, 0.0);
    let partial = |v: f32| v > 0.0 && v < 1.0;
    for i in 0..stats.pixels {
        let [m0, m1] = image.map(|f| f.data[i]);
        let [r0, r1] = reference.map(|f| f.data[i]);
        let values = [m0, m1, r0, r1];
        let (change, worst) = if values.iter().all(|&v| is_valid(v)) {
            let d = ((f64::from(m1) - f64::from(m0)) - (f64::from(r1) - f64::from(r0))).abs();
            (d, d)
        } else {
            stats.invalid_pixels += 1;
            (1.0, f64::INFINITY)
        };
        sum += change;
        let over = usize::from(worst > TEMPORAL_THRESHOLD);
        stats.pixels_over += over;
        if worst > stats.max {
            stats.max = worst;
            let width = image[0].width as usize;
            stats.worst_pixel = ((i % width) as u32, (i / width) as u32);
        }
        let edge = values.iter().any(|&v| !is_valid(v) || partial(v)) || m0 != r0 || m1 != r1;
        if edge {
            stats.edge.pixels += 1;
            edge_sum += change;
            stats.edge.max = stats.edge.max.max(worst);
            stats.edge.pixels_over += over;
        }
    }
    stats.mae_255 = sum / stats.pixels.max(1) as f64 * 255.0;
    stats.edge.mae_255 = edge_sum / stats.edge.pixels.max(1) as f64 * 255.0;
    Ok(stats)
}

/// The temporal error of a run of frames: each consecutive pair's, summed up.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct TemporalSummary {
    pub pairs: usize,
    /// Means over the pairs of each pair's figure, in 1/255.
    pub mae_255: f64,
    pub edge_mae_255: f64,
    /// The largest change of any pixel in any pair, as coverage.
    pub max: f64,
    /// Pixels over [`TEMPORAL_THRESHOLD`], per pair on average.
    pub pixels_over_per_pair: f64,
    /// The pair (its first frame) with the largest mean, and that mean in 1/255.
    pub worst_pair: usize,
    pub worst_pair_mae_255: f64,
}

impl TemporalSummary {
    /// Sums up the pairs' figures; `pairs[k]` is between frames k and k + 1.
    pub fn of(pairs: &[TemporalError]) -> TemporalSummary {
        let n = pairs.len().max(1) as f64;
        let mut summary = TemporalSummary {
            pairs: pairs.len(),
            ..Default::default()
        };
        for (k, pair) in pairs.iter().enumerate() {
            summary.mae_255 += pair.mae_255 / n;
            summary.edge_mae_255 += pair.edge.mae_255 / n;
            summary.max = summary.max.max(pair.max);
            summary.pixels_over_per_pair += pair.pixels_over as f64 / n;
            if k == 0 || pair.mae_255 > summary.worst_pair_mae_255 {
                summary.worst_pair = k;
                summary.worst_pair_mae_255 = pair.mae_255;
            }
        }
        summary
    }
}

/// A pixel's absolute error against the reference: ((x, y), error).
pub type PixelError = ((u32, u32), f64);

/// The pixels of `image` off from `reference` by more than `threshold`, largest error
/// first (ties in reading order, so the first is [`ErrorStats::worst_pixel`]). An
/// invalid pixel is infinitely far off, as in [`compare`].
pub fn pixels_over(
    image: &CoverageImage,
    reference: &CoverageImage,
    threshold: f64,
) -> Result<Vec<PixelError>, Error> {
    if (image.width, image.height) != (reference.width, reference.height) {
        return Err(Error::Input(format!(
            "cannot compare a {}x{} image with a {}x{} reference",
            image.width, image.height, reference.width, reference.height
        )));
    }
    let width = image.width as usize;
    let mut over: Vec<PixelError> = image
        .data
        .iter()
        .zip(&reference.data)
        .enumerate()
        .filter_map(|(i, (&a, &b))| {
            let error = if is_valid(a) && is_valid(b) {
                (f64::from(a) - f64::from(b)).abs()
            } else {
                f64::INFINITY
            };
            let pixel = ((i % width) as u32, (i / width) as u32);
            (error > threshold).then_some((pixel, error))
        })
        .collect();
    // Stable: equal errors keep their reading order.
    over.sort_by(|a, b| b.1.total_cmp(&a.1));
    Ok(over)
}

/// The middle value, the upper one of an even count (None for none): the one median
/// every timing in the project quotes.
pub fn median(values: impl IntoIterator<Item = f64>) -> Option<f64> {
    let mut v: Vec<f64> = values.into_iter().collect();
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied()
}

/// The value below which a fraction `q` of `values` lies (nearest rank; NaN counts as
/// the largest); 0 for none. Reorders `values`.
fn percentile(values: &mut [f64], q: f64) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    let rank = ((q * values.len() as f64).ceil() as usize).clamp(1, values.len()) - 1;
    *values
        .select_nth_unstable_by(rank, |a, b| {
            a.partial_cmp(b)
                .unwrap_or_else(|| a.is_nan().cmp(&b.is_nan()))
        })
        .1
}

/// Signed error image: red where `image` covers more than `reference`, blue where it
/// covers less, full intensity at an error of `full_scale`.
pub fn error_image(
    image: &CoverageImage,
    reference: &CoverageImage,
    full_scale: f32,
) -> image::RgbImage {
    let mut out = image::RgbImage::new(image.width, image.height);
    for (p, (&a, &b)) in out.pixels_mut().zip(image.data.iter().zip(&reference.data)) {
        let e = ((a - b) / full_scale).clamp(-1.0, 1.0);
        let v = (e.abs() * 255.0).round() as u8;
        *p = if e >= 0.0 {
            image::Rgb([v, 0, 0])
        } else {
            image::Rgb([0, 0, v])
        };
    }
    out
}

/// Indices of the (time, error) points that no other point beats on both, by increasing
/// time: the settings worth choosing. Of equal points the first listed is kept.
pub fn pareto_front(points: &[(f64, f64)]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_by(|&a, &b| {
        let (p, q) = (points[a], points[b]);
        p.0.total_cmp(&q.0).then(p.1.total_cmp(&q.1))
    });
    let mut front: Vec<usize> = Vec::new();
    for i in order {
        if front
            .last()
            .is_none_or(|&last| points[i].1 < points[last].1)
        {
            front.push(i);
        }
    }
    front
}

#[cfg(test)]
mod tests {
    use super::*;

    fn img(data: &[f32]) -> CoverageImage {
        CoverageImage {
            width: data.len() as u32,
            height: 1,
            data: data.to_vec(),
        }
    }

    #[test]
    fn figures_match_hand_computation() {
        let s = compare(&img(&[0.0, 0.5, 1.0, 0.3]), &img(&[0.0, 0.0, 0.4, 0.3])).unwrap();
        assert!((s.mae_255 - (0.5 + 0.6) / 4.0 * 255.0).abs() < 1e-4);
        assert!((s.rmse_255 - ((0.25 + 0.36) / 4.0f64).sqrt() * 255.0).abs() < 1e-3);
        assert!((s.max - 0.6).abs() < 1e-6);
        assert_eq!(s.worst_pixel, (2, 0));
        assert_eq!((s.pixels_over_025, s.pixels_over_05), (2, 1));
        // Errors 0, 0, 0.5, 0.6: the 99th percentile of four is the largest.
        assert!((s.p99_255 - 0.6 * 255.0).abs() < 1e-3);
    }

    #[test]
    fn pixels_over_are_listed_worst_first_with_ties_in_reading_order() {
        // A 3×2 image: errors 0.3, 0.1, 0.6 / 0.3, NaN, 0.25 (by hand).
        let image = CoverageImage {
            width: 3,
            height: 2,
            data: vec![0.3, 0.1, 1.0, 0.8, f32::NAN, 0.25],
        };
        let reference = CoverageImage {
            width: 3,
            height: 2,
            data: vec![0.0, 0.0, 0.4, 0.5, 0.5, 0.0],
        };
        let over = pixels_over(&image, &reference, 0.25).unwrap();
        let pixels: Vec<(u32, u32)> = over.iter().map(|p| p.0).collect();
        // 0.25 is not over 0.25; the NaN is infinitely off.
        assert_eq!(pixels, [(1, 1), (2, 0), (0, 0), (0, 1)]);
        assert!(over[0].1.is_infinite());
        assert!((over[1].1 - 0.6).abs() < 1e-6 && (over[3].1 - 0.3).abs() < 1e-6);
        let stats = compare(&image, &reference).unwrap();
        assert_eq!(over.len(), stats.pixels_over_025);
        assert_eq!(over[0].0, stats.worst_pixel);
        assert!(pixels_over(&image, &img(&[0.0; 6]), 0.25).is_err());
    }

    #[test]
    fn p99_ignores_the_worst_percent() {
        let mut data = vec![0.0f32; 1000];
        data[..10].fill(1.0);
        let s = compare(&img(&data), &img(&[0.0; 1000])).unwrap();
        assert_eq!(
            s.p99_255, 0.0,
            "ten bad pixels in a thousand are the top 1%"
        );
        data[10] = 0.5;
        let s = compare(&img(&data), &img(&[0.0; 1000])).unwrap();
        assert!((s.p99_255 - 0.5 * 255.0).abs() < 1e-3);
    }

    #[test]
    fn nan_is_the_worst_error() {
        let s = compare(&img(&[0.0, f32::NAN]), &img(&[0.0, 0.0])).unwrap();
        assert!(s.max.is_infinite());
        assert_eq!(s.worst_pixel, (1, 0));
        // Hand-worked: one pixel of two off by 1 (the most coverage can be off).
        assert!((s.mae_255 - 127.5).abs() < 1e-9, "{}", s.mae_255);
        assert_eq!((s.pixels_over_025, s.pixels_over_05), (1, 1));
        assert_eq!(
            (s.invalid_pixels, s.edge.pixels, s.edge.pixels_over_05),
            (1, 1, 1)
        );
    }

    /// Values outside [0, 1] are no coverage at all: artifacts, even where they land
    /// close to the reference (1.2 against 1.0 is off by 0.2 but still impossible).
    #[test]
    fn out_of_range_values_are_artifacts() {
        let s = compare(
            &img(&[1.2, -0.1, f32::INFINITY, 0.5]),
            &img(&[1.0, 0.0, 1.0, 0.5]),
        )
        .unwrap();
        assert_eq!(s.invalid_pixels, 3);
        assert_eq!(s.pixels_over_05, 3);
        assert!(s.max.is_infinite());
        // The reference is checked the same way.
        let s = compare(&img(&[0.5]), &img(&[f32::NAN])).unwrap();
        assert_eq!((s.invalid_pixels, s.pixels_over_05), (1, 1));
    }

    /// The edge figures look only at partial or differing pixels: one full-pixel
    /// artifact among 98 blank and one exact edge pixel is 1/100 of the frame's mean
    /// but half of the edges' (hand-worked: errors 1 and 0 over 2 edge pixels).
    #[test]
    fn edge_error_is_taken_over_partial_or_differing_pixels() {
        let mut image = vec![0.0f32; 100];
        let mut reference = vec![0.0f32; 100];
        image[0] = 1.0; // an artifact: the reference has nothing here
        image[1] = 0.5;
        reference[1] = 0.5; // an edge pixel drawn exactly
        image[2] = 1.0;
        reference[2] = 1.0; // an interior pixel: not an edge
        let s = compare(&img(&image), &img(&reference)).unwrap();
        assert!((s.mae_255 - 255.0 / 100.0).abs() < 1e-9);
        assert_eq!(s.edge.pixels, 2);
        assert!((s.edge.mae_255 - 255.0 / 2.0).abs() < 1e-9);
        assert_eq!((s.edge.max, s.edge.pixels_over_05), (1.0, 1));
    }

    /// A pixel that changes by the reference's amount scores 0, one that jumps where
    /// the reference moves a little scores the difference, an invalid one 1 (hand-worked:
    /// Δr = 0.125, 0, 0.5; Δm = 0.125, 0.25, 0.5; |Δm − Δr| = 0, 0.25, 0 and the NaN).
    #[test]
    fn temporal_error_is_the_change_less_the_references() {
        let m0 = img(&[0.25, 0.0, 0.0, 0.0]);
        let m1 = img(&[0.375, 0.25, 0.5, f32::NAN]);
        let r0 = img(&[0.25, 0.1, 0.0, 0.0]);
        let r1 = img(&[0.375, 0.1, 0.5, 0.0]);
        let t = temporal([&m0, &m1], [&r0, &r1]).unwrap();
        assert!(
            (t.mae_255 - (0.25 + 1.0) / 4.0 * 255.0).abs() < 1e-4,
            "{}",
            t.mae_255
        );
        assert!(t.max.is_infinite() && t.worst_pixel == (3, 0));
        assert_eq!((t.pixels_over, t.invalid_pixels), (2, 1));
        // Every pixel here is an edge pixel: partial, or different from the reference.
        assert_eq!(t.edge.pixels, 4);
        let still = temporal([&r0, &r1], [&r0, &r1]).unwrap();
        assert_eq!((still.mae_255, still.max, still.pixels_over), (0.0, 0.0, 0));
        let summary = TemporalSummary::of(&[still, t, still]);
        assert_eq!((summary.pairs, summary.worst_pair), (3, 1));
        assert!((summary.mae_255 - t.mae_255 / 3.0).abs() < 1e-9);
        assert!(temporal([&m0, &img(&[0.0])], [&r0, &r1]).is_err());
    }

    #[test]
    fn error_image_is_signed() {
        let e = error_image(&img(&[0.75, 0.25, 0.5]), &img(&[0.5, 0.5, 0.5]), 0.5);
        assert_eq!(e.get_pixel(0, 0).0, [128, 0, 0], "over-coverage is red");
        assert_eq!(e.get_pixel(1, 0).0, [0, 0, 128], "under-coverage is blue");
        assert_eq!(e.get_pixel(2, 0).0, [0, 0, 0]);
    }

    #[test]
    fn size_mismatch_is_an_error() {
        assert!(compare(&img(&[0.0]), &img(&[0.0, 0.0])).is_err());
    }

    #[test]
    fn pareto_front_keeps_only_unbeaten_points() {
        let points = [
            (1.0, 5.0),
            (2.0, 6.0), // slower and worse than the first
            (3.0, 1.0),
            (0.5, 9.0),
            (4.0, 1.0), // as good as the third, slower
            (3.0, 1.0), // the third again
        ];
        assert_eq!(pareto_front(&points), vec![3, 0, 2]);
        assert!(pareto_front(&[]).is_empty());
    }
}
