//! The scaling family's scenes, from the definitions in `families.rs`.

use zeitner::constrained_system;

use super::families::{horizontal_chain, ladder_span, sagging_ladder};
use super::Visit;
use crate::scenes::structure::{
    Structure100, Structure16, Structure256, Structure32, Structure512, Structure64,
};

chain!(Chain4, 4);
chain!(Chain8, 8);
chain!(Chain16, 16);
chain!(Chain32, 32);
chain!(Chain64, 64);
chain!(Chain100, 100);
chain!(Chain128, 128);
ladder!(Ladder4, 4);
ladder!(Ladder8, 8);
ladder!(Ladder16, 16);
ladder!(Ladder32, 32);
ladder!(Ladder64, 64);
// The in-process peers' ladders: without the three dependent pin rows that the dense
// `Simulator`'s rank check names, as the dense formulations need.
ladder!(IndependentLadder16, 16, 5, [0, 3, 4, 6, 7]);
ladder!(IndependentLadder64, 64, 5, [0, 3, 4, 6, 7]);

/// Every scene of the family, smallest first.
pub fn each(visit: &mut impl Visit) {
    macro_rules! chains {
        ($($name:ident),*) => {$(
            visit.visit(&format!("chain-{}", $name::LINKS), "chain", &$name::standard(), horizontal_chain());
        )*};
    }
    macro_rules! ladders {
        ($($name:ident),*) => {$(
            visit.visit(&format!("ladder-{}", $name::NODES), "ladder", &$name::standard(), sagging_ladder());
        )*};
    }
    macro_rules! structures {
        ($($name:ident),*) => {$(
            let scene = $name::paper();
            let q0 = zeitner::Vector::from(scene.start().0);
            visit.visit(&format!("structure-{}", $name::NODE_COUNT), "structure", &scene, q0);
        )*};
    }
    chains!(Chain4, Chain8, Chain16, Chain32, Chain64, Chain100, Chain128);
    ladders!(Ladder4, Ladder8, Ladder16, Ladder32, Ladder64);
    structures!(
        Structure16,
        Structure32,
        Structure64,
        Structure100,
        Structure256,
        Structure512
    );
}
