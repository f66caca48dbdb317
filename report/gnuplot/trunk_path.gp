# The trunk's path seen from above before and after learning (paper §5 tunnel test, Table 1),
# with the corridor walls when given; equal scales on both axes.
# Variables: data (series, x_m, y_m; blocks separated by blank lines), before_label, after_label.
load dir.'common.gp'
set size ratio -1
# A margin so walls and paths do not run along the frame.
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
set xlabel 'x (m)'
set ylabel 'y (m)'
set title 'Trunk path seen from above' font ',14'
set key outside right top box opaque font ',10'
is(s) = strcol('series') eq s
plot data using (is('wall') ? column('x_m') : NaN):'y_m' with lines lw 4 lc rgb 'black' title 'tunnel wall', \
     data using (is('before') ? column('x_m') : NaN):'y_m' with lines lw 2.5 lc rgb red title before_label, \
     data using (is('after') ? column('x_m') : NaN):'y_m' with lines lw 2.5 lc rgb blue title after_label, \
     data using (is('before') || is('after') ? column('x_m') : NaN):'y_m' every ::0::0 with points pt 7 ps 1.5 lc rgb 'black' title 'start'
