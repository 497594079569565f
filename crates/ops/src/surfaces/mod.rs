//! Tensor-product surfaces (chapter 5): one patch (evaluation, restriction, elevation,
//! derivatives, normals, continuity), closed forms and graphs, the Gaussian curvature, spline
//! surfaces split and their knots removed.

pub(crate) mod area;
pub(crate) mod continuity;
pub(crate) mod curvature;
pub(crate) mod patch;
pub(crate) mod surface;
pub(crate) mod surface_knots;
