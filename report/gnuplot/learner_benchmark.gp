# The learner benchmark (docs/learning.md "Learner benchmark"): per learner, over the scenarios
# where a combination holds, the share of runs held within the budget (95% Wilson interval) and
# the trials to a held combination (median, quartiles; none where more than half never held).
# Variables: data (learner, share_held, share_low, share_high, q1_trials, median_trials,
# q3_trials), robot, budget, scenarios, seeds.
load dir.'common.gp'
stats data using 'share_held' nooutput
n = STATS_records
set xrange [-0.6:n - 0.4]
set boxwidth 0.6
set style fill solid 0.85 border lc rgb 'black'
set key off
set lmargin 10
set grid noxtics
set xtics scale 0
set offsets 0, 0, graph 0.12, 0
set multiplot layout 2, 1 title sprintf('Learners replayed on the %s landscapes (%d scenarios x %d seeds)', robot, scenarios, seeds) font ',14'
set title sprintf('Share of runs held within %d trials (bars: 95%% interval)', budget)
set ylabel 'share held'
# Room above a full bar for its label.
set yrange [0:1.12]
set ytics 0, 0.2, 1
# Five columns: x, y, ylow, yhigh, half the box width (four would read as ydelta, xdelta).
plot data using 0:'share_held':'share_low':'share_high':(0.3):xtic(1) with boxerrorbars lc rgb blue, \
     data using 0:'share_high':(sprintf('%.0f%%', 100 * column('share_held'))) \
       with labels offset 0, 0.8 font ',10'
set title sprintf('Trials to a held combination (median; bars: quartiles; axis cut at %d)', 2 * budget)
set ylabel 'trials'
set yrange [0:2 * budget]
set ytics autofreq
set xlabel 'learner'
plot data using 0:'median_trials':'q1_trials':'q3_trials':(0.3):xtic(1) with boxerrorbars lc rgb orange, \
     data using 0:'median_trials':(sprintf('%g', column('median_trials'))) \
       with labels offset 0, 0.8 font ',10'
unset multiplot
