//! SVG plots with plotters: one chart shape (titled, labelled axes fitted to the data, one
//! tick-label style, a legend beside the plot, the papers' points marked) and one colour table.

pub mod chart;
pub mod palette;
