//! Lists, pairs, orders, points, meshes and grids of numbers, and data points.

use super::context::{expected, fail, Typed, QUICK};
use super::number::{json_number, Int, IntVisitor, Num};
use super::shape::{member, Deferred};
use crate::input::quoted;
use crate::message::found::Found;
use crate::message::read::{Read, Wanted};
use crate::value::exact::Number;
use cagd_linalg::Point;
use cagd_surface::{Grid, Mesh};
use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, SeqAccess, Visitor};
use serde::Deserialize;
use std::cell::Cell;
use std::fmt;

/// A list of at most [`Limits::max_points`] items.
#[derive(Debug, Clone, PartialEq)]
pub struct List<T>(pub Vec<T>);

/// Refuses a list longer than the points limit, before reading its items.
pub(super) fn check_length<E: de::Error>(hint: Option<usize>) -> Result<(), E> {
    let max = QUICK.with(Cell::get).max_points;
    match hint {
        Some(items) if items > max => Err(fail(Read::ListLonger { items, max })),
        _ => Ok(()),
    }
}

/// Refuses a list, as [`check_length`], once `count` items are read: a list read from a
/// problem's text has no length known before its items.
pub(super) fn check_count<E: de::Error>(count: usize) -> Result<(), E> {
    if count <= QUICK.with(Cell::get).max_points {
        return Ok(());
    }
    check_length(Some(count))
}

pub(super) struct ListVisitor<T>(std::marker::PhantomData<T>);

impl<'de, T: Deserialize<'de>> Visitor<'de> for ListVisitor<T> {
    type Value = List<T>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a list")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<List<T>, A::Error> {
        check_length(seq.size_hint())?;
        let mut out = Vec::with_capacity(seq.size_hint().unwrap_or(0));
        while let Some(x) = seq.next_element()? {
            out.push(x);
            check_count(out.len())?;
        }
        Ok(List(out))
    }
    refuse_others!(Wanted::List);
    refuse_numbers!(Wanted::List);
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for List<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(ListVisitor(std::marker::PhantomData))
    }
}

/// A pair of numbers `[a, b]` (an interval, a parameter pair (u, v)).
#[derive(Debug, Clone, PartialEq)]
pub struct Pair(pub Num, pub Num);

impl<'de> Deserialize<'de> for Pair {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let List(v) = List::<Num>::deserialize(d)?;
        let n = v.len();
        match <[Num; 2]>::try_from(v) {
            Ok([a, b]) => Ok(Pair(a, b)),
            Err(_) => Err(fail(Read::TwoNumbers { found: n })),
        }
    }
}

/// One integer or a pair `[r, s]` of non-negative integers (an elevation `by`, a derivative
/// `order`): a curve takes one, a surface two.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Orders {
    /// `r`.
    One(Int),
    /// `[r, s]`.
    Two(Int, Int),
}

pub(super) struct OrdersVisitor;

impl<'de> Visitor<'de> for OrdersVisitor {
    type Value = Orders;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an integer or two [r, s]")
    }
    fn visit_u64<E: de::Error>(self, n: u64) -> Result<Orders, E> {
        IntVisitor.visit_u64(n).map(Orders::One)
    }
    fn visit_i64<E: de::Error>(self, n: i64) -> Result<Orders, E> {
        IntVisitor.visit_i64(n).map(Orders::One)
    }
    fn visit_f64<E: de::Error>(self, n: f64) -> Result<Orders, E> {
        IntVisitor.visit_f64(n).map(Orders::One)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Orders, A::Error> {
        let n = seq.size_hint();
        let mut items: Vec<Int> = Vec::new();
        while let Some(x) = seq.next_element::<Int>()? {
            items.push(x);
            if items.len() > 2 {
                break;
            }
        }
        match items.as_slice() {
            [a, b] => Ok(Orders::Two(*a, *b)),
            _ => Err(fail(Read::TwoIntegers {
                found: n.unwrap_or(items.len()),
            })),
        }
    }
    refuse_others!(Wanted::IntegerOrPair);
}

impl<'de> Deserialize<'de> for Orders {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(OrdersVisitor)
    }
}

/// A point `[x, y, z]` (any dimension ≥ 1); in a list, of the dimension of the first.
#[derive(Debug, Clone, PartialEq)]
pub struct PointIn(pub Point<Number>);

/// Reads a point whose dimension must be `dim` (when known).
pub(super) struct PointSeed {
    dim: Option<usize>,
}

impl<'de> Visitor<'de> for PointSeed {
    type Value = PointIn;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a point")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<PointIn, A::Error> {
        check_length(seq.size_hint())?;
        let mut coords = Vec::with_capacity(seq.size_hint().unwrap_or(3));
        while let Some(Num(x)) = seq.next_element()? {
            coords.push(x);
            check_count(coords.len())?;
        }
        if coords.is_empty() {
            return Err(fail(Read::PointEmpty));
        }
        if let Some(first) = self.dim.filter(|d0| *d0 != coords.len()) {
            return Err(fail(Read::PointDim {
                found: coords.len(),
                first,
            }));
        }
        Ok(PointIn(Point::new(coords)))
    }
    refuse_others!(Wanted::Point);
    refuse_numbers!(Wanted::Point);
}

impl<'de> DeserializeSeed<'de> for PointSeed {
    type Value = PointIn;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<PointIn, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Deserialize<'de> for PointIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        PointSeed { dim: None }.deserialize(d)
    }
}

/// A non-empty list of points of one dimension.
#[derive(Debug, Clone, PartialEq)]
pub struct Points(pub Vec<Point<Number>>);

/// Reads a list of points, of dimension `dim` when known (the rows of a mesh), and of
/// `len` points when known (every row as long as the first).
pub(super) struct PointsSeed {
    dim: Option<usize>,
    len: Option<usize>,
    row: usize,
}

impl<'de> Visitor<'de> for PointsSeed {
    type Value = Points;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a list of points")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Points, A::Error> {
        check_length(seq.size_hint())?;
        if let (Some(n), Some(first)) = (seq.size_hint(), self.len) {
            if n != first {
                return Err(fail(Read::RowLength {
                    row: self.row,
                    found: n,
                    first,
                }));
            }
        }
        let mut pts: Vec<Point<Number>> =
            Vec::with_capacity(self.len.or(seq.size_hint()).unwrap_or(4));
        let mut dim = None;
        while let Some(PointIn(p)) = seq.next_element_seed(PointSeed { dim })? {
            dim = Some(p.dim());
            pts.push(p);
            check_count(pts.len())?;
        }
        if pts.is_empty() {
            return Err(fail(Read::NoPoint));
        }
        if let Some(first) = self.len.filter(|first| *first != pts.len()) {
            // a list read without its length known before (from a problem's text)
            return Err(fail(Read::RowLength {
                row: self.row,
                found: pts.len(),
                first,
            }));
        }
        if let (Some(first), Some(found)) = (self.dim, dim) {
            if first != found {
                return Err(fail(Read::RowDim { found, first }));
            }
        }
        Ok(Points(pts))
    }
    refuse_others!(Wanted::List);
    refuse_numbers!(Wanted::List);
}

impl<'de> DeserializeSeed<'de> for PointsSeed {
    type Value = Points;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Points, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Deserialize<'de> for Points {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        PointsSeed {
            dim: None,
            len: None,
            row: 0,
        }
        .deserialize(d)
    }
}

/// A mesh: a non-empty list of rows of points (outer index i along u), of equal lengths and
/// one dimension, at most [`Limits::max_points`] points in all.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshIn(pub Mesh<Number>);

/// Counts the points of the rows left, without reading their numbers.
pub(super) struct CountRow;

impl<'de> DeserializeSeed<'de> for CountRow {
    type Value = usize;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<usize, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = usize;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a row")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<usize, A::Error> {
                let mut n = 0usize;
                while seq.next_element::<IgnoredAny>()?.is_some() {
                    n = n.saturating_add(1);
                }
                Ok(n)
            }
        }
        d.deserialize_any(V).or(Ok(0))
    }
}

pub(super) struct MeshVisitor;

impl<'de> Visitor<'de> for MeshVisitor {
    type Value = MeshIn;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a mesh")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<MeshIn, A::Error> {
        check_length(seq.size_hint())?;
        let max = QUICK.with(Cell::get).max_points;
        // the points row after row: each row as long as row 0 and of its dimension, as
        // `PointsSeed` checks
        let mut points: Vec<Point<Number>> = Vec::new();
        let (mut rows, mut first) = (0usize, None::<(usize, usize)>);
        let mut total = 0usize;
        loop {
            let seed = PointsSeed {
                dim: first.map(|(_, dim)| dim),
                len: first.map(|(len, _)| len),
                row: rows,
            };
            let Some(Points(row)) = seq.next_element_seed(seed)? else {
                break;
            };
            total = total.saturating_add(row.len());
            if first.is_none() {
                first = Some((row.len(), row.first().map_or(0, Point::dim)));
                // as many rows as columns, most often
                points.reserve(
                    row.len()
                        .saturating_mul(seq.size_hint().unwrap_or(row.len())),
                );
            }
            points.extend(row);
            rows += 1;
            check_count(rows)?;
            if total > max {
                // count the rest without reading it, to say how large the mesh is
                while let Some(n) = seq.next_element_seed(CountRow)? {
                    total = total.saturating_add(n);
                }
                return Err(fail(Read::MeshLarger { points: total, max }));
            }
        }
        let Some((cols, _)) = first else {
            return Err(fail(Read::MeshEmpty));
        };
        // rows × cols points, checked as read: the grid takes them in order
        let mut points = points.into_iter();
        Ok(MeshIn(Grid::from_fn(rows, cols, |_, _| {
            points.next().unwrap_or_else(|| Point::new(Vec::new()))
        })))
    }
    refuse_others!(Wanted::List);
    refuse_numbers!(Wanted::List);
}

impl<'de> Deserialize<'de> for MeshIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(MeshVisitor)
    }
}

/// A grid of numbers (weights), rows like a mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct GridIn(pub Grid<Number>);

impl<'de> Deserialize<'de> for GridIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let List(rows) = List::<List<Num>>::deserialize(d)?;
        let rows: Vec<Vec<Number>> = rows
            .into_iter()
            .map(|List(r)| r.into_iter().map(|Num(x)| x).collect())
            .collect();
        Grid::from_rows(rows).map(GridIn).map_err(fail)
    }
}

/// Data points: a grid (a list of rows of points, for a surface) or a list of points (for a
/// curve), told apart by their shape.
#[derive(Debug, Clone, PartialEq)]
pub enum PointData {
    /// Rows of points.
    Grid(MeshIn),
    /// Points.
    List(Points),
}

impl<'de> Deserialize<'de> for PointData {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Deferred::deserialize(d)?;
        let grid = match &v {
            Deferred::Value(v) => v
                .as_array()
                .and_then(|rows| rows.first())
                .and_then(serde_json::Value::as_array)
                .and_then(|row| row.first())
                .is_some_and(serde_json::Value::is_array),
            // a list whose first item is a list whose first item is a list
            Deferred::Text(t) => ["[", "[", "["]
                .iter()
                .try_fold(t.as_str(), |rest, open| {
                    rest.trim_start().strip_prefix(open)
                })
                .is_some(),
        };
        if grid {
            member::<MeshIn>("", &v).map(PointData::Grid)
        } else {
            member::<Points>("", &v).map(PointData::List)
        }
        .map_err(Typed::serde)
    }
}
