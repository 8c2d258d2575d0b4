//! The enum parameters of the registry, declared with `param_enum!` (options, indices, labels).
//!
//! Each enum's behaviour stays with the stage that uses it, as inherent impls: [`CrownShape::ratio`]
//! in `crown.rs`, [`TwigDetail::step`] in `mesh/twig.rs`.

use super::macros::param_enum;

// Crown (Weber & Penn ShapeRatio, `crown.rs`).

param_enum! {
    /// The eight crown envelopes of Mtree's *Crown Shape User Guide*, in Weber & Penn's numbering,
    /// and the drawn one.
    CrownShape {
        /// Christmas tree: longest branches at the crown base (fir, spruce).
        Conical = 0, "Conical";
        /// Ball: longest in the middle (oak, maple).
        Spherical = 1, "Spherical";
        /// Dome: longest at the base, rounding to the top (umbrella trees).
        Hemispherical = 2, "Hemispherical";
        /// All branches the same length (the default).
        Cylindrical = 3, "Cylindrical";
        /// A gentle taper from base to top.
        TaperedCylindrical = 4, "Tapered Cylindrical";
        /// Widest at 70% of the crown from the top, pointed tip (cedar, cypress).
        Flame = 5, "Flame";
        /// Widest at the top: fan or mushroom.
        InverseConical = 6, "Inverse Conical";
        /// A softer flame.
        TendFlame = 7, "Tend Flame";
        /// The outline drawn by hand (a crown edit, `crate::edits::crown`); Cylindrical without one.
        Drawn = 8, "Drawn";
    }
}

// Growth (space colonization, `growth/`).

param_enum! {
    /// How the tree is made.
    GrowthMode {
        /// Weber & Penn's parametric model.
        Parametric = 0, "Parametric (Weber & Penn)";
        /// Space colonization growth.
        SpaceColonization = 1, "Space Colonization";
    }
}

param_enum! {
    /// The shape of the marker volume.
    CrownVolumeKind {
        /// An ellipsoid.
        Ellipsoid = 0, "Ellipsoid";
        /// The Crown Shape envelope as a solid of revolution.
        Envelope = 1, "Crown Shape envelope";
        /// The union of the user's crown-group primitives (`TreeParams::volumes`; the ellipsoid
        /// when there is none).
        Primitives = 2, "Primitives (user volumes)";
    }
}

// Bezier twigs (`mesh/twig.rs`).

param_enum! {
    /// The page's step along the control circle (`stu`): 1 is the finest, 8 the coarsest.
    TwigDetail {
        /// Step 1: four times the sides of a tube of the same radius.
        One = 0, "1 (finest)";
        /// Step 2: twice the tube's sides.
        Two = 1, "2";
        /// Step 4: the tube's sides.
        Four = 2, "4";
        /// Step 8: half the tube's sides (at least 3).
        Eight = 3, "8 (coarsest)";
    }
}

// The leaf (`leaf/`).

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
        /// None: colonization grows everything from the petiole (Mtree's *Leaf Generation Guide*, §4).
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

// Seasons (`season.rs`).

param_enum! {
    /// Whose calendar and autumn colours a tree's leaves follow through the Season
    /// ([`crate::season`]): one entry per species leaf of the leaf presets.
    LeafPhenology {
        /// Quaking aspen: early leaf-out, golden yellow in early October (the default leaf).
        Aspen = 0, "Aspen";
        /// Maple: scarlet to orange in October.
        Maple = 1, "Maple";
        /// Oak: late leaf-out, russet and brown, leaves held into December.
        Oak = 2, "Oak";
        /// Birch: yellow in October.
        Birch = 3, "Birch";
        /// Ginkgo: butter yellow late in October, then all leaves drop within days.
        Ginkgo = 4, "Ginkgo";
        /// Willow: first to leaf out, yellow late, leaves kept into November.
        Willow = 5, "Willow";
        /// Black tupelo: the first to turn, crimson and purple-red in late September.
        Tupelo = 6, "Tupelo";
        /// Evergreen conifer: keeps its needles, a slight bronzing in winter.
        Conifer = 7, "Evergreen Conifer";
        /// Wild cherry: white blossom in April just before and with its leaves, cherries ripe in
        /// June, orange and red in October.
        Cherry = 8, "Cherry";
        /// Apple: pink-budded white blossom with its leaves in May, apples through the summer,
        /// yellow-brown late in autumn.
        Apple = 9, "Apple";
    }
}

param_enum! {
    /// The fruit a tree bears in its months ([`crate::organs`]).
    Fruit {
        /// No fruit shown.
        None = 0, "None";
        /// Oak acorns in their cups, green in August, brown and dropping in October.
        Acorns = 1, "Acorns";
        /// Paired winged maple seeds, hanging in bunches, green then tan, falling in autumn.
        Samaras = 2, "Samaras";
        /// Pine cones hanging under the shoots, brown from August through the winter.
        HangingCones = 3, "Hanging Cones";
        /// Fir cones standing upright on the top of the upper branches, August to November.
        UprightCones = 4, "Upright Cones";
        /// Cherries in pairs on long stalks, green after the blossom, red in June.
        Cherries = 5, "Cherries";
        /// Apples on short stalks, swelling from June, red-cheeked by September.
        Apples = 6, "Apples";
    }
}

// Bark (`mesh/bark`).

param_enum! {
    /// The bark pattern of a tree (`docs/look.md`, "Bark types").
    BarkType {
        /// Deep vertical fissures between interlacing ridges (oaks, ash).
        Furrowed = 0, "Furrowed";
        /// Irregular plates separated by dark cracks (pines, spruces, firs).
        Plated = 1, "Plated";
        /// Smooth pale skin with horizontal lenticels and bands (birch, cherry, aspen).
        SmoothBanded = 2, "Smooth-banded";
        /// Long criss-crossing strips (willows, cedars, cypress).
        Fibrous = 3, "Fibrous";
    }
}
