//! What the curves and surfaces share: the keys of the three shapes, the generic control
//! points of a formula fixture (`{"generic": "c"}`), members read later, and their checks.

use super::context::{limits, Typed, CONTEXT};
use super::expr::ExprIn;
use crate::input::quoted;
use crate::message::read::Read;
use crate::value::exact::Number;
use cagd_linalg::Point;
use cagd_param::Name;
use serde::de::{self, Deserializer, IgnoredAny, Visitor};
use serde::Deserialize;
use std::cell::Cell;
use std::fmt;

/// A curve or surface as written: the keys of the three shapes; `P` is the type of its
/// control points ([`Points`] for a curve, [`MeshIn`] for a surface).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawShape<P> {
    pub(super) bezier: Option<Control<P>>,
    pub(super) bspline: Option<Control<P>>,
    pub(super) degree: Option<Deferred>,
    pub(super) knots: Option<Deferred>,
    pub(super) weights: Option<Deferred>,
    /// The control points are homogeneous, `(w x, w y, w z, w)`: the weights are their last
    /// coordinates (a last coordinate 0: the control vector of the other coordinates).
    pub(super) homogeneous: Option<bool>,
    pub(super) expr: Option<ExprIn>,
    /// The letter of a generic polygon or mesh (`"c"`: points c_{0}, ..., c_{n} or c_{i,j}).
    pub(super) generic: Option<String>,
    /// The dimension of a generic polygon or mesh: 1 (default, the point is the letter),
    /// 2 and 3 (the coordinates x_{i,j}, y_{i,j}, z_{i,j}), or `"xz"` (a profile of the XZ
    /// plane, (x_{i}, 0, z_{i}), for a surface of revolution).
    dim: Option<serde_json::Value>,
}

/// The control points of a shape (`bezier`, `bspline`). Read from a problem's text, they are
/// read where they stand, straight from the text (no copy of it, no second pass); given as a
/// JSON value, they are read once the shape's keys are known, with the path of an error.
pub(super) enum Control<P> {
    Read(P),
    Later(Deferred),
}

impl<'de, P: Deserialize<'de>> Deserialize<'de> for Control<P> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        if FROM_TEXT.with(Cell::get) {
            P::deserialize(d).map(Control::Read)
        } else {
            Deferred::deserialize(d).map(Control::Later)
        }
    }
}

impl<P: serde::de::DeserializeOwned> Control<P> {
    /// The points, read (an error below `key`).
    pub(super) fn points(self, key: &str) -> Result<P, Typed> {
        match self {
            Control::Read(p) => Ok(p),
            Control::Later(v) => member(key, &v),
        }
    }
}

impl<P> RawShape<P> {
    /// `Err` when points were read from the text that the shape does not use (a generic
    /// shape's, or `bspline` beside `bezier`): their numbers may have set the field. The
    /// problem is then read again as a value ([`crate::Problem::read_text`]), which reads
    /// only what is used.
    pub(super) fn unused_points_read(&self) -> Result<(), Typed> {
        let read = |c: &Option<Control<P>>| matches!(c, Some(Control::Read(_)));
        if (self.generic.is_some() && (read(&self.bezier) || read(&self.bspline)))
            || (self.bezier.is_some() && read(&self.bspline))
        {
            return Err(Read::UnusedPoints.into());
        }
        Ok(())
    }
}

/// The largest degree of a generic polygon or mesh (its answers are general formulas: a
/// degree past this is no clearer and much slower).
pub const MAX_GENERIC_DEGREE: usize = 6;

/// The letter of a generic shape, or of its weights.
pub(super) fn generic_letter(key: &str, letter: &str) -> Result<String, Typed> {
    let mut chars = letter.chars();
    match (chars.next(), chars.next()) {
        (Some(c), None) if c.is_alphabetic() => Ok(letter.to_string()),
        _ => Err(Typed::from(Read::GenericLetter {
            found: quoted(letter),
        })
        .below(key)),
    }
}

/// The symbolic number `letter_{indices}`, declared as a parameter of the problem being read
/// (so that `expected` and `values` may use it).
pub(super) fn generic_number(letter: &str, indices: &[usize]) -> Number {
    let sub: Vec<String> = indices.iter().map(usize::to_string).collect();
    let name = Name::new(&format!("{letter}_{{{}}}", sub.join(",")));
    CONTEXT.with(|c| {
        if let Some(ctx) = c.borrow_mut().as_mut() {
            if !ctx.parameters.contains(&name) {
                ctx.parameters.push(name.clone());
            }
        }
    });
    Number::named(name)
}

pub(super) fn generic_degree(degree: usize, key: &str) -> Result<usize, Typed> {
    if degree > MAX_GENERIC_DEGREE {
        return Err(Typed::from(Read::GenericDegree {
            max: MAX_GENERIC_DEGREE,
            found: degree,
        })
        .below(key));
    }
    Ok(degree)
}

/// The point of a generic shape at `indices`: `(c_{i,j})`, `(x_{i,j}, y_{i,j}, z_{i,j})`, or
/// `(x_{i}, 0, z_{i})` in the XZ plane (`dim` 0).
pub(super) fn generic_point(letter: &str, dim: usize, indices: &[usize]) -> Point<Number> {
    match dim {
        0 => Point::new(vec![
            generic_number("x", indices),
            <Number as num_traits::Zero>::zero(),
            generic_number("z", indices),
        ]),
        2 | 3 => Point::new(
            ["x", "y", "z"]
                .iter()
                .take(dim)
                .map(|l| generic_number(l, indices))
                .collect(),
        ),
        _ => Point::new(vec![generic_number(letter, indices)]),
    }
}

/// The dimension of a generic shape (1, 2 or 3; 0 for `"xz"`).
pub(super) fn generic_dim<P>(raw: &RawShape<P>) -> Result<usize, Typed> {
    match &raw.dim {
        None => Ok(1),
        Some(serde_json::Value::String(s)) if s == "xz" => Ok(0),
        Some(d) => match d.as_u64() {
            Some(d @ 1..=3) => Ok(usize::try_from(d).unwrap_or(1)),
            _ => Err(Typed::from(Read::GenericDim {
                found: d.to_string(),
            })
            .below("dim")),
        },
    }
}

/// The weights of a generic shape: a letter (`"w"`, the weights w_{i} or w_{i,j}) or numbers.
pub(super) fn generic_weights<P>(raw: &RawShape<P>) -> Result<Option<String>, Typed> {
    match raw.weights.as_ref().map(Deferred::value) {
        Some(Some(serde_json::Value::String(w))) => generic_letter("weights", &w).map(Some),
        _ => Ok(None),
    }
}

thread_local! {
    /// Whether the problem being read on this thread is read from its text
    /// ([`crate::Problem::read_text`]): its shapes' members are then kept as text.
    pub(super) static FROM_TEXT: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `read` with the members of shapes kept as text (the problem is read from its text).
pub(crate) fn from_text<T>(read: impl FnOnce() -> T) -> T {
    let before = FROM_TEXT.with(|f| f.replace(true));
    let out = read();
    FROM_TEXT.with(|f| f.set(before));
    out
}

/// serde_json's name of a value kept as its text (`RawValue`).
pub(super) const RAW_VALUE: &str = "$serde_json::private::RawValue";

/// A member of a shape, read once the shape's keys are known: as a JSON value, or, when the
/// problem is read from its text, as the text of that value (no value is built: a mesh's
/// numbers go from the text straight into its points).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Deferred {
    Value(serde_json::Value),
    Text(String),
}

impl Deferred {
    /// The member as a JSON value (for the small members looked at before reading).
    fn value(&self) -> Option<serde_json::Value> {
        match self {
            Deferred::Value(v) => Some(v.clone()),
            Deferred::Text(t) => serde_json::from_str(t).ok(),
        }
    }
}

impl<'de> Deserialize<'de> for Deferred {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Deferred;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a value")
            }
            fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<Deferred, A::Error> {
                // serde_json hands a raw value over as a map of one entry: its text
                let _ = map.next_key::<IgnoredAny>()?;
                map.next_value::<String>().map(Deferred::Text)
            }
        }
        if FROM_TEXT.with(std::cell::Cell::get) {
            d.deserialize_newtype_struct(RAW_VALUE, V)
        } else {
            serde_json::Value::deserialize(d).map(Deferred::Value)
        }
    }
}

/// Reads the member `key` of a shape, errors below it. Kept as text, the member is read
/// without tracking its path: an error there makes the problem be read again as a value
/// ([`crate::Problem::read_text`]), where it is named.
pub(crate) fn member<T: serde::de::DeserializeOwned>(key: &str, v: &Deferred) -> Result<T, Typed> {
    match v {
        Deferred::Value(v) => member_value(key, v),
        Deferred::Text(t) => {
            serde_json::from_str(t).map_err(|e| Typed::from_serde(e.to_string()).below(key))
        }
    }
}

/// Reads the member `key` of a shape given as a JSON value, errors below it.
pub(crate) fn member_value<T: serde::de::DeserializeOwned>(
    key: &str,
    v: &serde_json::Value,
) -> Result<T, Typed> {
    match serde_path_to_error::deserialize::<_, T>(v) {
        Ok(x) => Ok(x),
        Err(e) => {
            let path = e.path().to_string();
            let inner = e.into_inner().to_string();
            let sub = if path == "." || path.is_empty() {
                key.to_string()
            } else if path.starts_with('[') || key.is_empty() {
                format!("{key}{path}")
            } else {
                format!("{key}.{path}")
            };
            Err(Typed::from_serde(inner).below(&sub))
        }
    }
}

pub(super) fn missing(key: &str) -> Typed {
    Typed::from(crate::message::contract::Contract::Missing).below(key)
}

/// The degree of a Bézier curve (or of a patch in one direction) of `n` control points, n - 1,
/// within [`Limits::max_degree`]: the limit bounds a degree given by its points as it bounds
/// a `degree` written.
pub(super) fn bezier_degree(
    points: usize,
    what: fn(usize, usize, usize) -> Read,
) -> Result<(), Typed> {
    let max = limits().max_degree;
    let degree = points.saturating_sub(1);
    if degree > max {
        return Err(Typed::from(what(points, degree, max)).below("bezier"));
    }
    Ok(())
}

pub(super) fn weights_count(points: usize, w: &[Number]) -> Result<(), Typed> {
    if w.len() != points {
        return Err(Typed::from(Read::WeightsCount {
            weights: w.len(),
            points,
        })
        .below("weights"));
    }
    Ok(())
}
