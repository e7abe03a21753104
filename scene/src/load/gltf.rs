//! glTF 2.0.
use std::path::Path;
use super::{LoadError, LoadOptions, Location};
use crate::Scene;
pub(crate) fn parse(_bytes: &[u8], path: &Path, _opts: &LoadOptions) -> Result<Scene, LoadError> {
    Err(LoadError::Unsupported { at: Location::file(path), what: "glTF".into() })
}
