//! The device every method renders with, and the few helpers that turn wgpu's
//! callbacks and error handlers into plain `Result`s.

use glyphscope_core::Error;

/// The adapter, device and queue, chosen once per process. Cloning shares them (wgpu's
/// handles are reference-counted), e.g. with a background thread.
#[derive(Clone)]
pub struct GpuContext {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    /// None for a device a library caller gave (`glyphscope::text`): only the device
    /// and queue are needed to draw.
    adapter: Option<(wgpu::Instance, wgpu::Adapter)>,
    /// The bound on a wait for the GPU, where one was set ([`GpuContext::guard_waits`]).
    /// Shared by clones, as the device is.
    wait_guard: std::sync::Arc<std::sync::Mutex<Option<WaitGuard>>>,
}

/// How long [`GpuContext::wait_idle`] may wait, and what it does past that.
struct WaitGuard {
    limit: std::time::Duration,
    on_hang: std::sync::Arc<dyn Fn(std::time::Duration) + Send + Sync>,
}

/// The features `time_frames` needs: timestamps written on the command encoder, around
/// whatever passes a method records.
const TIMESTAMP_FEATURES: wgpu::Features =
    wgpu::Features::TIMESTAMP_QUERY.union(wgpu::Features::TIMESTAMP_QUERY_INSIDE_ENCODERS);

impl GpuContext {
    /// Opens any adapter. `WGPU_BACKEND`, `WGPU_POWER_PREF` and `WGPU_ADAPTER_NAME`
    /// choose among them. Timestamp queries are enabled when the adapter has them, and
    /// the device gets the adapter's own limits rather than WebGPU's portable defaults,
    /// so that 16384-pixel targets work wherever the hardware allows them.
    pub fn new() -> Result<GpuContext, Error> {
        Self::open(None)
    }

    /// Opens the adapter whose name contains `adapter` (case-insensitive; the command
    /// line's `--adapter`), else as [`GpuContext::new`] does. A name that matches no
    /// adapter is an error listing those there are.
    pub fn open(adapter: Option<&str>) -> Result<GpuContext, Error> {
        pollster::block_on(Self::open_async(adapter))
    }

    async fn open_async(wanted: Option<&str>) -> Result<GpuContext, Error> {
        // The primary backends (Vulkan, Metal, DX12) first, GL only where none of them
        // has an adapter; `WGPU_BACKEND`, when set, decides alone. An instance with GL
        // makes an EGL context per GL adapter it enumerates, and egui_wgpu enumerates
        // every adapter of the instance it is given again: dropping those failed with
        // EGL_BAD_ACCESS in one run of four of tests/app.rs on lavapipe.
        let descriptor = |primary_only: bool| {
            let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
            if primary_only {
                descriptor.backends &= wgpu::Backends::PRIMARY;
            }
            descriptor
        };
        let backend_from_env = std::env::var_os("WGPU_BACKEND").is_some();
        let from_env = std::env::var("WGPU_ADAPTER_NAME").ok();
        let wanted = wanted.or(from_env.as_deref());
        let mut instance = wgpu::Instance::new(descriptor(!backend_from_env));
        let adapter = match choose_adapter(&instance, wanted).await {
            Ok(adapter) => adapter,
            Err(_) if !backend_from_env => {
                instance = wgpu::Instance::new(descriptor(false));
                choose_adapter(&instance, wanted).await?
            }
            Err(e) => return Err(e),
        };
        let (device, queue) = adapter
            .request_device(&Self::device_descriptor(&adapter))
            .await
            .map_err(|e| Error::Gpu(format!("cannot open '{}': {e}", adapter.get_info().name)))?;
        Ok(GpuContext {
            device,
            queue,
            adapter: Some((instance, adapter)),
            wait_guard: Default::default(),
        })
    }

    /// What [`GpuContext::new`] asks of an adapter: timestamp queries where it has them,
    /// and its own limits. Whoever opens a device for the methods elsewhere (the app, on
    /// eframe's adapter) asks the same, so methods behave and time alike there.
    pub fn device_descriptor(adapter: &wgpu::Adapter) -> wgpu::DeviceDescriptor<'static> {
        wgpu::DeviceDescriptor {
            label: Some("glyphscope"),
            required_features: adapter.features() & TIMESTAMP_FEATURES,
            required_limits: adapter.limits(),
            ..Default::default()
        }
    }

    /// Wraps a device someone else opened (eframe's, in the app), so that methods render
    /// on it and their targets can be drawn by that device's own passes. Timestamps work
    /// only if the device was opened with them (see [`GpuContext::device_descriptor`]).
    pub fn from_device(
        instance: wgpu::Instance,
        adapter: wgpu::Adapter,
        device: wgpu::Device,
        queue: wgpu::Queue,
    ) -> Self {
        GpuContext {
            device,
            queue,
            adapter: Some((instance, adapter)),
            wait_guard: Default::default(),
        }
    }

    /// Wraps a device and queue a library caller opened (`glyphscope::text`): what
    /// drawing needs, without the adapter a report would name.
    pub fn from_device_and_queue(device: wgpu::Device, queue: wgpu::Queue) -> Self {
        GpuContext {
            device,
            queue,
            adapter: None,
            wait_guard: Default::default(),
        }
    }

    /// The instance and adapter the device came from, for handing the same device to
    /// a UI (the app's tests draw the explorer on the device their checks use).
    /// None for a device a library caller gave.
    pub fn instance_and_adapter(&self) -> Option<(&wgpu::Instance, &wgpu::Adapter)> {
        self.adapter
            .as_ref()
            .map(|(instance, adapter)| (instance, adapter))
    }

    /// The adapter's name, backend and driver, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)
    /// (Vulkan; driver llvmpipe, Mesa 22.3.6 (LLVM 15.0.6))": every report names it.
    pub fn adapter_name(&self) -> String {
        match &self.adapter {
            Some((_, adapter)) => describe(adapter),
            None => "the caller's device (adapter not given)".into(),
        }
    }

    /// What the adapter says of itself: its device type tells a CPU implementation
    /// (lavapipe, SwiftShader) from a GPU.
    pub fn adapter_info(&self) -> Option<wgpu::AdapterInfo> {
        self.adapter.as_ref().map(|(_, adapter)| adapter.get_info())
    }

    /// Whether `time_frames` can measure GPU time on this device.
    pub fn has_timestamps(&self) -> bool {
        self.device.features().contains(TIMESTAMP_FEATURES)
    }

    /// The largest width or height of a 2D texture, and so of a coverage target.
    pub fn max_texture_side(&self) -> u32 {
        self.device.limits().max_texture_dimension_2d
    }

    /// A buffer holding `items`, for `usage`. An empty list still gets one zeroed item:
    /// a binding cannot be empty, and a shader's array of `T` needs room for at least
    /// one (a fixed 16-byte stand-in failed validation for `winding`'s 48-byte curves
    /// on an outline whose every segment has zero length).
    pub fn buffer_of<T: bytemuck::Pod>(
        &self,
        label: &str,
        items: &[T],
        usage: wgpu::BufferUsages,
    ) -> wgpu::Buffer {
        use wgpu::util::DeviceExt;
        let placeholder = [T::zeroed()];
        let items = if items.is_empty() {
            &placeholder[..]
        } else {
            items
        };
        self.device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(items),
                usage,
            })
    }

    /// Runs `work` and reports the validation and out-of-memory errors wgpu raises
    /// meanwhile as [`Error::Gpu`], instead of letting wgpu's default handler panic.
    pub fn catching_errors<T>(
        &self,
        what: &str,
        work: impl FnOnce() -> Result<T, Error>,
    ) -> Result<T, Error> {
        let out_of_memory = self.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let validation = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let result = work();
        // Scopes pop in reverse order of their pushes, here, when `pop` is called.
        let validation = validation.pop();
        let out_of_memory = out_of_memory.pop();
        // A page cannot wait for the answer within the frame: its errors are logged to
        // the browser's console when they arrive.
        #[cfg(target_arch = "wasm32")]
        {
            let what = what.to_owned();
            wasm_bindgen_futures::spawn_local(async move {
                if let Some(e) = validation.await.or(out_of_memory.await) {
                    log::error!("{what} failed on the GPU: {e}");
                }
            });
            result
        }
        #[cfg(not(target_arch = "wasm32"))]
        match pollster::block_on(validation).or(pollster::block_on(out_of_memory)) {
            Some(e) => Err(Error::Gpu(format!("{what} failed on the GPU: {e}"))),
            None => result,
        }
    }

    /// Blocks until the GPU has finished everything submitted so far. A web page cannot
    /// block (WebGPU answers only between frames): there it is an error that says so,
    /// never a hang, until every caller reads back asynchronously.
    pub fn wait_idle(&self) -> Result<(), Error> {
        if cfg!(target_arch = "wasm32") {
            return Err(Error::Gpu(
                "a web page cannot wait for the GPU within a frame: this needs the desktop \
                 explorer for now"
                    .into(),
            ));
        }
        let guard = self
            .wait_guard
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
            .as_ref()
            .map(|g| (g.limit, g.on_hang.clone()));
        let start = std::time::Instant::now();
        loop {
            // GL waits at most 2.1 s a call (glClientWaitSync takes an i32 of
            // nanoseconds), whatever was asked; a large frame on a software GL driver (the
            // bench's scaling series) takes longer: wait again, up to the guard's limit.
            let timeout = guard
                .as_ref()
                .map(|(limit, _)| limit.saturating_sub(start.elapsed()));
            match self.device.poll(wgpu::PollType::Wait {
                submission_index: None,
                timeout,
            }) {
                Ok(_) => return Ok(()),
                Err(wgpu::PollError::Timeout) => match &guard {
                    Some((limit, on_hang)) if start.elapsed() >= *limit => {
                        on_hang(start.elapsed());
                        return Err(Error::Gpu(format!(
                            "the GPU has not finished a frame in {:.0} s: a shader may never \
                             return; the device stays busy with it",
                            limit.as_secs_f64()
                        )));
                    }
                    _ => continue,
                },
                Err(e) => return Err(Error::Gpu(format!("waiting for the GPU failed: {e}"))),
            }
        }
    }

    /// Bounds every later wait for the GPU ([`GpuContext::wait_idle`], and so every read
    /// back) by `limit`: past it, `on_hang` is called with the time waited, and where it
    /// returns, the wait fails with an error. For shaders not known to return (a user's
    /// method, `--method wgsl:PATH`): a software device has no GPU timeout, and a
    /// shader that never returns keeps it busy for good — dropping the device waits for
    /// it too, so a command line ends its process in `on_hang`.
    pub fn guard_waits(
        &self,
        limit: std::time::Duration,
        on_hang: impl Fn(std::time::Duration) + Send + Sync + 'static,
    ) {
        *self
            .wait_guard
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner()) = Some(WaitGuard {
            limit,
            on_hang: std::sync::Arc::new(on_hang),
        });
    }

    /// Maps a `MAP_READ` buffer whose copies have been submitted, and returns its bytes.
    pub fn read_buffer(&self, buffer: &wgpu::Buffer) -> Result<Vec<u8>, Error> {
        let (sender, receiver) = std::sync::mpsc::channel();
        buffer.map_async(wgpu::MapMode::Read, .., move |result| {
            // The receiver outlives the wait below, so sending cannot fail.
            let _ = sender.send(result);
        });
        self.wait_idle()?;
        let mapped = receiver
            .recv()
            .map_err(|_| Error::Gpu("the GPU never answered a buffer read".into()))?;
        mapped.map_err(|e| Error::Gpu(format!("cannot read a buffer back from the GPU: {e}")))?;
        let bytes = buffer
            .get_mapped_range(..)
            .map_err(|e| Error::Gpu(format!("cannot read a buffer back from the GPU: {e}")))?
            .to_vec();
        buffer.unmap();
        Ok(bytes)
    }
}

/// The adapter whose name contains `wanted` (case-insensitive) if one is asked for, else
/// wgpu's default choice under `WGPU_POWER_PREF`. wgpu's own helper for this panics when
/// the name matches nothing; this reports the adapters there are.
async fn choose_adapter(
    instance: &wgpu::Instance,
    wanted: Option<&str>,
) -> Result<wgpu::Adapter, Error> {
    if let Some(wanted) = wanted {
        let adapters = instance.enumerate_adapters(wgpu::Backends::all()).await;
        let names: Vec<String> = adapters.iter().map(describe).collect();
        return adapters
            .into_iter()
            .find(|a| {
                a.get_info()
                    .name
                    .to_lowercase()
                    .contains(&wanted.to_lowercase())
            })
            .ok_or_else(|| {
                Error::Gpu(format!(
                    "no adapter's name contains '{wanted}' (--adapter or WGPU_ADAPTER_NAME); \
                     found: {}",
                    if names.is_empty() {
                        "none".to_string()
                    } else {
                        names.join(", ")
                    }
                ))
            });
    }
    instance
        .request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::from_env().unwrap_or_default(),
            ..Default::default()
        })
        .await
        .map_err(|_| {
            Error::Gpu(
                "no GPU adapter found; on Debian install mesa-vulkan-drivers for lavapipe".into(),
            )
        })
}

/// An adapter's name, backend and driver: the same name can come through several
/// backends, and one device through several drivers (or versions of one).
fn describe(adapter: &wgpu::Adapter) -> String {
    let info = adapter.get_info();
    let driver: Vec<&str> = [info.driver.as_str(), info.driver_info.as_str()]
        .into_iter()
        .filter(|part| !part.is_empty())
        .collect();
    if driver.is_empty() {
        format!("{} ({:?})", info.name, info.backend)
    } else {
        format!(
            "{} ({:?}; driver {})",
            info.name,
            info.backend,
            driver.join(", ")
        )
    }
}

/// SwiftShader's Vulkan manifest as Debian's `chromium` package installs it.
pub const SWIFTSHADER_MANIFEST: &str = "/usr/lib/chromium/vk_swiftshader_icd.json";

/// Makes SwiftShader, a second software Vulkan implementation, one of the adapters
/// there are, where Chromium ships it and the user has not chosen the drivers
/// (`VK_ICD_FILENAMES`, `VK_DRIVER_FILES`): the Vulkan loader adds the drivers
/// `VK_ADD_DRIVER_FILES` lists to those it finds (Debian bookworm's, 1.3.239, does).
/// They come before lavapipe in the loader's order, so SwiftShader would become wgpu's
/// default choice: call this only where an adapter is asked for by name.
///
/// # Safety
///
/// Sets an environment variable: call it before the process starts a thread, as
/// nothing may read the environment meanwhile.
pub unsafe fn offer_swiftshader() {
    let set = |name: &str| std::env::var_os(name).is_some();
    if set("VK_ICD_FILENAMES")
        || set("VK_DRIVER_FILES")
        || !std::path::Path::new(SWIFTSHADER_MANIFEST).exists()
    {
        return;
    }
    let mut files = std::ffi::OsString::from(SWIFTSHADER_MANIFEST);
    if let Some(others) = std::env::var_os("VK_ADD_DRIVER_FILES") {
        files.push(":");
        files.push(others);
    }
    // SAFETY: this function's own contract: no other thread runs yet.
    unsafe { std::env::set_var("VK_ADD_DRIVER_FILES", files) };
}
