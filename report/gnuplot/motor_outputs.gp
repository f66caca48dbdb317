# Fig. 9 (paper §4): the motor outputs of every leg, one panel per leg (right legs left column,
# left legs right column), TC green, CTr red, FTi blue as in the paper.
# Variables: data (step, time_s, <leg>_TC, <leg>_CTr, <leg>_FTi ...), legs, title<i>, step_seconds.
load dir.'common.gp'
nlegs = words(legs)
rows = ceil(nlegs / 2.0)
# Head room above 1 keeps the key off the curves.
set yrange [-1.15:1.6]
set ytics -1, 0.5, 1
set xlabel sprintf('time step (1 step = %.3g s)', step_seconds)
set ylabel 'motor output m'
set key top right horizontal font ',9' samplen 2
set multiplot layout rows, 2 columnsfirst title sprintf('Motor outputs of the %d joints', 3 * nlegs) font ',14'
do for [i=1:nlegs] {
  leg = word(legs, i)
  set title sprintf('(%c) %s', 96 + i, value(sprintf('title%d', i)))
  plot data using 'step':(column(leg.'_TC')) with lines lw 2 lc rgb green title 'TC', \
       data using 'step':(column(leg.'_CTr')) with lines lw 2 lc rgb red title 'CTr', \
       data using 'step':(column(leg.'_FTi')) with lines lw 2 lc rgb blue title 'FTi'
}
unset multiplot
