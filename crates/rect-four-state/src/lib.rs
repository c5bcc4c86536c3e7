//! clip-rect-four-state: The four-state point-splitting polygon clipper for rectangle windows.
