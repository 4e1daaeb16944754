//! The classroom material of the default report: the explorer page (`explorer.html`), lecture
//! handouts of a scene of each model that names one (in English and Italian) and a worksheet of each model
//! with its answer key, written under `handouts/` and `worksheets/` beside the scene pages and
//! linked from the index with the speed and accuracy study (`bench/`, written by
//! `stickslip bench`). It composes the report, the handouts and the worksheets, so it sits
//! above all three (none of them imports it).

use std::path::Path;

use crate::error::Result;
use crate::lang::phrases::Translator;
use crate::models::{with_capability, Capability, Model};
use crate::present::Present;
use crate::report::{Format, Material, OutFile, Scene};
use crate::worksheet::{self, Lang, Request};

/// The built-in scenes with a handout, and what each teaches: each model's
/// [`Present::HANDOUT`], in the order of the registry.
fn handouts() -> Vec<(&'static str, &'static str)> {
    fn of<M: Present>(_: &M) -> Option<(&'static str, &'static str)> {
        M::HANDOUT
    }
    Model::offering(Capability::Present)
        .iter()
        .filter_map(|m| with_capability!(m, present, p => of(p), else None))
        .collect()
}
/// Students on each sample worksheet, and the seed of their draw.
const STUDENTS: u32 = 4;
const SEED: u64 = 1;

/// The files of the classroom material for the built-in `scenes` in `formats`, under their
/// folders, and the index's links to them.
pub fn material(scenes: &[Scene], formats: &[Format]) -> Result<(Vec<OutFile>, Vec<Material>)> {
    let mut files = Vec::new();
    let mut links = Vec::new();
    if formats.contains(&Format::Html) {
        files.push(crate::report::explorer::render(
            scenes,
            crate::report::explorer::Placement::InReport,
        )?);
        links.push(crate::report::explorer::material());
    }
    let (english, italian) = (Translator::new(Lang::En)?, Translator::new(Lang::It)?);
    for (id, what) in handouts() {
        let Some(scene) = scenes.iter().find(|s| s.id == id) else {
            continue;
        };
        files.extend(under(
            "handouts",
            crate::handout::render(scene, formats, None, &english)?,
        ));
        // The same handout in Italian, beside it.
        files.extend(under(
            "handouts/it",
            crate::handout::render(scene, formats, None, &italian)?,
        ));
        links.push(Material {
            html: format!("handouts/{id}.html"),
            md: format!("handouts/{id}.md"),
            title: format!("Handout: {}", scene.title),
            what: what.to_string(),
            key: None,
        });
        links.push(Material {
            html: format!("handouts/it/{id}.html"),
            md: format!("handouts/it/{id}.md"),
            title: format!("Dispensa: {}", italian.text(&scene.title)),
            what: "the same handout in Italian (words, figure labels, decimal commas)".to_string(),
            key: None,
        });
    }
    for model in Model::offering(Capability::Exercise) {
        let sheets = worksheet::generate(
            &Request {
                model,
                students: STUDENTS,
                seed: SEED,
                regime: None,
                questions: None,
            },
            &indicatif::ProgressBar::hidden(),
        )?;
        let folder = format!("worksheets/{}", model.id());
        files.extend(under(
            &folder,
            worksheet::render(&sheets, formats, Lang::En)?,
        ));
        let title = Lang::En
            .catalogue()?
            .text(&format!("{}.title", model.id()), &[])?;
        links.push(Material {
            html: format!("{folder}/worksheets.html"),
            md: format!("{folder}/worksheets.md"),
            title: format!("Worksheets: {title}"),
            what: format!(
                "{STUDENTS} students, each with their own parameters (seed {SEED}), and the \
                 answer key with every answer worked out"
            ),
            key: Some((
                format!("{folder}/answer-key.html"),
                format!("{folder}/answer-key.md"),
            )),
        });
    }
    links.push(Material {
        html: "bench/index.html".to_string(),
        md: "bench/bench.md".to_string(),
        title: "Speed and accuracy study".to_string(),
        what: "the exact engine against time-stepping integrators: work-precision charts and \
               where each method fails (written by `stickslip bench`)"
            .to_string(),
        key: None,
    });
    Ok((files, links))
}

/// `files` moved into `folder` (one or two levels below `reports/`), their links to the
/// physics guide (written for pages beside `reports/guide.html`) made relative to the new depth.
fn under(folder: &str, files: Vec<OutFile>) -> Vec<OutFile> {
    let up = "../".repeat(Path::new(folder).components().count());
    let stem = crate::report::guide::STEM;
    files
        .into_iter()
        .map(|f| {
            let bytes = match String::from_utf8(f.bytes) {
                Ok(text) => text
                    .replace(
                        &format!("href=\"{stem}.html"),
                        &format!("href=\"{up}{stem}.html"),
                    )
                    .replace(&format!("]({stem}.md"), &format!("]({up}{stem}.md"))
                    .into_bytes(),
                Err(e) => e.into_bytes(),
            };
            OutFile::new(Path::new(folder).join(&f.path), bytes)
        })
        .collect()
}
