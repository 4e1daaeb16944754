//! `stickslip worksheet`: one exercise sheet per student, each with its own parameter set in
//! the regime the teacher asks for, and an answer key that works every answer out from the
//! closed forms and confirms it with the exact integration of the linearized law.
//!
//! ```text
//! request (model, regime, questions, seed) → per student: draw (seeded) → round to 3 s.f.
//!     → regime of the rounded set? closed forms apply? → answers confirmed by the integration?
//!     (else draw again, at most MAX_ATTEMPTS times) → render (sheets, key, JSON)
//! ```
//!
//! Every student has a generator of its own, seeded from the request's seed, so the sheets are
//! the same whatever the number of threads.

pub mod answer;
pub mod exercise;
pub mod figure;
pub mod json;
pub mod moodle;
pub mod qti;
pub mod question;
pub mod render;
pub mod sample;

use crate::draws::Draws;
use indicatif::ProgressBar;
use rayon::prelude::*;

pub use crate::lang::Lang;
pub use answer::{Answer, Comparison, Value};
pub use question::{Kind, Question, Regime};
pub use render::{pdf, render};

use crate::error::{Error, Result};
use crate::models::{Capability, Model};

/// Draws per student before giving up on the requested regime and questions.
pub const MAX_ATTEMPTS: u32 = 20_000;
/// Largest number of students (one sheet each).
pub const MAX_STUDENTS: u32 = 500;
/// `--regime mixed`: the class drawn across every regime of the model, at least ⌊n/r⌋ of its
/// n students in each of the r regimes (the first n mod r regimes get one more), in a seeded
/// shuffled order; the sheets ask the questions that every regime can answer.
pub const MIXED: &str = "mixed";

/// What the teacher asks for.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    pub model: Model,
    pub students: u32,
    pub seed: u64,
    /// A regime id of [`question::regimes`], or [`MIXED`]; `None`: the model's standard regime.
    pub regime: Option<String>,
    /// Question keys of [`question::catalogue`]; `None`: every question that can be answered
    /// in the regime.
    pub questions: Option<Vec<String>>,
}

/// One student's sheet and key.
#[derive(Clone, Debug, PartialEq)]
pub struct Student {
    /// 1-based.
    pub number: u32,
    pub case: Model,
    pub answers: Vec<Answer>,
    /// SVG of v(t) from rest (in the answer key).
    pub key_figure: Option<String>,
}

/// The whole set: the request resolved, and every student.
#[derive(Clone, Debug, PartialEq)]
pub struct Worksheets {
    pub model: Model,
    pub seed: u64,
    pub regime: Regime,
    pub questions: Vec<&'static Question>,
    pub students: Vec<Student>,
}

/// The regime and the questions of `req`, checked against the model's catalogue.
pub fn resolve(req: &Request) -> Result<(Regime, Vec<&'static Question>)> {
    req.model.require(Capability::Exercise)?;
    let regimes = question::regimes(req.model);
    let regime = match &req.regime {
        None => regimes[0],
        Some(r) if r == MIXED => Regime::new(MIXED),
        Some(r) => regimes
            .iter()
            .copied()
            .find(|regime| regime.id() == r)
            .ok_or_else(|| Error::InvalidChoice {
                flag: "--regime",
                value: r.clone(),
                valid: format!(
                    "valid values for {} are {}",
                    req.model.id(),
                    regimes
                        .iter()
                        .map(|r| r.id())
                        .chain([MIXED])
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            })?,
    };
    let catalogue = question::catalogue(req.model);
    // Mixed: the questions of every regime.
    let in_regime: Vec<&'static Question> = catalogue
        .iter()
        .filter(|q| q.regimes.contains(&regime) || regimes.iter().all(|r| q.regimes.contains(r)))
        .collect();
    let Some(keys) = &req.questions else {
        return Ok((regime, in_regime));
    };
    for key in keys {
        let valid = if catalogue.iter().any(|q| q.key() == *key) {
            if in_regime.iter().any(|q| q.key() == *key) {
                continue;
            }
            format!(
                "in regime {} the valid values are {}",
                regime.id(),
                names(&in_regime)
            )
        } else {
            let all: Vec<&Question> = catalogue.iter().collect();
            format!("valid values for {} are {}", req.model.id(), names(&all))
        };
        return Err(Error::InvalidChoice {
            flag: "--questions",
            value: key.clone(),
            valid,
        });
    }
    // Sheet order, each question once.
    Ok((
        regime,
        in_regime
            .into_iter()
            .filter(|q| keys.iter().any(|k| *k == q.key()))
            .collect(),
    ))
}

fn names(questions: &[&Question]) -> String {
    questions
        .iter()
        .map(|q| q.key())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Draws, checks and answers every student's case, ticking `progress` once per student.
pub fn generate(req: &Request, progress: &ProgressBar) -> Result<Worksheets> {
    req.model.require(Capability::Exercise)?;
    if !(1..=MAX_STUDENTS).contains(&req.students) {
        return Err(crate::models::param::invalid(
            "students",
            req.students,
            format!("1 <= students <= {MAX_STUDENTS}"),
        ));
    }
    let (regime, questions) = resolve(req)?;
    let mut master = Draws::new(req.seed);
    let seeds: Vec<(u32, u64)> = (1..=req.students).map(|n| (n, master.word())).collect();
    let per_student = if regime.id() == MIXED {
        mixed(question::regimes(req.model), req.students, &mut master)
    } else {
        vec![regime; req.students as usize]
    };
    let students = seeds
        .par_iter()
        .zip(&per_student)
        .map(|(&(number, seed), &regime)| {
            let s = student(req.model, regime, &questions, number, seed, MAX_ATTEMPTS);
            progress.inc(1);
            s
        })
        .collect::<Result<Vec<_>>>()?;
    progress.finish_and_clear();
    Ok(Worksheets {
        model: req.model,
        seed: req.seed,
        regime,
        questions,
        students,
    })
}

/// The regimes of `n` students drawn across `regimes` ([`MIXED`]): each regime ⌊n/r⌋ times, the
/// first n mod r once more, shuffled (Fisher–Yates) by `draws`.
fn mixed(regimes: &[Regime], n: u32, draws: &mut Draws) -> Vec<Regime> {
    let mut out: Vec<Regime> = regimes.iter().copied().cycle().take(n as usize).collect();
    for i in (1..out.len()).rev() {
        let j = (draws.word() % (i as u64 + 1)) as usize;
        out.swap(i, j);
    }
    out
}

/// One student's case in `regime` whose every answer is confirmed, from at most `attempts`
/// draws of the generator seeded with `seed`.
pub fn student(
    model: Model,
    regime: Regime,
    questions: &[&'static Question],
    number: u32,
    seed: u64,
    attempts: u32,
) -> Result<Student> {
    let mut rng = Draws::new(seed);
    for _ in 0..attempts {
        let case = sample::draw(model, regime, &mut rng)?;
        if case.closed_form_regime() != regime.id() {
            continue;
        }
        let steps = answer::steps(&case);
        if !answer::closed_forms_apply(&steps, questions) {
            continue;
        }
        if let Some(a) = answer::answer(&case, &steps, questions)? {
            return Ok(Student {
                number,
                case,
                answers: a.answers,
                key_figure: a.key_figure,
            });
        }
    }
    Err(Error::Unreachable {
        regime: regime.id().to_string(),
        attempts,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::pulled_mass::formula::Regime as PulledRegime;
    use crate::models::woodpecker::formula::OrbitRegime;

    fn request(model: Model, regime: Option<&str>, questions: Option<&[&str]>) -> Request {
        Request {
            model,
            students: 1,
            seed: 1,
            regime: regime.map(str::to_string),
            questions: questions.map(|q| q.iter().map(|k| k.to_string()).collect()),
        }
    }

    fn keys(questions: &[&Question]) -> Vec<String> {
        questions.iter().map(|q| q.key()).collect()
    }

    /// Every regime a teacher can ask for gives a sheet of at least this many questions.
    const MIN_QUESTIONS: usize = 4;

    #[test]
    fn every_regime_asks_enough_questions() {
        for model in Model::offering(Capability::Exercise) {
            for regime in question::regimes(model) {
                let (_, qs) = resolve(&request(model, Some(regime.id()), None)).unwrap();
                assert!(
                    qs.len() >= MIN_QUESTIONS,
                    "{} {}: {:?}",
                    model.id(),
                    regime.id(),
                    keys(&qs)
                );
            }
        }
    }

    #[test]
    fn defaults_are_the_standard_regime_and_every_question_it_allows() {
        let (regime, qs) =
            resolve(&request(Model::PulledMass(Default::default()), None, None)).unwrap();
        assert_eq!(regime, Regime::new(PulledRegime::SlipStick.id()));
        // Every question but the acceleration at the onset, asked beyond the same period.
        assert_eq!(
            qs.len() + 1,
            question::catalogue(Model::PulledMass(Default::default())).len()
        );
        let (regime, qs) =
            resolve(&request(Model::Woodpecker(Default::default()), None, None)).unwrap();
        assert_eq!(regime, Regime::new(OrbitRegime::DoubleSlipStick.id()));
        assert_eq!(
            qs.len() + 1,
            question::catalogue(Model::Woodpecker(Default::default())).len()
        );
        let late = request(
            Model::PulledMass(Default::default()),
            Some("slip_stick_late"),
            None,
        );
        let (_, qs) = resolve(&late).unwrap();
        assert_eq!(
            keys(&qs),
            ["t_slip", "a_slip", "v_max", "regime", "read_t_slip"]
        );
    }

    #[test]
    fn choices_outside_the_catalogue_name_the_flag_and_the_valid_values() {
        let err = resolve(&request(
            Model::Woodpecker(Default::default()),
            Some("no_slip"),
            None,
        ))
        .unwrap_err();
        let msg = err.to_string();
        assert!(
            msg.contains("--regime") && msg.contains("single_slip_stick"),
            "{msg}"
        );
        let late = request(
            Model::PulledMass(Default::default()),
            Some("slip_stick_late"),
            Some(&["power"]),
        );
        let msg = resolve(&late).unwrap_err().to_string();
        assert!(
            msg.contains("--questions") && msg.contains("'power'"),
            "{msg}"
        );
        assert!(msg.contains("in regime slip_stick_late"), "{msg}");
        let mut zero = request(Model::PulledMass(Default::default()), None, None);
        zero.students = 0;
        assert!(generate(&zero, &ProgressBar::hidden())
            .unwrap_err()
            .to_string()
            .contains("students"));
    }

    #[test]
    fn a_regime_out_of_reach_of_the_draws_is_an_error_not_a_loop() {
        let req = request(
            Model::Woodpecker(Default::default()),
            Some("single_slip_stick"),
            Some(&["t_slip_1"]),
        );
        let (regime, qs) = resolve(&req).unwrap();
        // About one draw in a thousand is single slip-stick with a phase-I slip from rest.
        let err = student(Model::Woodpecker(Default::default()), regime, &qs, 1, 5, 3).unwrap_err();
        assert_eq!(
            err,
            Error::Unreachable {
                regime: "single_slip_stick".to_string(),
                attempts: 3
            }
        );
        assert!(err.to_string().contains("--regime"));
        assert!(student(
            Model::Woodpecker(Default::default()),
            regime,
            &qs,
            1,
            5,
            MAX_ATTEMPTS
        )
        .is_ok());
    }

    /// Every regime with its default questions is drawn in well under [`MAX_ATTEMPTS`] draws
    /// per student, so that 500 students take seconds: the woodpecker's never-halting regime
    /// once asked for a reading of a first maximum that its figure cannot show (4,000 draws
    /// per student, 306 s for 500).
    #[test]
    fn every_regime_is_drawn_in_a_bounded_number_of_draws() {
        for model in Model::offering(Capability::Exercise) {
            for regime in question::regimes(model) {
                let req = request(model, Some(regime.id()), None);
                let (regime, qs) = resolve(&req).unwrap();
                for seed in 0..10 {
                    student(model, regime, &qs, 1, seed, 2_000)
                        .unwrap_or_else(|e| panic!("{} {}: {e}", model.id(), regime.id()));
                }
            }
        }
    }
}
