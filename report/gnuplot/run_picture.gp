# `walk`, `learn` and `tunnel --plot FILE.png` (report/figures.h, RunPicture): the trunk's path
# seen from above, with the tunnel's walls and its axis (the course) where there is a tunnel; the
# learning trace when the run learned (as Fig. 8); a gait strip of the last steps (Fig. 2's
# colours: blue = stance, the foot on the ground).
# Variables: path (series = path | wall | course, x_m, y_m, y_low_m, y_high_m: the body's lateral
# reach; blocks separated by blank lines), has_walls, has_course, has_span, marks (kind = fault |
# detection | learned, label, x_m, y_m, step), has_marks, n_fault, n_detection, n_learned, trace
# (trial, deviation_deg, accepted, reference_deg; with has_predicted also predicted_deg,
# predicted_low_deg, predicted_high_deg: a model's forecast), has_trace, trace_note (non-empty: written
# instead of the trace), threshold (degrees), gait (leg, row, stance_start_step,
# stance_end_step), legs (names, space-separated, top to bottom), first_step, last_step, title,
# subtitle (a second line, may be empty).
load dir.'common.gp'
panels = has_trace ? 3 : 2
set multiplot layout panels, 1 title title.(subtitle ne '' ? "\n".subtitle : '') font ',12' noenhanced

# The trunk's path, equal scales on both axes, with the body's reach around it where known (the
# tunnel: a wall touched by a foot while the trunk stays clear) and what happened where.
set size ratio -1
set offsets graph 0.03, graph 0.03, graph 0.08, graph 0.08
set xlabel 'x (m)'
set ylabel 'y (m, + = left)'
set title 'Trunk path seen from above'
set key outside right top box opaque font ',10'
is(s) = strcol('series') eq s
kind(k) = strcol('kind') eq k
# Plot elements as macros: gnuplot has no conditional element inside one plot command.
band = has_span ? "path using (is('path') ? column('x_m') : NaN):'y_low_m':'y_high_m' with filledcurves fc rgb '#c9d8f0' title 'body (outermost parts)', " : ""
walls = has_walls ? "path using (is('wall') ? column('x_m') : NaN):'y_m' with lines lw 4 lc rgb 'black' title 'tunnel wall', " : ""
course = has_course ? "path using (is('course') ? column('x_m') : NaN):'y_m' with lines lw 1.5 dt 2 lc rgb grey title 'course (tunnel axis)', " : ""
# Labels: faults above, detections below, learned gaits to the right, so that marks at one place
# (a paper-mode run's detection and its first trial) stay readable.
events = has_marks ? ", marks using (kind('fault') ? column('x_m') : NaN):'y_m' with points pt 2 ps 2.5 lw 3 lc rgb red title (n_fault > 0 ? 'fault' : ''), marks using (kind('detection') ? column('x_m') : NaN):'y_m' with points pt 9 ps 2 lc rgb orange title (n_detection > 0 ? 'deviation detected' : ''), marks using (kind('learned') ? column('x_m') : NaN):'y_m' with points pt 6 ps 2.6 lw 2.5 lc rgb green title (n_learned > 0 ? 'learned gait starts' : ''), marks using 'x_m':'y_m':(kind('fault') ? strcol('label') : '') with labels offset 0, 1.5 font ',9' noenhanced notitle, marks using 'x_m':'y_m':(kind('detection') ? strcol('label') : '') with labels offset 0, -1.6 font ',9' noenhanced notitle, marks using 'x_m':'y_m':(kind('learned') ? strcol('label') : '') with labels left offset 1.6, 0 font ',9' noenhanced notitle" : ""
plot @band @walls @course \
     path using (is('path') ? column('x_m') : NaN):'y_m' with lines lw 2.5 lc rgb blue title 'trunk', \
     path using (is('path') ? column('x_m') : NaN):'y_m' every ::0::0 with points pt 7 ps 1.5 lc rgb 'black' title 'start' @events

# The learning trace: each trial's deviation, kept or rejected, E_ref and the threshold; a
# model's forecast of each trial's E a little left of the measured E it forecast (a macro, set
# outside the block that uses it: gnuplot expands a block's macros before running it).
predicted = has_predicted ? "trace using (column('trial') - 0.25):'predicted_deg':'predicted_low_deg':'predicted_high_deg' with yerrorbars pt 6 ps 1 lw 1.5 lc rgb blue title 'predicted E (median, band)', " : ""
set size noratio
set offsets 0.5, 0.5, graph 0.1, graph 0.05
if (has_trace && trace_note ne '') {
  # No trial: the sentence alone, not one lone point that would read as a trace.
  unset border
  unset xtics
  unset ytics
  unset grid
  set key off
  set xlabel ''
  set ylabel ''
  set title 'Learning trace'
  set xrange [0:1]
  set yrange [0:1]
  set label 1 trace_note at graph 0.5, 0.5 center font ',12' noenhanced
  plot 2 notitle
  unset label 1
  set border
  set xtics
  set ytics
  set key
}
if (has_trace && trace_note eq '') {
  max_labelled_trials = 30
  stats trace using 'trial' nooutput
  if (STATS_max <= max_labelled_trials) { set xtics 1 }
  set yrange [0:*]
  set xlabel 'trial (0 = detection window)'
  set ylabel 'deviation (degrees)'
  set title 'Learning trace'
  plot threshold with lines lw 2 dt 2 lc rgb 'black' title sprintf('threshold %g°', threshold), \
       @predicted \
       trace using 'trial':'reference_deg' with steps lw 2 lc rgb grey title 'E_{ref} (kept combination)', \
       trace using 'trial':(column('accepted') == 1 ? column('deviation_deg') : NaN) with points pt 7 ps 1.3 lc rgb green title 'kept', \
       trace using 'trial':(column('accepted') == 0 ? column('deviation_deg') : NaN) with points pt 2 ps 1.5 lw 2 lc rgb red title 'rejected'
}

# The gait strip: one row per leg, a blue box while its foot touches the ground.
set offsets 0, 0, 0, 0
set xtics autofreq
set autoscale y
nlegs = words(legs)
half_height = 0.38
set xrange [first_step:last_step]
set yrange [-0.6:nlegs - 0.4]
set ytics scale 0 ()
do for [k=1:nlegs] { set ytics add (word(legs, k) nlegs - k) }
unset grid
set key off
set xlabel 'controller step'
set ylabel ''
set title 'Gait strip: foot contact over the last steps (blue = stance, white = swing)'
y(row) = nlegs - 1 - row
plot gait using ((column('stance_start_step') + column('stance_end_step')) / 2.0):(y(column('row'))):\
  (column('stance_start_step')):(column('stance_end_step')):\
  (y(column('row')) - half_height):(y(column('row')) + half_height) with boxxyerror fc rgb blue
unset multiplot
