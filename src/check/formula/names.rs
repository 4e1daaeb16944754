//! A run of letters as the model's symbols: the fewest known names that spell it (`gT` → g·T,
//! `μs` → μ_s, `δ0` → δ_0), Greek variants allowed (`phi` for `varphi`), and the message with
//! the nearest names when none does.

use super::Symbol;

/// A Greek name and its variant spelling (`phi` ↔ `varphi`).
fn variant(name: &str) -> Option<String> {
    for base in ["phi", "theta", "epsilon", "rho", "sigma"] {
        if let Some(rest) = name.strip_prefix(base) {
            return Some(format!("var{base}{rest}"));
        }
        if let Some(rest) = name.strip_prefix(&format!("var{base}")) {
            return Some(format!("{base}{rest}"));
        }
    }
    None
}

/// The known symbol a spelling names, allowing a Greek variant (`phi` for `varphi`).
fn resolve(spelling: &str, known: &[Symbol]) -> Option<String> {
    if known.iter().any(|s| s.name == spelling) {
        return Some(spelling.to_string());
    }
    let v = variant(spelling)?;
    known.iter().any(|s| s.name == v).then_some(v)
}

/// `units` split into the fewest known symbols; a subscript unit never starts a symbol, and a
/// Greek letter followed by a letter may take it as its subscript (`μs` → `mu_s`).
pub(super) fn split(units: &[(String, bool)], known: &[Symbol]) -> Option<Vec<String>> {
    let n = units.len();
    // best[i]: the fewest symbols spelling units[..i], with the spelling.
    let mut best: Vec<Option<Vec<String>>> = vec![None; n + 1];
    best[0] = Some(Vec::new());
    for i in 0..n {
        let Some(prefix) = best[i].clone() else {
            continue;
        };
        if units[i]
            .0
            .starts_with(|c: char| c == '_' || c.is_ascii_digit())
        {
            continue;
        }
        for j in (i + 1..=n).rev() {
            for spelling in spellings(&units[i..j]) {
                if let Some(name) = resolve(&spelling, known) {
                    let mut candidate = prefix.clone();
                    candidate.push(name);
                    if best[j].as_ref().is_none_or(|b| candidate.len() < b.len()) {
                        best[j] = Some(candidate);
                    }
                    break;
                }
            }
        }
    }
    best[n].take()
}

/// The spellings of a run of units: joined as they are, and with `_` after a Greek letter
/// that a letter follows.
fn spellings(units: &[(String, bool)]) -> Vec<String> {
    let mut out = vec![String::new()];
    for (k, (text, _)) in units.iter().enumerate() {
        let digits = text.starts_with(|c: char| c.is_ascii_digit());
        let after_greek = k > 0 && (units[k - 1].1 || digits) && !text.starts_with('_');
        let mut next = Vec::new();
        for s in &out {
            next.push(format!("{s}{text}"));
            if after_greek {
                next.push(format!("{s}_{text}"));
            }
        }
        out = next;
        if out.len() > 64 {
            out.truncate(64);
        }
    }
    out
}

/// The message for a name that spells no known symbol: the nearest known names.
pub(super) fn unknown(text: &str, known: &[Symbol]) -> String {
    let mut near: Vec<(usize, &str)> = known
        .iter()
        .map(|s| {
            (
                distance(&text.to_lowercase(), &s.name.to_lowercase()),
                s.name.as_str(),
            )
        })
        .collect();
    near.sort_by_key(|(d, _)| *d);
    let near: Vec<&str> = near.iter().take(3).map(|(_, n)| *n).collect();
    if text == "log" {
        return "`log` is ambiguous: write ln (natural) or log10".to_string();
    }
    if text == "tau" || text == "e" || text == "E" {
        return format!(
            "unknown symbol {text} (the model has no symbol of that name; the constants are pi \
             and exp(1)); nearest: {}; all with --symbols",
            near.join(", ")
        );
    }
    format!(
        "unknown symbol {text}; nearest: {} (all with --symbols)",
        near.join(", ")
    )
}

/// Levenshtein distance.
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}
