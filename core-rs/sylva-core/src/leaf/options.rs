//! The leaf's enum parameters (outline mode, margin type, venation) and their registry wiring.
//! Every numeric leaf parameter lives in the registry (`params.rs`, groups "Leaf", "Leaf Veins"
//! and "Leaf Surface"), so the typed fields of [`crate::TreeParams`] are the leaf's options.

use crate::params::{ParamKind, ParamValue};
use serde::Serialize;

fn norm(s: &str) -> String {
    s.chars().filter(|c| c.is_ascii_alphanumeric()).collect::<String>().to_ascii_lowercase()
}

macro_rules! leaf_enum {
    ($(#[$doc:meta])* $name:ident { $( $(#[$vdoc:meta])* $v:ident = $i:literal, $label:literal; )* }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
        pub enum $name {
            $( $(#[$vdoc])* $v = $i, )*
        }

        impl $name {
            /// All values in index order.
            pub const ALL: &'static [$name] = &[$( $name::$v, )*];
            /// Display labels in index order (the registry's enum options).
            pub const LABELS: &'static [&'static str] = &[$( $label, )*];

            /// The value with this index (clamped into range).
            pub fn from_index(i: usize) -> $name {
                Self::ALL[i.min(Self::ALL.len() - 1)]
            }

            /// Look a value up by label, case- and separator-insensitively.
            pub fn from_name(name: &str) -> Option<$name> {
                let want = norm(name);
                Self::LABELS.iter().position(|l| norm(l) == want).map(Self::from_index)
            }

            /// The display label.
            pub fn label(self) -> &'static str {
                Self::LABELS[self as usize]
            }
        }

        impl ParamValue for $name {
            const KIND: ParamKind = ParamKind::Enum;
            fn to_wire(self) -> f64 {
                f64::from(self as u8)
            }
            fn from_wire(v: f64) -> Self {
                $name::from_index(v as usize)
            }
            fn options() -> Option<Vec<String>> {
                Some(Self::LABELS.iter().map(|s| s.to_string()).collect())
            }
        }
    };
}

leaf_enum! {
    /// How the blade outline is drawn.
    LeafOutline {
        /// Gielis' superformula over 360°, mirrored about the midrib.
        Superformula = 0, "Superformula";
        /// One cubic spline from base to tip (Angle1, L1, Angle2, L2), mirrored about the midrib.
        Spline = 1, "Spline";
    }
}

leaf_enum! {
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

leaf_enum! {
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

leaf_enum! {
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
