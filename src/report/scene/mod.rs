//! Scenes: one per figure (or figure group) of the paper, each a scenario file plus what to
//! show. The built-in scenes are the default report; a user's scenario file becomes a scene
//! with the standard figures of its model.

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::models::{with_capability, Capability, Model};
use crate::params::{Scenario, DEFAULT_PERIODS};
pub use crate::present::vocab::{Builtin, Drawing, Figure, FigureKind, Part, PartStory, Scene};
use crate::present::Present;

pub mod sampling;

impl Scene {
    /// A user's scenario as a scene: its parameters, title and description, and what to draw.
    pub fn from_scenario(
        id: &str,
        scenario: &Scenario,
        path: &Path,
        caption: &str,
        figures: Vec<FigureKind>,
        claims: Vec<u8>,
    ) -> Result<Self> {
        let setup = scenario.model_params(path)?;
        setup.validate()?;
        Ok(Self {
            id: id.to_string(),
            title: scenario.title.clone(),
            part: Part::SCENARIOS,
            why: String::new(),
            caption: caption.to_string(),
            description: scenario.description.trim().to_string(),
            setup,
            periods: scenario.periods.unwrap_or(DEFAULT_PERIODS),
            figures,
            claims,
        })
    }

    /// A user's scenario file as a scene with the standard figures of its model.
    pub fn from_file(path: &Path) -> Result<Self> {
        let scenario = Scenario::load(path)?;
        let id = path
            .file_stem()
            .map(|s| page_name(&s.to_string_lossy()))
            .filter(|s| !s.is_empty())
            .ok_or_else(|| Error::Scenario {
                path: path.display().to_string(),
                reason: "the file name gives no scene name".to_string(),
            })?;
        let model = scenario.model;
        let standard = with_capability!(&model, present, p => p.standard_scene(),
            else return Err(model.missing(Capability::Present)));
        let (figures, claims, caption) = (standard.figures, standard.claims, standard.caption);
        Self::from_scenario(&id, &scenario, path, caption, figures, claims)
    }

    /// Scenes from the user's scenario files, refused when two would write the same pages (their
    /// file stems equal, ignoring case as some file systems do) or when one would write a page of
    /// the report itself ([`RESERVED_PAGES`]).
    pub fn from_files(paths: &[PathBuf]) -> Result<Vec<Self>> {
        let mut scenes: Vec<Self> = Vec::with_capacity(paths.len());
        for path in paths {
            let scene = Self::from_file(path)?;
            let key = scene.id.to_lowercase();
            let clash = |reason: String| Error::Scenario {
                path: path.display().to_string(),
                reason,
            };
            if RESERVED_PAGES.contains(&key.as_str()) {
                return Err(clash(format!(
                    "its pages {0}.html and {0}.md would replace the report's own: rename the file",
                    scene.id
                )));
            }
            if let Some(j) = scenes.iter().position(|s| s.id.to_lowercase() == key) {
                return Err(clash(format!(
                    "would write the same pages ({}.html, {}.md) as {}: rename one of the files",
                    scene.id,
                    scene.id,
                    paths[j].display()
                )));
            }
            scenes.push(scene);
        }
        Ok(scenes)
    }

    /// The figures of the scene, built from its parameters.
    pub fn build_figures(&self) -> Result<Vec<Figure>> {
        let mut out = Vec::new();
        for kind in &self.figures {
            let built = with_capability!(&self.setup, present, p => p.figures_of(&self.id, *kind)?,
                else return Err(self.setup.missing(Capability::Present)));
            out.extend(built);
        }
        Ok(out)
    }
}

/// The page name of a scenario file's stem: letters, digits, `-`, `_` and `.` kept, any other
/// character (space, `|`, `<`, `#`, `%`, a control character…) as `-`, so that the name is
/// safe in a file name, a URL and a Markdown link.
pub fn page_name(stem: &str) -> String {
    stem.chars()
        .map(|c| {
            if c.is_alphanumeric() || matches!(c, '-' | '_' | '.') {
                c
            } else {
                '-'
            }
        })
        .collect()
}

/// Page names of the report itself, which no scene may take (compared in lower case).
pub const RESERVED_PAGES: &[&str] = &["index", "all-scenes"];

/// The parts of the reading path: each model that offers a presentation, numbered in the
/// order of the registry, then the user's scenarios ([`Part::SCENARIOS`]).
pub fn parts() -> Vec<(Model, Part)> {
    fn story<M: Present>(_: &M) -> PartStory {
        M::PART
    }
    let story_of = |model: &Model| with_capability!(model, present, p => Some(story(p)), else None);
    Model::offering(Capability::Present)
        .into_iter()
        .filter_map(|model| Some((model, story_of(&model)?)))
        .enumerate()
        .map(|(i, (model, story))| {
            let number = Some(i + 1);
            (model, Part { number, story })
        })
        .collect()
}

/// The built-in scenes of the default report, in order: each model's
/// ([`Present::builtin_scenes`]) in the order of the registry.
pub fn builtin_scenes() -> Result<Vec<Scene>> {
    fn of<M: Present>(_: &M) -> Vec<Builtin> {
        M::builtin_scenes()
    }
    let mut scenes = Vec::new();
    for (model, part) in parts() {
        let builtins = with_capability!(&model, present, p => of(p), else Vec::new());
        for b in builtins {
            let path = Path::new("scenarios").join(b.file);
            let scenario = Scenario::parse(b.text, &path)?;
            let scene = Scene::from_scenario(
                b.id,
                &scenario,
                &path,
                b.caption,
                b.figures,
                b.claims.to_vec(),
            )?;
            scenes.push(Scene {
                title: b.title.to_string(),
                part,
                why: b.why.to_string(),
                ..scene
            });
        }
    }
    Ok(scenes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_scenes_parse_and_have_unique_ids() {
        let scenes = builtin_scenes().unwrap();
        let mut ids: Vec<_> = scenes.iter().map(|s| s.id.clone()).collect();
        ids.sort();
        ids.dedup();
        assert_eq!(ids.len(), scenes.len());
        assert!(scenes.iter().all(|s| !s.figures.is_empty()));
        assert!(ids.iter().all(|id| !RESERVED_PAGES.contains(&id.as_str())));
    }

    /// Eight pages were once all titled after Fig. 15: a title names what its page shows.
    #[test]
    fn builtin_titles_are_unique_and_every_scene_says_why_it_matters() {
        let scenes = builtin_scenes().unwrap();
        let mut titles: Vec<_> = scenes.iter().map(|s| s.title.to_lowercase()).collect();
        titles.sort();
        titles.dedup();
        assert_eq!(titles.len(), scenes.len());
        for s in &scenes {
            assert!(s.why.ends_with('.') && s.why.len() > 40, "{}", s.id);
            assert_ne!(s.part, Part::SCENARIOS, "{}", s.id);
            let (model, _) = parts().into_iter().find(|(_, p)| *p == s.part).unwrap();
            assert_eq!(s.setup.id(), model.id(), "{}", s.id);
        }
    }
}
