//! clip-vatti: Vatti's generic polygon clipper (1992): intersection, union, difference and xor, polygon and trapezoid output.
