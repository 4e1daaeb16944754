//! The report: Markdown snapshots, structure of the pages, determinism, and the `report`
//! command's handling of user scenarios and bad input.

mod common;

use std::path::Path;

use assert_cmd::Command;
use stickslip::report::{builtin_scenes, render, Format, OutFile};

use common::rendered;

fn default_report() -> Vec<OutFile> {
    render(&builtin_scenes().unwrap(), &[Format::Html, Format::Md]).unwrap()
}

/// The belt's part: its pages exist in both formats, check every closed form against its own
/// integration, and carry none of the paper's words for its two laws or its two models (the
/// words of another model on a page were once served silently).
#[test]
fn the_belts_pages_are_its_own() {
    let files = default_report();
    let index = rendered(&files, "index.md");
    assert!(index.contains("Part 3. The textbook oscillator"), "{index}");
    for id in ["belt-textbook", "belt-touching", "belt-fast"] {
        for ext in ["html", "md"] {
            let page = rendered(&files, &format!("{id}.{ext}"));
            assert!(
                page.contains("Part 3. The textbook oscillator"),
                "{id}.{ext}"
            );
            assert!(
                page.contains("exact integration of the same autonomous system"),
                "{id}.{ext}"
            );
            // The words of the page, not its style sheet (whose classes name the tables).
            let body = page.split_once("</style>").map_or(page, |(_, b)| b);
            let lower = body.to_lowercase();
            for word in [
                "lineari",
                "pulled mass",
                "woodpecker",
                "harmonic law",
                "triangle",
            ] {
                assert!(!lower.contains(word), "{id}.{ext}: {word}");
            }
            assert!(page.contains("16 / 16"), "{id}.{ext}");
        }
        assert!(files
            .iter()
            .any(|f| f.path.to_string_lossy() == format!("figures/{id}-phase.svg")));
    }
}

#[test]
fn markdown_pages_match_their_snapshots() {
    let files = default_report();
    insta::assert_snapshot!("index_md", rendered(&files, "index.md"));
    insta::assert_snapshot!("fig10_md", rendered(&files, "fig10-linear-slip-stick.md"));
    insta::assert_snapshot!("fig15_md", rendered(&files, "fig15-double-slip-stick.md"));
}

#[test]
fn markdown_tables_have_as_many_cells_as_their_header() {
    for f in default_report()
        .iter()
        .filter(|f| f.path.extension().is_some_and(|e| e == "md"))
    {
        let text = std::str::from_utf8(&f.bytes).unwrap();
        let mut header_cells = None;
        for line in text.lines() {
            if !line.starts_with('|') {
                header_cells = None;
                continue;
            }
            // Cells are separated by unescaped pipes ("\|" is a pipe inside a cell).
            let unescaped = line.trim().replace("\\|", "");
            let cells = unescaped.trim_matches('|').split('|').count();
            match header_cells {
                None => header_cells = Some(cells),
                Some(n) => assert_eq!(cells, n, "{}: {line}", f.path.display()),
            }
        }
    }
}

#[test]
fn html_pages_are_self_contained_and_every_figure_is_inline() {
    let files = default_report();
    for f in files
        .iter()
        .filter(|f| f.path.extension().is_some_and(|e| e == "html"))
    {
        let text = std::str::from_utf8(&f.bytes).unwrap();
        assert!(text.contains("<style>"), "{}", f.path.display());
        for bad in ["<script", "<link", "<img"] {
            assert!(!text.contains(bad), "{}: {bad}", f.path.display());
        }
    }
    let page = rendered(&files, "fig09-domain.html");
    assert_eq!(
        page.matches("<svg").count(),
        3,
        "the apparatus and two regime maps inline"
    );
    // Every figure has a text alternative (axe: svg-img-alt) and the page its landmarks.
    for f in files
        .iter()
        .filter(|f| f.path.extension().is_some_and(|e| e == "html"))
    {
        let text = std::str::from_utf8(&f.bytes).unwrap();
        for svg in text.split("<svg").skip(1) {
            let head = &svg[..svg.find("</svg>").unwrap()];
            assert!(
                head.contains("role=\"img\"")
                    && head.contains("<title>")
                    && head.contains("<desc>"),
                "{}: a figure without title or description",
                f.path.display()
            );
        }
        assert!(text.contains("<main>"), "{}: no <main>", f.path.display());
        assert!(
            text.contains("prefers-color-scheme: dark"),
            "{}",
            f.path.display()
        );
    }
    assert!(page.contains("<math"), "MathML formulas");
    // Every Markdown figure link has its SVG file.
    for f in files
        .iter()
        .filter(|f| f.path.extension().is_some_and(|e| e == "md"))
    {
        let text = std::str::from_utf8(&f.bytes).unwrap();
        for link in text.split("](figures/").skip(1) {
            let name = format!("figures/{}", &link[..link.find(')').unwrap()]);
            assert!(files.iter().any(|g| g.path == Path::new(&name)), "{name}");
        }
    }
}

#[test]
fn the_report_is_deterministic() {
    assert_eq!(default_report(), default_report());
}

#[test]
fn every_default_scene_passes_all_its_checks() {
    let files = default_report();
    let index = rendered(&files, "index.md");
    let summary = index
        .split("counted once per parameter set (11 sets): **")
        .nth(1)
        .and_then(|s| s.split("**").next())
        .unwrap_or_else(|| panic!("no summary of the 11 parameter sets in {index}"));
    let (passed, total) = summary.split_once(" / ").unwrap();
    assert_eq!(passed, total, "{summary}");
    // Counted once per set: the Fig. 15 set's 18 checks once, not eight times (254); the
    // paper's 8 sets (89 checks) and the belt's 3 (16 each).
    let total: usize = total.parse().unwrap();
    assert!((120..160).contains(&total), "{summary}");
}

/// The index is a reading path: the two parts of the paper in order, each scene once with a
/// unique title and why it matters, and the classroom material linked.
#[test]
fn the_index_is_a_reading_path_through_the_paper() {
    let files = default_report();
    let scenes = builtin_scenes().unwrap();
    for ext in ["html", "md"] {
        let index = rendered(&files, &format!("index.{ext}"));
        let (one, two) = (
            index.find("Part 1. The pulled mass").unwrap(),
            index.find("Part 2. The falling woodpecker").unwrap(),
        );
        assert!(one < two);
        let mut last = 0;
        for s in &scenes {
            let at = index[last..]
                .find(&format!("{}.{ext}", s.id))
                .unwrap_or_else(|| panic!("{}: not in reading order", s.id))
                + last;
            let rest = index[at..]
                .replace("&#x2F;", "/")
                .replace("&gt;", ">")
                .replace("&#x27;", "'");
            assert!(rest.contains(&s.why), "{}", s.id);
            assert_eq!(s.part.number == Some(1), at < two, "{}", s.id);
            last = at;
        }
        assert!(index.contains("all-scenes.html") || ext == "md");
        assert!(
            index.contains(&format!("\"guide.{ext}\""))
                || index.contains(&format!("(guide.{ext})")),
            "{ext}"
        );
    }
}

/// The lecture notes show each parameter set's tables once: 11 verification tables for the 22
/// scenes (8 sets of the paper, 3 of the belt), and each claim once.
#[test]
fn the_lecture_notes_share_tables_once() {
    let files = default_report();
    let notes = rendered(&files, "all-scenes.html");
    let scenes = builtin_scenes().unwrap();
    assert_eq!(
        notes.matches("<section class=\"scene\"").count(),
        scenes.len()
    );
    assert_eq!(notes.matches("<table class=\"verification\">").count(), 11);
    for claim in 1..=8 {
        assert!(
            notes.matches(&format!("<strong>Claim {claim}:")).count() <= 1,
            "claim {claim} more than once"
        );
    }
    assert!(notes.contains("as in <a href=\"#fig15-double-slip-stick\">"));
}

fn stickslip() -> Command {
    Command::cargo_bin("stickslip").unwrap()
}

#[test]
fn a_user_scenario_becomes_a_scene() {
    let dir = tempfile::tempdir().unwrap();
    stickslip()
        .args([
            "report",
            "scenarios/set-c-late-stick.toml",
            "--format",
            "md",
            "--out",
        ])
        .arg(dir.path())
        .assert()
        .success();
    let md = std::fs::read_to_string(dir.path().join("set-c-late-stick.md")).unwrap();
    assert!(md.contains("the stick early in the next period"));
    assert!(dir
        .path()
        .join("figures/set-c-late-stick-motion.svg")
        .exists());
    assert!(
        !dir.path().join("index.html").exists(),
        "html not asked for"
    );
}

/// Runs `report` with `args` into a fresh folder: exit 2, one line on stderr, nothing written.
fn refused(args: &[&str], expect_in_error: &str) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let assert = stickslip()
        .arg("report")
        .args(args)
        .arg("--out")
        .arg(&out)
        .assert()
        .code(2);
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(stderr.contains(expect_in_error), "{stderr}");
    assert!(!stderr.contains("panicked"));
    let written = std::fs::read_dir(&out).map(|d| d.count()).unwrap_or(0);
    assert_eq!(written, 0, "nothing may be written");
}

#[test]
fn bad_report_input_is_refused_without_writing() {
    refused(&["scenarios/does-not-exist.toml"], "does-not-exist.toml");
    let dir = tempfile::tempdir().unwrap();
    let malformed = dir.path().join("bad.toml");
    std::fs::write(&malformed, "model = \"pulled-mass\"\ntitle = \n").unwrap();
    refused(&[malformed.to_str().unwrap()], "bad.toml");
    let unknown = dir.path().join("unknown.toml");
    std::fs::write(
        &unknown,
        "model = \"pulled-mass\"\ntitle = \"x\"\n[params]\nmu = 1\n",
    )
    .unwrap();
    refused(&[unknown.to_str().unwrap()], "unknown field `mu`");
    let invalid = dir.path().join("invalid.toml");
    std::fs::write(
        &invalid,
        "model = \"pulled-mass\"\ntitle = \"x\"\n[params]\nmu_d = 0.9\n",
    )
    .unwrap();
    refused(&[invalid.to_str().unwrap()], "mu_d");
    refused(&["--format", "pdf"], "--format");
}

#[test]
fn an_unwritable_output_folder_is_refused() {
    let mut cmd = stickslip();
    cmd.args(["report", "scenarios/set-b-slip-stick.toml"]);
    common::unwritable(cmd);
}

/// The handouts written beside the report link the physics guide from their own folder.
#[test]
fn the_classroom_handouts_link_the_guide_from_their_folder() {
    let handouts = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports/handouts");
    for name in ["fig10-linear-slip-stick.html", "fig15-double-slip-stick.md"] {
        let text = std::fs::read_to_string(handouts.join(name))
            .unwrap()
            .replace("&#x2F;", "/");
        assert!(
            text.contains("\"../guide.html#") || text.contains("](../guide.md#"),
            "{name}"
        );
        assert!(
            !text.contains("\"guide.html") && !text.contains("](guide.md"),
            "{name}"
        );
        assert!(handouts.join("../guide.html").exists() && handouts.join("../guide.md").exists());
    }
}

/// Every link of the committed index (HTML and Markdown) reaches a file: the scene pages, the
/// lecture notes, the handouts, worksheets and answer keys, the study and the physics guide.
#[test]
fn every_link_of_the_committed_index_reaches_a_file() {
    let reports = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    for (name, open, close) in [("index.html", "href=\"", '"'), ("index.md", "](", ')')] {
        let text = std::fs::read_to_string(reports.join(name))
            .unwrap()
            .replace("&#x2F;", "/");
        let links: Vec<&str> = text
            .split(open)
            .skip(1)
            .map(|rest| &rest[..rest.find(close).unwrap()])
            .collect();
        for wanted in ["handouts/", "worksheets/", "bench/", "guide.", "all-scenes"] {
            assert!(
                links.iter().any(|l| l.contains(wanted))
                    || (name == "index.md" && wanted == "all-scenes"),
                "{name}: no link to {wanted}"
            );
        }
        for link in links {
            let target = link.split('#').next().unwrap();
            assert!(
                reports.join(target).exists(),
                "{name}: {link} reaches nothing"
            );
        }
    }
}

/// Numbers for people: no e-notation and no trailing zeros in the parameter and verification
/// tables of any page, parameters in mm and g, and a unit column beside the values.
#[test]
fn tables_show_numbers_as_people_write_them() {
    let files = default_report();
    let page = rendered(&files, "fig10-linear-slip-stick.md");
    let tables: Vec<&str> = page
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| law"))
        .collect();
    assert!(tables.len() > 30);
    for line in &tables {
        for cell in line.split(" | ").skip(1) {
            let cell = cell.trim_end_matches(" |");
            if cell.starts_with('$') || cell.starts_with('(') {
                continue; // a formula or an equation number
            }
            assert!(
                !(cell.contains("e-") && cell.chars().next().is_some_and(|c| c.is_ascii_digit())),
                "e-notation: {line}"
            );
            if cell.contains('.') && cell.chars().all(|c| c.is_ascii_digit() || c == '.') {
                assert!(!cell.ends_with('0'), "trailing zero: {cell} in {line}");
            }
        }
    }
    assert!(
        page.contains("| m (block; hanging mass m' = m) | 60 | g |"),
        "{page}"
    );
    assert!(page.contains("| closed form | numeric | unit |"));
    assert!(page.contains("× 10⁻⁴ | W |"), "P in W with ×10ⁿ");
    let wood = rendered(&files, "fig15-double-slip-stick.md");
    assert!(wood.contains("| l (lever arm of the spring force) | 16 | mm |"));
}

/// Every formula of every HTML page the tool writes (report, handouts, worksheets and keys in
/// both languages, bench, check) is MathML Core that parses as XML (so `<` and `&` are
/// escaped), writes μ as U+03BC (never U+00B5 MICRO SIGN, which renders upright and reads
/// "micro"), marks the dots and bars over a symbol as accents, and holds no `merror`; no formula
/// fell back to its LaTeX source.
#[test]
fn every_formula_the_tool_writes_is_valid_mathml_core() {
    const ACCENTS: [&str; 7] = ["˙", "¨", "¯", "‾", "^", "ˆ", "~"];
    let dir = tempfile::tempdir().unwrap();
    let mut formulas = std::collections::BTreeSet::new();
    for page in common::write_every_page(dir.path()) {
        let html = std::fs::read_to_string(&page).unwrap();
        let name = page.strip_prefix(dir.path()).unwrap().display().to_string();
        assert!(
            !html.contains("<code>\\"),
            "{name}: a formula left as LaTeX"
        );
        let mut rest = html.as_str();
        while let Some(start) = rest.find("<math") {
            let end = rest[start..].find("</math>").expect("closed") + start + "</math>".len();
            formulas.insert(rest[start..end].to_string());
            rest = &rest[end..];
        }
    }
    for math in &formulas {
        let doc =
            roxmltree::Document::parse(math).unwrap_or_else(|e| panic!("not XML ({e}): {math}"));
        assert!(!math.contains('\u{b5}'), "micro sign: {math}");
        for node in doc.descendants().filter(|n| n.is_element()) {
            assert_ne!(node.tag_name().name(), "merror", "{math}");
            if node.text().is_some_and(|t| ACCENTS.contains(&t)) {
                let parent = node.parent_element().unwrap();
                assert!(
                    node.tag_name().name() == "mo"
                        && parent.tag_name().name() == "mover"
                        && parent.attribute("accent") == Some("true"),
                    "accent not marked: {math}"
                );
            }
        }
    }
    // The pages hold hundreds of distinct formulas (374 in November 2026).
    assert!(
        formulas.len() > 300,
        "only {} formulas found",
        formulas.len()
    );
}

/// Every relative link of the committed `reports/` (HTML `href`/`src`, Markdown `](…)`) names a
/// file that exists; the worksheets, their answer keys and the index link each other (issue 28).
#[test]
fn every_relative_link_of_the_reports_resolves_and_the_keys_are_linked() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    let mut pages = Vec::new();
    let mut stack = vec![root.clone()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if matches!(
                path.extension().and_then(|e| e.to_str()),
                Some("html" | "md")
            ) {
                pages.push(path);
            }
        }
    }
    let mut dead = Vec::new();
    for page in &pages {
        let text = std::fs::read_to_string(page).unwrap();
        let html = page.extension().is_some_and(|e| e == "html");
        let targets: Vec<String> = if html {
            ["href=\"", "src=\""]
                .iter()
                .flat_map(|open| text.split(open).skip(1))
                .filter_map(|rest| rest.split('"').next())
                .map(|t| t.replace("&#x2F;", "/"))
                .collect()
        } else {
            text.split("](")
                .skip(1)
                .filter_map(|rest| rest.split(')').next())
                .map(str::to_string)
                .collect()
        };
        for target in targets {
            let file = target.split('#').next().unwrap_or_default();
            if file.is_empty() || file.contains(':') || file.contains(' ') {
                continue; // a fragment, an absolute URL, a data: URI or prose in parentheses
            }
            let resolved = page.parent().unwrap().join(file);
            if !resolved.exists() {
                dead.push(format!("{} → {target}", page.display()));
            }
        }
    }
    assert!(dead.is_empty(), "dead links:\n{}", dead.join("\n"));

    let read = |p: &str| std::fs::read_to_string(root.join(p)).unwrap();
    for model in ["pulled-mass", "woodpecker", "belt"] {
        let folder = format!("worksheets/{model}");
        assert!(read("index.html")
            .contains(&format!("{folder}/answer-key.html").replace('/', "&#x2F;")));
        assert!(read("index.md").contains(&format!("({folder}/answer-key.md)")));
        assert!(read(&format!("{folder}/worksheets.html")).contains("href=\"answer-key.html\""));
        assert!(read(&format!("{folder}/answer-key.html")).contains("href=\"worksheets.html\""));
        assert!(read(&format!("{folder}/worksheets.md")).contains("(answer-key.md)"));
        assert!(read(&format!("{folder}/answer-key.md")).contains("(worksheets.md)"));
    }
}
