//! Typed parameter values for presets: [`param_values!`](crate::param_values) turns assignments on the stage structs
//! (`skeleton.shape = CrownShape::Conical`, `skeleton.level[1].length = 0.32`,
//! `foliage.leaf_petiole = 0.05`) into a [`ParamValues`]: the assignments themselves, checked by
//! the compiler (an unknown field, a field of another stage, a float for an int, a number for an
//! enum, a per-level parameter the trunk does not have: none compiles), and the same values as
//! wire numbers by id, in the order written, for share links and the presets' JSON.

use super::spec::ParamValue;
use super::stages::TreeParams;
use std::fmt;

/// How a preset writes a value of a parameter's type ([`param_values!`](crate::param_values)). Floats are written as
/// decimals read as `f64` (the wire value, kept as written for the presets' JSON) and stored as the
/// `f32` that wire value rounds to, exactly as [`TreeParams::set`] stores it; ints, booleans and
/// enums are written as themselves.
pub trait Written: ParamValue {
    /// The type of the value as a preset writes it.
    type Literal;
    /// The stored value.
    fn from_literal(literal: Self::Literal) -> Self;
    /// The wire number.
    fn wire(literal: Self::Literal) -> f64;
}

impl Written for f32 {
    type Literal = f64;
    fn from_literal(literal: f64) -> f32 {
        f32::from_wire(literal)
    }
    fn wire(literal: f64) -> f64 {
        literal
    }
}

/// `Written` for the types written as themselves.
macro_rules! written_as_itself {
    ($($t:ty),*) => {$(
        impl Written for $t {
            type Literal = $t;
            fn from_literal(literal: $t) -> $t {
                literal
            }
            fn wire(literal: $t) -> f64 {
                literal.to_wire()
            }
        }
    )*};
}
written_as_itself!(u32, bool);

/// Stores `literal` in `field` (typed by the field: an `f64` decimal for an `f32`).
#[doc(hidden)]
pub fn set<T: Written>(field: &mut T, literal: T::Literal) {
    *field = T::from_literal(literal);
}

/// The wire number of `literal` written for the field `slot` reaches (the slot is never called:
/// it only types the literal).
#[doc(hidden)]
pub fn wire<T: Written>(_slot: fn(&mut TreeParams) -> &mut T, literal: T::Literal) -> f64 {
    T::wire(literal)
}

/// A preset's parameter values, written once as typed assignments with
/// [`param_values!`](crate::param_values):
/// [`ParamValues::apply`] makes the assignments, [`ParamValues::wire`] lists the same values as
/// `(id, wire number)` in the order written (values equal to a default included).
#[derive(Clone, Copy)]
pub struct ParamValues {
    apply: fn(&mut TreeParams),
    wire: fn() -> Vec<(&'static str, f64)>,
}

impl ParamValues {
    /// No values.
    pub const NONE: ParamValues = ParamValues { apply: |_| {}, wire: Vec::new };

    /// Made by [`param_values!`](crate::param_values).
    #[doc(hidden)]
    pub const fn new(apply: fn(&mut TreeParams), wire: fn() -> Vec<(&'static str, f64)>) -> ParamValues {
        ParamValues { apply, wire }
    }

    /// Sets the values on `params` (unchecked: [`TreeParams::validate`] checks the result).
    pub fn apply(&self, params: &mut TreeParams) {
        (self.apply)(params);
    }

    /// The values as `(id, wire number)`, in the order written.
    pub fn wire(&self) -> Vec<(&'static str, f64)> {
        (self.wire)()
    }
}

impl fmt::Debug for ParamValues {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_map().entries(self.wire()).finish()
    }
}

/// Typed parameter values ([`ParamValues`]): comma-separated assignments
/// `stage.field = value` or `skeleton.level[n].field = value`, where `stage` is the field's
/// struct in [`TreeParams`] and `value` is written as [`Written`] says (`0.32` for a float, `3`
/// for an int, `true`, `CrownShape::Conical`).
///
/// ```
/// use sylva_core::param_values;
/// use sylva_core::params::{CrownShape, TreeParams};
///
/// let values = param_values! {
///     skeleton.shape = CrownShape::Conical,
///     skeleton.level[1].length = 0.32,
///     foliage.leaves = 16,
/// };
/// assert_eq!(values.wire(), [("shape", 0.0), ("l1_length", 0.32), ("leaves", 16.0)]);
/// let mut params = TreeParams::default();
/// values.apply(&mut params);
/// assert_eq!(params, TreeParams::from_values(values.wire())?);
/// # Ok::<(), sylva_core::SylvaError>(())
/// ```
///
/// A typo, a field of another stage or a value of the wrong type does not compile:
///
/// ```compile_fail
/// # use sylva_core::param_values;
/// let values = param_values! { skeleton.leaves = 16 }; // `leaves` is a foliage parameter
/// ```
///
/// ```compile_fail
/// # use sylva_core::param_values;
/// let values = param_values! { skeleton.shape = 7.0 }; // an enum, not its index
/// ```
///
/// ```compile_fail
/// # use sylva_core::param_values;
/// let values = param_values! { foliage.leaves = 16.0 }; // an int
/// ```
///
/// ```compile_fail
/// # use sylva_core::param_values;
/// let values = param_values! { skeleton.level[0].down_angle = 10.0 }; // the trunk has none
/// ```
///
/// ```compile_fail
/// # use sylva_core::param_values;
/// let values = param_values! { skeleton.level[4].length = 0.3 }; // levels are 0 to 3
/// ```
#[macro_export]
macro_rules! param_values {
    ($($stage:ident . $field:ident $([$n:literal] . $sub:ident)? = $v:expr),* $(,)?) => {
        $crate::params::ParamValues::new(
            |_p: &mut $crate::params::TreeParams| {
                $( $crate::param_values!(@set _p, $stage . $field $([$n] . $sub)? = $v); )*
            },
            || vec![$( $crate::param_values!(@wire $stage . $field $([$n] . $sub)? = $v) ),*],
        )
    };
    (@set $p:ident, $stage:ident . $field:ident = $v:expr) => {
        $crate::params::values::set(&mut $p.$stage.$field, $v)
    };
    (@set $p:ident, $stage:ident . $field:ident [$n:literal] . $sub:ident = $v:expr) => {{
        const _: () = assert!($n < 4, "per-level parameters are of levels 0 (the trunk) to 3");
        const _: () = assert!(
            $n != 0 || $crate::params::LevelParams::on_trunk(stringify!($sub)),
            concat!("the trunk (level 0) has no ", stringify!($sub)),
        );
        $crate::params::values::set(&mut $p.$stage.$field[$n].$sub, $v)
    }};
    (@wire $stage:ident . $field:ident = $v:expr) => {
        (stringify!($field), $crate::params::values::wire(|p| &mut p.$stage.$field, $v))
    };
    (@wire $stage:ident . $field:ident [$n:literal] . $sub:ident = $v:expr) => {
        (
            concat!("l", $n, "_", stringify!($sub)),
            $crate::params::values::wire(|p| &mut p.$stage.$field[$n].$sub, $v),
        )
    };
}
