//! Hand edits applied to a tree (the edit list's data model is [`crate::params::edits`]):
//! [`paint`] grows new shoots toward a painted stroke by space colonization from the tree's
//! existing stems, [`crown`] turns a drawn outline into the crown (the *Drawn* crown shape of a
//! Weber & Penn tree, the marker volume of a grown one).

pub mod crown;
pub mod paint;
