//! The words of the handout: the equation of motion of each model in symbols (physics.md §1,
//! §2–3), each line with a sentence of physics.

use crate::report::scene::Setup;

/// (LaTeX, sentence) lines of the pulled mass: physics.md §1.1–1.2.
const PULLED_MASS: &[(&str, &str)] = &[
    (
        r"(m + m')\,\ddot x = 2m\,\ddot x = F - \mu_d\,N(t) \quad (\dot x > 0)",
        "While the block slips, the hanging mass moves with it: the inertial mass is 2m (14); \
         the pull F is opposed by dynamic friction on the normal force N(t) (5).",
    ),
    (
        r"N(t) = W\,(1 + \cos\omega t), \quad W = mg, \quad \omega = \sqrt{k/m'}",
        "The hanging mass oscillates on its spring and presses the block with a force between \
         2W (t = 0) and 0 (t = T/2) (8).",
    ),
    (
        r"N(\tau) = 2W\,|1 - 2\tau|, \quad \tau = t/T\;\text{mod}\;1",
        "The paper's linearized law: a triangle wave with the same extremes. The closed forms \
         below are exact for it.",
    ),
    (
        r"\ddot x = g\left[\frac{\varphi}{2} - \mu_d\,|1 - 2\tau|\right], \quad \varphi = F/W",
        "Dividing by 2m: the acceleration while slipping, in units of g (15).",
    ),
    (
        r"F \le \mu_s\,N(t) \;\Rightarrow\;\dot x = 0",
        "The block stays stuck while the pull does not exceed the static capacity; it slips at \
         the first crossing and sticks again when its speed returns to zero.",
    ),
];

/// (LaTeX, sentence) lines of the woodpecker: physics.md §2–3.1.
const WOODPECKER: &[(&str, &str)] = &[
    (
        r"m_S\,\ddot y = W_S + F_e(t) - 2\lambda\mu_d\,|F_e(t)| \quad (\dot y > 0)",
        "The sleeve (y downward) is driven by its weight W_S = m_S g and the spring force F_e, \
         and braked by dynamic friction at its two contacts with the pole.",
    ),
    (
        r"F_e(t) = k\,(z_0 + d_0\cos\omega t), \quad \omega = \sqrt{k/m_W}",
        "The bird oscillates on the spring; the spring force on the sleeve is prescribed.",
    ),
    (
        r"N = \lambda\,|F_e|, \quad \lambda = l/h",
        "Torque balance about the sleeve centre: each contact carries λ|F_e|, so the friction \
         capacity is 2λμ|F_e|.",
    ),
    (
        r"F_e(t) = k\,(\delta_0 + \zeta(t)), \quad \zeta(t) = \zeta_0\,(1 - t/\tau)\;\;(0 \le t \le 2\tau), \quad \tau = T/4",
        "The linearized law: a triangle wave ζ falling from ζ0 to −ζ0 and back (37), the \
         counterpart of the harmonic z0, d0. The closed forms below are exact for it.",
    ),
    (
        r"|W_S + F_e| \le 2\lambda\mu_s\,|F_e| \;\Rightarrow\;\dot y = 0",
        "The sleeve stays stuck while the driving force does not exceed the static capacity; \
         it slips at the first crossing and sticks again when its speed returns to zero.",
    ),
];

/// The equation of motion of the scene's model, line by line.
pub fn equation_of_motion(setup: &Setup) -> &'static [(&'static str, &'static str)] {
    match setup {
        Setup::PulledMass(_) => PULLED_MASS,
        Setup::Woodpecker(_) => WOODPECKER,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::math::mathml;

    #[test]
    fn every_line_renders_to_mathml() {
        for (tex, _) in PULLED_MASS.iter().chain(WOODPECKER) {
            let m = mathml(tex);
            assert!(m.starts_with("<math"), "{tex}: {m}");
            assert!(!m.contains("merror") && !m.contains("&amp;"), "{tex}: {m}");
        }
    }
}
