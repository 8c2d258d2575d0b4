//! The leaf's enum parameters (outline mode, margin type, venation) and their registry wiring.
//! Every numeric leaf parameter lives in the registry (`params/mod.rs`, groups "Leaf", "Leaf Veins"
//! and "Leaf Surface"), so the typed fields of [`crate::TreeParams`] are the leaf's options.

use crate::param_enum::param_enum;

param_enum! {
    /// How the blade outline is drawn.
    LeafOutline {
        /// Gielis' superformula over 360°, mirrored about the midrib.
        Superformula = 0, "Superformula";
        /// One cubic spline from base to tip (Angle1, L1, Angle2, L2), mirrored about the midrib.
        Spline = 1, "Spline";
        /// A blade profile along the midrib with lobes placed along it (oak, birch, aspen,
        /// willow): [`crate::leaf::lobes::Pinnate`].
        Pinnate = 2, "Pinnate";
        /// Lobes radiating from the petiole junction (maple, ginkgo's fan):
        /// [`crate::leaf::lobes::Palmate`].
        Palmate = 3, "Palmate";
    }
}

param_enum! {
    /// The small-scale shape of the leaf edge.
    LeafMargin {
        /// Smooth edge (magnolia).
        Entire = 0, "Entire";
        /// Asymmetric saw teeth leaning toward the tip (elm, cherry, birch).
        Serrate = 1, "Serrate";
        /// Symmetric pointed teeth (chestnut).
        Dentate = 2, "Dentate";
        /// Rounded scallops (beech).
        Crenate = 3, "Crenate";
        /// Deep rounded lobes (oak, maple).
        Lobed = 4, "Lobed";
    }
}

param_enum! {
    /// How the vein network is made.
    LeafVenation {
        /// No veins (needles).
        None = 0, "None";
        /// Space colonization, open: a tree of veins, every vein tip a dead end.
        Open = 1, "Open";
        /// Space colonization, closed: veins reconnect into loops (most flowering plants).
        Closed = 2, "Closed";
        /// Arcuate / pinnate spline veins from the midrib to the edge.
        Spline = 3, "Spline";
    }
}

param_enum! {
    /// The primary veins laid down before space colonization fills the rest
    /// ([`crate::leaf::veins::primary`]).
    LeafPrimaries {
        /// None: colonization grows everything from the petiole (the guide's method).
        None = 0, "None";
        /// A midrib with secondary veins along it, one per lobe on a lobed blade.
        Pinnate = 1, "Pinnate";
        /// Primary veins radiating from the petiole junction, one per lobe.
        Palmate = 2, "Palmate";
        /// Veins forking repeatedly in two from the petiole (ginkgo).
        Dichotomous = 3, "Dichotomous";
    }
}

param_enum! {
    /// Which leaf geometry the tree's foliage instances.
    LeafLod {
        /// The full blade while leaves × blade triangles stay under the foliage triangle
        /// budget, else the billboard cloud, else the card.
        Auto = 0, "Auto";
        /// The full deformed blade (LOD0).
        Blade = 1, "Blade";
        /// Four quads fitted to the blade (the billboard cloud).
        Billboards = 2, "Billboards";
        /// One flat textured quad (for far views).
        Card = 3, "Card";
    }
}
