# Figs. 11 and 13 (paper §4): per disabled-leg scenario the trials learning needed
# and the final deviation, mean ± SD over the runs; the label is the share of runs that
# converged (reached the threshold within the trial cap), or "n/d" when no run had
# anything to learn.
# Variables: data (scenario, mean_trials, sd_trials, mean_deviation_deg, sd_deviation_deg,
# share_converged, label), robot, threshold.
load dir.'common.gp'
stats data using 'mean_trials' nooutput
n = STATS_records
set xrange [-0.6:n - 0.4]
set boxwidth 0.6
set style fill solid 0.85 border lc rgb 'black'
set key off
# The same left margin in both panels keeps their bars aligned.
set lmargin 10
set grid noxtics
set xtics rotate by -40 left font ',10' scale 0
set yrange [0:*]
# Head room for the labels above the bars.
set offsets 0, 0, graph 0.12, 0
set multiplot layout 2, 1 title sprintf('Learning results, %s (mean ± SD over runs)', robot) font ',14'
set title 'Trials to converge (label: share of runs converged; n/d: never deviated, nothing to learn)'
set ylabel 'trials'
top(m, s) = m + (s > 0 ? s : 0)
plot data using 0:'mean_trials':'sd_trials':xtic(1) with boxerrorbars lc rgb blue, \
     data using 0:(top(column('mean_trials'), column('sd_trials'))):(stringcolumn('label')) \
       with labels offset 0, 0.8 font ',9'
set title sprintf('Final deviation (dashed: threshold %g°)', threshold)
set ylabel 'deviation (degrees)'
set xlabel 'disabled legs'
plot data using 0:'mean_deviation_deg':'sd_deviation_deg':xtic(1) with boxerrorbars lc rgb orange, \
     threshold with lines lw 2 dt 2 lc rgb 'black'
unset multiplot
