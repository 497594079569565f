//! `Terms<M, S>`: the storage of a [`crate::Poly`], its (monomial, coefficient) pairs in
//! increasing monomial order with distinct monomials, in one vector.
//!
//! A polynomial is built far more often than it is searched: the fast paths and the merges of
//! sums produce their terms in order, and a vector takes them as they come (no tree nodes, no
//! sort), is read in order by the printers, and drops as one allocation. Lookups are binary
//! searches; an insertion in the middle shifts the terms after it, so code that adds many terms
//! out of order collects them and builds the vector once ([`Terms::from_iter`] sorts, the last
//! of equal monomials kept, as a `BTreeMap` collects).

use std::cmp::Ordering;

/// The terms of a polynomial: strictly increasing monomials (see the module documentation).
#[derive(Clone, PartialEq)]
pub(crate) struct Terms<M, S>(Vec<(M, S)>);

impl<M: Ord, S> Terms<M, S> {
    /// No term.
    pub(crate) fn new() -> Self {
        Terms(Vec::new())
    }

    /// The terms of a vector already in strictly increasing monomial order (checked in debug
    /// builds).
    pub(crate) fn from_sorted(terms: Vec<(M, S)>) -> Self {
        debug_assert!(terms.windows(2).all(|w| matches!(w, [a, b] if a.0 < b.0)));
        Terms(terms)
    }

    /// Where `m` is (`Ok`) or would go (`Err`): the end is tried first, where terms built in
    /// order go.
    fn position(&self, m: &M) -> Result<usize, usize> {
        match self.0.last() {
            None => Err(0),
            Some((last, _)) => match last.cmp(m) {
                Ordering::Less => Err(self.0.len()),
                Ordering::Equal => Ok(self.0.len() - 1),
                Ordering::Greater => self.0.binary_search_by(|(k, _)| k.cmp(m)),
            },
        }
    }

    /// The coefficient of `m`, if it is a term.
    pub(crate) fn get(&self, m: &M) -> Option<&S> {
        let i = self.position(m).ok()?;
        self.0.get(i).map(|(_, c)| c)
    }

    /// The coefficient of `m`, mutable, if it is a term.
    pub(crate) fn get_mut(&mut self, m: &M) -> Option<&mut S> {
        let i = self.position(m).ok()?;
        self.0.get_mut(i).map(|(_, c)| c)
    }

    /// Sets the coefficient of `m` (a new term in its place, or the old one replaced).
    pub(crate) fn insert(&mut self, m: M, c: S) {
        match self.position(&m) {
            Ok(i) => {
                if let Some(slot) = self.0.get_mut(i) {
                    slot.1 = c;
                }
            }
            Err(i) => self.0.insert(i, (m, c)),
        }
    }

    /// Removes the term of `m`, if there is one.
    pub(crate) fn remove(&mut self, m: &M) {
        if let Ok(i) = self.position(m) {
            self.0.remove(i);
        }
    }

    /// Whether `m` is a term.
    pub(crate) fn contains_key(&self, m: &M) -> bool {
        self.position(m).is_ok()
    }

    /// Whether there is no term.
    pub(crate) fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The number of terms.
    pub(crate) fn len(&self) -> usize {
        self.0.len()
    }

    /// The terms in increasing monomial order.
    pub(crate) fn iter(
        &self,
    ) -> impl DoubleEndedIterator<Item = (&M, &S)> + ExactSizeIterator + Clone + '_ {
        self.0.iter().map(|(m, c)| (m, c))
    }

    /// The term of the largest monomial (the leading term of the graded orders).
    pub(crate) fn last(&self) -> Option<(&M, &S)> {
        self.0.last().map(|(m, c)| (m, c))
    }

    /// The monomials in increasing order.
    pub(crate) fn keys(&self) -> impl DoubleEndedIterator<Item = &M> + Clone + '_ {
        self.0.iter().map(|(m, _)| m)
    }

    /// The coefficients, in the monomials' order.
    pub(crate) fn values(&self) -> impl DoubleEndedIterator<Item = &S> + Clone + '_ {
        self.0.iter().map(|(_, c)| c)
    }

    /// The coefficients, mutable, in the monomials' order.
    pub(crate) fn values_mut(&mut self) -> impl Iterator<Item = &mut S> + '_ {
        self.0.iter_mut().map(|(_, c)| c)
    }
}

impl<M: Ord, S> FromIterator<(M, S)> for Terms<M, S> {
    /// The terms of any pairs: sorted unless already in order, and of equal monomials the
    /// last kept (as a `BTreeMap` collects them).
    fn from_iter<I: IntoIterator<Item = (M, S)>>(pairs: I) -> Self {
        let mut v: Vec<(M, S)> = pairs.into_iter().collect();
        if !v.windows(2).all(|w| matches!(w, [a, b] if a.0 < b.0)) {
            // stable: equal monomials stay in their order, and the last of each run is kept
            v.sort_by(|a, b| a.0.cmp(&b.0));
            let mut out: Vec<(M, S)> = Vec::with_capacity(v.len());
            for (m, c) in v {
                match out.last_mut() {
                    Some(last) if last.0 == m => last.1 = c,
                    _ => out.push((m, c)),
                }
            }
            v = out;
        }
        Terms(v)
    }
}

impl<M, S> IntoIterator for Terms<M, S> {
    type Item = (M, S);
    type IntoIter = std::vec::IntoIter<(M, S)>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.into_iter()
    }
}

impl<'a, M, S> IntoIterator for &'a Terms<M, S> {
    type Item = (&'a M, &'a S);
    type IntoIter = std::iter::Map<std::slice::Iter<'a, (M, S)>, fn(&'a (M, S)) -> (&'a M, &'a S)>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter().map(|(m, c)| (m, c))
    }
}

#[cfg(test)]
mod tests {
    use super::Terms;
    use proptest::prelude::*;
    use std::collections::BTreeMap;

    proptest! {
        /// Every operation agrees with a `BTreeMap` given the same pairs and edits.
        #[test]
        fn terms_behave_as_an_ordered_map(
            pairs in prop::collection::vec((0u8..20, -5i32..5), 0..30),
            edits in prop::collection::vec((0u8..24, -5i32..5, 0u8..3), 0..30),
        ) {
            let mut t: Terms<u8, i32> = pairs.iter().copied().collect();
            let mut b: BTreeMap<u8, i32> = pairs.iter().copied().collect();
            for (m, c, op) in edits {
                match op {
                    0 => { t.insert(m, c); b.insert(m, c); }
                    1 => { t.remove(&m); b.remove(&m); }
                    _ => {
                        if let Some(x) = t.get_mut(&m) { *x += c; }
                        if let Some(x) = b.get_mut(&m) { *x += c; }
                    }
                }
                prop_assert_eq!(t.get(&m), b.get(&m));
                prop_assert_eq!(t.contains_key(&m), b.contains_key(&m));
            }
            prop_assert_eq!(t.len(), b.len());
            prop_assert_eq!(t.is_empty(), b.is_empty());
            let tv: Vec<(u8, i32)> = t.iter().map(|(m, c)| (*m, *c)).collect();
            let bv: Vec<(u8, i32)> = b.iter().map(|(m, c)| (*m, *c)).collect();
            prop_assert_eq!(&tv, &bv);
            prop_assert_eq!(t.keys().next_back(), b.keys().next_back());
            let owned: Vec<(u8, i32)> = t.into_iter().collect();
            prop_assert_eq!(owned, bv);
        }
    }
}
