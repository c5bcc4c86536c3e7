//! clipbench: verify clipping algorithms against exact oracles, peer libraries and external
//! suites, reproduce the papers' performance tables (Vatti 1992, Table 3; Wang, Lu, Peng and Wu
//! 2005, Table 4; full citations in `papers` and the README), benchmark every polygon clipper
//! against geo and Clipper2, and run one clipping operation on files by hand. One module per
//! command; the clippers are in `registry`. Results flow one way: `bench` and `reproduce` measure
//! and write the raw files (`results_files`), then this dispatcher has `report` turn them into
//! REPORT.md. The conventions every check relies on are set out in the repository's
//! `docs/DESIGN.md`.
//!
//! The commands live in this library so that its readers (`read`, the conformance suites'
//! readers, `verify`'s case files) can be fuzzed (`fuzz/`, through `clip-fuzz-checks`); the
//! binary in `main.rs` only parses the command line.

pub mod bench;
pub mod checks;
pub mod cli_error;
pub mod clip;
pub mod clip_curves;
pub mod clip_features;
pub mod compare;
pub mod conformance;
pub mod console;
pub mod curve_input;
pub mod external;
pub mod hostile;
pub mod measure;
pub mod merge;
pub mod papers;
pub mod partition;
pub mod plot;
pub mod read;
pub mod referee;
pub mod registry;
pub mod report;
pub mod reproduce;
pub mod results_files;
pub mod text_cmd;
pub mod text_paragraph;
pub mod text_svg;
pub mod verify;
pub mod write;
