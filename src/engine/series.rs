//! A value per period start (x, v or the dissipation of a run), stored in pieces so that the
//! replayed periods of a long run cost no memory and little time, with every value the one
//! full integration gives, bit for bit.
//!
//! Replayed periods repeat one start value (v, the dissipation: [`Gap::repeated`]) or
//! move x by the same displacements Δx₁ … Δx_k in the same order each period: x ← ((x + Δx₁) +
//! Δx₂) + … Within one binade of |x| (spacing u = ulp), as long as every partial sum stays at
//! least one u inside it and no Δx_i/u is a half-integer, each addition is exact rounding to a
//! multiple of u, so it adds round(Δx_i/u)·u whatever x is: the period moves x by a fixed
//! integer number of u, and x after k periods is (X + k·Δ)·u with X = x/u. [`Steps::jump`]
//! finds how many periods stay so; a step that crosses a binade (or meets a tie) is taken one
//! period at a time by the same additions as the integration.

/// Values at the start of periods 0, 1, …, in order: explicit values, with the long stretch of
/// replayed periods (if any) kept as a [`Gap`] of pieces before the value of its first period
/// (boxed: a run without one carries a pointer, not the gap's fields).
#[derive(Clone, Default)]
pub struct Series {
    values: Vec<f64>,
    gap: Option<Box<(usize, Gap)>>,
}

/// Below this many periods a replayed stretch is stored value by value, as full integration
/// stores it: pieces would cost an allocation where a few values cost none.
pub(super) const SHORT: usize = 64;

/// Values of consecutive periods as pieces: runs of steps, repeated values and explicit values.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Gap {
    pieces: Vec<Piece>,
    len: usize,
}

#[derive(Clone, Debug, PartialEq)]
enum Piece {
    /// Explicit values.
    Values(Vec<f64>),
    /// `n` times the same value (bits included: −0 stays −0).
    Repeated { value: f64, n: usize },
    /// (start + k·step)·unit for k = 0 … n − 1: exact integers times a power of two.
    Steps {
        start: i64,
        step: i64,
        unit: f64,
        n: usize,
    },
}

impl Piece {
    fn len(&self) -> usize {
        match self {
            Piece::Values(values) => values.len(),
            Piece::Repeated { n, .. } | Piece::Steps { n, .. } => *n,
        }
    }

    fn get(&self, k: usize) -> f64 {
        match self {
            Piece::Values(values) => values[k],
            Piece::Repeated { value, .. } => *value,
            Piece::Steps {
                start, step, unit, ..
            } => (start + k as i64 * step) as f64 * unit,
        }
    }

    /// Words stored.
    fn stored(&self) -> usize {
        match self {
            Piece::Values(values) => values.len(),
            Piece::Repeated { .. } | Piece::Steps { .. } => 1,
        }
    }
}

impl Gap {
    /// `n` times `value`.
    pub(super) fn repeated(value: f64, n: usize) -> Self {
        Gap {
            pieces: vec![Piece::Repeated { value, n }],
            len: n,
        }
    }

    /// Number of values.
    pub(super) fn len(&self) -> usize {
        self.len
    }

    fn get(&self, mut k: usize) -> Option<f64> {
        for piece in &self.pieces {
            if k < piece.len() {
                return Some(piece.get(k));
            }
            k -= piece.len();
        }
        None
    }

    fn iter(&self) -> impl Iterator<Item = f64> + '_ {
        self.pieces
            .iter()
            .flat_map(|piece| (0..piece.len()).map(move |k| piece.get(k)))
    }

    /// Appends the starts of `n` periods from `x` (m) that each add `moves` (m) in order, and
    /// returns the position after them: what `n` times `for dx in moves { x += dx }` gives,
    /// bit for bit.
    pub(super) fn push_periods<I>(&mut self, mut x: f64, moves: I, n: usize) -> f64
    where
        I: Iterator<Item = f64> + Clone,
    {
        self.len += n;
        if moves.clone().next().is_none() {
            self.pieces.push(Piece::Repeated { value: x, n });
            return x;
        }
        let mut left = n;
        while left > 0 {
            match Steps::jump(x, moves.clone(), left) {
                Some(steps) => {
                    x = steps.end();
                    left -= steps.n;
                    self.pieces.push(Piece::Steps {
                        start: steps.start,
                        step: steps.step,
                        unit: steps.unit,
                        n: steps.n,
                    });
                }
                None => {
                    match self.pieces.last_mut() {
                        Some(Piece::Values(values)) => values.push(x),
                        _ => self.pieces.push(Piece::Values(vec![x])),
                    }
                    for dx in moves.clone() {
                        x += dx;
                    }
                    left -= 1;
                }
            }
        }
        x
    }
}

impl Series {
    /// `values`, with `gap` inserted before the value of period `at`.
    pub(super) fn with_gap(values: Vec<f64>, at: usize, gap: Gap) -> Self {
        Series {
            values,
            gap: Some(Box::new((at, gap))),
        }
    }

    /// The first period of the gap and the gap (empty at the end when there is none).
    fn gap(&self) -> (usize, &Gap) {
        const NONE: &Gap = &Gap {
            pieces: Vec::new(),
            len: 0,
        };
        self.gap
            .as_deref()
            .map_or((self.values.len(), NONE), |(at, gap)| (*at, gap))
    }

    /// Number of values.
    pub fn len(&self) -> usize {
        self.values.len() + self.gap().1.len
    }

    /// Whether there is no value.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The value at period start `i`.
    pub fn get(&self, i: usize) -> Option<f64> {
        let (at, gap) = self.gap();
        if i < at {
            self.values.get(i).copied()
        } else if i - at < gap.len {
            gap.get(i - at)
        } else {
            self.values.get(i - gap.len).copied()
        }
    }

    /// The last value.
    pub fn last(&self) -> Option<f64> {
        self.len().checked_sub(1).and_then(|i| self.get(i))
    }

    /// The values in order.
    pub fn iter(&self) -> impl Iterator<Item = f64> + '_ {
        let (at, gap) = self.gap();
        let (before, after) = self.values.split_at(at.min(self.values.len()));
        before
            .iter()
            .copied()
            .chain(gap.iter())
            .chain(after.iter().copied())
    }

    /// Words stored: explicit values, and one per piece of repeated values or steps.
    pub fn stored(&self) -> usize {
        self.values.len() + self.gap().1.pieces.iter().map(Piece::stored).sum::<usize>()
    }

    /// Appends one value.
    pub fn push(&mut self, value: f64) {
        self.values.push(value);
    }
}

impl From<Vec<f64>> for Series {
    /// The explicit values.
    fn from(values: Vec<f64>) -> Self {
        Series { values, gap: None }
    }
}

impl PartialEq for Series {
    /// Equal values in order, as for a `Vec<f64>` of them, however they are stored (a replayed
    /// run's series equals the fully integrated one's).
    fn eq(&self, other: &Self) -> bool {
        self.len() == other.len() && self.iter().eq(other.iter())
    }
}

impl std::fmt::Debug for Series {
    /// As the list of values (what a `Vec<f64>` of them prints).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

/// Periods over which x moves by a whole number of units u per period, exactly.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Steps {
    /// x / u at the first period start.
    start: i64,
    /// The period's displacement in units.
    step: i64,
    /// u: the spacing of doubles in the binade of |x| (a power of two).
    unit: f64,
    /// Periods covered (at least 2).
    n: usize,
}

impl Steps {
    /// x after the `n` periods.
    fn end(&self) -> f64 {
        (self.start + self.n as i64 * self.step) as f64 * self.unit
    }

    /// The longest run of at most `limit` periods from `x` that adds `moves` as whole units of
    /// x's binade (see the module's doc), if it covers two periods or more.
    fn jump(x: f64, moves: impl Iterator<Item = f64>, limit: usize) -> Option<Steps> {
        const MANTISSA: u32 = 52;
        let (lo, hi) = (1_i64 << MANTISSA, 1_i64 << (MANTISSA + 1));
        let exponent = (x.to_bits() >> MANTISSA) & 0x7ff;
        // Subnormal, tiny (u would be subnormal), infinite or NaN x: no jump.
        if !(u64::from(MANTISSA) < exponent && exponent < 0x7ff) || limit < 2 {
            return None;
        }
        let unit = f64::from_bits((exponent - u64::from(MANTISSA)) << MANTISSA);
        let sign = if x < 0.0 { -1 } else { 1 };
        let start = (x / unit) as i64;
        // Signed partial sums, in units, along the period (0 included).
        let (mut sum, mut low, mut high) = (0_i64, 0_i64, 0_i64);
        for dx in moves {
            let q = dx / unit;
            if !q.is_finite() || q.abs() >= (1_u64 << MANTISSA) as f64 {
                return None;
            }
            let r = q.round();
            if (q - q.trunc()).abs() == 0.5 {
                return None; // a tie: rounding to even depends on x
            }
            sum += sign * r as i64;
            low = low.min(sum);
            high = high.max(sum);
        }
        // |x| = sign·X + partial, kept within [lo + 1, hi − 1] over periods 0 … n − 1.
        let a = sign * start;
        if a + low < lo + 1 || a + high > hi - 1 {
            return None;
        }
        let n = match sum {
            0 => limit as i64,
            d if d > 0 => (hi - 1 - high - a) / d + 1,
            d => (a + low - (lo + 1)) / -d + 1,
        }
        .min(limit as i64);
        (n >= 2).then_some(Steps {
            start,
            step: sign * sum,
            unit,
            n: n as usize,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// x at the start of `n` periods and after them, the way the integration adds.
    fn added(mut x: f64, moves: &[f64], n: usize) -> Vec<f64> {
        let mut starts = Vec::with_capacity(n + 1);
        for _ in 0..n {
            starts.push(x);
            for dx in moves {
                x += dx;
            }
        }
        starts.push(x);
        starts
    }

    /// The same as a series: one explicit value before, the periods as a gap, the end after.
    fn series(x: f64, moves: &[f64], n: usize) -> Series {
        let mut gap = Gap::default();
        let end = gap.push_periods(x, moves.iter().copied(), n);
        Series::with_gap(vec![-1.0, end], 1, gap)
    }

    fn pushed(x: f64, moves: &[f64], n: usize) -> Vec<f64> {
        series(x, moves, n).iter().skip(1).collect()
    }

    fn bits(values: &[f64]) -> Vec<u64> {
        values.iter().map(|v| v.to_bits()).collect()
    }

    #[test]
    fn a_long_run_is_the_added_one_bit_for_bit_and_in_few_pieces() {
        // The woodpecker's four displacements per period, 10⁵ periods: x crosses binades.
        let moves = [-1.3e-4, 2.1e-6, -7.7e-5, 3.3e-7];
        let series = series(-0.0123, &moves, 100_000);
        assert!(series.stored() < 200, "{} words", series.stored());
        let mut full = added(-0.0123, &moves, 100_000);
        full.insert(0, -1.0);
        assert_eq!(bits(&series.iter().collect::<Vec<_>>()), bits(&full));
        assert_eq!(series.len(), full.len());
        assert_eq!(series.last(), full.last().copied());
        for i in [0, 1, 2, 4_095, 50_000, 99_999, 100_000, 100_001] {
            assert_eq!(series.get(i).map(f64::to_bits), Some(full[i].to_bits()));
        }
        assert_eq!(series.get(100_002), None);
    }

    #[test]
    fn ties_and_tiny_starts_are_added_one_by_one() {
        // x = 1.5 (u = 2⁻⁵²): a move of 1.5 u is a tie.
        let u = f64::EPSILON;
        let jump = |x: f64, moves: &[f64]| Steps::jump(x, moves.iter().copied(), 10);
        assert_eq!(jump(1.5, &[1.5 * u]), None);
        assert_eq!(jump(0.0, &[1.0]), None);
        assert_eq!(jump(f64::MIN_POSITIVE, &[1e-300]), None);
        assert!(jump(1.5, &[2.25 * u]).is_some());
        assert_eq!(
            bits(&pushed(1.5, &[1.5 * u, 0.25], 400)),
            bits(&added(1.5, &[1.5 * u, 0.25], 400))
        );
        assert_eq!(
            bits(&pushed(0.0, &[1e-3], 400)),
            bits(&added(0.0, &[1e-3], 400))
        );
        // No move (a body that never slips): one stored word for the periods.
        let mut gap = Gap::default();
        let end = gap.push_periods(-0.0, std::iter::empty(), 1_000);
        assert_eq!(end.to_bits(), (-0.0_f64).to_bits());
        let series = Series::with_gap(Vec::new(), 0, gap);
        assert_eq!((series.len(), series.stored()), (1_000, 1));
        assert_eq!(
            series.get(999).map(f64::to_bits),
            Some((-0.0_f64).to_bits())
        );
    }

    #[test]
    fn repeated_values_keep_their_bits_and_print_as_a_list() {
        let mut series = Series::with_gap(vec![1.0], 1, Gap::repeated(-0.0, 3));
        series.push(5.0);
        let values: Vec<f64> = series.iter().collect();
        assert_eq!(bits(&values), bits(&[1.0, -0.0, -0.0, -0.0, 5.0]));
        assert_eq!(format!("{series:?}"), format!("{values:?}"));
        assert_eq!(series.get(3).map(f64::to_bits), Some((-0.0_f64).to_bits()));
        assert_eq!(series.get(4), Some(5.0));
        assert_eq!(
            Series::from(vec![2.0, 3.0]).iter().collect::<Vec<_>>(),
            [2.0, 3.0]
        );
    }

    proptest! {
        #[test]
        fn any_moves_from_any_start_are_added_bit_for_bit(
            x in prop_oneof![-1e3..1e3_f64, -1e-3..1e-3_f64, Just(0.0), 0.999..1.001_f64],
            moves in prop::collection::vec(
                prop_oneof![-1e-2..1e-2_f64, -1e-9..1e-9_f64, Just(0.0), -3e-16..3e-16_f64],
                0..6,
            ),
            n in 0_usize..3_000,
        ) {
            prop_assert_eq!(bits(&pushed(x, &moves, n)), bits(&added(x, &moves, n)));
        }

        #[test]
        fn moves_near_a_power_of_two_are_added_bit_for_bit(
            e in -30_i32..10,
            below in 1_u64..2_000,
            step in 1_u64..64,
            back in 0_u64..64,
            n in 1_usize..400,
        ) {
            // Start `below` doubles under 2^e, move up `step` and back `back` spacings a period.
            let top = 2f64.powi(e);
            let u = top * f64::EPSILON / 2.0;
            let x = top - below as f64 * u;
            let moves = [step as f64 * u * 1.3, -(back as f64) * u * 0.7];
            prop_assert_eq!(bits(&pushed(x, &moves, n)), bits(&added(x, &moves, n)));
            prop_assert_eq!(bits(&pushed(-x, &moves, n)), bits(&added(-x, &moves, n)));
        }
    }
}
