# The landscape of one leg-failure scenario. Every combination of working-leg periods,
# sorted by its worst deviation (the largest |yaw change| or |path angle| over its windows, with the
# steering reflex its effort too); the grey dots are each window's own worst deviation (NaN for a
# window not walked after one over the threshold), the dashed line the threshold. A combination
# holds when its curve point is under the line. The green diamond is the best holding
# combination, red circles the combinations learning answered.
# Variables: data (rank, worst_deg, holds, first_window_passes, best, learned, label, then one
# w<n>_worst_deg column per window), title, subtitle, threshold (degrees), windows, count and
# learned (how many learned answers are marked).
# The best one's label is an empty text at every other point, never an undefined y: gnuplot 5.4
# crashes on labels whose every y is undefined when the data has one row (one combination).
load dir.'common.gp'
first_window_column = 8
floor_deg = 0.01
# A yaw change wraps at 180 degrees and a path angle is at most 180 degrees.
max_deg = 180
clamp(d) = d > floor_deg ? d : floor_deg
set logscale y
set yrange [*:max_deg]
set xrange [0:count + 1]
set xlabel 'combinations, sorted by worst deviation'
set ylabel 'deviation (degrees, log scale)'
set title title."\n{/*0.8 ".subtitle."}" font ',14'
set key outside right top vertical font ',10' noenhanced
plot for [w=1:windows] data using 'rank':(clamp(column(first_window_column + w - 1))) \
       with points pt 7 ps 0.25 lc rgb '#c8c8c8' title (w == 1 ? 'one window' : ''), \
     data using 'rank':(clamp(column('worst_deg'))) with lines lw 2 lc rgb blue \
       title 'worst window of the combination', \
     threshold with lines lw 2 dt 2 lc rgb 'black' title sprintf('threshold %g° (holds below)', threshold), \
     data using 'rank':(column('learned') > 0 ? clamp(column('worst_deg')) : NaN) \
       with points pt 6 ps 2 lw 2 lc rgb red title (learned > 0 ? 'learned' : ''), \
     data using 'rank':(column('best') == 1 ? clamp(column('worst_deg')) : NaN) \
       with points pt 13 ps 2.5 lc rgb green title 'best holding', \
     data using 'rank':(clamp(column('worst_deg'))):(column('best') == 1 ? strcol('label') : '') \
       with labels left offset 1.5, -1 font ',10' noenhanced notitle
