//! Text the tool writes in English (scene captions, notes of the chain of formulas, figure
//! labels, the paper's claims) in another language, gettext-style: the catalogue's
//! `[phrases]` table is keyed by the English text with its numbers masked (`#0`, `#1`, … in
//! order), so that one entry serves every parameter set; the numbers go back into the
//! translation, which may reorder them, with the language's decimal sign.
//!
//! A [`Translator`] keeps the English of a phrase it has no translation for and lists it, so
//! that a test can require every phrase of the built-in pages to be translated.

use std::cell::RefCell;
use std::collections::BTreeSet;

use super::Lang;
use crate::error::Result;

/// Translates phrases into one language and remembers the ones it could not.
#[derive(Debug)]
pub struct Translator {
    lang: Lang,
    phrases: Option<&'static toml::Table>,
    missing: RefCell<BTreeSet<String>>,
}

impl Translator {
    pub fn new(lang: Lang) -> Result<Translator> {
        let phrases = match lang {
            Lang::En => None,
            _ => Some(lang.catalogue()?.phrases()),
        };
        Ok(Translator {
            lang,
            phrases,
            missing: RefCell::default(),
        })
    }

    pub fn lang(&self) -> Lang {
        self.lang
    }

    /// `english` in this language, or `english` itself (remembered as missing) when the
    /// catalogue has no such phrase. Text without a word (symbols, numbers) only gets the
    /// language's decimal sign.
    pub fn text(&self, english: &str) -> String {
        self.lookup(english).unwrap_or_else(|| {
            self.missing.borrow_mut().insert(mask(english).0);
            english.to_string()
        })
    }

    /// The phrases (numbers masked) asked for and not found, sorted.
    pub fn missing(&self) -> Vec<String> {
        self.missing.borrow().iter().cloned().collect()
    }

    /// An SVG's text content in this language: each text node as a phrase ([`Self::text`]),
    /// decimal signs in the numbers; attributes, tags and style sheets untouched.
    pub fn svg(&self, svg: &str) -> String {
        if self.phrases.is_none() {
            return svg.to_string();
        }
        map_text_nodes(svg, |text| {
            let trimmed = text.trim();
            text.replace(trimmed, &self.text(trimmed))
        })
    }

    fn lookup(&self, english: &str) -> Option<String> {
        let Some(phrases) = self.phrases else {
            return Some(english.to_string());
        };
        if !has_word(english) {
            // Symbols and numbers only ("φ = 0.17 ≤ 1/Θ = 0.29 (20)", "F (N)").
            return Some(self.lang.number(english));
        }
        let (key, numbers) = mask(english);
        let here = phrases.get(&key)?.as_str()?;
        // Highest index first, so that #1 does not match the start of #10.
        let filled = (0..numbers.len()).rev().fold(here.to_string(), |t, i| {
            t.replace(&format!("#{i}"), &self.lang.number(&numbers[i]))
        });
        Some(filled)
    }
}

/// Whether `text` has a word to translate: three ASCII letters in a row (symbols such as
/// "μs", "mN", "F_e" do not count).
fn has_word(text: &str) -> bool {
    text.split(|c: char| !c.is_ascii_alphabetic())
        .any(|run| run.len() >= 3)
}

/// The characters of a power written after its number.
const SUPERSCRIPTS: &str = "⁰¹²³⁴⁵⁶⁷⁸⁹⁻";

/// `text` with each number (digits, a decimal part, a power in superscripts) replaced by `#i`
/// in order, and the numbers.
pub fn mask(text: &str) -> (String, Vec<String>) {
    let mut key = String::with_capacity(text.len());
    let mut numbers = Vec::new();
    let mut chars = text.char_indices().peekable();
    while let Some((start, c)) = chars.next() {
        if !c.is_ascii_digit() {
            key.push(c);
            continue;
        }
        let mut end = start + 1;
        let mut seen_point = false;
        let mut exponent = false;
        while let Some(&(i, next)) = chars.peek() {
            let decimal_point = !exponent
                && next == '.'
                && !seen_point
                && text[i + 1..].starts_with(|d: char| d.is_ascii_digit());
            // A power written in superscripts belongs to its number (10⁻¹⁶, 2³).
            let superscript = SUPERSCRIPTS.contains(next);
            if (!exponent && next.is_ascii_digit()) || decimal_point || superscript {
                seen_point |= decimal_point;
                exponent |= superscript;
                end = i + next.len_utf8();
                chars.next();
            } else {
                break;
            }
        }
        key.push_str(&format!("#{}", numbers.len()));
        numbers.push(text[start..end].to_string());
    }
    (key, numbers)
}

/// `svg` with every text node (outside `<style>`) passed through `f`.
pub fn map_text_nodes(svg: &str, mut f: impl FnMut(&str) -> String) -> String {
    let mut out = String::with_capacity(svg.len());
    let mut in_style = false;
    let mut rest = svg;
    while let Some(open) = rest.find('<') {
        let text = &rest[..open];
        if in_style || text.is_empty() {
            out.push_str(text);
        } else {
            out.push_str(&f(text));
        }
        let close = rest[open..].find('>').map_or(rest.len(), |c| open + c + 1);
        let tag = &rest[open..close];
        in_style = tag.starts_with("<style");
        out.push_str(tag);
        rest = &rest[close..];
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each translation uses exactly the numbers of its English key, each once.
    #[test]
    fn every_phrase_keeps_its_numbers() {
        let placeholders = |text: &str| {
            let mut found: Vec<String> = text
                .match_indices('#')
                .map(|(i, _)| {
                    let digits: String = text[i + 1..]
                        .chars()
                        .take_while(char::is_ascii_digit)
                        .collect();
                    digits
                })
                .filter(|d| !d.is_empty())
                .collect();
            found.sort();
            found
        };
        let phrases = Lang::It.catalogue().unwrap().phrases();
        assert!(phrases.len() > 250, "{}", phrases.len());
        for (english, here) in phrases {
            let here = here.as_str().expect("a text");
            assert!(!here.trim().is_empty(), "{english:?} has no translation");
            assert_eq!(placeholders(english), placeholders(here), "{english:?}");
        }
    }

    #[test]
    fn numbers_are_masked_in_order_with_their_decimals() {
        let (key, numbers) = mask("The pull F = 0.1 N against (20), Fig. 10.");
        assert_eq!(key, "The pull F = #0 N against (#1), Fig. #2.");
        assert_eq!(numbers, ["0.1", "20", "10"]);
        assert_eq!(mask("μs² and D^{3/2}").0, "μs² and D^{#0/#1}");
        let (key, numbers) = mask("error 1.6 × 10⁻¹⁶, 2³ not 2²");
        assert_eq!(key, "error #0 × #1, #2 not #3");
        assert_eq!(numbers, ["1.6", "10⁻¹⁶", "2³", "2²"]);
    }

    #[test]
    fn a_phrase_comes_back_with_its_numbers_in_the_language_and_misses_are_listed() {
        let it = Translator::new(Lang::It).unwrap();
        assert_eq!(it.text("harmonic law"), "legge armonica");
        assert_eq!(
            it.text("Fig. 10: slip-stick within one period"),
            "Fig. 10: slittamento e arresto entro un periodo"
        );
        assert_eq!(it.text("no such phrase 1.5"), "no such phrase 1.5");
        assert_eq!(it.text("t_SL = 0.5"), "t_SL = 0,5");
        assert_eq!(it.missing(), ["no such phrase #0"]);
        let svg = "<svg><style>a{b:0.5}</style><text>harmonic law</text><text>0.25</text></svg>";
        assert_eq!(
            it.svg(svg),
            "<svg><style>a{b:0.5}</style><text>legge armonica</text><text>0,25</text></svg>"
        );
        let en = Translator::new(Lang::En).unwrap();
        assert_eq!(en.text("anything 1.5"), "anything 1.5");
        assert!(en.missing().is_empty());
    }
}
