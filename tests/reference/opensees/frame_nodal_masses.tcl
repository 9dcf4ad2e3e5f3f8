# OpenSees model of frame_nodal_masses.toml: frame_elastic.tcl with massless members.
set name frame_nodal_masses
set rho 1e-12
source frame_elastic.tcl
