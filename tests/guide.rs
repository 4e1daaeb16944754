//! The physics guide as a page of `reports/` (issue 28): every citation of it in the code, the
//! templates, the docs and the committed reports names a section the guide has, in one form
//! ("guide §7.5", "guida §7.5" on the Italian pages); every link into it reaches a heading's
//! id; and no link of `reports/` leaves the folder, so that a copy of it works offline.

use std::path::{Path, PathBuf};

use stickslip::report::guide::{cite, sections, PREFIX};

mod common;
use common::files;

/// The words that may stand before "§n": the guide's name in English and in Italian.
const NAMES: [&str; 2] = ["guide ", "guida "];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

/// The citations of `text` that name no section of the guide or are not in the guide's form:
/// each "§" followed by a digit must follow "guide " (or "guida ") and name a section
/// ("guide §7.5" → 7.5); the private specification's "physics.md §n" is never cited.
fn dangling(text: &str) -> Vec<String> {
    let mut bad = Vec::new();
    for (at, _) in text.match_indices('§') {
        let after = &text[at + '§'.len_utf8()..];
        let number: String = after
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.')
            .collect();
        let number = number.trim_end_matches('.');
        if number.is_empty() {
            continue; // "§{{ r.section }}" in a template, a § in prose
        }
        let before = &text[..at];
        let named = NAMES.iter().any(|n| before.ends_with(n));
        let exists = sections().iter().any(|s| s.number == number);
        if !named || !exists {
            let start = before.char_indices().rev().nth(20).map_or(0, |(i, _)| i);
            bad.push(format!("…{}§{number}", &text[start..at]));
        }
    }
    bad
}

/// The anchor a link target `…guide.html#a` / `…guide.md#a` / `#a` (in the guide) points at.
fn fragment(target: &str) -> Option<&str> {
    target.split_once('#').map(|(_, a)| a)
}

/// (href, link text) of every `<a href="…">…</a>` of an HTML page, `&#x2F;` unescaped.
fn html_links(text: &str) -> Vec<(String, String)> {
    text.split("<a href=\"")
        .skip(1)
        .filter_map(|rest| {
            let (href, rest) = rest.split_once('"')?;
            let inner = &rest[rest.find('>')? + 1..rest.find("</a>")?];
            Some((href.replace("&#x2F;", "/"), inner.to_string()))
        })
        .collect()
}

/// (target, link text) of every `[text](target)` of a Markdown page.
fn markdown_links(text: &str) -> Vec<(String, String)> {
    text.split("](")
        .collect::<Vec<_>>()
        .windows(2)
        .filter_map(|w| {
            let label = &w[0][w[0].rfind('[')? + 1..];
            let target = w[1].split(')').next()?;
            Some((target.to_string(), label.to_string()))
        })
        .collect()
}

/// The anchor of a link text "guide §7.5" (or "guida §7.5"), when it is a citation.
fn cited_anchor(label: &str) -> Option<&'static str> {
    let english = NAMES
        .iter()
        .find_map(|n| label.strip_prefix(n))
        .map(|rest| format!("guide {rest}"))?;
    cite(&english).map(|(_, anchor)| anchor)
}

#[test]
fn a_dangling_or_bare_citation_is_found() {
    // Written so that this file holds no citation of its own.
    let section = |n: &str| format!("{}{n}", PREFIX);
    assert!(dangling(&section("7.5")).is_empty());
    assert!(dangling(&format!("guida §{}", "7.5")).is_empty());
    assert_eq!(dangling(&section("99")).len(), 1);
    assert_eq!(dangling(&format!("physics.md §{}", "1.4")).len(), 1);
    assert_eq!(dangling(&format!("(§{})", "7.5")).len(), 1);
    assert_eq!(dangling(&format!("end of {}.", section("13"))).len(), 0);
    assert_eq!(cited_anchor(&section("7.5")), Some("late-stick"));
    assert_eq!(
        cited_anchor(&format!("guida §{}", "4")),
        Some("stick-and-slip")
    );
}

/// Every "§" in the code, the templates, the tests, the Python package, the docs and the
/// README is a citation of a section the guide has.
#[test]
fn every_citation_in_the_sources_names_a_section_of_the_guide() {
    let exts = ["rs", "tera", "toml", "js", "css", "py", "md"];
    let mut sources = Vec::new();
    for dir in ["src", "templates", "tests", "python", "docs"] {
        sources.extend(files(&root().join(dir), &exts));
    }
    sources.push(root().join("README.md"));
    let mut bad = Vec::new();
    for path in &sources {
        // Snapshots are output, checked with the reports below.
        if path.components().any(|c| c.as_os_str() == "snapshots") {
            continue;
        }
        let text = std::fs::read_to_string(path).unwrap();
        for b in dangling(&text) {
            bad.push(format!("{}: {b}", path.display()));
        }
        // Split so that this file does not hold the link it looks for.
        let source = ["../", "docs/physics.md"].concat();
        assert!(
            !text.contains(&format!("\"{source}")) && !text.contains(&format!("({source}")),
            "{}: links the guide's source, not the page",
            path.display()
        );
    }
    assert!(sources.len() > 100, "only {} files read", sources.len());
    assert!(bad.is_empty(), "dangling citations:\n{}", bad.join("\n"));
}

/// Every page of the committed `reports/` cites only sections of the guide, every link into
/// the guide reaches a heading (and a link worded "guide §n" reaches section n), and no
/// relative link leaves `reports/`.
#[test]
fn every_citation_and_link_of_the_reports_reaches_a_heading_of_the_guide() {
    let reports = root().join("reports");
    let guide_html = std::fs::read_to_string(reports.join("guide.html")).unwrap();
    let guide_md = std::fs::read_to_string(reports.join("guide.md")).unwrap();
    for s in sections() {
        assert!(
            guide_html.contains(&format!(" id=\"{}\"", s.anchor)),
            "guide.html: {s:?}"
        );
        assert!(
            guide_md.contains(&format!("<a id=\"{}\"></a>", s.anchor)),
            "guide.md: {s:?}"
        );
    }
    let ids = |html: bool| -> Vec<String> {
        let (text, open) = if html {
            (&guide_html, " id=\"")
        } else {
            (&guide_md, "<a id=\"")
        };
        text.split(open)
            .skip(1)
            .filter_map(|r| r.split('"').next().map(str::to_string))
            .collect()
    };
    let (html_ids, md_ids) = (ids(true), ids(false));
    let pages = files(&reports, &["html", "md"]);
    let mut bad = Vec::new();
    let mut into_guide = 0;
    for page in &pages {
        let text = std::fs::read_to_string(page).unwrap();
        let name = page.strip_prefix(&reports).unwrap().display().to_string();
        for b in dangling(&text) {
            bad.push(format!("{name}: {b}"));
        }
        let html = page.extension().is_some_and(|e| e == "html");
        let links = if html {
            html_links(&text)
        } else {
            markdown_links(&text)
        };
        for (target, label) in links {
            if target.contains(':') || target.contains(' ') {
                continue; // an absolute URL, a data: URI or prose in parentheses
            }
            let file = target.split('#').next().unwrap_or_default();
            let resolved = if file.is_empty() {
                page.clone()
            } else {
                page.parent().unwrap().join(file)
            };
            // No `..` may climb above reports/ (a copy of the folder has nothing there).
            let mut depth = page
                .parent()
                .unwrap()
                .strip_prefix(&reports)
                .unwrap()
                .components()
                .count() as i64;
            for c in Path::new(file).components() {
                match c {
                    std::path::Component::ParentDir => depth -= 1,
                    std::path::Component::Normal(_) => depth += 1,
                    _ => {}
                }
                if depth < 0 {
                    bad.push(format!("{name}: {target} leaves reports/"));
                    break;
                }
            }
            let in_guide = resolved
                .file_name()
                .is_some_and(|f| f == "guide.html" || f == "guide.md");
            if !in_guide {
                continue;
            }
            into_guide += 1;
            let Some(anchor) = fragment(&target) else {
                continue; // the page itself
            };
            let known = if resolved.extension().is_some_and(|e| e == "html") {
                &html_ids
            } else {
                &md_ids
            };
            if !known.iter().any(|id| id == anchor) {
                bad.push(format!("{name}: {target} reaches no heading"));
            }
            if let Some(cited) = cited_anchor(&label) {
                if cited != anchor {
                    bad.push(format!("{name}: \"{label}\" links #{anchor}, not #{cited}"));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    // The index, every scene page, the handouts and the guide's own contents link into it.
    assert!(into_guide > 200, "only {into_guide} links into the guide");
}
