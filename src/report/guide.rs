//! The physics guide as a page of the report. Its sources are `docs/physics.md` (sections
//! "## 7. Title", "### 7.5 Title") and `docs/belt.md` (the third model, one level deeper in its
//! file, appended as section 16); `report` writes them as `guide.html` (MathML, a table of
//! contents, an id on every section) and `guide.md` (GitHub: TeX kept, `<a id>` anchors) beside
//! the scene pages, so that the pages' links work from a copy of the folder, offline.
//!
//! ```text
//! docs/physics.md + docs/belt.md → sections (number, title, anchor)
//!     → guide.html (pulldown-cmark events: ids, MathML, citations linked) and guide.md
//! ```
//!
//! Code, terminal and pages cite a section as "guide §7.5" ([`PREFIX`]); [`cite`] finds its
//! anchor, and tests/guide.rs fails on a citation of a section the guide does not have.

use std::sync::OnceLock;

use pulldown_cmark::{CowStr, Event, HeadingLevel, Options, Parser, Tag, TagEnd};
use serde::Serialize;

use super::math::{escape, mathml, mathml_block};
use super::render::{page, templates, CSS};
use super::writer::OutFile;
use super::Format;
use crate::error::Result;

const PHYSICS: &str = include_str!("../../docs/physics.md");
const BELT: &str = include_str!("../../docs/belt.md");
const GUIDE_CSS: &str = include_str!("../../templates/guide.css");
const TEMPLATE: (&str, &str) = (
    "guide.html",
    include_str!("../../templates/guide.html.tera"),
);
/// LaTeX longer than this (characters) may render wider than a 390-px phone's column.
const LONG_TEX: usize = 40;
/// How code and output cite a section: "guide §7.5".
pub const PREFIX: &str = "guide §";
/// The page's file name in `reports/` without its extension (`guide.html`, `guide.md`).
pub const STEM: &str = "guide";

/// A numbered section of the guide.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Section {
    /// "7" or "7.5".
    pub number: String,
    /// The title without its number: "Late stick".
    pub title: String,
    /// The heading's id on both pages: the title in lower case with hyphens, "late-stick".
    pub anchor: String,
    /// 2 for a section, 3 for a subsection.
    pub level: usize,
}

/// Both sources as one Markdown document: the belt's headings one level deeper.
fn source() -> &'static str {
    static SOURCE: OnceLock<String> = OnceLock::new();
    SOURCE.get_or_init(|| {
        let mut text = PHYSICS.trim_end().to_string();
        text.push_str("\n\n");
        let mut fenced = false;
        for line in BELT.lines() {
            fenced ^= line.starts_with("```");
            if !fenced && line.starts_with('#') {
                text.push('#');
            }
            text.push_str(line);
            text.push('\n');
        }
        text
    })
}

/// The headings of the source outside code blocks: (level, text), the title (level 1) included.
fn headings(source: &str) -> Vec<(usize, &str)> {
    let mut fenced = false;
    source
        .lines()
        .filter(|line| {
            fenced ^= line.starts_with("```");
            !fenced && line.starts_with('#')
        })
        .filter_map(|line| {
            let level = line.chars().take_while(|&c| c == '#').count();
            line[level..].strip_prefix(' ').map(|text| (level, text))
        })
        .collect()
}

/// The anchor GitHub would give a heading `title`: lower case, spaces as hyphens, letters,
/// digits, `-` and `_` kept, everything else dropped.
pub fn slug(title: &str) -> String {
    title
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// "7.5 Late stick" or "7. Closed forms" → ("7.5", "Late stick"); None without a number.
fn numbered(text: &str) -> Option<(&str, &str)> {
    let (number, title) = text.split_once(' ')?;
    let number = number.strip_suffix('.').unwrap_or(number);
    let ok = !number.is_empty()
        && number
            .split('.')
            .all(|p| !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()));
    ok.then_some((number, title))
}

/// Every section and subsection of the guide, in order. Anchors repeat nowhere: a title
/// already used gets "-1", "-2" … as on GitHub.
pub fn sections() -> &'static [Section] {
    static SECTIONS: OnceLock<Vec<Section>> = OnceLock::new();
    SECTIONS.get_or_init(|| {
        let mut out: Vec<Section> = Vec::new();
        for (level, text) in headings(source()).into_iter().filter(|(l, _)| *l > 1) {
            let (number, title) = numbered(text).unwrap_or(("", text));
            let base = slug(title);
            let mut anchor = base.clone();
            let mut n = 0;
            while out.iter().any(|s| s.anchor == anchor) {
                n += 1;
                anchor = format!("{base}-{n}");
            }
            out.push(Section {
                number: number.to_string(),
                title: title.to_string(),
                anchor,
                level,
            });
        }
        out
    })
}

/// The section a citation "guide §7.5" names: its number ("7.5") and anchor; None when
/// `citation` is not a citation of the guide or names no section.
pub fn cite(citation: &str) -> Option<(&str, &'static str)> {
    let number = citation.trim().strip_prefix(PREFIX)?;
    let section = sections().iter().find(|s| s.number == number)?;
    Some((number, section.anchor.as_str()))
}

/// `text` with each "guide §n" that names a section made a link by `link(citation, anchor)`.
fn link_citations(text: &str, link: impl Fn(&str, &str) -> String) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(PREFIX) {
        let digits = rest[at + PREFIX.len()..]
            .find(|c: char| !(c.is_ascii_digit() || c == '.'))
            .map_or(rest.len(), |i| at + PREFIX.len() + i);
        // A sentence's full stop is not part of the number.
        let end = if rest[..digits].ends_with('.') {
            digits - 1
        } else {
            digits
        };
        out.push_str(&rest[..at]);
        match cite(&rest[at..end]) {
            Some((_, anchor)) => out.push_str(&link(&rest[at..end], anchor)),
            None => out.push_str(&rest[at..end]),
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

/// The body of guide.html: the title's introduction, the contents, then every section with
/// its id, formulas as MathML, tables and text blocks in boxes that scroll on a phone.
fn html_body() -> String {
    let sections = sections();
    let mut next = sections.iter();
    let mut current = "";
    let mut toc_done = false;
    let mut in_link = false;
    let mut events: Vec<Event> = Vec::new();
    let parser = Parser::new_ext(source(), Options::ENABLE_TABLES | Options::ENABLE_MATH);
    for event in pulldown_cmark::TextMergeStream::new(parser) {
        match event {
            Event::Start(Tag::Heading {
                level,
                classes,
                attrs,
                ..
            }) if level != HeadingLevel::H1 => {
                if !toc_done {
                    events.push(Event::Html(CowStr::from(contents_html())));
                    toc_done = true;
                }
                let section = next.next();
                current = section.map_or("", |s| s.title.as_str());
                events.push(Event::Start(Tag::Heading {
                    level,
                    id: section.map(|s| CowStr::from(s.anchor.as_str())),
                    classes,
                    attrs,
                }));
            }
            // A long formula can be wider than a phone: it scrolls in its own box, which a
            // keyboard can reach (a short one wraps to the next line as a whole).
            Event::InlineMath(tex) if tex.len() > LONG_TEX => {
                events.push(Event::InlineHtml(CowStr::from(format!(
                    "<span class=\"formula\" tabindex=\"0\">{}</span>",
                    mathml(&tex)
                ))))
            }
            Event::InlineMath(tex) => events.push(Event::InlineHtml(CowStr::from(mathml(&tex)))),
            Event::DisplayMath(tex) => events.push(Event::InlineHtml(CowStr::from(format!(
                "<span class=\"display\" tabindex=\"0\">{}</span>",
                mathml_block(&tex)
            )))),
            Event::Start(Tag::Table(_)) => {
                events.push(Event::Html(CowStr::from(format!(
                    "<div class=\"wide\" tabindex=\"0\" role=\"region\" aria-label=\"{}: table\">",
                    escape(current)
                ))));
                events.push(event);
            }
            Event::End(TagEnd::Table) => {
                events.push(event);
                events.push(Event::Html(CowStr::from("</div>\n")));
            }
            Event::Start(Tag::Link { .. }) => {
                in_link = true;
                events.push(event);
            }
            Event::End(TagEnd::Link) => {
                in_link = false;
                events.push(event);
            }
            Event::Text(text) if !in_link && text.contains(PREFIX) => {
                let linked =
                    link_citations(&escape(&text), |c, a| format!("<a href=\"#{a}\">{c}</a>"));
                events.push(Event::InlineHtml(CowStr::from(linked)));
            }
            other => events.push(other),
        }
    }
    let mut html = String::new();
    pulldown_cmark::html::push_html(&mut html, events.into_iter());
    html
}

/// The table of contents: every section and subsection, linked to its id.
fn contents_html() -> String {
    let mut html = String::from(
        "<nav class=\"toc\" aria-labelledby=\"contents\"><h2 id=\"contents\">Contents</h2>\n<ol>",
    );
    let sections = sections();
    for (i, s) in sections.iter().enumerate() {
        html.push_str(&format!(
            "<li><a href=\"#{}\">{} {}</a>",
            escape(&s.anchor),
            escape(&s.number),
            escape(&s.title)
        ));
        match sections.get(i + 1).map(|n| n.level) {
            Some(l) if l > s.level => html.push_str("<ol>"),
            Some(l) if l < s.level => html.push_str("</li></ol></li>"),
            Some(_) => html.push_str("</li>"),
            None if s.level > 2 => html.push_str("</li></ol></li>"),
            None => html.push_str("</li>"),
        }
        html.push('\n');
    }
    html.push_str("</ol></nav>\n");
    html
}

/// guide.md: the sources with an `<a id>` in every heading (GitHub keeps it as the heading's
/// anchor), a table of contents before the first section and each "guide §n" linked.
fn markdown() -> String {
    let sections = sections();
    let mut next = sections.iter();
    let mut out = String::new();
    let mut fenced = false;
    let mut toc_done = false;
    for line in source().lines() {
        fenced ^= line.starts_with("```");
        let level = line.chars().take_while(|&c| c == '#').count();
        if !fenced && level > 1 && line[level..].starts_with(' ') {
            if !toc_done {
                out.push_str("## Contents\n\n");
                for s in sections {
                    let indent = "  ".repeat(s.level - 2);
                    let number = &s.number;
                    out.push_str(&format!(
                        "{indent}- [{number} {}](#{})\n",
                        s.title, s.anchor
                    ));
                }
                out.push('\n');
                toc_done = true;
            }
            let anchor = next.next().map_or("", |s| s.anchor.as_str());
            out.push_str(&format!(
                "{} <a id=\"{anchor}\"></a>{}\n",
                &line[..level],
                &line[level + 1..]
            ));
        } else if !fenced && line.contains(PREFIX) {
            out.push_str(&link_markdown_citations(line));
            out.push('\n');
        } else {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// A Markdown line with each "guide §n" outside code spans and links made a link.
fn link_markdown_citations(line: &str) -> String {
    line.split('`')
        .enumerate()
        .map(|(i, piece)| {
            if i % 2 == 1 || piece.contains("[guide §") {
                piece.to_string()
            } else {
                link_citations(piece, |c, a| format!("[{c}](#{a})"))
            }
        })
        .collect::<Vec<_>>()
        .join("`")
}

/// The guide's page in each of `formats`. `index`: the page sits beside a report's index and
/// links back to it.
pub fn files(formats: &[Format], index: bool) -> Result<Vec<OutFile>> {
    let mut out = Vec::new();
    for format in formats {
        let bytes = match format {
            Format::Md => markdown(),
            Format::Html => {
                let tera = templates(&[TEMPLATE])?;
                let mut ctx = tera::Context::new();
                ctx.insert("css", &format!("{CSS}{GUIDE_CSS}"));
                ctx.insert("body", &html_body());
                ctx.insert("index", &index);
                ctx.insert("version", env!("CARGO_PKG_VERSION"));
                page(&tera, "guide.html", &ctx)?
            }
        };
        out.push(OutFile::new(
            format!("{STEM}.{}", format.ext()),
            bytes.into_bytes(),
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sections are numbered 1, 2, … and subsections n.1, n.2, … in order, every one of them.
    #[test]
    fn sections_are_numbered_in_order() {
        let (mut major, mut minor) = (0, 0);
        for s in sections() {
            match s.level {
                2 => {
                    major += 1;
                    minor = 0;
                    assert_eq!(s.number, major.to_string(), "{s:?}");
                }
                3 => {
                    minor += 1;
                    assert_eq!(s.number, format!("{major}.{minor}"), "{s:?}");
                }
                _ => panic!("a heading below ###: {s:?}"),
            }
        }
        assert_eq!(major, 16);
    }

    #[test]
    fn citations_resolve_to_anchors() {
        // Citations are spelled with PREFIX here, so that this file cites no missing section.
        assert_eq!(cite(&format!("{PREFIX}7.5")), Some(("7.5", "late-stick")));
        assert_eq!(
            cite(&format!("{PREFIX}16")).map(|c| c.1),
            Some("the-textbook-stick-slip-oscillator-a-block-on-a-moving-belt")
        );
        assert_eq!(cite(&format!("{PREFIX}17")), None);
        assert_eq!(cite("(13),(25)"), None);
        assert_eq!(
            sections()
                .iter()
                .filter(|s| s.title == "Machine-readable output")
                .map(|s| s.anchor.as_str())
                .collect::<Vec<_>>(),
            ["machine-readable-output", "machine-readable-output-1"]
        );
    }

    #[test]
    fn a_citation_in_the_text_becomes_a_link_but_not_its_full_stop() {
        let text = format!("see {PREFIX}7.5. And {PREFIX}99.");
        let linked = link_citations(&text, |c, a| format!("<{c}|{a}>"));
        assert_eq!(
            linked,
            format!("see <{PREFIX}7.5|late-stick>. And {PREFIX}99.")
        );
        assert_eq!(
            link_markdown_citations("`guide §7.5` and guide §4"),
            "`guide §7.5` and [guide §4](#stick-and-slip)"
        );
    }

    #[test]
    fn every_formula_of_the_guide_is_mathml_and_every_section_has_its_id() {
        let html = html_body();
        assert!(
            !html.contains("merror") && !html.contains("<code>\\"),
            "a formula left as TeX"
        );
        assert!(html.matches("<math").count() > 250);
        for s in sections() {
            assert!(html.contains(&format!(" id=\"{}\">", s.anchor)), "{s:?}");
            assert!(
                html.contains(&format!("<a href=\"#{}\">", s.anchor)),
                "{s:?}"
            );
        }
        let md = markdown();
        for s in sections() {
            assert!(
                md.contains(&format!("<a id=\"{}\"></a>", s.anchor)),
                "{s:?}"
            );
        }
    }
}
