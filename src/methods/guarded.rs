//! The last net at the method boundary: every method [`MethodInfo::create`] makes
//! (peers first among them: code the project does not control) runs behind
//! [`Guarded`], which turns a panic inside it into an [`Error::Refused`] naming the row
//! and the cause — one line and exit 2 on the command line, an n/a with its reason in
//! the bench, a refused frame in the survey, a message in the explorer's pane — and
//! keeps the panic's own report off the terminal. A row that panicked refuses every
//! later call: its state may be half-changed.
//!
//! Where a panic aborts (the web build), nothing is caught: there the checks that stop
//! bad input before a row sees it (a font's axes, its tables) are the net.
//!
//! [`MethodInfo::create`]: super::info::MethodInfo::create

use std::cell::{Cell, RefCell};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Once;

use super::{CurveCost, LayoutOffset, MeshStats, Method, Overlay, PeerGpuTime};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::scene::Scene;

thread_local! {
    /// Whether this thread is inside a guarded call: then a panic's report is kept
    /// here for the error instead of printed.
    static GUARDED: Cell<bool> = const { Cell::new(false) };
    static REPORT: RefCell<Option<String>> = const { RefCell::new(None) };
}

static HOOK: Once = Once::new();

/// Runs `work`, catching a panic: its message and where it happened, as `Err`.
pub fn catching<T>(work: impl FnOnce() -> T) -> Result<T, String> {
    HOOK.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            // try_with: a panic while the thread's locals are torn down is printed.
            if GUARDED.try_with(Cell::get).unwrap_or(false) {
                let message = info
                    .payload()
                    .downcast_ref::<&str>()
                    .map(|s| (*s).to_owned())
                    .or_else(|| info.payload().downcast_ref::<String>().cloned())
                    .unwrap_or_else(|| "a panic without a message".into());
                let at = info
                    .location()
                    .map(|l| format!(" at {}:{}", l.file(), l.line()))
                    .unwrap_or_default();
                // One line, whatever the message held.
                let line = format!("{message}{at}").replace('\n', " ");
                let _ = REPORT.try_with(|r| *r.borrow_mut() = Some(line));
            } else {
                previous(info);
            }
        }));
    });
    // A report left by a panic something inside caught itself is not this call's: each
    // call starts with none, and gives back an enclosing call's when it ends.
    let outer = GUARDED.with(|g| g.replace(true));
    let enclosing = REPORT.with(|r| r.borrow_mut().take());
    let result = catch_unwind(AssertUnwindSafe(work));
    GUARDED.with(|g| g.set(outer));
    let report = REPORT.with(|r| std::mem::replace(&mut *r.borrow_mut(), enclosing));
    result.map_err(|_| {
        // A panic re-raised from another thread (rayon's workers) passes no hook here.
        report.unwrap_or_else(|| "a panic on a worker thread, its message printed there".into())
    })
}

/// A method behind the net.
pub struct Guarded {
    inner: Box<dyn Method>,
    /// Why it refuses everything since it panicked.
    broken: Option<String>,
}

impl Guarded {
    pub fn wrap(inner: Box<dyn Method>) -> Box<dyn Method> {
        Box::new(Guarded {
            inner,
            broken: None,
        })
    }

    fn call<T>(
        &mut self,
        what: &str,
        work: impl FnOnce(&mut dyn Method) -> Result<T, Error>,
    ) -> Result<T, Error> {
        if let Some(why) = &self.broken {
            return Err(Error::Refused(why.clone()));
        }
        let inner = self.inner.as_mut();
        match catching(|| work(inner)) {
            Ok(result) => result,
            Err(cause) => {
                let why = format!(
                    "{} failed in its {what} (a panic, caught: {cause}); it draws nothing more \
                     until made anew",
                    self.inner.name()
                );
                self.broken = Some(why.clone());
                Err(Error::Refused(why))
            }
        }
    }

    /// A figure the method reports, or `fallback` where asking panicked.
    fn figure<T>(&self, fallback: T, work: impl FnOnce(&dyn Method) -> T) -> T {
        if self.broken.is_some() {
            return fallback;
        }
        catching(|| work(self.inner.as_ref())).unwrap_or(fallback)
    }
}

impl Method for Guarded {
    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        self.call("preparation", |m| m.prepare(gpu, scene))
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        self.call("frame", |m| m.encode(gpu, encoder, target, camera))
    }

    fn gpu_bytes(&self) -> u64 {
        self.figure(0, |m| m.gpu_bytes())
    }

    fn cache_bytes(&self) -> Option<u64> {
        self.figure(None, |m| m.cache_bytes())
    }

    fn overlays(&self) -> &'static [Overlay] {
        self.inner.overlays()
    }

    fn curves_per_pixel(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
    ) -> Result<Option<CurveCost>, Error> {
        self.call("cost count", |m| m.curves_per_pixel(gpu, camera))
    }

    fn mesh_stats(&self) -> Option<MeshStats> {
        self.figure(None, |m| m.mesh_stats())
    }

    fn peer_gpu_time(&mut self, gpu: &GpuContext) -> Result<Option<PeerGpuTime>, Error> {
        self.call("timing", |m| m.peer_gpu_time(gpu))
    }

    fn layout_offset(&self) -> Option<LayoutOffset> {
        self.figure(None, |m| m.layout_offset())
    }

    fn refused_glyphs(&self) -> Vec<(u16, String)> {
        self.figure(Vec::new(), |m| m.refused_glyphs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A method that panics where told to.
    struct Panicky;

    impl Method for Panicky {
        fn name(&self) -> &'static str {
            "panicky"
        }

        fn prepare(&mut self, _gpu: &GpuContext, _scene: &Scene) -> Result<(), Error> {
            // What glyphon did on a broken axis: clamp with its bounds the wrong way.
            let (min, max) = std::hint::black_box((100.0f32, -1.5e-5f32));
            std::hint::black_box(1.0f32.clamp(min, max));
            Ok(())
        }

        fn encode(
            &mut self,
            _gpu: &GpuContext,
            _encoder: &mut wgpu::CommandEncoder,
            _target: &CoverageTarget,
            _camera: &Camera,
        ) -> Result<(), Error> {
            Ok(())
        }

        fn gpu_bytes(&self) -> u64 {
            panic!("no figure")
        }
    }

    #[test]
    fn a_panic_in_a_row_is_a_one_line_refusal_naming_it_and_later_calls_refuse() {
        let mut method = Guarded::wrap(Box::new(Panicky));
        let scene = Scene::from_outlines(1000.0, Vec::new());
        // No device is needed to reach the panic: prepare panics before using it.
        let gpu = match GpuContext::new() {
            Ok(gpu) => gpu,
            Err(_) => return,
        };
        match method.prepare(&gpu, &scene) {
            Err(Error::Refused(why)) => {
                assert!(
                    why.starts_with("panicky failed in its preparation"),
                    "{why}"
                );
                assert!(why.contains("min > max") || why.contains("clamp"), "{why}");
                assert!(!why.contains('\n'), "{why}");
            }
            other => panic!("{other:?}"),
        }
        assert!(matches!(
            method.prepare(&gpu, &scene),
            Err(Error::Refused(_))
        ));
        assert_eq!(method.gpu_bytes(), 0);
    }

    #[test]
    fn a_caught_panic_is_its_message_and_place_on_one_line() {
        let caught = catching(|| -> u32 { panic!("two\nlines") });
        let message = caught.unwrap_err();
        assert!(message.starts_with("two lines at "), "{message}");
        assert!(message.contains("guarded.rs"), "{message}");
        assert_eq!(catching(|| 7), Ok(7));
    }

    #[test]
    fn a_panic_outside_a_guarded_call_is_not_swallowed() {
        let outside = std::panic::catch_unwind(|| {
            let _ = catching(|| 1);
            panic!("still a panic");
        });
        assert!(outside.is_err());
    }
}
