//! Portable seeded random numbers, for worksheets and synthetic data: a seed draws the same
//! numbers on every platform and after any upgrade of `rand`.
//!
//! The stream is ChaCha8 (`rand_chacha`, fixed by the ChaCha specification) keyed by the seed's
//! little-endian bytes (not `seed_from_u64`, whose expansion `rand_core` may change); the
//! mapping from its 64-bit words to numbers is ours:
//!
//! ```text
//! unit()          = (word >> 11) · 2⁻⁵³                  uniform in [0, 1), 53 bits
//! between(a, b)   = a + (b − a) · unit()                 uniform in [a, b)
//! gaussian()      = √(−2 ln(1 − u₁)) · cos(2π u₂)        Box–Muller, one of the pair
//! ```

use rand_chacha::rand_core::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A seeded stream of draws.
#[derive(Clone, Debug)]
pub struct Draws(ChaCha8Rng);

impl Draws {
    /// The stream of `seed`.
    pub fn new(seed: u64) -> Self {
        let mut key = [0u8; 32];
        key[..8].copy_from_slice(&seed.to_le_bytes());
        Self(ChaCha8Rng::from_seed(key))
    }

    /// The next 64-bit word (e.g. the seed of a sub-stream).
    pub fn word(&mut self) -> u64 {
        self.0.next_u64()
    }

    /// Uniform in [0, 1), from the top 53 bits of the next word.
    pub fn unit(&mut self) -> f64 {
        (self.word() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [lo, hi).
    pub fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// A standard normal deviate (Box–Muller).
    pub fn gaussian(&mut self) -> f64 {
        let u1 = self.unit();
        let u2 = self.unit();
        (-2.0 * (1.0 - u1).ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }

    /// Log-uniform in [lo, hi) (0 < lo < hi): every decade as likely.
    pub fn log_between(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stream is pinned: these are ChaCha8's first words for seed 1 and our mapping of
    /// them. A change here changes every worksheet and synthetic track made with a seed.
    #[test]
    fn seed_one_draws_pinned_numbers() {
        let mut d = Draws::new(1);
        let words: Vec<u64> = (0..3).map(|_| d.word()).collect();
        assert_eq!(words, PINNED_WORDS);
        let mut d = Draws::new(1);
        let units: Vec<f64> = (0..3).map(|_| d.unit()).collect();
        let expected: Vec<f64> = PINNED_WORDS
            .iter()
            .map(|w| (w >> 11) as f64 / 9_007_199_254_740_992.0)
            .collect();
        assert_eq!(units, expected);
    }

    /// ChaCha8 (RFC 7539 block function, 8 rounds, key = seed 1 little-endian, counter and
    /// nonce 0), first block as little-endian u64 pairs; checked against an independent
    /// 20-line Python implementation of the block function.
    const PINNED_WORDS: [u64; 3] = [
        7_037_237_572_835_827_407,
        5_440_448_899_038_119_230,
        14_725_191_807_199_933_458,
    ];

    #[test]
    fn draws_stay_in_range_and_are_spread() {
        let mut d = Draws::new(42);
        let xs: Vec<f64> = (0..20_000).map(|_| d.between(2.0, 5.0)).collect();
        assert!(xs.iter().all(|x| (2.0..5.0).contains(x)));
        let mean = xs.iter().sum::<f64>() / xs.len() as f64;
        assert!((mean - 3.5).abs() < 0.03, "{mean}");
        let g: Vec<f64> = (0..20_000).map(|_| d.gaussian()).collect();
        let m = g.iter().sum::<f64>() / g.len() as f64;
        let sd = (g.iter().map(|x| (x - m).powi(2)).sum::<f64>() / g.len() as f64).sqrt();
        assert!(m.abs() < 0.03 && (sd - 1.0).abs() < 0.03, "{m} {sd}");
        assert!(g.iter().all(|x| x.is_finite()));
    }

    #[test]
    fn different_seeds_give_different_streams() {
        assert_ne!(Draws::new(1).word(), Draws::new(2).word());
    }
}
