//! The presets' typed values agree with their wire listing, and every preset is valid.

use super::PRESETS;
use crate::leaf::presets::LEAF_PRESETS;
use crate::params::{registry, TreeParams};

/// Every value listed for the JSON and share links goes through the registry's checks (known
/// id, range, whole numbers) and rebuilds, bit for bit, the parameters the typed assignments make.
#[test]
fn every_preset_validates_and_its_wire_values_match_its_typed_values() {
    for p in PRESETS {
        let typed = p.params().unwrap_or_else(|e| panic!("{}: {e}", p.name));
        let wire = TreeParams::from_values(p.all_values()).unwrap_or_else(|e| panic!("{}: {e}", p.name));
        assert_eq!(typed, wire, "{}", p.name);
        for s in registry() {
            let (a, b) = (typed.get(&s.id).unwrap(), wire.get(&s.id).unwrap());
            assert_eq!(a.to_bits(), b.to_bits(), "{}: {}", p.name, s.id);
        }
    }
    for p in LEAF_PRESETS {
        let typed = p.params().unwrap_or_else(|e| panic!("{}: {e}", p.name));
        let wire = TreeParams::from_values(p.values.wire()).unwrap_or_else(|e| panic!("{}: {e}", p.name));
        for s in registry() {
            let (a, b) = (typed.get(&s.id).unwrap(), wire.get(&s.id).unwrap());
            assert_eq!(a.to_bits(), b.to_bits(), "{}: {}", p.name, s.id);
        }
    }
}

/// A preset names each parameter once: a second assignment would silently win over the first
/// (and the JSON object would keep one of them).
#[test]
fn no_preset_sets_a_parameter_twice() {
    let lists =
        PRESETS.iter().map(|p| (p.name, p.values.wire())).chain(LEAF_PRESETS.iter().map(|p| (p.name, p.values.wire())));
    for (name, values) in lists {
        let mut seen = std::collections::BTreeSet::new();
        for (id, _) in values {
            assert!(seen.insert(id), "{name}: {id} twice");
        }
    }
}
