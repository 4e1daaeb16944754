//! The pulled mass for the presentation layer: scene, figures, tables, derivation, notes.

use super::scene::PulledFigure;
use super::{derivation, results, scene, scenes, sketch, tables, teaching, PulledMassParams};
use crate::derivation::{Step, StepKey, Value};
use crate::error::Result;
use crate::export::law_files;
use crate::models::paper;
use crate::present::vocab::{
    Builtin, Figure, FigureKinds, LawName, LawPoint, LawWords, Note, OutFile, PartStory, Phase,
    Scene, SceneCtx,
};
use crate::present::{DefaultSweep, Laws, Present, StandardScene};

impl Present for PulledMassParams {
    const SKETCH_WHAT: &'static str =
        "the block on the table pulled by F, pressed by the spring and the hanging mass under it";
    /// The pull F from 0.02 to 0.6 N in 0.01 N steps: slip-stick up to about 0.14 N, then
    /// continuous slip (from t = 0 above 2μsW = 0.47 N).
    const SWEEP: DefaultSweep = DefaultSweep {
        param: "force",
        from: 0.02,
        to: 0.6,
        steps: 59,
    };
    const PART: PartStory = PartStory {
        title: "The pulled mass",
        story: "A block on a table is pulled by a constant force F while a spring presses it \
                down with a mass hanging under the table: the normal force N oscillates, so \
                friction alternately holds the block and lets it slide. Read the pages in order: \
                the pull against the friction limits, then each kind of motion, then the price \
                of the linearized law that makes every result a closed formula.",
    };
    const LAWS: &'static [LawName] = paper::LAWS;
    const HANDOUT: Option<(&'static str, &'static str)> = Some((
        "fig10-linear-slip-stick",
        "the pulled mass from its equation of motion to every characteristic time, with the \
         numbers substituted; two A4 pages",
    ));
    const LAW_WORDS: LawWords = paper::LAW_WORDS;
    type Figure = PulledFigure;

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
                PulledFigure::Motion { periods: 2.0 }.kind(),
                PulledFigure::Forces.kind(),
                PulledFigure::Compare.kind(),
            ],
            claims: vec![1, 2, 3, 7],
            caption: "Motion of the pulled mass under both force laws, the competing forces, \
                      and the harmonic law against its linearization.",
        }
    }

    fn figures(&self, scene_id: &str, kind: PulledFigure) -> Result<Vec<Figure>> {
        scene::figures(scene_id, self, kind)
    }

    fn scene_tables(&self, scene: &Scene) -> Result<SceneCtx> {
        tables::scene_tables(scene, self)
    }

    fn derivation(&self) -> Vec<Step> {
        derivation::pulled_mass(self)
    }

    fn derivation_values(&self) -> Vec<Step<Value>> {
        derivation::pulled_mass_values(self)
    }

    fn handout_note(key: StepKey) -> Option<(Note, Option<&'static str>)> {
        let heading = None;
        teaching::STEPS
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, n)| (*n, heading))
    }

    fn equation_of_motion() -> &'static [(&'static str, &'static str)] {
        teaching::EQUATION_OF_MOTION
    }

    fn sketch(&self, phase: Phase) -> String {
        sketch::pulled_mass(self, phase)
    }

    fn laws(e: &results::Evaluation) -> Laws {
        Laws {
            runs: vec![
                Some(LawPoint::of(&e.harmonic)),
                Some(LawPoint::of(&e.linear)),
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
        for (law, run) in [("harmonic", &runs.harmonic), ("linear", &runs.linear)] {
            files.extend(law_files(law, run, "x_m", None));
        }
        Ok((evaluation, files))
    }
}
