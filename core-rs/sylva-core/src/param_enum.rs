//! `param_enum!`: declares an enum parameter once (variants, indices, labels) and derives what
//! the registry needs from it: `ALL`, `LABELS`, `from_index`, `from_name`, `label` and the
//! [`crate::params::ParamValue`] wire conversion. Every enum in the registry uses it, so the
//! panel's options, the URL codec and the CLI's name lookup cannot drift apart.

/// Lower-case ASCII letters and digits only: labels compare without case or separators.
#[doc(hidden)]
pub fn norm(s: &str) -> String {
    s.chars().filter(|c| c.is_ascii_alphanumeric()).collect::<String>().to_ascii_lowercase()
}

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
                let want = $crate::param_enum::norm(name);
                Self::LABELS.iter().position(|l| $crate::param_enum::norm(l) == want).map(Self::from_index)
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
pub(crate) use param_enum;
