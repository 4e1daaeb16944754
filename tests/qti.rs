//! `stickslip worksheet --format qti`: the QTI 1.2 package for Canvas, read back as Canvas
//! reads it. The zip holds the manifest, the assessment and the figures the manifest lists,
//! with fixed times (the same sheets give the same bytes); the assessment has one question group
//! per question of the sheet drawing one item, one item per student; every numerical item
//! accepts the answer-key.json value and the interval ± its tolerance (one unit in the third
//! significant figure, the reading tolerance for the figure question); every regime item is a
//! multiple choice whose one right option is the key's regime.

use std::collections::HashMap;
use std::fs;
use std::io::{Cursor, Read};
use std::path::Path;

use assert_cmd::Command;
use serde_json::Value;

use stickslip::models::Model;
use stickslip::worksheet::moodle::tolerance;
use stickslip::worksheet::question::{regime_option, regime_rules};

const QTI_NS: &str = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2";

/// Writes the package and the key of `students` students of `model` (mixed regimes) to `out`.
fn package(model: &str, students: u32, out: &Path) -> (Vec<u8>, Value) {
    Command::cargo_bin("stickslip")
        .unwrap()
        .args([
            "worksheet",
            "--model",
            model,
            "--regime",
            "mixed",
            "--seed",
            "11",
        ])
        .args([
            "--students",
            &students.to_string(),
            "--format",
            "qti",
            "--out",
        ])
        .arg(out)
        .assert()
        .success();
    let zip = fs::read(out.join("worksheets.qti.zip")).unwrap();
    let key = serde_json::from_slice(&fs::read(out.join("answer-key.json")).unwrap()).unwrap();
    (zip, key)
}

/// Every entry of the zip by name; each must carry the zip epoch as its time.
fn entries(zip: &[u8]) -> HashMap<String, Vec<u8>> {
    let mut archive = zip::ZipArchive::new(Cursor::new(zip)).unwrap();
    let mut out = HashMap::new();
    for i in 0..archive.len() {
        let mut f = archive.by_index(i).unwrap();
        let name = f.name().unwrap().to_string();
        assert_eq!(
            f.last_modified(),
            Some(zip::DateTime::DEFAULT),
            "{name} has a time"
        );
        let mut bytes = Vec::new();
        f.read_to_end(&mut bytes).unwrap();
        out.insert(name, bytes);
    }
    out
}

fn child<'a, 'i>(node: roxmltree::Node<'a, 'i>, name: &str) -> roxmltree::Node<'a, 'i> {
    node.children()
        .find(|n| n.has_tag_name(name))
        .unwrap_or_else(|| panic!("<{}> has no <{name}>", node.tag_name().name()))
}

fn descendants<'a, 'i>(
    node: roxmltree::Node<'a, 'i>,
    name: &'a str,
) -> impl Iterator<Item = roxmltree::Node<'a, 'i>> + 'a {
    node.descendants().filter(move |n| n.has_tag_name(name))
}

fn number(node: roxmltree::Node) -> f64 {
    node.text().unwrap().parse().unwrap()
}

/// The item's metadata field `label`.
fn field(item: roxmltree::Node, label: &str) -> String {
    descendants(item, "qtimetadatafield")
        .find(|f| child(*f, "fieldlabel").text() == Some(label))
        .map(|f| child(f, "fieldentry").text().unwrap().to_string())
        .unwrap_or_else(|| panic!("no {label}"))
}

/// Checks the package against the key; returns the number of items checked.
fn check(zip: &[u8], key: &Value) -> usize {
    let files = entries(zip);
    let manifest = std::str::from_utf8(&files["imsmanifest.xml"]).unwrap();
    let manifest = roxmltree::Document::parse(manifest).unwrap();
    let resources: Vec<_> = descendants(manifest.root_element(), "resource").collect();
    let assessments: Vec<_> = resources
        .iter()
        .filter(|r| r.attribute("type") == Some("imsqti_xmlv1p2"))
        .collect();
    assert_eq!(assessments.len(), 1);
    let href = child(*assessments[0], "file").attribute("href").unwrap();
    for r in &resources {
        let file = child(*r, "file").attribute("href").unwrap();
        assert!(
            files.contains_key(file),
            "manifest lists {file}, not in the zip"
        );
    }
    // Every file of the zip is the manifest or listed in it.
    assert_eq!(files.len(), resources.len() + 1);

    let xml = std::str::from_utf8(&files[href]).unwrap();
    let doc = roxmltree::Document::parse(xml).unwrap();
    let root = doc.root_element();
    assert_eq!(root.tag_name().namespace(), Some(QTI_NS));
    let top = child(child(root, "assessment"), "section");
    let groups: Vec<_> = top
        .children()
        .filter(|n| n.has_tag_name("section"))
        .collect();
    let questions: Vec<&str> = key["questions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|q| q.as_str().unwrap())
        .collect();
    assert_eq!(groups.len(), questions.len(), "one group per question");
    let model = Model::defaults()
        .into_iter()
        .find(|m| m.id() == key["model"])
        .unwrap();
    let students = key["students"].as_array().unwrap();
    let mut checked = 0;
    for (group, question) in groups.iter().zip(&questions) {
        assert!(group.attribute("title").unwrap().ends_with(question));
        let selection = child(child(*group, "selection_ordering"), "selection");
        assert_eq!(child(selection, "selection_number").text(), Some("1"));
        let items: Vec<_> = group
            .children()
            .filter(|n| n.has_tag_name("item"))
            .collect();
        let answered: Vec<(&Value, &Value)> = students
            .iter()
            .filter_map(|s| {
                let a = s["answers"]
                    .as_array()?
                    .iter()
                    .find(|a| a["key"] == *question)?;
                Some((s, a))
            })
            .collect();
        assert_eq!(
            items.len(),
            answered.len(),
            "{question}: one item per student"
        );
        for (item, (student, answer)) in items.iter().zip(answered) {
            let ident = item.attribute("ident").unwrap();
            let n = student["student"].as_u64().unwrap();
            assert!(ident.ends_with(&format!("-s{n:03}")), "{ident}");
            let text = descendants(child(*item, "presentation"), "mattext")
                .next()
                .unwrap()
                .text()
                .unwrap();
            // Self-contained: the parameters and the symbols' definitions are in the text.
            assert!(text.contains("<table>") && text.contains("\\("), "{ident}");
            if let Some(src) = text.split("src=\"").nth(1) {
                let path = src.split('"').next().unwrap();
                let path = path.strip_prefix("%24IMS-CC-FILEBASE%24/").unwrap();
                assert!(files.contains_key(path), "{ident} shows {path}");
            }
            let condition = child(
                descendants(*item, "respcondition")
                    .find(|r| r.attribute("continue") == Some("No"))
                    .unwrap(),
                "conditionvar",
            );
            match &answer["value"] {
                Value::Number(x) => {
                    let x = x.as_f64().unwrap();
                    assert_eq!(field(*item, "question_type"), "numerical_question");
                    let tol = answer["tolerance"].as_f64().unwrap_or_else(|| tolerance(x));
                    let exact = number(descendants(condition, "varequal").next().unwrap());
                    let low = number(descendants(condition, "vargte").next().unwrap());
                    let high = number(descendants(condition, "varlte").next().unwrap());
                    assert_eq!(exact, x, "{ident}: the key's value");
                    assert!(tol > 0.0, "{ident}");
                    assert!((low - (x - tol)).abs() <= 1e-12 * x.abs(), "{ident}: {low}");
                    assert!(
                        (high - (x + tol)).abs() <= 1e-12 * x.abs(),
                        "{ident}: {high}"
                    );
                }
                Value::String(regime) => {
                    assert_eq!(field(*item, "question_type"), "multiple_choice_question");
                    let labels: Vec<&str> = descendants(*item, "response_label")
                        .map(|l| l.attribute("ident").unwrap())
                        .collect();
                    let rules = regime_rules(model);
                    assert_eq!(labels.len(), rules.len(), "{ident}");
                    let right: Vec<&str> = descendants(condition, "varequal")
                        .map(|v| v.text().unwrap())
                        .collect();
                    assert_eq!(right.len(), 1, "{ident}");
                    let at = labels.iter().position(|l| *l == right[0]).unwrap();
                    assert_eq!(rules[at].0.id(), regime_option(model, regime), "{ident}");
                }
                other => panic!("{ident}: {other}"),
            }
            checked += 1;
        }
    }
    checked
}

#[test]
fn the_package_holds_one_group_per_question_and_the_keys_answers() {
    let tmp = tempfile::tempdir().unwrap();
    for model in ["pulled-mass", "woodpecker"] {
        let (zip, key) = package(model, 7, &tmp.path().join(model));
        let items = check(&zip, &key);
        assert!(items >= 7 * 2, "{model}: {items} items");
    }
}

#[test]
fn the_same_sheets_give_the_same_bytes() {
    let tmp = tempfile::tempdir().unwrap();
    let (a, _) = package("woodpecker", 3, &tmp.path().join("a"));
    let (b, _) = package("woodpecker", 3, &tmp.path().join("b"));
    assert!(a == b, "two runs differ");
}
