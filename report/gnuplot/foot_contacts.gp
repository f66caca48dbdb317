# Fig. 10 (paper §4): foot contact of every leg over time, 1 = touching the ground (stance),
# 0 = in the air (swing); one row per leg, front to hind, right then left.
# Variables: data (step, time_s, one 0/1 column per leg), legs, step_seconds.
load dir.'common.gp'
nlegs = words(legs)
set yrange [-0.15:1.3]
set ytics (0, 1)
set grid noytics
set key off
# Light fill with a border of its own colour: adjacent steps then show no seams.
light_blue = '#9bb8e6'
set multiplot layout nlegs, 1 title 'Foot contact signals (1 = ground contact)' font ',14' \
    margins 0.08, 0.97, 0.08, 0.93 spacing 0, 0.012
do for [i=1:nlegs] {
  leg = word(legs, i)
  set ylabel leg rotate by 0 offset 1, 0
  if (i < nlegs) { set format x ''; unset xlabel } else {
    set format x '%g'; set xlabel sprintf('time step (1 step = %.3g s)', step_seconds) }
  plot data using 'step':(column(leg)) with fillsteps fs solid 1 border lc rgb light_blue lc rgb light_blue, \
       data using 'step':(column(leg)) with steps lw 1.5 lc rgb blue
}
unset multiplot
