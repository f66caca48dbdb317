# Fig. 14 (paper §4.3): trials to converge for each annealing factor beta, mean ± SD,
# the mean written in blue above each bar as in the paper. Bar colours follow the paper:
# beta = 0 (random search) blue, beta >= 10 (about greedy) green, simulated annealing red.
# Variables: data (beta, mean_trials, sd_trials, share_converged), disabled_legs.
load dir.'common.gp'
stats data using 'beta' nooutput
n = STATS_records
colour(b) = b == 0 ? 0x1f5fbf : (b >= 10 ? 0x2ca02c : 0xd62728)
top(m, s) = m + (s > 0 ? s : 0)
set xrange [-0.6:n - 0.4]
set yrange [0:*]
# Head room for the labels above the bars.
set offsets 0, 0, graph 0.12, 0
set boxwidth 0.6
set style fill solid 0.85 border lc rgb 'black'
set grid noxtics
set xtics scale 0
set xlabel 'annealing factor β'
set ylabel 'trials to converge (mean ± SD)'
set title sprintf('Trials needed for each β (%s disabled; labels: mean, share converged)', disabled_legs) font ',13'
set key top left box opaque font ',10'
plot data using 0:'mean_trials':'sd_trials':(colour(column('beta'))):xtic(sprintf('%g', column('beta'))) \
       with boxerrorbars lc rgb variable notitle, \
     data using 0:(top(column('mean_trials'), column('sd_trials'))):(sprintf('%.1f', column('mean_trials'))) \
       with labels offset 0, 1.6 tc rgb blue font ',10,Bold' notitle, \
     data using 0:(top(column('mean_trials'), column('sd_trials'))):(sprintf('%.0f%%', 100 * column('share_converged'))) \
       with labels offset 0, 0.6 tc rgb grey font ',9' notitle, \
     keyentry with boxes lc rgb blue title 'random search (β = 0)', \
     keyentry with boxes lc rgb red title 'simulated annealing', \
     keyentry with boxes lc rgb green title 'about greedy (β ≥ 10)'
