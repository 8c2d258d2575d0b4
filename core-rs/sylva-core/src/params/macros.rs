//! The two declaration macros of the registry.
//!
//! - `define_params!` turns the table of `params/registry.rs` into `TreeParams`, its `Default`,
//!   `LevelParams`, the registry's specs and the typed `get` / `set_unchecked` by id.
//! - `param_enum!` declares one enum parameter (variants, indices, labels) for `params/enums.rs`.

/// Declares the parameters (used once, in `params/registry.rs`). Tree-level entries read
/// `id: Type = default; [min, max, step] "unit", "Group", "Label", Stage, "description";`
/// where `Stage` is the first pipeline [`Stage`] the parameter affects,
/// and per-level entries (Weber & Penn's `n*`, one value per level 0..3)
/// `id: Type = [d0, d1, d2, d3]; [min, max, step] "unit", "Label", "description", trunk: bool;`
/// where `trunk: false` means level 0 (the trunk) has no such parameter. Per-level parameters
/// all shape the stems: their stage is [`Stage::Skeleton`].
macro_rules! define_params {
    (
        tree {
            $( $tf:ident : $tt:ty = $td:expr ; [$tmin:expr, $tmax:expr, $tstep:expr]
               $tunit:literal, $tgroup:literal, $tlabel:literal, $tstage:ident, $tdesc:literal ; )*
        }
        level {
            $( $lf:ident : $lt:ty = [$d0:expr, $d1:expr, $d2:expr, $d3:expr] ; [$lmin:expr, $lmax:expr, $lstep:expr]
               $lunit:literal, $llabel:literal, $ldesc:literal, trunk: $ltrunk:literal ; )*
        }
    ) => {
        /// Every parameter of a tree. Build with `TreeParams::default()` and change fields, or
        /// from wire values with [`TreeParams::from_values`]; [`TreeParams::validate`] checks all.
        #[derive(Clone, Debug, PartialEq)]
        pub struct TreeParams {
            $(
                #[doc = concat!($tdesc, " Default `", stringify!($td), "`, range ", stringify!($tmin), " to ", stringify!($tmax), " ", $tunit, ".")]
                pub $tf: $tt,
            )*
            /// Per-level parameters; index 0 is the trunk.
            pub level: [LevelParams; 4],
            /// Growth mode: the user's volume primitives (crown, shadow and exclusion groups);
            /// structured data beside the registry, JSON key `"volumes"` (see [`crate::params::volumes`]).
            pub volumes: Vec<$crate::params::VolumePrimitive>,
        }

        /// Weber & Penn's per-level parameters (`nLength`, `nDownAngle`, ...).
        #[derive(Clone, Debug, PartialEq)]
        pub struct LevelParams {
            $(
                #[doc = concat!($ldesc, " Defaults per level `", stringify!([$d0, $d1, $d2, $d3]), "`, range ", stringify!($lmin), " to ", stringify!($lmax), " ", $lunit, ".")]
                pub $lf: $lt,
            )*
        }

        impl Default for TreeParams {
            fn default() -> Self {
                let level = |n: usize| LevelParams { $( $lf: [$d0, $d1, $d2, $d3][n], )* };
                TreeParams { $( $tf: $td, )* level: [level(0), level(1), level(2), level(3)], volumes: Vec::new() }
            }
        }

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

        impl TreeParams {
            /// The wire value of parameter `id`, or `None` for an unknown id.
            pub fn get(&self, id: &str) -> Option<f64> {
                match id {
                    $( stringify!($tf) => return Some(ParamValue::to_wire(self.$tf)), )*
                    _ => {}
                }
                let (n, name) = split_level_id(id)?;
                let l = &self.level[n];
                match name {
                    $( stringify!($lf) => Some(ParamValue::to_wire(l.$lf)), )*
                    _ => None,
                }
            }

            /// Set parameter `id` to the wire value `v` without checking it ([`TreeParams::set`] checks).
            pub(super) fn set_unchecked(&mut self, id: &str, v: f64) {
                match id {
                    $( stringify!($tf) => { self.$tf = ParamValue::from_wire(v); return; } )*
                    _ => {}
                }
                if let Some((n, name)) = split_level_id(id) {
                    let l = &mut self.level[n];
                    match name {
                        $( stringify!($lf) => l.$lf = ParamValue::from_wire(v), )*
                        _ => {}
                    }
                }
            }
        }
    };
}
pub(super) use define_params;

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
    };
}
pub(super) use param_enum;
