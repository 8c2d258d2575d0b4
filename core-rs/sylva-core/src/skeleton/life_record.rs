//! The record of a tree's life past its Mature Age, kept on its skeleton ([`Skeleton::life`]).

use super::Skeleton;

/// What the years past the Mature Age started from and how they acted: kept on the
/// skeleton ([`Skeleton::life`]) so the growth animation can show the tree in any year between
/// (`LifeRecord::at`, in [`crate::life`]).
#[derive(Clone, Debug)]
pub struct LifeRecord {
    /// The stems at the Mature Age, before any year of life.
    pub mature: Skeleton,
    /// Ring Width (m a year).
    pub ring: f32,
    /// Shedding Light and Shedding Delay.
    pub shed: (f32, f32),
    /// Droop (degrees a decade).
    pub droop: f32,
    /// The Mature Age and the Age.
    pub years: (f32, f32),
}
