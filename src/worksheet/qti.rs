//! The worksheet as a QTI 1.2 package for Canvas (`worksheets.qti.zip`): Canvas imports QTI,
//! not Moodle XML (Settings > Import course content > QTI .zip file).
//!
//! The same questions as the Moodle bank ([`super::moodle`]): one question group per question
//! of the sheet, holding one item per student (that student's parameters and answer), of which
//! a quiz draws one; the teacher's answer key maps item to student.
//!
//! ```text
//! closed form, threshold, figure  →  numerical_question: the answer, or within ± one unit in
//!                                    its third significant figure (the figure: the reading
//!                                    tolerance), the worked step as general feedback
//! regime                          →  multiple_choice_question: the inequalities that decide it
//! ```
//!
//! The package (text2qti's layout, which Canvas reads):
//!
//! ```text
//! imsmanifest.xml                    IMS content package: the assessment and its images
//! <ident>/<ident>.xml                the assessment (questestinterop)
//! images/forces-<student>.svg        the figure of each student's figure question
//! ```
//!
//! Question texts are HTML with formulas as `\( … \)` (Canvas renders them with MathJax) and
//! every symbol defined in the question itself. The zip stores its entries uncompressed with
//! the zip epoch (1980-01-01) as their time and fixed permissions: the same sheets give the
//! same bytes.

use std::io::{Cursor, Write};

use base64::Engine;
use serde::Serialize;

use super::moodle::{self, answer_number, Category, FIGURE_FILE};
use super::render::Words;
use super::Worksheets;
use crate::error::{Error, Result};
use crate::lang::Lang;
use crate::report::render::{page, template_error};
use crate::report::OutFile;

const TEMPLATES: &[(&str, &str)] = &[
    ("qti.xml", include_str!("../../templates/qti.xml.tera")),
    (
        "imsmanifest.xml",
        include_str!("../../templates/imsmanifest.xml.tera"),
    ),
];

/// The file the package is written to.
pub const FILE: &str = "worksheets.qti.zip";

/// A question group (one question of the sheet).
#[derive(Serialize)]
struct Group {
    ident: String,
    title: String,
    numerical: bool,
    items: Vec<Item>,
}

/// One student's variant of a question.
#[derive(Serialize)]
struct Item {
    ident: String,
    title: String,
    html: String,
    feedback: String,
    /// Numerical: the answer and the interval answer ± tolerance.
    answer: String,
    low: String,
    high: String,
    /// Multiple choice: the options and the ident of the right one.
    choices: Vec<Choice>,
    right: String,
}

#[derive(Serialize)]
struct Choice {
    ident: String,
    html: String,
}

/// An image of the package: its manifest identifier and path in the zip.
#[derive(Serialize)]
struct Image {
    ident: String,
    path: String,
    #[serde(skip)]
    bytes: Vec<u8>,
}

fn package_error(reason: impl std::fmt::Display) -> Error {
    Error::Template {
        name: FILE.to_string(),
        reason: reason.to_string(),
    }
}

/// The groups of the assessment and the images its items show.
fn groups(categories: Vec<Category>, ident: &str) -> Result<(Vec<Group>, Vec<Image>)> {
    let mut images = Vec::new();
    let mut groups = Vec::new();
    for (g, category) in categories.into_iter().enumerate() {
        let group = format!("{ident}-g{}", g + 1);
        let title = category
            .path
            .rsplit('/')
            .next()
            .unwrap_or(&category.path)
            .to_string();
        let mut items = Vec::new();
        for v in category.variants {
            let item = format!("{group}-s{:03}", v.student);
            let mut html = v.html;
            if let Some((_, data)) = &v.file {
                let path = format!("images/forces-{:03}.svg", v.student);
                let bytes = base64::engine::general_purpose::STANDARD
                    .decode(data)
                    .map_err(package_error)?;
                // Canvas resolves the package's files under $IMS-CC-FILEBASE$ (escaped, as in
                // the question texts Canvas exports).
                html = html.replace(
                    &format!("@@PLUGINFILE@@/{FIGURE_FILE}"),
                    &format!("%24IMS-CC-FILEBASE%24/{path}"),
                );
                images.push(Image {
                    ident: format!("{item}-figure"),
                    path,
                    bytes,
                });
            }
            let (low, high) = match v.number {
                Some((x, tol)) => (answer_number(x - tol), answer_number(x + tol)),
                None => (String::new(), String::new()),
            };
            let choices: Vec<Choice> = v
                .choices
                .iter()
                .enumerate()
                .map(|(c, ch)| Choice {
                    ident: format!("{item}-c{}", c + 1),
                    html: ch.html.clone(),
                })
                .collect();
            let right = v
                .choices
                .iter()
                .zip(&choices)
                .find(|(ch, _)| ch.right)
                .map(|(_, c)| c.ident.clone())
                .unwrap_or_default();
            items.push(Item {
                ident: item,
                title: v.name,
                html,
                feedback: v.feedback,
                answer: v.answer,
                low,
                high,
                choices,
                right,
            });
        }
        groups.push(Group {
            ident: group,
            title,
            numerical: category.numerical,
            items,
        });
    }
    Ok((groups, images))
}

/// The zip: `entries` stored in order, each with the zip epoch as its time.
fn zip(entries: &[(&str, &[u8])]) -> Result<Vec<u8>> {
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Stored)
        .last_modified_time(zip::DateTime::DEFAULT)
        .unix_permissions(0o644);
    let mut writer = zip::ZipWriter::new(Cursor::new(Vec::new()));
    for (name, bytes) in entries {
        writer.start_file(*name, options).map_err(package_error)?;
        writer.write_all(bytes).map_err(package_error)?;
    }
    Ok(writer.finish().map_err(package_error)?.into_inner())
}

/// `worksheets.qti.zip` of the set, in the words of `lang` (answers keep `.`: QTI reads them so).
pub fn render(w: &Worksheets, lang: Lang) -> Result<OutFile> {
    let words = Words::new(lang, w.model)?;
    let title = format!("stickslip {} (seed {})", words.model_text("title")?, w.seed);
    let ident = format!("stickslip-{}-seed-{}", w.model.id(), w.seed);
    let (groups, images) = groups(moodle::categories(w, &words)?, &ident)?;
    let mut tera = tera::Tera::default();
    // XML escaping: tera's HTML escape writes entities XML reads (`&#x27;`, `&#x2F;` …).
    tera.autoescape_on(vec![".xml"]);
    tera.add_raw_templates(TEMPLATES.iter().copied())
        .map_err(|e| template_error("qti", &e))?;
    let assessment = format!("{ident}/{ident}.xml");
    let mut ctx = tera::Context::new();
    ctx.insert("ident", &ident);
    ctx.insert("title", &title);
    ctx.insert("groups", &groups);
    ctx.insert("assessment", &assessment);
    ctx.insert("images", &images);
    let manifest = page(&tera, "imsmanifest.xml", &ctx)?;
    let xml = page(&tera, "qti.xml", &ctx)?;
    let mut entries: Vec<(&str, &[u8])> = vec![
        ("imsmanifest.xml", manifest.as_bytes()),
        (&assessment, xml.as_bytes()),
    ];
    entries.extend(images.iter().map(|i| (i.path.as_str(), i.bytes.as_slice())));
    Ok(OutFile::new(FILE, zip(&entries)?))
}
