//! The pulled mass for the presentation layer: scene, figures, tables, derivation, notes.

use super::{derivation, results, scene, sketch, tables, teaching, PulledMassParams};
use crate::derivation::{Step, StepKey, Value};
use crate::error::Result;
use crate::export::law_files;
use crate::present::vocab::{Figure, FigureKind, Note, OutFile, Phase, Scene, SceneCtx};
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

    fn standard_scene(&self) -> StandardScene {
        StandardScene {
            figures: vec![
                FigureKind::PulledMotion { periods: 2.0 },
                FigureKind::PulledForces,
                FigureKind::PulledCompare,
            ],
            claims: vec![1, 2, 3, 7],
            caption: "Motion of the pulled mass under both force laws, the competing forces, \
                      and the harmonic law against its linearization.",
        }
    }

    fn figures(&self, scene_id: &str, kind: FigureKind) -> Result<Vec<Figure>> {
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

    fn laws(e: &results::Evaluation) -> Laws<'_> {
        Laws {
            harmonic: &e.harmonic,
            linear: Some(&e.linear),
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
