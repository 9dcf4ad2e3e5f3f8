# OpenSees model of frame_elastic.toml: the same nodes, elements, masses, gravity, record and
# damping. Run from this folder: OpenSees frame_elastic.tcl (writes frame_elastic_opensees.out:
# time and the drift of the left beam end, and frame_elastic_periods.out). frame_nodal_masses.tcl
# sets rho and name, then runs this.
wipe
if {![info exists name]} { set name frame_elastic }
if {![info exists rho]} { set rho 7.85 }
model BasicBuilder -ndm 2 -ndf 3
set E 2.1e8
set Ac 1.491e-2; set Ic 2.517e-4
set Ab 8.446e-3; set Ib 2.313e-4
geomTransf Corotational 1
# Left column: nodes 1-7 up x = 0; beam 7-15 along y = 4; right column 15-21 down x = 6.
set n 0
for {set k 0} {$k <= 6} {incr k} { incr n; node $n 0.0 [expr 4.0*$k/6.0] }
for {set k 1} {$k <= 8} {incr k} { incr n; node $n [expr 6.0*$k/8.0] 4.0 }
for {set k 1} {$k <= 6} {incr k} { incr n; node $n 6.0 [expr 4.0 - 4.0*$k/6.0] }
fix 1 1 1 1
fix 21 1 1 1
set e 0
for {set k 1} {$k <= 20} {incr k} {
    incr e
    if {$k <= 6 || $k > 14} { set A $Ac; set I $Ic } else { set A $Ab; set I $Ib }
    element elasticBeamColumn $e $k [expr $k+1] $A $E $I 1 -mass [expr $rho*$A] -cMass
}
mass 7 50.0 50.0 0.0
mass 15 50.0 50.0 0.0

timeSeries Linear 1
pattern Plain 1 1 {
    load 7 0.0 -490.3 0.0
    load 15 0.0 -490.3 0.0
}
constraints Plain
numberer RCM
system UmfPack
test NormDispIncr 1.0e-12 30
algorithm Newton
integrator LoadControl 0.25
analysis Static
analyze 4
loadConst -time 0.0

# Rayleigh damping on the committed stiffness, 2 % in modes 1 and 2 of the state under gravity.
set lambda [eigen -fullGenLapack 2]
set w1 [expr sqrt([lindex $lambda 0])]
set w2 [expr sqrt([lindex $lambda 1])]
set out [open ${name}_periods.out w]
puts $out "[expr 2*acos(-1)/$w1] [expr 2*acos(-1)/$w2]"
close $out
set zeta 0.02
rayleigh [expr 2*$zeta*$w1*$w2/($w1+$w2)] 0.0 0.0 [expr 2*$zeta/($w1+$w2)]

# The record in g without its four header lines (ARL360.dat), linear between samples.
timeSeries Path 2 -dt 0.02 -filePath ARL360.dat -factor 9.80665
pattern UniformExcitation 2 1 -accel 2
wipeAnalysis
constraints Plain
numberer RCM
system UmfPack
test NormDispIncr 1.0e-12 30
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
recorder Node -file ${name}_opensees.out -time -node 7 -dof 1 disp
analyze 1000 0.01
wipe
