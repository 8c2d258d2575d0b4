//! The two declaration macros of the registry.
//!
//! - `define_params!` turns the table of `params/registry.rs` into one parameter struct per
//!   pipeline stage (`SkeletonParams`, ..., `ViewerParams`, with `LevelParams`), their `Default`
//!   and bitwise `PartialEq`, the registry's specs and the typed get / set by id.
//! - `param_enum!` declares one enum parameter (variants, indices, labels) for `params/enums.rs`.
//!
//! The presets' `param_values!` is in `params/values.rs`.

/// Declares the parameters (used once, in `params/registry.rs`). Tree-level entries read
/// `id: Type = default; [min, max, step] "unit", "Group", "Label", Stage, "description";`
/// where `Stage` is the pipeline [`Stage`](super::Stage) whose parameter struct holds the field (the first
/// stage it affects), and per-level entries (Weber & Penn's `n*`, one value per level 0..3)
/// `id: Type = [d0, d1, d2, d3]; [min, max, step] "unit", "Label", "description", trunk: bool;`
/// where `trunk: false` means level 0 (the trunk) has no such parameter. Per-level parameters
/// all shape the stems: they live in [`SkeletonParams::level`](super::SkeletonParams::level).
///
/// The entries are sorted into one struct per stage ([`SkeletonParams`](super::SkeletonParams),
/// [`MeshParams`](super::MeshParams), [`FoliageParams`](super::FoliageParams),
/// [`LeafParams`](super::LeafParams), [`ViewerParams`](super::ViewerParams)) by a recursive walk
/// (`@split`); the registry keeps the table's order.
macro_rules! define_params {
    (tree { $($tree:tt)* } level { $($level:tt)* }) => {
        define_params!(@split [] [] [] [] [] $($tree)*);
        define_params!(@level $($level)*);
        define_params!(@registry { $($tree)* } { $($level)* });
    };

    // One entry goes to the accumulator of its stage.
    (@split [$($s:tt)*] [$($m:tt)*] [$($f:tt)*] [$($l:tt)*] [$($v:tt)*]
        $tf:ident : $tt:ty = $td:expr ; [$tmin:expr, $tmax:expr, $tstep:expr]
        $tunit:literal, $tgroup:literal, $tlabel:literal, Skeleton, $tdesc:literal ; $($rest:tt)*) => {
        define_params!(@split [$($s)* ($tf, $tt, $td, $tmin, $tmax, $tunit, $tdesc)] [$($m)*] [$($f)*] [$($l)*] [$($v)*] $($rest)*);
    };
    (@split [$($s:tt)*] [$($m:tt)*] [$($f:tt)*] [$($l:tt)*] [$($v:tt)*]
        $tf:ident : $tt:ty = $td:expr ; [$tmin:expr, $tmax:expr, $tstep:expr]
        $tunit:literal, $tgroup:literal, $tlabel:literal, Mesh, $tdesc:literal ; $($rest:tt)*) => {
        define_params!(@split [$($s)*] [$($m)* ($tf, $tt, $td, $tmin, $tmax, $tunit, $tdesc)] [$($f)*] [$($l)*] [$($v)*] $($rest)*);
    };
    (@split [$($s:tt)*] [$($m:tt)*] [$($f:tt)*] [$($l:tt)*] [$($v:tt)*]
        $tf:ident : $tt:ty = $td:expr ; [$tmin:expr, $tmax:expr, $tstep:expr]
        $tunit:literal, $tgroup:literal, $tlabel:literal, Foliage, $tdesc:literal ; $($rest:tt)*) => {
        define_params!(@split [$($s)*] [$($m)*] [$($f)* ($tf, $tt, $td, $tmin, $tmax, $tunit, $tdesc)] [$($l)*] [$($v)*] $($rest)*);
    };
    (@split [$($s:tt)*] [$($m:tt)*] [$($f:tt)*] [$($l:tt)*] [$($v:tt)*]
        $tf:ident : $tt:ty = $td:expr ; [$tmin:expr, $tmax:expr, $tstep:expr]
        $tunit:literal, $tgroup:literal, $tlabel:literal, Leaf, $tdesc:literal ; $($rest:tt)*) => {
        define_params!(@split [$($s)*] [$($m)*] [$($f)*] [$($l)* ($tf, $tt, $td, $tmin, $tmax, $tunit, $tdesc)] [$($v)*] $($rest)*);
    };
    (@split [$($s:tt)*] [$($m:tt)*] [$($f:tt)*] [$($l:tt)*] [$($v:tt)*]
        $tf:ident : $tt:ty = $td:expr ; [$tmin:expr, $tmax:expr, $tstep:expr]
        $tunit:literal, $tgroup:literal, $tlabel:literal, Viewer, $tdesc:literal ; $($rest:tt)*) => {
        define_params!(@split [$($s)*] [$($m)*] [$($f)*] [$($l)*] [$($v)* ($tf, $tt, $td, $tmin, $tmax, $tunit, $tdesc)] $($rest)*);
    };
    (@split [$($s:tt)*] [$($m:tt)*] [$($f:tt)*] [$($l:tt)*] [$($v:tt)*]) => {
        define_params!(@stage SkeletonParams, Skeleton,
            "The skeleton stage's parameters: the stems (Weber & Penn or space colonization), the crown \
             envelope, the per-level parameters, the growth volumes and the hand edits. What later stages need of them \
             travels on the [`crate::skeleton::Skeleton`].",
            [$($s)*]
            {
                /// Per-level parameters; index 0 is the trunk.
                pub level: [LevelParams; 4],
                /// Growth mode: the user's volume primitives (crown, shadow and exclusion groups);
                /// structured data beside the registry, JSON key `"volumes"` (see [`crate::params::volumes`]).
                pub volumes: Vec<$crate::params::VolumePrimitive>,
                /// The hand edits (paint, crown, cut, bend), applied in order after the stems are
                /// built; structured data beside the registry, JSON key `"edits"` (see
                /// [`crate::params::edits`]).
                pub edits: Vec<$crate::params::Edit>,
            }
            { level: [0, 1, 2, 3].map(LevelParams::of_level), volumes: Vec::new(), edits: Vec::new(), }
            (|a: &Self, b: &Self| a.level == b.level && a.volumes == b.volumes && a.edits == b.edits));
        define_params!(@stage MeshParams, Mesh,
            "The mesh stage's parameters: how the bark is swept, welded, fluted and cut.",
            [$($m)*] {} {} (|_: &Self, _: &Self| true));
        define_params!(@stage FoliageParams, Foliage,
            "The foliage stage's parameters: where the leaves sit, how large and how tinted.",
            [$($f)*] {} {} (|_: &Self, _: &Self| true));
        define_params!(@stage LeafParams, Leaf,
            "The leaf stage's parameters: the leaf's outline, veins and surface, and the mesh drawn per leaf.",
            [$($l)*] {} {} (|_: &Self, _: &Self| true));
        define_params!(@stage ViewerParams, Viewer,
            "Viewer-only parameters: they regenerate nothing.",
            [$($v)*] {} {} (|_: &Self, _: &Self| true));
    };

    // One stage's struct: its fields, `Default`, the bitwise `PartialEq` the session compares
    // with, and the typed get / set by id.
    (@stage $name:ident, $stage:ident, $doc:literal,
        [$( ($tf:ident, $tt:ty, $td:expr, $tmin:expr, $tmax:expr, $tunit:literal, $tdesc:literal) )*]
        { $($extra:tt)* } { $($extra_default:tt)* } ($extra_eq:expr)) => {
        #[doc = $doc]
        #[derive(Clone, Debug)]
        pub struct $name {
            $(
                #[doc = concat!($tdesc, " Default `", stringify!($td), "`, range ", stringify!($tmin), " to ", stringify!($tmax), " ", $tunit, ".")]
                pub $tf: $tt,
            )*
            $($extra)*
        }

        impl Default for $name {
            fn default() -> Self {
                $name { $( $tf: $td, )* $($extra_default)* }
            }
        }

        /// Equal when every value has the same wire bits (what a rerun would read), so
        /// `old != new` says exactly whether the stage must run again.
        impl PartialEq for $name {
            fn eq(&self, other: &Self) -> bool {
                $( ParamValue::to_wire(self.$tf).to_bits() == ParamValue::to_wire(other.$tf).to_bits() && )*
                ($extra_eq)(self, other)
            }
        }

        impl $name {
            /// The pipeline stage these parameters belong to.
            pub const STAGE: Stage = Stage::$stage;

            /// The wire value of this struct's own (not per-level) parameter `id`.
            pub(super) fn get_field(&self, id: &str) -> Option<f64> {
                match id {
                    $( stringify!($tf) => Some(ParamValue::to_wire(self.$tf)), )*
                    _ => None,
                }
            }

            /// Sets this struct's own parameter `id` (unchecked); false for an id it does not hold.
            pub(super) fn set_field(&mut self, id: &str, v: f64) -> bool {
                match id {
                    $( stringify!($tf) => self.$tf = ParamValue::from_wire(v), )*
                    _ => return false,
                }
                true
            }
        }
    };

    (@level $( $lf:ident : $lt:ty = [$d0:expr, $d1:expr, $d2:expr, $d3:expr] ; [$lmin:expr, $lmax:expr, $lstep:expr]
               $lunit:literal, $llabel:literal, $ldesc:literal, trunk: $ltrunk:literal ; )*) => {
        /// Weber & Penn's per-level parameters (`nLength`, `nDownAngle`, ...).
        #[derive(Clone, Debug)]
        pub struct LevelParams {
            $(
                #[doc = concat!($ldesc, " Defaults per level `", stringify!([$d0, $d1, $d2, $d3]), "`, range ", stringify!($lmin), " to ", stringify!($lmax), " ", $lunit, ".")]
                pub $lf: $lt,
            )*
        }

        /// Equal when every value has the same wire bits.
        impl PartialEq for LevelParams {
            fn eq(&self, other: &Self) -> bool {
                $( ParamValue::to_wire(self.$lf).to_bits() == ParamValue::to_wire(other.$lf).to_bits() && )* true
            }
        }

        impl LevelParams {
            /// The defaults of level `n` (0 = the trunk).
            fn of_level(n: usize) -> LevelParams {
                LevelParams { $( $lf: [$d0, $d1, $d2, $d3][n], )* }
            }

            /// Whether level 0 (the trunk) has per-level parameter `name` (false for an unknown
            /// name): `param_values!` checks it at compile time.
            pub const fn on_trunk(name: &str) -> bool {
                $( if super::macros::same(name, stringify!($lf)) { return $ltrunk; } )*
                false
            }

            /// The wire value of per-level parameter `name` (the id without `l{n}_`).
            pub(super) fn get(&self, name: &str) -> Option<f64> {
                match name {
                    $( stringify!($lf) => Some(ParamValue::to_wire(self.$lf)), )*
                    _ => None,
                }
            }

            /// Sets per-level parameter `name` (unchecked); false for an unknown name.
            pub(super) fn set(&mut self, name: &str, v: f64) -> bool {
                match name {
                    $( stringify!($lf) => self.$lf = ParamValue::from_wire(v), )*
                    _ => return false,
                }
                true
            }
        }
    };

    (@registry {
            $( $tf:ident : $tt:ty = $td:expr ; [$tmin:expr, $tmax:expr, $tstep:expr]
               $tunit:literal, $tgroup:literal, $tlabel:literal, $tstage:ident, $tdesc:literal ; )*
        } {
            $( $lf:ident : $lt:ty = [$d0:expr, $d1:expr, $d2:expr, $d3:expr] ; [$lmin:expr, $lmax:expr, $lstep:expr]
               $lunit:literal, $llabel:literal, $ldesc:literal, trunk: $ltrunk:literal ; )*
        }) => {
        pub(super) fn build_registry() -> Vec<ParamSpec> {
            let mut specs = vec![$(
                ParamSpec {
                    id: stringify!($tf).to_string(),
                    group: $tgroup.to_string(),
                    label: $tlabel.to_string(),
                    kind: <$tt as ParamValue>::KIND,
                    default: ParamValue::to_wire($td as $tt),
                    min: $tmin as f64,
                    max: $tmax as f64,
                    step: $tstep as f64,
                    unit: $tunit.to_string(),
                    description: $tdesc.to_string(),
                    options: <$tt as ParamValue>::options(),
                    stage: Stage::$tstage,
                },
            )*];
            for n in 0..4usize {
                let group = if n == 0 { "Trunk".to_string() } else { format!("Level {n}") };
                $(
                    if n > 0 || $ltrunk {
                        specs.push(ParamSpec {
                            id: format!("l{n}_{}", stringify!($lf)),
                            group: group.clone(),
                            label: $llabel.to_string(),
                            kind: <$lt as ParamValue>::KIND,
                            default: ParamValue::to_wire([$d0, $d1, $d2, $d3][n] as $lt),
                            min: $lmin as f64,
                            max: $lmax as f64,
                            step: $lstep as f64,
                            unit: $lunit.to_string(),
                            description: $ldesc.to_string(),
                            options: <$lt as ParamValue>::options(),
                            stage: Stage::Skeleton,
                        });
                    }
                )*
            }
            specs.sort_by_key(|s| GROUPS.iter().position(|g| *g == s.group).unwrap_or(GROUPS.len()));
            specs
        }
    };
}
pub(super) use define_params;

/// Whether two strings are equal, in a constant (`LevelParams::on_trunk`).
pub(super) const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// Declares an enum parameter once (variants, indices, labels) and derives what the registry
/// needs from it: `ALL`, `LABELS`, `from_index`, `from_name`, `label` and the `ParamValue` wire
/// conversion, so the panel's options, the URL codec and the CLI's name lookup cannot drift
/// apart. Every enum of the registry is declared with it in `params/enums.rs`.
macro_rules! param_enum {
    ($(#[$doc:meta])* $name:ident { $( $(#[$vdoc:meta])* $v:ident = $i:literal, $label:literal; )* }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
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
                let want = $crate::params::norm(name);
                Self::LABELS.iter().position(|l| $crate::params::norm(l) == want).map(Self::from_index)
            }

            /// The display label.
            pub fn label(self) -> &'static str {
                Self::LABELS[self as usize]
            }
        }

        impl $crate::params::ParamValue for $name {
            const KIND: $crate::params::ParamKind = $crate::params::ParamKind::Enum;
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

        impl $crate::params::Written for $name {
            type Literal = $name;
            fn from_literal(literal: $name) -> $name {
                literal
            }
            fn wire(literal: $name) -> f64 {
                $crate::params::ParamValue::to_wire(literal)
            }
        }
    };
}
pub(super) use param_enum;
