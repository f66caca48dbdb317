# Fig. 2 (paper §2.1; docs/controller.md "Gaits"): gait diagrams, one panel per period, legs as
# rows top to bottom; blue = stance (the leg supports the body), white = swing.
# Variables: data (period,leg,row,stance_start_step,stance_end_step), panels, period<i>,
# title<i> (i = 1..panels), steps, step_seconds, legs (names, space-separated, top to bottom).
load dir.'common.gp'
nlegs = words(legs)
half_height = 0.38
set xrange [0:steps]
set yrange [-0.6:nlegs - 0.4]
set ytics scale 0 ()
do for [k=1:nlegs] { set ytics add (word(legs, k) nlegs - k) }
unset grid
set xlabel sprintf('time step (1 step = %.3g s)', step_seconds)
set key off
y(row) = nlegs - 1 - row
cols = panels > 1 ? 2 : 1
rows = ceil(panels / (1.0 * cols))
set multiplot layout rows, cols title 'Gait diagrams (blue = stance, white = swing)' font ',14'
do for [i=1:panels] {
  p = value(sprintf('period%d', i))
  set title value(sprintf('title%d', i))
  plot data using (column('period') == p ? (column('stance_start_step') + column('stance_end_step')) / 2.0 : NaN):\
    (y(column('row'))):(column('stance_start_step')):(column('stance_end_step')):\
    (y(column('row')) - half_height):(y(column('row')) + half_height) with boxxyerror fc rgb blue
}
unset multiplot
