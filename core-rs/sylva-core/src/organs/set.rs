//! One kind of part drawn as instances ([`OrganSet`]) and what it is ([`OrganKind`]).

use crate::mesh::TreeMesh;

/// What one set of instances is, for viewers and exporters (names, materials, LODs).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum OrganKind {
    /// Blossom petals (five to a flower).
    Petals,
    /// A flower's centre: its stamens.
    FlowerCentre,
    /// A catkin (birch, aspen, willow).
    Catkin,
    /// A winter bud at a shoot tip.
    Bud,
    /// A fruit's body: the acorn's nut, the cherry, the apple, the cone, the samara's seeds.
    Fruit,
    /// A fruit's second part: the acorn's cup, the samara's wings.
    FruitPart,
    /// The stalk a fruit or flower hangs from.
    Stalk,
}

/// One kind of part, instanced: `mesh` drawn once per instance.
#[derive(Clone, Debug, PartialEq)]
pub struct OrganSet {
    /// What it is.
    pub kind: OrganKind,
    /// A name for nodes and materials (`"cherry blossom petals"`).
    pub name: &'static str,
    /// The part in metres: its attachment at the origin, pointing along `+y` (a hanging part's
    /// matrix turns `+y` down). One group.
    pub mesh: TreeMesh,
    /// The material's base colour (sRGB, 0..1).
    pub color: [f32; 3],
    /// The material's roughness (0..1).
    pub roughness: f32,
    /// Per-instance 4×4 matrices, column-major, 16 floats per instance (the leaves' layout).
    pub matrices: Vec<f32>,
    /// Per-instance RGB tint (linear light, multiplies `color`), 3 floats per instance.
    pub colors: Vec<f32>,
}

impl OrganSet {
    /// Number of instances.
    pub fn count(&self) -> usize {
        self.colors.len() / 3
    }

    /// Feeds the set into a content hash (FNV-1a over 32-bit words, as the foliage's).
    pub fn hash_into(&self, mut h: u64) -> u64 {
        let mut word = |w: u32| h = (h ^ u64::from(w)).wrapping_mul(0x0000_0100_0000_01b3);
        word(self.kind as u32);
        let m = self.mesh.content_hash();
        word(m as u32);
        word((m >> 32) as u32);
        self.color.iter().chain([&self.roughness]).for_each(|v| word(v.to_bits()));
        self.matrices.iter().chain(&self.colors).for_each(|v| word(v.to_bits()));
        h
    }
}
