//! A paragraph turning and zooming without end, drawn by `glyphscope::text` in a winit
//! window with wgpu: exact coverage at every angle and scale, the frame time in the
//! title. `cargo run --release --example spinning_text`; Escape or closing quits.

use std::sync::Arc;
use std::time::Instant;

use glam::{Mat3, vec2};
use glyphscope::text::{Content, FontId, TextRenderer, TextRun};
use winit::application::ApplicationHandler;
use winit::event::{ElementState, KeyEvent, WindowEvent};
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

const PARAGRAPH: &str = "Sharp text at any zoom, in your own app.\n\
    Each pixel's coverage is the exact integral\n\
    of the outline's winding number over it,\n\
    turned, scaled or seen in perspective.";

/// Everything drawn with, made once the window exists.
struct Drawing {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    device: wgpu::Device,
    queue: wgpu::Queue,
    config: wgpu::SurfaceConfiguration,
    text: TextRenderer,
    font: FontId,
}

#[derive(Default)]
struct App {
    drawing: Option<Drawing>,
    start: Option<Instant>,
    /// Frames since the title last changed, and when it did.
    frames: (u32, Option<Instant>),
}

impl Drawing {
    fn new(event_loop: &ActiveEventLoop) -> Result<Drawing, Box<dyn std::error::Error>> {
        let attributes = Window::default_attributes().with_title("spinning text");
        let window = Arc::new(event_loop.create_window(attributes)?);
        let instance = wgpu::Instance::default();
        let surface = instance.create_surface(window.clone())?;
        let options = wgpu::RequestAdapterOptions {
            compatible_surface: Some(&surface),
            ..Default::default()
        };
        let adapter = pollster::block_on(instance.request_adapter(&options))?;
        let (device, queue) = pollster::block_on(adapter.request_device(&Default::default()))?;
        let size = window.inner_size();
        let mut config = surface
            .get_default_config(&adapter, size.width.max(1), size.height.max(1))
            .ok_or("the surface does not suit this adapter")?;
        // An sRGB format, so that the text is blended in linear light.
        let formats = surface.get_capabilities(&adapter).formats;
        config.format = *formats
            .iter()
            .find(|f| f.is_srgb())
            .unwrap_or(&config.format);
        surface.configure(&device, &config);
        let mut text = TextRenderer::new(&device, &queue, config.format);
        let font = text.add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())?;
        Ok(Drawing {
            window,
            surface,
            device,
            queue,
            config,
            text,
            font,
        })
    }

    fn draw(&mut self, seconds: f32) -> Result<(), glyphscope::Error> {
        let [w, h] = [self.config.width, self.config.height];
        // Turn about the window's centre and zoom between 0.5× and 4×.
        let zoom = 1.4_f32.powf(3.0 * (0.4 * seconds).sin() + 1.0);
        let transform = Mat3::from_translation(vec2(w as f32, h as f32) / 2.0)
            * Mat3::from_scale_angle_translation(vec2(zoom, zoom), 0.3 * seconds, vec2(0.0, 0.0))
            * Mat3::from_translation(vec2(-330.0, -40.0));
        let run = TextRun {
            font: self.font,
            content: Content::Text(PARAGRAPH),
            size_px: 28.0,
            transform,
            color: [0.08, 0.08, 0.12, 1.0],
        };
        let mut encoder = self.device.create_command_encoder(&Default::default());
        self.text.prepare(&mut encoder, [w, h], &[run])?;
        let frame = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(frame) => frame,
            wgpu::CurrentSurfaceTexture::Suboptimal(frame) => {
                self.surface.configure(&self.device, &self.config);
                frame
            }
            // Outdated, lost, hidden or late: configure again and skip this frame.
            _ => {
                self.surface.configure(&self.device, &self.config);
                return Ok(());
            }
        };
        let view = frame.texture.create_view(&Default::default());
        let ops = wgpu::Operations {
            load: wgpu::LoadOp::Clear(wgpu::Color {
                r: 0.93,
                g: 0.9,
                b: 0.82,
                a: 1.0,
            }),
            store: wgpu::StoreOp::Store,
        };
        let attachment = wgpu::RenderPassColorAttachment {
            view: &view,
            depth_slice: None,
            resolve_target: None,
            ops,
        };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            color_attachments: &[Some(attachment)],
            ..Default::default()
        });
        self.text.render(&mut pass);
        drop(pass);
        self.queue.submit([encoder.finish()]);
        self.window.pre_present_notify();
        self.queue.present(frame);
        Ok(())
    }
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.drawing.is_none() {
            match Drawing::new(event_loop) {
                Ok(drawing) => self.drawing = Some(drawing),
                Err(e) => fail(e),
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        let Some(drawing) = &mut self.drawing else {
            return;
        };
        match event {
            WindowEvent::CloseRequested
            | WindowEvent::KeyboardInput {
                event:
                    KeyEvent {
                        logical_key: Key::Named(NamedKey::Escape),
                        state: ElementState::Pressed,
                        ..
                    },
                ..
            } => event_loop.exit(),
            WindowEvent::Resized(size) => {
                drawing.config.width = size.width.max(1);
                drawing.config.height = size.height.max(1);
                drawing.surface.configure(&drawing.device, &drawing.config);
            }
            WindowEvent::RedrawRequested => {
                let start = *self.start.get_or_insert_with(Instant::now);
                if let Err(e) = drawing.draw(start.elapsed().as_secs_f32()) {
                    fail(e)
                }
                // The mean frame time over about half a second, in the title.
                let (frames, since) = &mut self.frames;
                *frames += 1;
                let since = since.get_or_insert_with(Instant::now);
                if since.elapsed().as_secs_f32() >= 0.5 {
                    let ms = since.elapsed().as_secs_f64() * 1e3 / f64::from(*frames);
                    drawing
                        .window
                        .set_title(&format!("spinning text — {ms:.2} ms a frame"));
                    self.frames = (0, Some(Instant::now()));
                }
                drawing.window.request_redraw();
            }
            _ => {}
        }
    }
}

/// One line and exit 2: no display, no adapter, a surface that cannot be drawn on.
fn fail(e: impl std::fmt::Display) -> ! {
    eprintln!("spinning_text: {e}");
    std::process::exit(2);
}

fn main() {
    let event_loop =
        EventLoop::new().unwrap_or_else(|e| fail(format!("no display to open a window on: {e}")));
    if let Err(e) = event_loop.run_app(&mut App::default()) {
        fail(e)
    }
}
