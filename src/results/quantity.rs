//! The closed-form quantities, described once. Each model keeps its registry in its own folder
//! (`src/models/<model>/quantity.rs`: a `Key` enum with one variant per quantity and the table of
//! entries), beside the closed forms it describes, so that a model brings its quantities with it
//! and the two tables never share a key type. This module holds what both registries share: the
//! shape of an entry ([`Entry`], [`Quantity`]), the trait of a model's key ([`Registry`]), and
//! [`AnyKey`], a key of any model, for the data both models share (checks, applicability,
//! derivation steps, worksheet questions).
//!
//! The guide §14 JSON key of a quantity is written in its entry only: the `closed_form` object is
//! serialized through the registry, and every other place names the quantity by its typed key.

use serde::Serialize;

/// How a closed-form quantity is shown, and what it means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quantity {
    /// The JSON key (guide §14) (JSON).
    pub id: &'static str,
    /// Plain-text symbol.
    pub symbol: &'static str,
    /// The symbol in LaTeX (the left-hand side of a worked step).
    pub tex: &'static str,
    /// SI unit ("" for dimensionless).
    pub unit: &'static str,
    /// Paper's equation number, or the section of the guide that derives a result ("guide §7.5").
    pub equation: &'static str,
    /// \[P\], \[P*\], \[G\] or \[D\] (guide §6).
    pub tag: &'static str,
    /// The formula in LaTeX.
    pub latex: &'static str,
    /// What it is, in one plain line.
    pub words: &'static str,
}

/// What kind of value a quantity has, and where it appears.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A number of the guide §14 `closed_form` object, shown in the closed-form tables.
    Number,
    /// A flag or the regime id of the guide §14 `closed_form` object (checked as a label).
    Label,
    /// A number checked against the integration that is not a key of the guide §14 `closed_form`
    /// object.
    Checked,
}

/// One quantity of a model's registry: its key, how it is shown, what kind of value it has, and
/// where it describes the motion (`R`: the model's regimes, or its own notion of them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Entry<K: 'static, R: 'static> {
    pub key: K,
    pub kind: Kind,
    pub quantity: Quantity,
    /// Where the quantity describes the motion.
    pub regimes: R,
}

impl<K, R> Entry<K, R> {
    /// An entry of a model's table from its parts, in the columns' order (a `const` table reads
    /// one call per quantity).
    #[allow(clippy::too_many_arguments)]
    pub const fn new(
        key: K,
        kind: Kind,
        regimes: R,
        id: &'static str,
        symbol: &'static str,
        tex: &'static str,
        unit: &'static str,
        equation: &'static str,
        tag: &'static str,
        latex: &'static str,
        words: &'static str,
    ) -> Self {
        Entry {
            key,
            kind,
            quantity: Quantity {
                id,
                symbol,
                tex,
                unit,
                equation,
                tag,
                latex,
                words,
            },
            regimes,
        }
    }
}

/// The typed key of a model's quantities, and the model's registry.
pub trait Registry: Copy + Eq + std::fmt::Debug + 'static {
    /// Where a quantity of this model describes the motion.
    type Regimes: Copy + 'static;
    /// Every quantity of the model, in the order of the guide §14 `closed_form` object and of the
    /// tables; the entry of a key is at the key's [`Registry::index`].
    const ENTRIES: &'static [Entry<Self, Self::Regimes>];

    /// The position of the key's entry in [`Registry::ENTRIES`].
    fn index(self) -> usize;

    /// The time t = T·τ of a time fraction τ, checked in its place (`None` for the others).
    fn time(self) -> Option<Self> {
        None
    }

    /// The key's entry.
    fn entry(self) -> &'static Entry<Self, Self::Regimes> {
        &Self::ENTRIES[self.index()]
    }

    /// How the quantity is shown.
    fn quantity(self) -> &'static Quantity {
        &self.entry().quantity
    }

    /// The JSON key (guide §14).
    fn id(self) -> &'static str {
        self.quantity().id
    }

    /// The key whose JSON key (guide §14) is `id`.
    fn from_id(id: &str) -> Option<Self> {
        Self::ENTRIES
            .iter()
            .find(|e| e.quantity.id == id)
            .map(|e| e.key)
    }

    /// The numbers of the guide §14 `closed_form` object, in the order of the tables.
    fn numbers() -> impl Iterator<Item = &'static Entry<Self, Self::Regimes>> {
        Self::ENTRIES.iter().filter(|e| e.kind == Kind::Number)
    }
}

/// A closed-form quantity of any model: a reference to its registry entry's [`Quantity`].
/// Keys compare by the whole entry (symbol, equation, formula …), not by address: registry
/// tables are constants, which have no unique address; two models' quantities that share a
/// JSON key (guide §14) differ in their equation and formula.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AnyKey(&'static Quantity);

impl AnyKey {
    /// The key of a registry entry's quantity (each model's `quantity::any` makes one in const
    /// context).
    pub const fn new(quantity: &'static Quantity) -> Self {
        Self(quantity)
    }

    /// How the quantity is shown.
    pub fn quantity(self) -> &'static Quantity {
        self.0
    }

    /// The JSON key (guide §14).
    pub fn id(self) -> &'static str {
        self.0.id
    }
}

impl<K: Registry> From<K> for AnyKey {
    fn from(k: K) -> Self {
        Self(k.quantity())
    }
}

impl Serialize for AnyKey {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.id())
    }
}

/// The value of a quantity of the guide §14 `closed_form` object, as serialized.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    /// A number; `None` (null) where the expression is undefined.
    Number(Option<f64>),
    Flag(bool),
    /// A regime id.
    Label(&'static str),
}

impl Value {
    /// The number, if the value is one and is defined (finite: what JSON shows as a number).
    pub fn number(self) -> Option<f64> {
        match self {
            Value::Number(x) => x.filter(|x| x.is_finite()),
            Value::Flag(_) | Value::Label(_) => None,
        }
    }

    /// The number as computed, finite or not (`None` for a label or an undefined value): what
    /// [`crate::results::ensure_in_range`] inspects.
    pub fn computed(self) -> Option<f64> {
        match self {
            Value::Number(x) => x,
            Value::Flag(_) | Value::Label(_) => None,
        }
    }
}

impl From<f64> for Value {
    fn from(x: f64) -> Self {
        Value::Number(Some(x))
    }
}

impl From<Option<f64>> for Value {
    fn from(x: Option<f64>) -> Self {
        Value::Number(x)
    }
}

impl From<bool> for Value {
    fn from(b: bool) -> Self {
        Value::Flag(b)
    }
}

impl Serialize for Value {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match *self {
            Value::Number(x) => x.serialize(s),
            Value::Flag(b) => s.serialize_bool(b),
            Value::Label(id) => s.serialize_str(id),
        }
    }
}

/// Serializes the guide §14 `closed_form` object of a model: every entry of its registry that is a key
/// of the object, in registry order, with `value` of it.
pub fn serialize_closed_form<K: Registry, S: serde::Serializer>(
    s: S,
    value: impl Fn(K) -> Value,
) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let entries = K::ENTRIES.iter().filter(|e| e.kind != Kind::Checked);
    let mut map = s.serialize_map(Some(entries.clone().count()))?;
    for e in entries {
        map.serialize_entry(e.quantity.id, &value(e.key))?;
    }
    map.end()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::models::{pulled_mass::quantity as pm, woodpecker::quantity as wp};

    #[test]
    fn any_keys_equal_their_own_key_and_no_other_models() {
        for &p in &pm::ALL {
            assert_eq!(pm::any(p), AnyKey::from(p), "{p:?}");
            for &w in &wp::ALL {
                assert_ne!(AnyKey::from(p), AnyKey::from(w), "{p:?} {w:?}");
            }
        }
        for &w in &wp::ALL {
            assert_eq!(wp::any(w), AnyKey::from(w), "{w:?}");
        }
    }

    /// Every entry sits at its key's index, ids are unique, and every key has an entry.
    pub(crate) fn registry_is_consistent<K: Registry>(all: &[K]) {
        assert_eq!(all.len(), K::ENTRIES.len());
        for (i, e) in K::ENTRIES.iter().enumerate() {
            assert_eq!(e.key.index(), i, "{:?}", e.key);
            assert_eq!(all[i], e.key);
            let q = &e.quantity;
            assert!(!q.id.is_empty() && !q.symbol.is_empty() && !q.tex.is_empty());
            assert!(!q.equation.is_empty() && !q.tag.is_empty() && !q.latex.is_empty());
            assert!(!q.words.is_empty(), "{}", q.id);
            // The tag is shown beside the equation; an equation that carries it prints it twice.
            assert!(!q.equation.contains('['), "{}: {}", q.id, q.equation);
            let twins = K::ENTRIES.iter().filter(|f| f.quantity.id == q.id).count();
            assert_eq!(twins, 1, "{}", q.id);
        }
    }

    /// The guide §14 `closed_form` object has exactly the registry's keys of the object, in order.
    pub(crate) fn serialized_keys_are_the_registry<K: Registry>(object: &serde_json::Value) {
        let keys: Vec<&str> = object
            .as_object()
            .expect("closed_form is an object")
            .keys()
            .map(String::as_str)
            .collect();
        let mut want: Vec<&str> = K::ENTRIES
            .iter()
            .filter(|e| e.kind != Kind::Checked)
            .map(|e| e.quantity.id)
            .collect();
        want.sort_unstable();
        let mut keys = keys;
        keys.sort_unstable();
        assert_eq!(keys, want);
    }
}
