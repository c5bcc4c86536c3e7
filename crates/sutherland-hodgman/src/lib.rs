//! clip-sutherland-hodgman: Sutherland-Hodgman reentrant polygon clipping against a convex window.
