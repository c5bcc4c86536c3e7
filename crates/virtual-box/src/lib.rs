//! clip-virtual-box: Line clipping against polygons by multiple virtual boxes (MEB, 45-degree box, slope-adaptive box), after Wang et al. 2005.
