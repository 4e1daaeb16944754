//! What the presentation layer asks of a model: its standard scene and figures, its report
//! tables, its worked derivation, its teaching notes, its terminal tables and CSV files.
//! Implemented by each model's params struct in `src/models/<name>/present.rs`; the report,
//! handout, worksheet, sweep and command line reach it through [`crate::models::with_model!`].
//! The types of its signatures live in [`vocab`], a leaf that names no model.

use crate::derivation::{Expr, Step, StepKey, Value};
use crate::error::Result;
use crate::models::Physics;
use vocab::{
    Builtin, Figure, FigureKind, FigureKinds, LawName, LawPoint, LawWords, Note, OutFile,
    PartStory, Phase, Scene, SceneCtx, SweepColumn,
};

pub mod spec;
pub mod vocab;

/// The figures, claims and caption of a user's scenario of this model.
pub struct StandardScene {
    pub figures: Vec<FigureKind>,
    pub claims: Vec<u8>,
    pub caption: &'static str,
}

/// The grid `stickslip sweep` runs without a model: one parameter over the paper's set,
/// across the regimes it shows.
pub struct DefaultSweep {
    /// A numeric parameter of the model (its flag's name).
    pub param: &'static str,
    /// First and last grid values (SI units, as the model flag).
    pub from: f64,
    pub to: f64,
    /// Grid points, both ends included.
    pub steps: u32,
}

/// The runs of an evaluation as a sweep or a table reads them: one per law of
/// [`Present::LAWS`], in that order.
pub struct Laws {
    /// The outcome of each law's run; `None` where the law does not exist for the parameters
    /// (the woodpecker's linear law with an undefined counterpart).
    pub runs: Vec<Option<LawPoint>>,
    /// The regime id of the closed forms.
    pub closed_form_regime: &'static str,
}

/// The presentation of a model.
pub trait Present: Physics {
    /// What the sketch of the apparatus shows, for its caption ("the block on the table …").
    const SKETCH_WHAT: &'static str;
    /// The instant whose forces the report's sketch ([`Phase::Slipping`]) draws, for its
    /// caption.
    const SKETCH_WHEN: &'static str = "at the slip onset";
    /// The sweep of `stickslip sweep` without a model.
    const SWEEP: DefaultSweep;
    /// The model's part of the report: its title and story.
    const PART: PartStory;
    /// The model's laws, in the order of [`Laws::runs`] (the first is the one a sweep follows
    /// for its regime changes).
    const LAWS: &'static [LawName];
    /// How its pages name what the closed forms are checked against.
    const LAW_WORDS: LawWords;
    /// The model's own figure kinds (an enum made with [`vocab::figure_kinds!`]).
    type Figure: FigureKinds;
    /// The words of the model in language `code` ("en", "it"): TOML whose tables are merged
    /// into that language's catalogue (the model's section, `[<id>]`, and any `[phrases]`);
    /// `None` for a language it has no words in (a test requires every language).
    fn words(code: &str) -> Option<&'static str>;
    /// The built-in scene whose handout the default report writes, and what it teaches (none
    /// by default).
    const HANDOUT: Option<(&'static str, &'static str)> = None;
    /// The built-in scenes of the default report, in order (none by default).
    fn builtin_scenes() -> Vec<Builtin> {
        Vec::new()
    }
    /// The standard figures, claims and caption of a scenario of this model.
    fn standard_scene(&self) -> StandardScene;
    /// The figures of `kind` for the scene `scene_id`.
    fn figures(&self, scene_id: &str, kind: Self::Figure) -> Result<Vec<Figure>>;
    /// The figures of a shared [`FigureKind`]: refused when the model has no such kind.
    fn figures_of(&self, scene_id: &str, kind: FigureKind) -> Result<Vec<Figure>> {
        let own = Self::Figure::from_kind(kind).ok_or_else(|| crate::error::Error::Figure {
            id: format!("{scene_id}-{}", kind.name),
            reason: format!("the {} model draws no figure `{}`", Self::ID, kind.name),
        })?;
        self.figures(scene_id, own)
    }
    /// The report's tables of a scene of this model.
    fn scene_tables(&self, scene: &Scene) -> Result<SceneCtx>;
    /// The worked substitutions of every closed form.
    fn derivation(&self) -> Vec<Step>;
    /// [`Present::derivation`] as values only (no expression tree), the same numbers bit for bit:
    /// what a caller that reads only the steps' values uses (`stickslip check` per set).
    fn derivation_values(&self) -> Vec<Step<Value>> {
        self.derivation()
            .into_iter()
            .map(|s| Step {
                expr: Value(Expr::eval(&s.expr)),
                key: s.key,
                symbol: s.symbol,
                equation: s.equation,
                value: s.value,
                unit: s.unit,
                reason: s.reason,
            })
            .collect()
    }
    /// How the handout explains the step of `key`, and the heading before it.
    fn handout_note(key: StepKey) -> Option<(Note, Option<&'static str>)>;
    /// The equation of motion, line by line: (formula, its physics).
    fn equation_of_motion() -> &'static [(&'static str, &'static str)];
    /// A sketch of the apparatus with these parameters and the forces of `phase` (SVG).
    fn sketch(&self, phase: Phase) -> String;
    /// The laws of an evaluation.
    fn laws(e: &Self::Evaluation) -> Laws;
    /// The model's own quantities that `sweep` tabulates after the laws' columns and plots
    /// instead of v̄ and slips per period (none by default: a model whose body advances is
    /// swept by its mean speed).
    fn sweep_columns() -> Vec<SweepColumn<Self::Evaluation>> {
        Vec::new()
    }
    /// The evaluation as terminal tables.
    fn text(e: &Self::Evaluation) -> String;
    /// The evaluation, and the CSV files of its runs (time series and events of both laws).
    fn evaluate_with_csv(&self, periods: u32) -> Result<(Self::Evaluation, Vec<OutFile>)>;
}

#[cfg(test)]
mod tests {
    use crate::models::Model;

    /// The shared presentation names no model: a model with [`super::Present`] plugs in from
    /// its folder and its registry line alone. Every file of these modules, test modules cut
    /// off, is searched for each registered model's module path (`models::pulled_mass`) and
    /// enum variant (`Model::PulledMass`), the test build's dummy included; so are the shared
    /// half of `stickslip fit` (the model's fit is its capability) and the JSON Schemas.
    #[test]
    fn no_shared_presentation_module_names_a_model() {
        const SHARED: [&str; 15] = [
            "check",
            "classroom.rs",
            "derivation",
            "format.rs",
            "claims",
            "report",
            "present",
            "handout",
            "worksheet",
            "sweep",
            "output",
            "lang",
            "explorer",
            "fit",
            "schema.rs",
        ];
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
        let names: Vec<(String, String)> = Model::defaults()
            .iter()
            .map(|m| {
                let variant = format!("{m:?}");
                let variant = variant.split('(').next().unwrap_or_default().to_string();
                (m.id().replace('-', "_"), variant)
            })
            .collect();
        assert!(names.len() >= 3, "{names:?}");
        let mut files = Vec::new();
        let mut stack: Vec<_> = SHARED.iter().map(|d| root.join(d)).collect();
        while let Some(dir) = stack.pop() {
            if dir.is_file() {
                files.push(dir);
                continue;
            }
            let Ok(entries) = std::fs::read_dir(&dir) else {
                continue;
            };
            for entry in entries.flatten() {
                let path = entry.path();
                if path.is_dir() {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == "rs")
                    && path.file_name().is_some_and(|n| n != "tests.rs")
                {
                    files.push(path);
                }
            }
        }
        assert!(files.len() > 20, "{}", files.len());
        for path in files {
            let text = std::fs::read_to_string(&path).unwrap();
            let code = text
                .split("#[cfg(test)]\nmod tests")
                .next()
                .unwrap_or_default();
            for (module, variant) in &names {
                for needle in [
                    format!("models::{module}"),
                    format!("Model::{variant}"),
                    format!("{module}::"),
                ] {
                    assert!(
                        !code.contains(&needle),
                        "{} names the model: {needle}",
                        path.display()
                    );
                }
            }
        }
    }

    /// Each law's `summary` names the key of its summary in the model's `eval --json` (an
    /// object, or null for a law that does not exist for the parameters), and every law has
    /// a CSV time series of its id: what the Python package reads by these names.
    #[test]
    fn every_law_names_its_summary_and_its_csv_files() {
        fn check<M: super::Present>(p: &M) {
            let (evaluation, files) = p.evaluate_with_csv(2).unwrap();
            let json = serde_json::to_value(&evaluation).unwrap();
            for law in M::LAWS {
                let summary = &json[law.summary];
                assert!(
                    summary.is_object(),
                    "{}: {} is {summary}",
                    M::ID,
                    law.summary
                );
                let series = format!("timeseries_{}.csv", law.id);
                assert!(
                    files.iter().any(|f| f.path.to_string_lossy() == series),
                    "{}: no {series}",
                    M::ID
                );
            }
        }
        let presented = Model::offering(crate::models::Capability::Present);
        assert!(presented.len() >= 3);
        for m in presented {
            crate::models::with_capability!(&m, present, p => check(p), else unreachable!());
        }
    }
}
