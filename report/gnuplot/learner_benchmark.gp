# The learner benchmark (docs/learning.md "Learner benchmark"): per learner, over the scenarios
# where a combination holds, the share of runs held within the budget (95% Wilson interval) and
# the trials to a held combination (median, quartiles; "never" where that share never held).
# Variables: data (learner, share_held, share_low, share_high, share_label, bar_trials (the
# median, NaN where over half never held), whisker_low, whisker_high (the quartiles, at most
# cut), trials_label ("11 (4–never)"), trials_label_y), robot, budget, replayed ("27 scenarios
# where a combination holds x 100 seeds"), cut (no median is above it).
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
set multiplot layout 2, 1 title sprintf('Learners replayed on the %s landscapes (%s)', robot, replayed) font ',14'
set title sprintf('Share of runs held within %d trials (bars: 95%% interval)', budget)
set ylabel 'share held'
# Room above a full bar for its label.
set yrange [0:1.12]
set ytics 0, 0.2, 1
# Five columns: x, y, ylow, yhigh, half the box width (four would read as ydelta, xdelta).
plot data using 0:'share_held':'share_low':'share_high':(0.3) with boxerrorbars lc rgb blue, \
     data using 0:'share_high':'share_label':xtic(1) with labels offset 0, 0.8 font ',10'
set title sprintf('Trials to a held combination: median (bar), quartiles (whisker; one past %g ends there)', cut)
set ylabel 'trials'
# A fifth above the highest bar or whisker for the labels over it.
label_room = 1.2
set yrange [0:label_room * cut]
set ytics autofreq
set xlabel 'learner'
plot data using 0:'bar_trials':'whisker_low':'whisker_high':(0.3) with boxerrorbars lc rgb orange, \
     data using 0:'trials_label_y':'trials_label':xtic(1) with labels offset 0, 0.8 font ',10'
unset multiplot
