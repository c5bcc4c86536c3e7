//! The files a run leaves in the results folder, by name and row type: written by `bench` and
//! `reproduce`, read by `report`, so neither side imports the other.

pub mod atlas;
pub mod bench;
pub mod beyond_paper;
pub mod lecture_curves;
pub mod lecture_sh;
pub mod lecture_text;
pub mod vatti_table3;
pub mod verify;
pub mod wang_table4;
