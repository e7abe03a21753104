//! What a render draws: a mesh or scene file, or a scene built in memory, loaded with
//! its warnings reported and refused when it has nothing to draw.

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use limn_load::{load_scene_file, LoadOptions, SceneOptions};
use limn_scene::Scene;

use crate::error::Error;
use crate::events::Events;
use crate::options::ViewOptions;

/// The input of a render or a check.
// One is made per render: its size does not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub enum Input<'a> {
    /// A mesh file (OBJ, STL, PLY, glTF, GLB) or a TOML scene file.
    File(PathBuf),
    /// A scene built in memory, with the settings a scene file would give.
    Scene {
        /// The scene (borrowed, or owned).
        scene: Cow<'a, Scene>,
        /// Settings a scene file would give (all unset for none).
        settings: SceneOptions,
        /// Its name in messages.
        name: String,
    },
}

impl Input<'_> {
    /// The input's name in messages.
    pub fn name(&self) -> String {
        match self {
            Input::File(p) => p.display().to_string(),
            Input::Scene { name, .. } => name.clone(),
        }
    }

    /// The input file, if it is one.
    pub fn path(&self) -> Option<&Path> {
        match self {
            Input::File(p) => Some(p),
            Input::Scene { .. } => None,
        }
    }
}

/// A loaded input.
#[derive(Debug)]
pub struct Loaded<'a> {
    /// The scene.
    pub scene: Cow<'a, Scene>,
    /// The settings of its scene file (all unset for mesh files).
    pub settings: SceneOptions,
    /// Its name in messages.
    pub name: String,
}

/// Loads `input` (files with the view's `allow_outside`), applies the view's shading,
/// reports the scene's warnings to `events`, and refuses a scene with nothing to draw.
pub fn load<'a>(
    input: &Input<'a>,
    view: &ViewOptions,
    events: &mut dyn Events,
) -> Result<Loaded<'a>, Error> {
    let mut loaded = match input {
        Input::File(path) => {
            let opts = LoadOptions {
                allow_outside: view.allow_outside,
            };
            let is_toml = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("toml"));
            let (scene, settings) = if is_toml {
                load_scene_file(path, &opts).map_err(Error::load)?
            } else {
                let scene = limn_load::load(path, &opts).map_err(Error::load)?;
                (scene, SceneOptions::default())
            };
            Loaded {
                scene: Cow::Owned(scene),
                settings,
                name: input.name(),
            }
        }
        Input::Scene {
            scene,
            settings,
            name,
        } => {
            scene.validate().map_err(|source| Error::Scene {
                input: name.clone(),
                source,
            })?;
            Loaded {
                scene: scene.clone(),
                settings: settings.clone(),
                name: name.clone(),
            }
        }
    };
    if let Some(s) = view.shading {
        if loaded.scene.shading != Some(s) {
            loaded.scene.to_mut().shading = Some(s);
        }
    }
    for w in &loaded.scene.warnings {
        events.warning(w);
    }
    let s = &loaded.scene;
    if s.faces.is_empty() && s.lines.is_empty() && s.points.is_empty() && s.labels.is_empty() {
        let what = if s.vertices.is_empty() {
            "no faces, lines, points or labels"
        } else {
            "vertices but no faces, lines, points or labels"
        };
        return Err(Error::Empty {
            input: loaded.name,
            what,
        });
    }
    Ok(loaded)
}
