//! clip-raster: Scanline polygon fill and Vatti trapezoid fill into a frame buffer.
