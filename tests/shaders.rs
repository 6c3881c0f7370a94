//! Every method shader, exactly as it is compiled (common part prepended), parses and
//! validates with naga; and every WGSL file in `shaders/` is one of them, so none goes
//! unchecked.

use std::path::Path;

use glyphscope::gpu::shaders::{METHOD_SHADERS, source};

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

#[test]
fn every_shader_parses_and_validates() {
    let failures: Vec<String> = METHOD_SHADERS
        .iter()
        .filter_map(|(name, _)| validate(name, &source(name)).err())
        .collect();
    assert!(
        failures.is_empty(),
        "{} shader(s) failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn every_wgsl_file_is_compiled_somewhere() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    for entry in std::fs::read_dir(&dir).expect("shaders/ exists") {
        let name = entry
            .expect("entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        if name.ends_with(".wgsl") && name != "common.wgsl" {
            assert!(
                METHOD_SHADERS.iter().any(|(n, _)| *n == name),
                "shaders/{name} is not in gpu::shaders::METHOD_SHADERS"
            );
        }
    }
}
