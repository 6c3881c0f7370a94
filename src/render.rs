//! `glyphscope render`: a view drawn by one method, with its statistics, its signed
//! error against the reference and the magnifier's picture where they are asked for.
//! Every figure of the docs and every outside check drives it, and tests call it as
//! users run it.

use std::path::PathBuf;
use web_time::Instant;

use crate::Error;
use crate::coverage::CoverageImage;
use crate::coverage::Png as _;
use crate::gpu::GpuContext;
use crate::magnify::{self, Focus, Window};
use crate::measure::{self, Measured, RENDER_TIMING, RenderStats};
use crate::methods::frame::ms_since;
use crate::methods::registry;
use crate::metrics;
use crate::outline_overlay;
use crate::reference;
use crate::scene::JoinCounts;
use crate::view_args::ViewArgs;

/// What to draw, with which method, and what to write.
#[derive(Clone, Debug)]
pub struct RenderOptions {
    pub view: ViewArgs,
    /// A named view instead of `view` (see [`crate::named_views`]).
    pub case: Option<String>,
    /// The method's name in the registry.
    pub method: String,
    /// Its parameters, KEY=VALUE.
    pub params: Vec<(String, String)>,
    /// The PNG: the coverage, or the picture in colour (an overlay, the magnifier's).
    pub out: PathBuf,
    /// Where to write the statistics as JSON, if anywhere.
    pub stats: Option<PathBuf>,
    /// Where to write the signed error against the reference, if anywhere.
    pub error_image: Option<PathBuf>,
    /// The magnifier's factor: each pixel an N×N block (1: no magnifier).
    pub magnify: u32,
    /// The pixel the magnified picture is centred on (the worst when None).
    pub focus: Option<Focus>,
    /// What the magnified picture draws over the pixels.
    pub overlays: Vec<PictureOverlay>,
    /// A part of the name of the adapter to draw with (see [`GpuContext::open`]).
    pub adapter: Option<String>,
}

/// A layer of `render`'s magnified picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PictureOverlay {
    Error,
    Outline,
}

impl RenderOptions {
    /// `view` drawn by the reference, with no output: the start of a render built in
    /// code.
    pub fn of(view: ViewArgs) -> RenderOptions {
        RenderOptions {
            view,
            case: None,
            method: registry::REFERENCE.name.into(),
            params: Vec::new(),
            out: PathBuf::new(),
            stats: None,
            error_image: None,
            magnify: 1,
            focus: None,
            overlays: Vec::new(),
            adapter: None,
        }
    }

    /// Whether the PNG is the magnifier's picture rather than the frame's coverage.
    pub fn wants_picture(&self) -> bool {
        self.magnify > 1 || self.focus.is_some() || !self.overlays.is_empty()
    }

    fn wants_reference(&self) -> bool {
        // The statistics report the error against the reference.
        self.stats.is_some()
            || self.error_image.is_some()
            || (self.wants_picture()
                && (self.focus.is_none_or(|f| f == Focus::Worst)
                    || self.overlays.contains(&PictureOverlay::Error)))
    }
}

/// A rendered image, its statistics, and the reference it was compared with (if any).
pub struct Rendered {
    pub image: CoverageImage,
    /// The overlay picture, when the `overlay` parameter asked for one.
    pub overlay: Option<image::RgbImage>,
    pub reference: Option<CoverageImage>,
    pub stats: RenderStats,
    /// The magnifier's picture and the pixels it shows, when one was asked for.
    pub picture: Option<(image::RgbImage, Window)>,
    /// The scene's instances whose ink overlaps, as `between=union` joins them: a fact of
    /// the scene, whichever method drew it.
    pub ink_overlaps: JoinCounts,
    /// A user's file's claim against the frame, where it makes one and the error was
    /// measured.
    pub claim: Option<ClaimVerdict>,
}

/// A user's file's claim (its header's, or `claim=` given with it) against a frame: what
/// it states and whether the frame keeps to it. A built-in row's claim depends on the
/// glyphs' traits: the survey and the stability sweep judge those.
#[derive(Clone, Debug, serde::Serialize)]
pub struct ClaimVerdict {
    pub statement: &'static str,
    pub held: bool,
}

/// Renders what `options` describe (nothing is written).
pub fn render(options: &RenderOptions) -> Result<Rendered, Error> {
    let method = registry::find(&options.method)?;
    let start = Instant::now();
    let (scene, camera) = match &options.case {
        Some(name) => crate::named_views::build(name)?,
        None => options.view.build()?,
    };
    let scene_ms = ms_since(start);
    let gpu = if method.is_reference() {
        None
    } else {
        Some(GpuContext::open(options.adapter.as_deref())?)
    };
    let Measured {
        image,
        overlay,
        mut stats,
    } = measure::measure(
        gpu.as_ref(),
        &scene,
        &camera,
        method,
        &options.params,
        RENDER_TIMING,
    )?;
    stats.cpu_prepare_ms += scene_ms;
    let reference = match options.wants_reference() {
        true if method.is_reference() => Some(image.clone()),
        true => Some(reference::rasterize(&scene, &camera)?),
        false => None,
    };
    if let Some(reference) = &reference {
        stats.error = Some(metrics::compare(&image, reference)?);
    }
    let picture = if options.wants_picture() {
        let focus = options.focus.unwrap_or(Focus::Worst);
        let pixel = focus.pixel(image.width, image.height, stats.error.as_ref())?;
        let window = Window::around(image.width, image.height, options.magnify, pixel);
        let outline = if options.overlays.contains(&PictureOverlay::Outline) {
            let tolerance_px = 0.2 / f64::from(window.factor);
            Some(
                outline_overlay::trace(
                    &scene,
                    &camera,
                    &window.rect(),
                    tolerance_px,
                    f64::from(window.factor),
                )
                .map_err(Error::Input)?,
            )
        } else {
            None
        };
        let layers = magnify::Layers {
            overlay: overlay.as_ref(),
            error_against: reference
                .as_ref()
                .filter(|_| options.overlays.contains(&PictureOverlay::Error)),
            outline: outline.as_ref(),
        };
        let picture = magnify::picture(&image, &window, &layers, image.width, image.height);
        Some((picture, window))
    } else {
        None
    };
    let claim = match (&stats.error, method.claims) {
        (Some(error), [only]) if method.name.starts_with(crate::methods::user::PREFIX) => {
            only.claim.bound.map(|bound| ClaimVerdict {
                statement: only.claim.statement,
                held: bound.holds(error.max, error.mae_255, error.edge.mae_255),
            })
        }
        _ => None,
    };
    Ok(Rendered {
        image,
        overlay,
        reference,
        stats,
        picture,
        ink_overlaps: scene.with_overlapping_instances_joined().1,
        claim,
    })
}

/// Renders, then writes the PNG and, if asked, the error image and the statistics.
pub fn run(options: &RenderOptions) -> Result<(), Error> {
    let rendered = render(options)?;
    let colour = rendered
        .picture
        .as_ref()
        .map(|(picture, _)| picture)
        .or(rendered.overlay.as_ref());
    match colour {
        // A picture is not coverage: it is written in colour.
        Some(picture) => picture
            .save(&options.out)
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", options.out.display())))?,
        None => rendered.image.save_png(&options.out)?,
    }
    if let (Some(path), Some(reference)) = (&options.error_image, &rendered.reference) {
        metrics::error_image(&rendered.image, reference, 0.5)
            .save(path)
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))?;
    }
    if let Some(path) = &options.stats {
        /// The statistics, and the magnified window where there is one.
        #[derive(serde::Serialize)]
        struct Written<'a> {
            #[serde(flatten)]
            stats: &'a RenderStats,
            #[serde(skip_serializing_if = "Option::is_none")]
            magnified: Option<Window>,
            ink_overlaps: JoinCounts,
            #[serde(skip_serializing_if = "Option::is_none")]
            claim: Option<&'a ClaimVerdict>,
        }
        let written = Written {
            stats: &rendered.stats,
            magnified: rendered.picture.as_ref().map(|(_, window)| *window),
            ink_overlaps: rendered.ink_overlaps,
            claim: rendered.claim.as_ref(),
        };
        let json = serde_json::to_string_pretty(&written).expect("stats serialize");
        std::fs::write(path, json + "\n")
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))?;
    }
    Ok(())
}
