//! The explorer without a window: frames run on an egui context and are drawn by
//! egui_wgpu into an offscreen texture, paint callbacks and all, then read back. It is
//! what `glyphscope screenshots` photographs and what the frame-time measurement times.

use std::iter;
use web_time::Instant;

use eframe::egui;
use egui_wgpu::wgpu;

use super::explorer::Explorer;
use super::settings::Settings;
use crate::Error;
use crate::gpu::GpuContext;

pub struct Headless {
    ctx: egui::Context,
    render_state: egui_wgpu::RenderState,
    width: u32,
    height: u32,
    started: Instant,
}

impl Headless {
    /// A `width`×`height`-pixel screen at one pixel per point, on the device the app asks for.
    pub fn new(width: u32, height: u32) -> Result<Headless, Error> {
        let setup = super::wgpu_setup();
        let instance = pollster::block_on(setup.new_instance());
        let render_state = pollster::block_on(egui_wgpu::RenderState::create(
            &egui_wgpu::WgpuConfiguration {
                wgpu_setup: setup,
                ..Default::default()
            },
            &instance,
            None,
            egui_wgpu::RendererOptions::PREDICTABLE,
        ))
        .map_err(|e| {
            Error::Gpu(format!(
                "no GPU for the explorer ({e}); on Debian install mesa-vulkan-drivers"
            ))
        })?;
        let ctx = egui::Context::default();
        ctx.set_pixels_per_point(1.0);
        Ok(Headless {
            ctx,
            render_state,
            width,
            height,
            started: Instant::now(),
        })
    }

    /// The explorer with `settings`, on this screen's device.
    pub fn explorer(&self, settings: Settings) -> Explorer {
        Explorer::with_render_state(&self.ctx, Some(&self.render_state), settings)
    }

    pub fn context(&self) -> &egui::Context {
        &self.ctx
    }

    /// The device, as the methods see it.
    pub fn gpu(&self) -> GpuContext {
        let rs = &self.render_state;
        GpuContext::from_device(
            rs.instance.clone(),
            rs.adapter.clone(),
            rs.device.clone(),
            rs.queue.clone(),
        )
    }

    /// Runs and draws one frame, waiting for the GPU to finish it.
    pub fn frame(&mut self, app: &mut Explorer) -> Result<(), Error> {
        self.draw(app, false).map(drop)
    }

    /// Runs and draws one frame and returns its pixels.
    pub fn screenshot(&mut self, app: &mut Explorer) -> Result<image::RgbaImage, Error> {
        self.draw(app, true)
            .map(|image| image.expect("asked for pixels"))
    }

    fn draw(&mut self, app: &mut Explorer, read: bool) -> Result<Option<image::RgbaImage>, Error> {
        let size = egui::vec2(self.width as f32, self.height as f32);
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(egui::Pos2::ZERO, size)),
            time: Some(self.started.elapsed().as_secs_f64()),
            ..Default::default()
        };
        let output = self.ctx.run_ui(input, |ui| app.show(ui));
        let rs = &self.render_state;
        let (device, queue) = (&rs.device, &rs.queue);
        let mut renderer = rs.renderer.write();
        for (id, deltas) in &output.textures_delta.set {
            for delta in deltas {
                renderer.update_texture(device, queue, *id, delta);
            }
        }
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [self.width, self.height],
            pixels_per_point: 1.0,
        };
        let primitives = self.ctx.tessellate(output.shapes, 1.0);
        let mut encoder = device.create_command_encoder(&Default::default());
        let callbacks = renderer.update_buffers(device, queue, &mut encoder, &primitives, &screen);
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("headless screen"),
            size: wgpu::Extent3d {
                width: self.width,
                height: self.height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: rs.target_format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = texture.create_view(&Default::default());
        {
            let mut pass = encoder
                .begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("egui"),
                    color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                        view: &view,
                        depth_slice: None,
                        resolve_target: None,
                        ops: wgpu::Operations {
                            load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                            store: wgpu::StoreOp::Store,
                        },
                    })],
                    ..Default::default()
                })
                .forget_lifetime();
            renderer.render(&mut pass, &primitives, &screen);
        }
        queue.submit(callbacks.into_iter().chain(iter::once(encoder.finish())));
        for id in &output.textures_delta.free {
            renderer.free_texture(id);
        }
        drop(renderer);
        let gpu = self.gpu();
        if !read {
            return gpu.wait_idle().map(|()| None);
        }
        let bytes = read_rgba8(&gpu, &texture)?;
        let mut image =
            image::RgbaImage::from_raw(self.width, self.height, bytes).expect("size matches");
        if matches!(
            rs.target_format,
            wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
        ) {
            for p in image.pixels_mut() {
                p.0.swap(0, 2);
            }
        }
        Ok(Some(image))
    }
}

/// The pixels of a 4-byte-per-texel texture, rows unpadded.
fn read_rgba8(gpu: &GpuContext, texture: &wgpu::Texture) -> Result<Vec<u8>, Error> {
    let (width, height) = (texture.width(), texture.height());
    let row = width * 4;
    // Buffer rows of a texture copy start on 256-byte boundaries.
    let padded = row.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("screen readback"),
        size: u64::from(padded) * u64::from(height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    encoder.copy_texture_to_buffer(
        texture.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded),
                rows_per_image: None,
            },
        },
        texture.size(),
    );
    gpu.queue.submit([encoder.finish()]);
    let bytes = gpu.read_buffer(&buffer)?;
    Ok(bytes
        .chunks_exact(padded as usize)
        .flat_map(|r| &r[..row as usize])
        .copied()
        .collect())
}
