# OpenSees model of models/gallery/rc_column.toml: a 300 × 500 column of C30 (Concrete01 with fpcu = fpc: the
# parabola to eps_c2 = 0.002, then fc) with 2 × 942 mm² of B500 (Steel01, no hardening), 3 m
# tall on a clamp, 1000 kN held, then pushed sideways at its top to 100 mm in 1 mm steps.
# Units N and mm. The bars' concrete is taken out by fibres of negative area, as Plastica does.
# Run from this folder: OpenSees rc_column.tcl (writes rc_column_opensees.out: top displacement,
# lateral load). Its force-based elements stop converging at 49 mm, past the peak.
wipe
model BasicBuilder -ndm 2 -ndf 3
uniaxialMaterial Concrete01 1 -30.0 -0.002 -30.0 -0.0035
uniaxialMaterial Steel01 2 500.0 200000.0 0.0
section Fiber 1 {
    for {set k 0} {$k < 100} {incr k} { fiber [expr -250.0 + 5.0*($k + 0.5)] 0.0 1500.0 1 }
    fiber 200.0 0.0 942.0 2
    fiber -200.0 0.0 942.0 2
    fiber 200.0 0.0 -942.0 1
    fiber -200.0 0.0 -942.0 1
}
geomTransf Corotational 1
for {set k 0} {$k <= 4} {incr k} { node [expr $k+1] 0.0 [expr 750.0*$k] }
fix 1 1 1 1
beamIntegration Lobatto 1 1 5
for {set k 1} {$k <= 4} {incr k} { element forceBeamColumn $k $k [expr $k+1] 1 1 }

timeSeries Linear 1
pattern Plain 1 1 { load 5 0.0 -1.0e6 0.0 }
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator LoadControl 0.25
analysis Static
analyze 4
loadConst -time 0.0

timeSeries Linear 2
pattern Plain 2 2 { load 5 1000.0 0.0 0.0 }
integrator DisplacementControl 5 1 1.0
set out [open rc_column_opensees.out w]
for {set k 1} {$k <= 100} {incr k} {
    set ok [analyze 1]
    if {$ok != 0} { algorithm ModifiedNewton -initial; set ok [analyze 1]; algorithm Newton }
    if {$ok != 0} { break }
    puts $out "[nodeDisp 5 1] [expr 1000.0*[getTime]]"
}
close $out
