//! clip-cyrus-beck: Cyrus-Beck parametric line clipping (convex windows) and a Liu-style line clipper (concave windows).
