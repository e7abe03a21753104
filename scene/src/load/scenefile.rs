//! Scene files.
use std::path::Path;
use super::{LoadError, LoadOptions, Location};
use crate::Scene;
/// Output options of a scene file.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SceneOptions {}
/// Loads a scene file.
pub fn load_scene_file(path: &Path, opts: &LoadOptions) -> Result<(Scene, SceneOptions), LoadError> {
    let b = super::refs::read(path)?;
    parse(&b, path, opts)
}
pub(crate) fn parse(_bytes: &[u8], path: &Path, _opts: &LoadOptions) -> Result<(Scene, SceneOptions), LoadError> {
    Err(LoadError::Unsupported { at: Location::file(path), what: "toml".into() })
}
