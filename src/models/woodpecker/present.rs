//! The woodpecker for the presentation layer: scene, figures, tables, derivation, notes.

use super::scene::WoodFigure;
use super::{
    derivation, results, scene, scenes, sketch, spring_coordinate, tables, teaching,
    WoodpeckerParams,
};
use crate::derivation::{Step, StepKey, Value};
use crate::error::Result;
use crate::export::law_files;
use crate::models::paper;
use crate::models::LawKind;
use crate::present::vocab::{
    Builtin, Figure, FigureKinds, LawName, LawPoint, LawWords, Note, OutFile, PartStory, Phase,
    Scene, SceneCtx,
};
use crate::present::{DefaultSweep, Laws, Present, StandardScene};

impl Present for WoodpeckerParams {
    const SKETCH_WHAT: &'static str = "the sleeve on the pole, tilted by the spring that carries \
                                       the bird, gripping at two contacts";
    /// The offset z0 from 0 to 12 mm in 0.2 mm steps: the double slip-stick, the slip that
    /// slows down without stopping, one slip-stick, and no slip.
    const SWEEP: DefaultSweep = DefaultSweep {
        param: "z0",
        from: 0.0,
        to: 0.012,
        steps: 61,
    };
    const PART: PartStory = PartStory {
        title: "The falling woodpecker",
        story: "The toy woodpecker slides down its pole in jerks: the bird swings on a spring, \
                tilting the sleeve so that it grips the pole and lets go twice per swing. The \
                same stick-slip rule as in Part 1, with the grip set by the lever l/h; the pages \
                follow one period phase by phase, then the regimes and the real toy.",
    };
    const LAWS: &'static [LawName] = paper::LAWS;
    const HANDOUT: Option<(&'static str, &'static str)> = Some((
        "fig15-double-slip-stick",
        "the woodpecker's two phases from the equation of motion to the mean speed; two A4 pages",
    ));
    const LAW_WORDS: LawWords = paper::LAW_WORDS;
    type Figure = WoodFigure;

    fn words(code: &str) -> Option<&'static str> {
        match code {
            "en" => Some(include_str!("lang/en.toml")),
            "it" => Some(include_str!("lang/it.toml")),
            _ => None,
        }
    }

    fn builtin_scenes() -> Vec<Builtin> {
        scenes::builtins()
    }

    fn standard_scene(&self) -> StandardScene {
        StandardScene {
            figures: vec![
                WoodFigure::Motion { periods: 2.0 }.kind(),
                WoodFigure::Forces.kind(),
                WoodFigure::Spring.kind(),
            ],
            claims: vec![3, 4, 5, 6, 7, 8],
            caption: "Motion of the woodpecker's sleeve under both force laws, the forces that \
                      decide the slip, and the linear counterparts of the spring coordinate.",
        }
    }

    fn figures(&self, scene_id: &str, kind: WoodFigure) -> Result<Vec<Figure>> {
        scene::figures(scene_id, self, kind)
    }

    fn scene_tables(&self, scene: &Scene) -> Result<SceneCtx> {
        tables::scene_tables(scene, self)
    }

    fn derivation(&self) -> Vec<Step> {
        derivation::woodpecker(self)
    }

    fn derivation_values(&self) -> Vec<Step<Value>> {
        derivation::woodpecker_values(self)
    }

    fn handout_note(key: StepKey) -> Option<(Note, Option<&'static str>)> {
        let heading = teaching::HEADINGS
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, h)| *h);
        teaching::STEPS
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, n)| (*n, heading))
    }

    fn equation_of_motion() -> &'static [(&'static str, &'static str)] {
        teaching::EQUATION_OF_MOTION
    }

    fn sketch(&self, phase: Phase) -> String {
        sketch::woodpecker(self, phase)
    }

    fn laws(e: &results::Evaluation) -> Laws {
        Laws {
            runs: vec![
                Some(LawPoint::of(&e.harmonic)),
                e.linear.as_ref().map(LawPoint::of),
            ],
            closed_form_regime: e.closed_form.regime.id(),
        }
    }

    fn text(e: &results::Evaluation) -> String {
        tables::text(e)
    }

    fn evaluate_with_csv(&self, periods: u32) -> Result<(results::Evaluation, Vec<OutFile>)> {
        let (evaluation, runs) = results::evaluate_with_runs(self, periods, true)?;
        let mut files = Vec::with_capacity(4);
        let laws = [
            ("harmonic", LawKind::Harmonic, Some(&runs.harmonic)),
            ("linear", LawKind::Linear, runs.linear.as_ref()),
        ];
        for (name, law, run) in laws {
            let Some(run) = run else { continue };
            // The bird's position y_W = y_S + z beside the sleeve's.
            let spring = move |t: f64| spring_coordinate(self, law, t);
            files.extend(law_files(name, run, "y_m", Some(&spring)));
        }
        Ok((evaluation, files))
    }
}
