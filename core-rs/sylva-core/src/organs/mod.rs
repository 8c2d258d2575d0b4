//! # Flowers, fruit, catkins and buds
//!
//! What a tree carries besides its leaves through the **Season** ([`crate::season`]): blossom
//! in spring (cherry and apple: five petals made by the leaf pipeline, [`meshes`]), catkins
//! (birch, aspen, willow), the **Fruit** in its months (acorns, samaras, cones, cherries,
//! apples) and, on a bare deciduous tree in winter, a bud at every shoot tip. When each shows,
//! at what size and colour, is the species' calendar in [`calendar`]; where, is [`place`](mod@place).
//!
//! Each kind of part is one [`OrganSet`]: one small mesh in metres drawn once per instance
//! through a 4×4 matrix and an RGB tint, like the leaves ([`crate::foliage`]), in a plain
//! material of the set's colour. A part of two colours (an acorn and its cup, a cherry and its
//! stalk) is two sets whose instances pair up.
//!
//! July, the default Season, carries none on every preset older than the cherry and apple,
//! so their trees are unchanged; **Flowers & Fruit** off carries none in any month.
//! Randomness: the named stream `"organs"`.

pub mod calendar;
pub mod meshes;
mod place;
mod set;

pub use place::place;
pub use set::{OrganKind, OrganSet};
