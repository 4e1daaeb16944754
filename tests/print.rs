//! Every printed word at 8 pt or more: the handouts, four students' worksheets (one A4 page
//! each) and answer keys of each model, in English and in Italian, and the lecture notes
//! (`reports/all-scenes.html`, English only) are printed by headless Chromium as `stickslip`
//! prints them, and the height of every word that `pdftotext -bbox-layout` finds is compared
//! with that of a known 8 pt text.
//!
//! pdftotext gives a word's box in PDF points (1/72 in), from the font's ascent to its
//! descent: about 1.1–1.2 × the font size for the text fonts (DejaVu Serif 1.164, Liberation
//! Sans 1.116, Liberation Serif 1.107) and 1.0 × for the math font's italic letters (DejaVu
//! Math TeX Gyre). The factors are not hard-coded: a calibration page of 8 pt text in each
//! font and in MathML and SVG is printed first, and a word passes when its box is at least the
//! smallest box of its kind there (text, or a word set in the math font: one with a
//! mathematical alphanumeric or operator). The test is thus at most ~5 % lenient for DejaVu
//! Serif (the tallest factor), never strict by mistake. Text rotated a quarter turn (the
//! charts' y labels) stacks its words vertically in one line, and is measured across.
//!
//! Needs `chromium` and `pdftotext` (Debian: chromium, poppler-utils); without them the test is
//! skipped locally but fails on CI (CI=true).

mod common;
use common::find;

use std::path::{Path, PathBuf};
use std::process::Command;

use stickslip::handout::pdf::HEADLESS_FLAGS;

/// The smallest printed size (pt).
const MIN_PT: f64 = 8.0;

/// Students of the printed class sets: each sheet's length varies with its parameters.
const STUDENTS: usize = 4;

fn tools() -> Option<(PathBuf, PathBuf)> {
    let tools = (
        find(&["chromium", "chromium-browser", "google-chrome"]),
        find(&["pdftotext"]),
    );
    if let (Some(browser), Some(pdftotext)) = tools {
        return Some((browser, pdftotext));
    }
    assert!(
        std::env::var("CI").is_err(),
        "CI must install chromium and poppler-utils"
    );
    eprintln!("skipped: chromium or poppler-utils not installed");
    None
}

/// Prints `html` to `pdf` with `stickslip … --pdf`'s flags, by the browser's one-shot print
/// (no page header or footer, as the tool's DevTools print asks).
fn print(browser: &Path, profile: &Path, html: &Path, pdf: &Path) {
    let out = Command::new(browser)
        .args(HEADLESS_FLAGS)
        .arg("--no-pdf-header-footer")
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--print-to-pdf={}", pdf.display()))
        .arg(html)
        .output()
        .expect("chromium runs");
    assert!(pdf.exists(), "{}: {out:?}", html.display());
}

/// A printed word: its page, text and height across its line of text (pt).
#[derive(Debug)]
struct Word {
    page: usize,
    text: String,
    size: f64,
}

fn attribute(tag: &str, name: &str) -> f64 {
    let start = tag.find(&format!(" {name}=\"")).expect("bbox attribute") + name.len() + 3;
    tag[start..]
        .split('"')
        .next()
        .and_then(|v| v.parse().ok())
        .expect("a number")
}

/// The words of `pdf` with their heights (pt): across the line for a line whose words stack
/// vertically (rotated text), else the box's height.
fn words(pdftotext: &Path, pdf: &Path) -> Vec<Word> {
    let out = Command::new(pdftotext)
        .arg("-bbox-layout")
        .arg(pdf)
        .arg("-")
        .output()
        .expect("pdftotext runs");
    let xml = String::from_utf8_lossy(&out.stdout);
    let mut words = Vec::new();
    let (mut page, mut line): (usize, Vec<(String, [f64; 4])>) = (0, Vec::new());
    let flush = |line: &mut Vec<(String, [f64; 4])>, page: usize, words: &mut Vec<Word>| {
        let stacked = line.len() > 1
            && line.windows(2).all(|w| {
                let ([_, a0, _, a1], [_, b0, _, b1]) = (w[0].1, w[1].1);
                a1 <= b0 + 0.5 || b1 <= a0 + 0.5
            });
        for (text, [x0, y0, x1, y1]) in line.drain(..) {
            let size = if stacked { x1 - x0 } else { y1 - y0 };
            words.push(Word { page, text, size });
        }
    };
    for row in xml.lines().map(str::trim) {
        if row.starts_with("<page ") {
            page += 1;
        } else if row.starts_with("</line>") {
            flush(&mut line, page, &mut words);
        } else if let Some(rest) = row.strip_prefix("<word ") {
            let tag = &rest[..rest.find('>').unwrap_or(rest.len())];
            let text = rest[tag.len() + 1..]
                .trim_end_matches("</word>")
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&amp;", "&");
            let bbox = ["xMin", "yMin", "xMax", "yMax"].map(|n| attribute(&format!(" {tag}"), n));
            line.push((text, bbox));
        }
    }
    words
}

/// The pages of `pdf`.
fn pages(pdftotext: &Path, pdf: &Path) -> usize {
    let out = Command::new(pdftotext)
        .arg("-bbox")
        .arg(pdf)
        .arg("-")
        .output()
        .expect("pdftotext runs");
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter(|l| l.trim_start().starts_with("<page "))
        .count()
}

/// A word set in the math font: a mathematical alphanumeric (italic letters of MathML) or an
/// operator such as √.
fn in_math_font(text: &str) -> bool {
    text.chars()
        .any(|c| matches!(c as u32, 0x1D400..=0x1D7FF | 0x2200..=0x22FF))
}

/// Words, not rules or accents: a letter or digit in it.
fn is_word(text: &str) -> bool {
    text.chars().any(char::is_alphanumeric)
}

/// The calibration page: 8 pt text in the fonts the printed outputs use, MathML and SVG text.
const CALIBRATION: &str = r#"<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>8 pt</title>
<style>body { font-size: 8pt; margin: 0; } p { margin: 2pt 0; }
math { font-family: "Latin Modern Math", "STIX Two Math", "Cambria Math", "DejaVu Math TeX Gyre", math; }</style></head><body>
<p style="font-family: 'DejaVu Serif'">Serif text 0.123 <b>bold</b> <i>italic</i> μs λ Γ</p>
<p style="font-family: 'DejaVu Sans'">Sans text 0.123 <b>bold</b> <i>italic</i> μs</p>
<p style="font-family: serif">Generic serif text 0.123</p>
<p style="font-family: sans-serif">Generic sans text 0.123</p>
<p style="font-family: 'DejaVu Serif'"><math><mi>μ</mi><mo>=</mo><mi mathvariant="normal">Γ</mi><mo>+</mo><mn>0.25</mn><msqrt><mn>1.971</mn></msqrt><mi>sin</mi><mi>ω</mi><mi>t</mi><mtext>rad</mtext></math></p>
<svg width="400" height="60" viewBox="0 0 400 60" font-family="sans-serif"><text x="2" y="20" font-size="10.667">svg sans text 0.123</text>
<text x="2" y="45" font-size="10.667" font-family="DejaVu Sans, Helvetica, Arial, sans-serif">svg chart text 0.25</text></svg>
</body></html>"#;

/// The smallest 8 pt boxes: (text, math font) in pt.
fn calibrate(browser: &Path, pdftotext: &Path, dir: &Path) -> (f64, f64) {
    let html = dir.join("calibration.html");
    std::fs::write(&html, CALIBRATION).unwrap();
    let pdf = dir.join("calibration.pdf");
    print(browser, &dir.join("profile"), &html, &pdf);
    let words = words(pdftotext, &pdf);
    let smallest = |math: bool| {
        words
            .iter()
            .filter(|w| is_word(&w.text) && in_math_font(&w.text) == math)
            .map(|w| w.size)
            .fold(f64::INFINITY, f64::min)
    };
    let (text, math) = (smallest(false), smallest(true));
    // Sanity: the boxes are 0.9–1.3 × the size, as for every font in use.
    for h in [text, math] {
        assert!(
            (0.9 * MIN_PT..1.3 * MIN_PT).contains(&h),
            "calibration {h} pt"
        );
    }
    (text, math)
}

fn stickslip(args: &[&str], out: &Path, browser: &Path) {
    let run = Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(args)
        .arg("--out")
        .arg(out)
        .env("STICKSLIP_CHROMIUM", browser)
        .output()
        .unwrap();
    assert!(run.status.success(), "{args:?}: {run:?}");
}

#[test]
fn every_printed_word_is_at_least_8_pt() {
    let Some((browser, pdftotext)) = tools() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let dir = dir.path();
    let (text_8pt, math_8pt) = calibrate(&browser, &pdftotext, dir);

    let mut pdfs = Vec::new();
    for lang in ["en", "it"] {
        for scene in ["fig10-linear-slip-stick", "fig15-double-slip-stick"] {
            let out = dir.join(format!("handout-{lang}"));
            stickslip(
                &["handout", scene, "--pdf", "--format", "md", "--lang", lang],
                &out,
                &browser,
            );
            pdfs.push(out.join(format!("{scene}.pdf")));
        }
        for model in ["pulled-mass", "woodpecker", "belt"] {
            let out = dir.join(format!("{model}-{lang}"));
            stickslip(
                &[
                    "worksheet",
                    "--model",
                    model,
                    "--students",
                    &STUDENTS.to_string(),
                    "--pdf",
                    "--format",
                    "md",
                    "--lang",
                    lang,
                ],
                &out,
                &browser,
            );
            // One A4 page per student: no question spills onto a second, mostly empty page.
            let sheets = out.join("worksheets.pdf");
            assert_eq!(
                pages(&pdftotext, &sheets),
                STUDENTS,
                "{model} {lang}: pages of {STUDENTS} students' sheets"
            );
            pdfs.push(sheets);
            pdfs.push(out.join("answer-key.pdf"));
        }
    }
    assert_legible(&pdfs, dir, &pdftotext, (text_8pt, math_8pt));
}

/// The lecture notes as `stickslip report` writes them: their charts are drawn on the column
/// canvas ([`stickslip::report::figures::style::Geometry::COLUMN`]), two to a row or one beside
/// its caption, and no table is wider than the page (Chromium would shrink the whole page).
#[test]
fn every_word_of_the_lecture_notes_is_at_least_8_pt() {
    let Some((browser, pdftotext)) = tools() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let dir = dir.path();
    let factors = calibrate(&browser, &pdftotext, dir);
    let notes = dir.join("all-scenes.pdf");
    let html = Path::new("reports/all-scenes.html").canonicalize().unwrap();
    print(&browser, &dir.join("profile"), &html, &notes);
    assert_legible(&[notes], dir, &pdftotext, factors);
}

/// Every word of `pdfs` at least [`MIN_PT`], given the boxes of 8 pt text and math-font words.
fn assert_legible(
    pdfs: &[PathBuf],
    dir: &Path,
    pdftotext: &Path,
    (text_8pt, math_8pt): (f64, f64),
) {
    let mut small = Vec::new();
    for pdf in pdfs {
        let words = words(pdftotext, pdf);
        assert!(
            words.len() > 200,
            "{}: {} words",
            pdf.display(),
            words.len()
        );
        for w in words.iter().filter(|w| is_word(&w.text)) {
            let factor = if in_math_font(&w.text) {
                math_8pt
            } else {
                text_8pt
            } / MIN_PT;
            // 0.01 pt: the rounding of pdftotext's coordinates.
            if w.size < MIN_PT * factor - 0.01 {
                small.push(format!(
                    "{} p. {}: {:?} at {:.2} pt",
                    pdf.strip_prefix(dir).unwrap_or(pdf).display(),
                    w.page,
                    w.text,
                    w.size / factor
                ));
            }
        }
    }
    assert!(
        small.is_empty(),
        "{} words below {MIN_PT} pt, e.g.\n{}",
        small.len(),
        small[..small.len().min(40)].join("\n")
    );
}
