//! [`TreeParams`]: the parameters of one tree, one struct per pipeline stage, and the flat
//! get / set by id (`scale`, `l1_length`, ...) that the panel, share links, presets and the CLI
//! use. The stage structs themselves are declared by the registry's table (`registry.rs`).

use super::registry::{FoliageParams, LeafParams, MeshParams, SkeletonParams, ViewerParams};
use super::{registry, split_level_id, Stage};
use crate::error::SylvaError;

/// Every parameter of a tree, grouped by the pipeline stage that reads it. Build with
/// `TreeParams::default()` and change fields, or from wire values with
/// [`TreeParams::from_values`]; [`TreeParams::validate`] checks all.
///
/// Each stage takes only its own struct (plus what earlier stages made), so a stage cannot
/// read another stage's parameter, and a session reruns a stage exactly when its struct
/// changed ([`crate::session::Session`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TreeParams {
    /// The stems, the per-level parameters and the growth volumes.
    pub skeleton: SkeletonParams,
    /// The bark surface.
    pub mesh: MeshParams,
    /// The leaf placements.
    pub foliage: FoliageParams,
    /// The leaf and the mesh drawn per leaf.
    pub leaf: LeafParams,
    /// What the viewer shows; regenerates nothing.
    pub viewer: ViewerParams,
}

impl SkeletonParams {
    /// The wire value of skeleton parameter `id` (per-level ids included).
    pub fn get(&self, id: &str) -> Option<f64> {
        self.get_field(id).or_else(|| {
            let (n, name) = split_level_id(id)?;
            self.level[n].get(name)
        })
    }

    fn set_unchecked(&mut self, id: &str, v: f64) -> bool {
        self.set_field(id, v) || split_level_id(id).is_some_and(|(n, name)| self.level[n].set(name, v))
    }

    /// Checks every skeleton parameter and the growth volumes.
    pub fn validate(&self) -> Result<(), SylvaError> {
        check_stage(Self::STAGE, |id| self.get(id))?;
        super::volumes::validate(&self.volumes)
    }
}

/// `get`, `set_unchecked` and `validate` of a stage struct without per-level parameters.
macro_rules! plain_stage {
    ($($name:ident),*) => {$(
        impl $name {
            /// The wire value of this stage's parameter `id`.
            pub fn get(&self, id: &str) -> Option<f64> {
                self.get_field(id)
            }

            fn set_unchecked(&mut self, id: &str, v: f64) -> bool {
                self.set_field(id, v)
            }

            /// Checks every parameter of this stage against its spec.
            pub fn validate(&self) -> Result<(), SylvaError> {
                check_stage(Self::STAGE, |id| self.get(id))
            }
        }
    )*};
}
plain_stage!(MeshParams, FoliageParams, LeafParams, ViewerParams);

/// Checks every registry parameter of `stage` read through `get`.
fn check_stage(stage: Stage, get: impl Fn(&str) -> Option<f64>) -> Result<(), SylvaError> {
    for spec in registry().iter().filter(|s| s.stage == stage) {
        spec.check(get(&spec.id).expect("every registry id is gettable"))?;
    }
    Ok(())
}

impl TreeParams {
    /// The wire value of parameter `id`, or `None` for an unknown id.
    pub fn get(&self, id: &str) -> Option<f64> {
        self.skeleton
            .get(id)
            .or_else(|| self.mesh.get(id))
            .or_else(|| self.foliage.get(id))
            .or_else(|| self.leaf.get(id))
            .or_else(|| self.viewer.get(id))
    }

    /// Set parameter `id` to the wire value `v` without checking it ([`TreeParams::set`] checks).
    pub(super) fn set_unchecked(&mut self, id: &str, v: f64) {
        let _ = self.skeleton.set_unchecked(id, v)
            || self.mesh.set_unchecked(id, v)
            || self.foliage.set_unchecked(id, v)
            || self.leaf.set_unchecked(id, v)
            || self.viewer.set_unchecked(id, v);
    }

    /// The first pipeline stage whose parameters differ between `self` and `other`
    /// ([`Stage::Viewer`] when only viewer parameters, or none, differ).
    pub fn first_difference(&self, other: &Self) -> Stage {
        if self.skeleton != other.skeleton {
            Stage::Skeleton
        } else if self.mesh != other.mesh {
            Stage::Mesh
        } else if self.foliage != other.foliage {
            Stage::Foliage
        } else if self.leaf != other.leaf {
            Stage::Leaf
        } else {
            Stage::Viewer
        }
    }
}
