//! Which limit of a run a refusal is about (its name, which the front ends spell as a flag).

/// Which of the [`crate::Limits`] a refusal is about.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Limit {
    /// [`crate::Limits::max_degree`].
    Degree,
    /// [`crate::Limits::max_points`].
    Points,
    /// [`crate::Limits::max_digits`].
    Digits,
    /// [`crate::Limits::max_batch`].
    Batch,
    /// [`crate::Limits::max_depth`].
    Depth,
    /// [`crate::Limits::max_exponent`].
    Exponent,
    /// [`crate::Limits::max_seconds`].
    Seconds,
    /// [`crate::Limits::max_memory`].
    Memory,
}

impl Limit {
    /// The name of the limit: its field of [`crate::Limits`] (`max_degree`), which the front ends
    /// spell as a flag (`--max-degree`) or a keyword (`max_degree=`).
    pub fn name(self) -> &'static str {
        match self {
            Limit::Degree => "max_degree",
            Limit::Points => "max_points",
            Limit::Digits => "max_digits",
            Limit::Batch => "max_batch",
            Limit::Depth => "max_depth",
            Limit::Exponent => "max_exponent",
            Limit::Seconds => "max_seconds",
            Limit::Memory => "max_memory",
        }
    }
}
