//! SVG plots with plotters: one chart shape (titled, labelled axes, legend, the papers' points
//! marked) and one colour table.

pub mod chart;
pub mod palette;
