//! Surface generation (chapter 6): translational, ruled, developable, Coons, revolution;
//! conics and the tangent developable.

pub(crate) mod generate;
pub(crate) mod loft;
pub(crate) mod shapes;
