//! Closed forms of the paper's linearized laws: one pure function per quantity, each citing
//! the paper's equation number and the tag of physics.md (\[P\], \[P*\], \[G\], \[D\]).

pub mod lobe;
pub mod pulled_mass;
pub mod woodpecker;
