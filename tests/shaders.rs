//! Every shader of every method in the registry, exactly as it is compiled (common part
//! prepended), parses and validates with naga; every WGSL file in `shaders/` belongs to
//! a method, so none goes unchecked; and every cost heat map draws on the one shared
//! scale the app's legend reads.

use std::path::Path;

use glyphscope::methods::registry;

fn validate(name: &str, source: &str) -> Result<(), String> {
    let module = naga::front::wgsl::parse_str(source)
        .map_err(|e| e.emit_to_string_with_path(source, name))?;
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::default(),
    )
    .validate(&module)
    .map_err(|e| e.emit_to_string_with_path(source, name))?;
    Ok(())
}

fn shaders() -> impl Iterator<Item = glyphscope::gpu::shaders::Shader> {
    registry::METHODS.iter().filter_map(|m| m.shader)
}

#[test]
fn every_shader_parses_and_validates() {
    let failures: Vec<String> = shaders()
        .filter_map(|s| validate(s.file, &s.source()).err())
        .collect();
    assert!(
        failures.is_empty(),
        "{} shader(s) failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The examples of your own method (docs/your-method.md), each in the source it is
/// compiled as: the prelude, then the file.
#[test]
fn every_example_user_method_validates() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/methods");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).expect("examples/methods exists") {
        let path = entry.expect("entry").path();
        if path.extension().is_some_and(|e| e == "wgsl") {
            let text = std::fs::read_to_string(&path).unwrap();
            let source = glyphscope::text::winding::user_source(&text);
            validate(&path.display().to_string(), &source).unwrap();
            checked += 1;
        }
    }
    assert!(checked >= 3, "the examples: {checked} files");
}

#[test]
fn every_wgsl_file_belongs_to_a_method() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in [root.join("shaders"), root.join("crates/text/shaders")] {
        for entry in std::fs::read_dir(&dir).expect("shaders/ exists") {
            let name = entry
                .expect("entry")
                .file_name()
                .to_string_lossy()
                .into_owned();
            // A peer's shader belongs to no row in a build without that peer.
            let left_out = match name.as_str() {
                "peers.wgsl" => !cfg!(any(
                    feature = "glyphon",
                    feature = "vello",
                    feature = "vello-cpu"
                )),
                "msdf.wgsl" => !cfg!(feature = "msdf"),
                _ => false,
            };
            if name.ends_with(".wgsl") && name != "common.wgsl" && !left_out {
                assert!(
                    shaders().any(|s| s.files.contains(&name.as_str())),
                    "{}/{name} is no method's shader in the registry",
                    dir.display()
                );
            }
        }
    }
}

/// The legend labels the top of the heat scale with `COST_SCALE_CURVES`: a shader that
/// divided its cost by a scale of its own (as sdf-cells once did, by 32 under a "16+"
/// legend) would draw a different picture than the legend says.
#[test]
fn every_cost_heat_map_uses_the_shared_scale() {
    let mut drawing = 0;
    for shader in shaders() {
        assert!(
            !shader.body.contains("COST_SCALE:") && !shader.body.contains("heat_scale"),
            "{}: a cost scale of its own",
            shader.file
        );
        if shader.body.contains("/ COST_SCALE)") {
            drawing += 1;
        }
    }
    assert!(drawing >= 2, "winding and sdf-cells draw cost heat maps");
}
