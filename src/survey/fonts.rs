//! The fonts a survey reads: the files named and those found in the folders named, in
//! one sorted list (the unit a shard takes and a resumed run skips), and each file's
//! faces at the instances asked for.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use crate::Error;
use crate::font::Font;

/// The file names a folder's fonts are found by (any case).
const EXTENSIONS: [&str; 4] = ["ttf", "otf", "ttc", "otc"];

/// Every font file under `paths` (a file as named, whatever its extension; a folder's
/// files with a font extension, in its subfolders too), sorted and each once. A path
/// that does not exist, or a list with no font at all, is an input error.
pub fn files(paths: &[PathBuf]) -> Result<Vec<PathBuf>, Error> {
    let mut found = Vec::new();
    for path in paths {
        let meta = std::fs::metadata(path)
            .map_err(|e| Error::Input(format!("--fonts: cannot read '{}': {e}", path.display())))?;
        if meta.is_dir() {
            walk(path, &mut found, &mut HashSet::new())?;
        } else {
            found.push(path.clone());
        }
    }
    found.sort();
    found.dedup();
    if found.is_empty() {
        return Err(Error::Input(format!(
            "--fonts: no font files ({}) under {}",
            EXTENSIONS.map(|e| format!(".{e}")).join(", "),
            paths
                .iter()
                .map(|p| format!("'{}'", p.display()))
                .collect::<Vec<_>>()
                .join(", ")
        )));
    }
    Ok(found)
}

/// The font files under `dir`, each folder visited once by its real path: a link back
/// to a folder above (or to any folder already walked) is not followed again.
fn walk(dir: &Path, found: &mut Vec<PathBuf>, visited: &mut HashSet<PathBuf>) -> Result<(), Error> {
    let real = std::fs::canonicalize(dir)
        .map_err(|e| Error::Input(format!("--fonts: cannot resolve '{}': {e}", dir.display())))?;
    if !visited.insert(real) {
        return Ok(());
    }
    let entries = std::fs::read_dir(dir)
        .map_err(|e| Error::Input(format!("--fonts: cannot list '{}': {e}", dir.display())))?;
    for entry in entries {
        let path = entry
            .map_err(|e| Error::Input(format!("--fonts: cannot list '{}': {e}", dir.display())))?
            .path();
        if path.is_dir() {
            walk(&path, found, visited)?;
        } else if path
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()))
        {
            found.push(path);
        }
    }
    Ok(())
}

/// The files shard `index` of `count` takes: those whose place in the sorted list is
/// `index` mod `count`.
pub fn shard(files: Vec<PathBuf>, index: usize, count: usize) -> Vec<PathBuf> {
    files
        .into_iter()
        .enumerate()
        .filter(|(place, _)| place % count == index)
        .map(|(_, file)| file)
        .collect()
}

/// One face of a file at one instance, or why it cannot be read.
pub struct Face {
    /// Which face of a collection (0 for a single font).
    pub index: u32,
    /// The axis values set (empty: the default instance).
    pub instance: Vec<(String, f32)>,
    pub font: Result<Font, String>,
}

impl Face {
    /// `face N` and the instance's `TAG=VALUE`s, as the report names it (empty for the
    /// first face of a single font at its default).
    pub fn label(&self, collection: bool) -> String {
        let mut parts = Vec::new();
        if collection {
            parts.push(format!("face {}", self.index));
        }
        parts.extend(self.instance.iter().map(|(tag, v)| format!("{tag}={v}")));
        parts.join(" ")
    }
}

/// Every face of `file` (each of a collection's), each at its default instance and, for
/// a variable font, at each of `instances` whose axes it has (an instance naming an
/// axis the face lacks is not its instance and is left out; a value outside an axis's
/// range is a face that cannot be read, with the reason). A file that is no font is
/// one face with the reason. Also returns whether the file is a collection.
pub fn faces(file: &Path, instances: &[Vec<(String, f32)>]) -> (Vec<Face>, bool) {
    let name = file.display().to_string();
    let unreadable = |why: String| {
        vec![Face {
            index: 0,
            instance: Vec::new(),
            font: Err(why),
        }]
    };
    let data = match std::fs::read(file) {
        Ok(data) => data,
        Err(e) => return (unreadable(format!("cannot read '{name}': {e}")), false),
    };
    let count = Font::face_count(&data);
    if count == 0 {
        return (
            unreadable(format!("'{name}' is not a font ttf-parser can read")),
            false,
        );
    }
    let collection = ttf_parser::fonts_in_collection(&data).is_some();
    let mut faces = Vec::new();
    for index in 0..count {
        let font = Font::from_bytes_face(data.clone(), &name, index).map_err(|e| e.to_string());
        let axes: Vec<String> = font
            .as_ref()
            .map(|f| f.axes().into_iter().map(|a| a.tag).collect())
            .unwrap_or_default();
        let at_instances: Vec<Face> = instances
            .iter()
            .filter(|instance| {
                instance
                    .iter()
                    .all(|(tag, _)| crate::font::axis_tag(tag).is_ok_and(|tag| axes.contains(&tag)))
            })
            .filter_map(|instance| {
                let base = font.as_ref().ok()?;
                Some(Face {
                    index,
                    instance: instance.clone(),
                    font: base.with_variations(instance).map_err(|e| e.to_string()),
                })
            })
            .collect();
        faces.push(Face {
            index,
            instance: Vec::new(),
            font,
        });
        faces.extend(at_instances);
    }
    (faces, collection)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A folder holding a font, a link back to itself from a subfolder (a loop) and a
    /// link to nowhere with a font's name: the walk ends, the font is listed once, and
    /// the broken link is listed for its row to say why it cannot be read.
    #[cfg(unix)]
    #[test]
    fn a_link_to_a_parent_folder_is_walked_once() {
        let root = std::env::temp_dir().join(format!("glyphscope-loop-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(root.join("sub")).unwrap();
        std::fs::write(root.join("a.ttf"), crate::font::DEFAULT_FONT_BYTES).unwrap();
        std::os::unix::fs::symlink(&root, root.join("sub").join("up")).unwrap();
        std::os::unix::fs::symlink(root.join("missing.ttf"), root.join("gone.ttf")).unwrap();
        let listed = files(std::slice::from_ref(&root));
        let _ = std::fs::remove_dir_all(&root);
        let listed = listed.unwrap();
        let names: Vec<_> = listed
            .iter()
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(names, ["a.ttf", "gone.ttf"], "{listed:?}");
    }

    #[test]
    fn shards_split_the_sorted_list_by_place_and_cover_it_once() {
        let files: Vec<PathBuf> = (0..7).map(|i| PathBuf::from(format!("f{i}"))).collect();
        let shards: Vec<Vec<PathBuf>> = (0..3).map(|i| shard(files.clone(), i, 3)).collect();
        assert_eq!(shards[0], [PathBuf::from("f0"), "f3".into(), "f6".into()]);
        assert_eq!(shards[2], [PathBuf::from("f2"), "f5".into()]);
        let mut all: Vec<PathBuf> = shards.concat();
        all.sort();
        assert_eq!(all, files);
    }

    #[test]
    fn a_variable_font_is_surveyed_at_its_default_and_at_the_instances_it_has() {
        let (faces, collection) = faces(
            Path::new("fonts/Inter-roman.var.ttf"),
            &[vec![("wght".into(), 700.0)], vec![("XXXX".into(), 1.0)]],
        );
        assert!(!collection);
        assert_eq!(
            faces.len(),
            2,
            "the default and wght=700; XXXX is not its axis"
        );
        assert!(faces[0].instance.is_empty());
        assert_eq!(faces[1].label(false), "wght=700");
        let (faces, _) = faces_of_static();
        assert_eq!(faces.len(), 1);
        assert!(faces[0].font.is_ok());
    }

    fn faces_of_static() -> (Vec<Face>, bool) {
        faces(
            Path::new("fonts/DejaVuSans.ttf"),
            &[vec![("wght".into(), 700.0)]],
        )
    }

    #[test]
    fn a_file_that_is_no_font_is_one_face_with_its_reason() {
        let dir = std::env::temp_dir().join(format!("glyphscope-fonts-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("broken.ttf");
        std::fs::write(&path, b"not a font at all").unwrap();
        let (faces, _) = faces(&path, &[]);
        assert_eq!(faces.len(), 1);
        let why = faces[0].font.as_ref().err().unwrap();
        assert!(why.contains("broken.ttf"), "{why}");
        assert_eq!(files(std::slice::from_ref(&dir)).unwrap(), [path]);
        std::fs::remove_dir_all(&dir).unwrap();
        let err = files(&[PathBuf::from("no/such/folder")]).unwrap_err();
        assert!(err.to_string().contains("no/such/folder"), "{err}");
    }
}
